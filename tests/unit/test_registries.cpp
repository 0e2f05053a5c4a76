// test_registries.cpp - every kind with a registry (material models, shapes, boundaries, probes) refuses a type
// it does not list, at the loader, with a message naming the key and the registered types; and a scene whose
// objects are all registered builds a simulation whose parts are the registered ones.
#include <gtest/gtest.h>

#include <string>

#include "probe/probe.h"
#include "scene/scene_loader.h"
#include "sim/simulation.h"

namespace cdmpm {
namespace {

nlohmann::json base_scene() {
  return {{"dim", 2},
          {"domain", {{"size", {1.0, 1.0}}, {"dx", 0.1}}},
          {"time", {{"end", 0.1}, {"frame_interval", 0.1}}},
          {"materials", {{"water", {{"type", "water"}, {"density", 1000}, {"bulk_modulus", 1e5}}}}},
          {"bodies", {{{"material", "water"}, {"particles_per_cell", 4},
                       {"shape", {{"type", "box"}, {"min", {0.0, 0.0}}, {"max", {0.5, 0.5}}}}}}},
          {"boundaries", {{{"type", "walls"}}}},
          {"probes", {{"list", {{{"name", "m"}, {"type", "mass"}}}}}}};
}

// Loading `j` fails with a message that contains every one of `parts`.
void expect_refused(const nlohmann::json& j, const std::vector<std::string>& parts) {
  try {
    scene_from_json(j, "registry.json");
    FAIL() << "scene was accepted";
  } catch (const SceneError& e) {
    for (const auto& p : parts) EXPECT_NE(std::string(e.what()).find(p), std::string::npos) << e.what() << " lacks " << p;
  }
}

TEST(Registries, BaseSceneLoadsAndBuilds) {
  const Scene s = scene_from_json(base_scene(), "registry.json");
  Simulation<2> sim(s);
  EXPECT_EQ(sim.boundaries.size(), 1u);
  EXPECT_EQ(make_probes<2>(s).size(), 1u);
  EXPECT_TRUE(sim.materials[0].traits().fluid);
  EXPECT_EQ(sim.materials[0].type(), "water");
}

TEST(Registries, UnknownMaterialTypeIsRefused) {
  nlohmann::json j = base_scene();
  j["materials"]["water"]["type"] = "lava";
  expect_refused(j, {"materials.water.type", "\"water\", \"ice\", \"rigid\"", "lava"});
}

TEST(Registries, UnknownShapeTypeIsRefused) {
  nlohmann::json j = base_scene();
  j["bodies"][0]["shape"]["type"] = "torus";
  expect_refused(j, {"bodies[0].shape.type", "\"box\", \"ball\", \"polygon\"", "torus"});
}

TEST(Registries, PolygonIsNotA3DShape) {
  nlohmann::json j = base_scene();
  j["dim"] = 3;
  j["domain"]["size"] = {1.0, 1.0, 1.0};
  j["bodies"][0]["particles_per_cell"] = 8;
  j["bodies"][0]["shape"] = {{"type", "polygon"}, {"vertices", {{0, 0}, {1, 0}, {0, 1}}}};
  expect_refused(j, {"bodies[0].shape.type", "\"box\", \"ball\", \"prism\"", "polygon"});
}

TEST(Registries, UnknownBoundaryTypeIsRefused) {
  nlohmann::json j = base_scene();
  j["boundaries"][0]["type"] = "moat";
  expect_refused(j, {"boundaries[0].type", "\"walls\", \"half_plane\", \"box\", \"bathymetry\"", "moat"});
}

TEST(Registries, UnknownProbeTypeIsRefused) {
  nlohmann::json j = base_scene();
  j["probes"]["list"][0]["type"] = "thermometer";
  expect_refused(j, {"probes.list[0].type", "\"wave_gauge\"", "\"mass\"", "thermometer"});
}

TEST(Registries, KeyOfAnotherTypeIsRefusedByTheTypeThatReadsIt) {
  nlohmann::json j = base_scene();
  j["boundaries"][0]["points"] = {{0, 0}, {1, 0}};  // a bathymetry key on walls
  expect_refused(j, {"boundaries[0].points", "unknown key"});
  j = base_scene();
  j["materials"]["water"]["youngs_modulus"] = 1e9;  // an ice key on water
  expect_refused(j, {"materials.water.youngs_modulus", "unknown key"});
}

}  // namespace
}  // namespace cdmpm
