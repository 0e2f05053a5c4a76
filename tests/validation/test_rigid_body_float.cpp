// test_rigid_body_float.cpp - a rigid block lighter than water (sim/rigid_bodies.h), released in still water,
// floats at the draft of Archimedes' principle within 5 % and comes to rest.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>

#include "cli_helpers.h"
#include "rise_reference.h"
#include "scene/scene_loader.h"
#include "sim/simulation.h"
#include "scene_builders.h"

namespace cdmpm {
namespace {

using json = nlohmann::json;

// A block of density 920 and height H_b, released with its bottom at the still water level in a 2 m wide
// tank, floats and comes to rest with draft d = (920 / 1000) H_b (Archimedes) within 5 %: draft = water level
// far from the block (gauge, absolute height) - bottom of the block (centre - H_b / 2), averaged over the
// last second; the block is then at rest (its speed is small against the heave speed sqrt(g d)).
TEST(RigidBody, LightBlockFloatsAtArchimedesDraft) {
  using namespace cdmpm::testing;
  const double H_b = 0.2, level = 0.5;
  json j = testing::float_tank(0.45, 0.65);
  j.update(json::parse(R"({
    "probes": {"interval": 0.05, "list": [
      {"name": "block", "type": "rigid_position", "material": "block"},
      {"name": "speed", "type": "rigid_velocity", "material": "block"},
      {"name": "angle", "type": "rigid_angle", "material": "block"},
      {"name": "level", "type": "wave_gauge", "position": [0.2], "still_level": 0}]},
    "output": {"frames": false}
  })"));
  ASSERT_DOUBLE_EQ(j["bodies"][0]["shape"]["max"][1].get<double>() - j["bodies"][0]["shape"]["min"][1].get<double>(), H_b);
  ASSERT_DOUBLE_EQ(j["bodies"][1]["shape"]["max"][1].get<double>(), level);
  TempDir dir;
  std::ofstream(dir / "float.json") << j.dump();
  const auto r = run_cdmpm({"run", dir / "float.json", "--out", dir / "out", "--quiet"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto p = read_probes(dir / "out/probes.csv");
  const auto& t = p.at("time");
  double draft = 0, speed = 0, n = 0;
  for (size_t i = 0; i < t.size(); ++i)
    if (t[i] >= t.back() - 1.0) {
      draft += p.at("level")[i] - (p.at("block_y")[i] - H_b / 2);
      speed = std::max(speed, std::hypot(p.at("speed_x")[i], p.at("speed_y")[i]));
      EXPECT_NEAR(p.at("angle")[i], 0, std::max(1e-6, 1e3 * std::numeric_limits<Real>::epsilon()));  // symmetry
      ++n;
    }
  testing::expect_archimedes_draft(draft / n, speed, H_b);
}

}  // namespace
}  // namespace cdmpm
