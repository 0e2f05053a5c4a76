// test_scene_loader.cpp - scene loading: every malformed scene of tests/bad_scenes/patches.json is rejected with
// the expected message (its base scenes load), a valid scene round-trips with defaults filled, and --set overrides behave.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "bad_scenes.h"
#include "probe/probes.h"
#include "scene/scene_loader.h"
#include "sim/simulation.h"

namespace cdmpm {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

// A small valid 2D scene using only required keys.
json minimal_scene() {
  return json::parse(R"({
    "dim": 2,
    "domain": {"size": [0.6, 0.3], "dx": 0.01},
    "time": {"end": 0.5, "frame_interval": 0.01},
    "materials": {"water": {"type": "water", "density": 1000, "bulk_modulus": 2e5}},
    "bodies": [{"material": "water", "particles_per_cell": 4,
                "shape": {"type": "box", "min": [0, 0], "max": [0.1, 0.2]}}]
  })");
}

// Runs `f`, expects a SceneError and returns its message.
template <class F>
std::string error_of(F f) {
  try {
    f();
  } catch (const SceneError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no SceneError thrown";
  return "";
}

TEST(SceneLoader, BadScenesAreRejectedWithExpectedMessage) {
  testing::TempDir dir;
  const std::vector<testing::BadScene> scenes = testing::write_bad_scenes(dir.path);
  for (const testing::BadScene& s : scenes) {
    std::string msg = error_of([&] { load_scene(s.path); });
    EXPECT_NE(msg.find(s.message), std::string::npos)
        << s.name << ": message \"" << msg << "\" lacks \"" << s.message << "\"";
    EXPECT_NE(msg.find(s.name + ".json"), std::string::npos)
        << s.name << ": message \"" << msg << "\" lacks the file name";
  }
  EXPECT_GE(scenes.size(), 15u);
  // Every file of tests/bad_scenes is a row's; each base scene loads, so that a row is refused for its change.
  EXPECT_EQ(testing::unused_bad_scene_files(), std::vector<std::string>{});
  for (const std::string& base : testing::bad_scene_bases()) {
    EXPECT_NO_THROW(load_scene(base)) << base;
  }
}

TEST(SceneLoader, MissingFileIsAnError) {
  std::string msg = error_of([] { load_scene("/nonexistent/scene.json"); });
  EXPECT_NE(msg.find("/nonexistent/scene.json"), std::string::npos);
}

TEST(SceneLoader, DefaultsAreFilled) {
  Scene s = scene_from_json(minimal_scene(), "scenes/my_pool.json");
  EXPECT_EQ(s.path, "scenes/my_pool.json");
  EXPECT_EQ(s.name, "my_pool");
  EXPECT_EQ(s.dim, 2);
  EXPECT_EQ(s.gravity, (std::vector<double>{0, -9.81}));
  EXPECT_DOUBLE_EQ(s.time.cfl, 0.4);
  EXPECT_DOUBLE_EQ(s.time.wave_cfl, 0.4);
  EXPECT_DOUBLE_EQ(s.time.max_dt, 0);
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_DOUBLE_EQ(std::get<Water>(s.materials[0].model).eos.gamma, 7);
  EXPECT_DOUBLE_EQ(std::get<Water>(s.materials[0].model).eos.mu, 0);
  ASSERT_EQ(s.bodies.size(), 1u);
  EXPECT_EQ(s.bodies[0].material_index, 0);
  EXPECT_EQ(s.bodies[0].velocity, (std::vector<double>{0, 0}));
  EXPECT_TRUE(s.bodies[0].hydrostatic);
  EXPECT_FALSE(s.bodies[0].surface_level.has_value());
  EXPECT_TRUE(s.boundaries.empty());
  EXPECT_TRUE(s.probes.empty());
  EXPECT_TRUE(s.output.frames);
  EXPECT_EQ(s.output.checkpoint_every, 0);
  EXPECT_DOUBLE_EQ(s.output.probe_interval, 0.001);
  EXPECT_EQ(s.json, minimal_scene());
}

TEST(SceneLoader, FullSceneRoundTrips) {
  json j = minimal_scene();
  j["name"] = "full";
  j["time"].update(json{{"cfl", 0.3}, {"wave_cfl", 0.5}, {"max_dt", 1e-4}});
  j["gravity"] = {1, -9};
  j["materials"]["ice"] = {{"type", "water"}, {"density", 900}, {"bulk_modulus", 1e6}, {"gamma", 3}, {"viscosity", 0.1}};
  j["bodies"].push_back(json::parse(R"({"material": "water", "particles_per_cell": 9, "velocity": [1, 2],
      "hydrostatic": false, "surface_level": 0.25, "shape": {"type": "ball", "center": [0.3, 0.15], "radius": 0.1}})"));
  j["bodies"].push_back(json::parse(R"({"material": "ice", "particles_per_cell": 1,
      "shape": {"type": "polygon", "vertices": [[0.2, 0], [0.4, 0], [0.3, 0.1]]}})"));
  j["boundaries"] = json::parse(R"([
    {"type": "walls", "condition": "slip", "friction": 0.0, "faces": ["x-", "x+", "y-"]},
    {"type": "half_plane", "point": [0, 0.01], "normal": [0, 2], "condition": "sticky"},
    {"type": "box", "min": [0.5, 0], "max": [0.6, 0.05], "friction": 0.3},
    {"type": "bathymetry", "points": [[0, 0.0], [0.6, 0.1]], "condition": "slip"}])");
  j["probes"] = json::parse(R"({"interval": 0.002, "list": [
    {"name": "p_bottom", "type": "pressure", "position": [0.25, 0.0]},
    {"name": "ke", "type": "kinetic_energy", "material": "ice"},
    {"name": "front", "type": "front", "material": "water", "axis": 1, "direction": -1},
    {"name": "g1", "type": "wave_gauge", "position": [0.4], "still_level": 0.1},
    {"name": "m", "type": "mass"}]})");
  j["output"] = {{"frames", false}, {"checkpoint_every", 10}};

  Scene s = scene_from_json(j, "x.json");
  EXPECT_EQ(s.name, "full");
  EXPECT_DOUBLE_EQ(s.time.cfl, 0.3);
  EXPECT_DOUBLE_EQ(s.time.wave_cfl, 0.5);
  EXPECT_DOUBLE_EQ(s.time.max_dt, 1e-4);
  EXPECT_EQ(s.gravity, (std::vector<double>{1, -9}));
  ASSERT_EQ(s.materials.size(), 2u);
  int ice = s.material_index("ice"), water = s.material_index("water");
  const WeaklyCompressibleWater& eos = std::get<Water>(s.materials[ice].model).eos;
  EXPECT_DOUBLE_EQ(s.materials[ice].density(), 900);
  EXPECT_DOUBLE_EQ(eos.K, 1e6);
  EXPECT_DOUBLE_EQ(eos.gamma, 3);
  EXPECT_DOUBLE_EQ(eos.mu, 0.1);

  ASSERT_EQ(s.bodies.size(), 3u);
  const BodySpec& ball = s.bodies[1];
  EXPECT_EQ(ball.material_index, water);
  EXPECT_EQ(ball.particles_per_cell, 9);
  const auto& sphere = std::get<BallShape>(ball.shape.model());
  EXPECT_EQ(sphere.center, (std::vector<double>{0.3, 0.15}));
  EXPECT_DOUBLE_EQ(sphere.radius, 0.1);
  EXPECT_EQ(ball.velocity, (std::vector<double>{1, 2}));
  EXPECT_FALSE(ball.hydrostatic);
  EXPECT_DOUBLE_EQ(ball.surface_level.value(), 0.25);
  EXPECT_EQ(s.bodies[2].material, "ice");
  EXPECT_EQ(s.bodies[2].material_index, ice);
  const auto& triangle = std::get<PolygonShape>(s.bodies[2].shape.model());
  ASSERT_EQ(triangle.vertices.size(), 3u);
  EXPECT_DOUBLE_EQ(triangle.vertices[2][1], 0.1);

  // Boundaries and probes keep the object their type checked; the simulation and the run build them from it.
  ASSERT_EQ(s.boundaries.size(), 4u);
  const std::vector<std::string> boundary_types = {"walls", "half_plane", "box", "bathymetry"};
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(s.boundaries[i].type, boundary_types[i]);
    EXPECT_EQ(s.boundaries[i].path, "boundaries[" + std::to_string(i) + "]");
    EXPECT_EQ(s.boundaries[i].json, j["boundaries"][i]);
  }
  ASSERT_EQ(s.probes.size(), 5u);
  EXPECT_DOUBLE_EQ(s.output.probe_interval, 0.002);
  const std::vector<std::string> probe_names = {"p_bottom", "ke", "front", "g1", "m"};
  for (size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(s.probes[i].name, probe_names[i]);
    EXPECT_EQ(s.probes[i].type, j["probes"]["list"][i]["type"]);
    EXPECT_EQ(s.probes[i].path, "probes.list[" + std::to_string(i) + "]");
  }
  Simulation<2> sim(s);
  EXPECT_EQ(sim.boundaries.size(), 4u);
  Probes<2> probes(s, sim);
  EXPECT_EQ(probes.csv_header(), "time,p_bottom,ke,front,g1,m");
  EXPECT_FALSE(s.output.frames);
  EXPECT_EQ(s.output.checkpoint_every, 10);
  EXPECT_EQ(s.json, j);
}

TEST(SceneLoader, ThreeDimensionalScene) {
  json j = json::parse(R"({
    "dim": 3,
    "domain": {"size": [1, 1, 1], "dx": 0.05},
    "time": {"end": 1, "frame_interval": 0.1},
    "materials": {"water": {"type": "water", "density": 1000, "bulk_modulus": 2e5}},
    "bodies": [{"material": "water", "particles_per_cell": 8,
                "shape": {"type": "box", "min": [0, 0, 0], "max": [0.5, 1, 0.5]}}],
    "boundaries": [{"type": "walls"},
                   {"type": "bathymetry", "origin": [0, 0], "spacing": [0.5, 1],
                    "heights": [[0, 0.1, 0.2], [0, 0.1, 0.3]]}],
    "probes": {"list": [{"name": "g", "type": "wave_gauge", "position": [0.7, 0.5]}]}
  })");
  Scene s = scene_from_json(j, "s3.json");
  EXPECT_EQ(s.gravity, (std::vector<double>{0, 0, -9.81}));
  EXPECT_EQ(s.boundaries[1].type, "bathymetry");
  EXPECT_EQ(s.probes[0].json["position"], (std::vector<double>{0.7, 0.5}));
  EXPECT_EQ(Simulation<3>(s).boundaries.size(), 2u);

  j["bodies"][0]["particles_per_cell"] = 4;  // 4 is not a cube
  EXPECT_NE(error_of([&] { scene_from_json(j, "s3.json"); }).find("bodies[0].particles_per_cell"), std::string::npos);
  j["bodies"][0]["particles_per_cell"] = 8;
  j["boundaries"][1]["heights"][1] = {0, 0.1};  // ragged
  EXPECT_NE(error_of([&] { scene_from_json(j, "s3.json"); }).find("boundaries[1].heights[1]"), std::string::npos);
  j["boundaries"][1]["heights"][1] = {0, 0.1, 0.3};
  j["bodies"][0]["shape"] = {{"type", "polygon"}, {"vertices", {{0, 0}, {1, 0}, {0, 1}}}};  // 2D only
  EXPECT_NE(error_of([&] { scene_from_json(j, "s3.json"); }).find("bodies[0].shape.type"), std::string::npos);
}

// The output switches (frames written raw, positions in single precision) and the hazard record switched off.
TEST(SceneLoader, OutputAndHazardSwitchesAreRead) {
  Scene s = scene_from_json(minimal_scene(), "x.json");
  EXPECT_TRUE(s.output.compress);
  EXPECT_FALSE(s.output.float32_positions);
  EXPECT_TRUE(s.hazard.enabled);
  json j = minimal_scene();
  j["output"] = {{"compress", false}, {"positions", "float32"}};
  j["hazard"] = {{"enabled", false}};
  s = scene_from_json(j, "x.json");
  EXPECT_FALSE(s.output.compress);
  EXPECT_TRUE(s.output.float32_positions);
  EXPECT_FALSE(s.hazard.enabled);
  j["output"]["positions"] = "float16";
  EXPECT_NE(error_of([&] { scene_from_json(j, "x.json"); }).find("output.positions: expected one of"), std::string::npos);
}

// An ice's initial strength given as its hardening variable alpha0 (p0 = kappa (1e-4 + sinh(xi max(-alpha0, 0))),
// docs/ice.md), and perfect plasticity (no hardening) at that strength.
TEST(SceneLoader, IceStrengthFromAlpha0AndHardeningOff) {
  json j = minimal_scene();
  j["materials"]["ice"] = {{"type", "ice"}, {"density", 917}, {"youngs_modulus", 1e9}, {"M", 1.85}, {"beta", 0.3},
                           {"xi", 3}, {"alpha0", -0.01}, {"hardening", false}};
  Scene s = scene_from_json(j, "x.json");
  const Ice& ice = std::get<Ice>(s.materials[s.material_index("ice")].model);
  EXPECT_FALSE(ice.plastic.hardening);
  const double kappa = ice.elastic.kappa;
  EXPECT_NEAR(ice.p0_initial, kappa * (1e-4 + std::sinh(3 * 0.01)), 1e-5 * kappa);
  j["materials"]["ice"].erase("hardening");
  s = scene_from_json(j, "x.json");
  EXPECT_TRUE(std::get<Ice>(s.materials[s.material_index("ice")].model).plastic.hardening);
  j["materials"]["ice"]["alpha0"] = 0.5;  // alpha0 <= 0
  EXPECT_NE(error_of([&] { scene_from_json(j, "x.json"); }).find("materials.ice.alpha0"), std::string::npos);
}

TEST(SceneLoader, OverridesApplyBeforeValidation) {
  Scene s = scene_from_json(minimal_scene(), "x.json",
                            {"domain.dx=0.005", "bodies.0.particles_per_cell=16", "bodies.0.shape.max.1=0.25",
                             "name=renamed", "bodies.0.hydrostatic=false", "time.max_dt=0.001",
                             "materials.water.viscosity=1e-3", "gravity=[0,-1]"});
  EXPECT_DOUBLE_EQ(s.domain.dx, 0.005);
  EXPECT_EQ(s.bodies[0].particles_per_cell, 16);
  EXPECT_DOUBLE_EQ(s.bodies[0].shape.upper(1), 0.25);
  EXPECT_EQ(s.name, "renamed");
  EXPECT_FALSE(s.bodies[0].hydrostatic);
  EXPECT_DOUBLE_EQ(s.time.max_dt, 0.001);
  EXPECT_DOUBLE_EQ(std::get<Water>(s.materials[0].model).eos.mu, 1e-3);
  EXPECT_EQ(s.gravity, (std::vector<double>{0, -1}));
  EXPECT_EQ(s.json["time"]["max_dt"], 0.001);
  // A quoted JSON string works too.
  EXPECT_EQ(scene_from_json(minimal_scene(), "x.json", {R"(name="quoted")"}).name, "quoted");
}

TEST(SceneLoader, BadOverridesAreRejected) {
  auto msg = [](const std::string& o) { return error_of([&] { scene_from_json(minimal_scene(), "x.json", {o}); }); };
  // Unknown key: the override is applied, then validation names the key.
  EXPECT_NE(msg("time.max_dtt=0.1").find("x.json: time.max_dtt: unknown key"), std::string::npos);
  // An override can make a value invalid.
  EXPECT_NE(msg("bodies.0.particles_per_cell=5").find("bodies[0].particles_per_cell"), std::string::npos);
  EXPECT_NE(msg("domain.dx=abc").find("domain.dx: expected a number"), std::string::npos);
  // Malformed or dangling overrides name the override and the file.
  for (const std::string o : {"domain.dx", "=1", "domain..dx=1", "domain.dx.=1", "nothere.x=1", "bodies.1.material=w",
                              "bodies.x.material=w", "domain.dx.sub=1"}) {
    std::string m = msg(o);
    EXPECT_NE(m.find("x.json"), std::string::npos) << m;
    EXPECT_NE(m.find(o), std::string::npos) << m;
  }
  EXPECT_NE(msg("bodies.1.material=w").find("bodies.1 does not exist"), std::string::npos);
}

TEST(SceneLoader, LoadSceneReadsFileAndAppliesOverrides) {
  fs::path path = fs::temp_directory_path() / "cdmpm_scene_loader_test.json";
  std::ofstream(path) << minimal_scene().dump(2);
  Scene s = load_scene(path.string(), {"time.end=2"});
  EXPECT_EQ(s.name, "cdmpm_scene_loader_test");
  EXPECT_DOUBLE_EQ(s.time.end, 2);
  EXPECT_EQ(s.path, path.string());
  fs::remove(path);
}

}  // namespace
}  // namespace cdmpm
