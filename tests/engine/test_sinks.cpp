// test_sinks.cpp - sinks (scene.h SinkSpec): a piston pushed into a closed 2D pool displaces water; a sink
// along the top of the far end, with its lower edge at the still-water level, must hold the level there
// (a spillway), whereas the closed pool's level rises by travel x depth / length. Also: the sink removes
// only its own material.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/scene_loader.h"
#include "sim/simulation.h"

namespace cdmpm {
namespace {

constexpr double kDepth = 40, kLength = 100, kSpeed = 0.2, kRamp = 2, kEnd = 30;
constexpr double kTravel = kSpeed * (kEnd - kRamp / 2);  // piston travel at kEnd: 5.8 m

nlohmann::json pool(bool with_sink) {
  nlohmann::json j = {
      {"dim", 2},
      {"domain", {{"size", {kLength, 60.0}}, {"dx", 2.5}}},
      {"time", {{"end", kEnd}, {"frame_interval", kEnd}}},
      {"materials", {{"water", {{"type", "water"}, {"density", 1000}, {"bulk_modulus", 1e8}}}}},
      {"bodies", {{{"material", "water"}, {"particles_per_cell", 4},
                   {"shape", {{"type", "box"}, {"min", {10.0, 0.0}}, {"max", {kLength, kDepth}}}}}}},
      {"boundaries", {{{"type", "walls"}, {"condition", "slip"}},
                      {{"type", "box"}, {"condition", "sticky"}, {"min", {0.0, 0.0}}, {"max", {10.0, 60.0}},
                       {"velocity", {kSpeed, 0.0}}, {"ramp_time", kRamp}}}},
      {"output", {{"frames", false}}}};
  if (with_sink) j["sinks"] = {{{"material", "water"}, {"min", {80.0, kDepth}}, {"max", {kLength, 60.0}}}};
  return j;
}

// Mean water level: current water volume (sum of V0 J) over the pool length left in front of the piston.
double run_and_measure_level(bool with_sink) {
  const Scene scene = scene_from_json(pool(with_sink), "pool.json");
  Simulation<2> sim(scene);
  sim.run_until(scene.time.end);
  double volume = 0;
  for (size_t q = 0; q < sim.particles.size(); ++q) volume += reference_volume(sim.materials[sim.particles.material[q]], sim.particles.mass[q]) * sim.particles.J[q];
  return volume / (kLength - 10 - kTravel);
}

TEST(Sinks, SpillwayHoldsTheLevelOfAPoolIntoWhichAPistonIsPushed) {
  const double rise = kTravel * kDepth / (kLength - 10 - kTravel);  // closed pool: ~2.8 m
  const double closed = run_and_measure_level(false);
  const double open = run_and_measure_level(true);
  // Closed pool: volume is conserved (J within 1e-3 of its hydrostatic value), the level rises by `rise`.
  EXPECT_NEAR(closed, kDepth + rise, 0.05 * rise);
  // With the spillway: the displaced volume has left. A particle stands for the water up to half a particle
  // spacing h/2 above it and is removed only when its own position enters the sink, so the sink holds the
  // surface within h/2 (dx/4 at 4 particles per cell) above its edge; on top of that the piston's wave,
  // amplitude U D / sqrt(g D) = 0.4 m.
  const double half_spacing = 2.5 / 4;
  EXPECT_GE(open, kDepth - kSpeed * kDepth / std::sqrt(9.81 * kDepth));
  EXPECT_LE(open, kDepth + half_spacing + kSpeed * kDepth / std::sqrt(9.81 * kDepth));
}

TEST(Sinks, RemoveOnlyTheirMaterial) {
  nlohmann::json j = pool(false);
  j["materials"]["sand"] = {{"type", "water"}, {"density", 2000}, {"bulk_modulus", 1e8}};
  j["bodies"].push_back({{"material", "sand"}, {"particles_per_cell", 4},
                         {"shape", {{"type", "box"}, {"min", {80.0, 40.0}}, {"max", {90.0, 45.0}}}}});
  j["boundaries"][1].erase("velocity");
  j["sinks"] = {{{"material", "water"}, {"min", {0.0, 20.0}}, {"max", {kLength, 60.0}}}};
  const Scene scene = scene_from_json(j, "pool.json");
  Simulation<2> sim(scene);
  const size_t sand = 2 * 4 * 4;  // 10 m x 5 m at dx 2.5 with 4 particles per cell
  sim.step(sim.stable_dt());
  size_t n_sand = 0, n_water_above = 0;
  for (size_t q = 0; q < sim.particles.size(); ++q) {
    if (sim.particles.material[q] == scene.material_index("sand")) ++n_sand;
    else if (sim.particles.x[q][1] >= 20) ++n_water_above;
  }
  EXPECT_EQ(n_sand, sand);
  EXPECT_EQ(n_water_above, 0u);
  EXPECT_EQ(sim.particles.size(), sand + 36 * 8 * 4);  // water below 20 m: 36 x 8 cells, 4 per cell
}

}  // namespace
}  // namespace cdmpm
