// test_replay.cpp - a replayed body (rigid key `track`, sim/rigid_bodies.h) in the engine: its particles are where the
// track puts them, x = X + u(X, t), to round-off after any number of steps; they are seeded only where the recorded
// ice was (fill >= 1/2), and water is seeded in the rest of its shape.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_helpers.h"
#include "scene/scene_loader.h"
#include "sim/simulation.h"
#include "source_track_files.h"

namespace cdmpm {
namespace {

using json = nlohmann::json;

// A 2D box of 10 m x 6 m in a 20 m x 12 m domain with water beside it in a pool, replayed along u = t (a + b X + c Z):
// it translates, stretches and shears. Its particles are where the track puts them.
TEST(Replay, ParticlesAreWhereTheTrackPutsThem) {
  testing::TempDir dir;
  const double a[2] = {0.8, 0.3}, b[2] = {0.02, 0.0}, c[2] = {0.0, -0.01};
  // Lattice over X in [-10, 0], Z in [0, 6] relative to the origin (12, 2); the ice filled X <= -2.5 only.
  const std::string track = write_file(dir, "track.txt", linear_track(11, 7, -10, 0, 1, {0, 0.3, 1.0, 2.0}, a, b, c, -2.5));
  json s;
  s["dim"] = 2;
  s["domain"] = {{"size", {20.0, 12.0}}, {"dx", 0.5}};
  s["time"] = {{"end", 1.0}, {"frame_interval", 1.0}};
  s["gravity"] = {0, -9.81};
  s["materials"] = {{"source", {{"type", "rigid"}, {"density", 917}, {"bulk_modulus", 1e6}}},
                    {"water", {{"type", "water"}, {"density", 1000}, {"bulk_modulus", 1e6}}}};
  s["bodies"] = json::array(
      {{{"material", "source"}, {"particles_per_cell", 4}, {"hydrostatic", false},
        {"shape", {{"type", "box"}, {"min", {2.0, 2.0}}, {"max", {12.0, 8.0}}}},
        {"rigid", {{"track", {{"file", track}, {"origin", {12.0, 2.0}}}}}}},
       {{"material", "water"}, {"particles_per_cell", 4},
        {"shape", {{"type", "box"}, {"min", {2.0, 0.0}}, {"max", {20.0, 4.0}}}}}});
  s["boundaries"] = json::array({{{"type", "walls"}, {"condition", "slip"}, {"faces", {"x-", "x+", "y-"}}}});
  Simulation<2> sim(scene_from_json(s, (dir / "replay.json")));
  const auto& p = sim.particles;
  // Seeded where the ice was: nearest node X <= -2.5, i.e. X < -2.5 + ... (nodes at -3 and below: X < -2.5).
  size_t source = 0, water_in_shape = 0;
  std::vector<Vec<2>> start;
  std::vector<uint64_t> ids;
  for (size_t q = 0; q < p.size(); ++q) {
    if (p.material[q] == 0) {
      ++source;
      EXPECT_LT(p.x[q][0], 12 - 2.5) << "a source particle where the ice was not";
      start.push_back(p.x[q]), ids.push_back(p.id[q]);
    } else if (p.x[q][0] > 2 && p.x[q][0] < 12 && p.x[q][1] > 2) {
      ++water_in_shape;
    }
  }
  EXPECT_EQ(source, size_t(4 * 15 * 12));  // 4 per cell; X in [-10, -2.5]: 15 cells of 0.5 m; Z in [0, 6]: 12
  EXPECT_GT(water_in_shape, 0u);               // the water fills the part of the shape the ice did not
  sim.run_until(1.7);
  const double t = sim.time();
  ASSERT_NEAR(t, 1.7, 1e-9);
  for (size_t q = 0; q < p.size(); ++q) {
    if (p.material[q] != 0) continue;
    const size_t k = size_t(std::find(ids.begin(), ids.end(), p.id[q]) - ids.begin());
    ASSERT_LT(k, ids.size());
    const double X = start[k][0] - 12, Z = start[k][1] - 2;
    for (int c2 = 0; c2 < 2; ++c2)
      EXPECT_NEAR(p.x[q][c2], start[k][c2] + t * (a[c2] + b[c2] * X + c[c2] * Z), 1e-4) << "particle " << p.id[q];
  }
}

}  // namespace
}  // namespace cdmpm
