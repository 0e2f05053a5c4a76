// test_absorbing_layer_input.cpp - the "absorbing_layer" boundary (boundary/absorbing_layer.cpp): bad keys are
// refused naming the key. Its reflection: tests/validation/test_absorbing_layer.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cli_helpers.h"
#include "scene/scene_loader.h"
#include "validation/linear_dispersion.h"

namespace cdmpm::testing {
namespace {

std::string refused(const nlohmann::json& boundary, const nlohmann::json& wall_faces = {"x-", "x+", "y-"}) {
  nlohmann::json j = {{"dim", 2},
                      {"domain", {{"size", {20.0, 1.5}}, {"dx", 0.125}}},
                      {"time", {{"end", 1.0}, {"frame_interval", 1.0}}},
                      {"materials", {{"water", {{"type", "water"}, {"density", 1000}, {"bulk_modulus", 1e6}}}}},
                      {"bodies", {{{"material", "water"}, {"particles_per_cell", 4}, {"shape", {{"type", "box"}, {"min", {0, 0}}, {"max", {20, 1}}}}}}},
                      {"boundaries", {{{"type", "walls"}, {"condition", "slip"}, {"faces", wall_faces}}, boundary}}};
  try {
    scene_from_json(j, "layer.json");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(AbsorbingBoundary, InputErrorsNameTheKey) {
  const nlohmann::json ok = {{"type", "absorbing_layer"}, {"face", "x+"}, {"width", 3.0}, {"still_level", 1.0}, {"depth", 1.0}};
  EXPECT_EQ(refused(ok), "accepted");
  auto with = [&](const std::string& key, const nlohmann::json& value) {
    nlohmann::json b = ok;
    b[key] = value;
    return refused(b);
  };
  auto without = [&](const std::string& key) {
    nlohmann::json b = ok;
    b.erase(key);
    return refused(b);
  };
  auto has = [](const std::string& msg, const std::string& part) { return msg.find(part) != std::string::npos; };
  std::string m = with("sponge", 1.0);
  EXPECT_TRUE(has(m, "layer.json") && has(m, "boundaries[1].sponge") && has(m, "unknown key")) << m;
  m = with("width", -1.0);
  EXPECT_TRUE(has(m, "boundaries[1].width") && has(m, "at least 2 dx")) << m;
  m = with("width", 30.0);
  EXPECT_TRUE(has(m, "boundaries[1].width")) << m;
  m = with("face", "y-");
  EXPECT_TRUE(has(m, "boundaries[1].face") && has(m, "x+")) << m;
  m = with("face", "z+");
  EXPECT_TRUE(has(m, "boundaries[1].face")) << m;
  m = with("depth", 2.0);
  EXPECT_TRUE(has(m, "boundaries[1].depth") && has(m, "still_level")) << m;
  m = with("still_level", 0.0);
  EXPECT_TRUE(has(m, "boundaries[1].still_level")) << m;
  m = with("strength", -5.0);
  EXPECT_TRUE(has(m, "boundaries[1].strength")) << m;
  m = with("spill_width", 4.0);
  EXPECT_TRUE(has(m, "boundaries[1].spill_width")) << m;
  m = with("spill_level", 0.5);  // the spillway's lower edge below the still level
  EXPECT_TRUE(has(m, "boundaries[1].spill_level") && has(m, "[1, 1.5]")) << m;
  EXPECT_EQ(with("spill_level", 1.2), "accepted");
  m = with("condition", "slip");
  EXPECT_TRUE(has(m, "boundaries[1].condition") && has(m, "unknown key")) << m;
  m = refused(ok, {"x-", "y-"});  // the face the layer lies in front of is open
  EXPECT_TRUE(has(m, "boundaries[1].face") && has(m, "walls") && has(m, "x+")) << m;
  m = without("face");
  EXPECT_TRUE(has(m, "boundaries[1].face") && has(m, "required")) << m;
  m = without("width");
  EXPECT_TRUE(has(m, "boundaries[1].width") && has(m, "required")) << m;
}

}  // namespace
}  // namespace cdmpm::testing
