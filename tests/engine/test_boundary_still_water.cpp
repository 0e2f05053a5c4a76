// test_boundary_still_water.cpp - still water beside a static slip box (boundary/boundary.h) is as hydrostatic as
// beside a mirrored domain wall.
#include <gtest/gtest.h>

#include <cmath>

#include "boundary/boundary.h"
#include "material/stress.h"
#include "scene/scene_loader.h"
#include "sim/simulation.h"

namespace cdmpm {
namespace {

TEST(BoxObstacle, StillWaterBesideASlipBoxIsAsHydrostaticAsBesideAWall) {
  nlohmann::json j = {
      {"dim", 2},
      {"domain", {{"size", {100.0, 60.0}}, {"dx", 2.5}}},
      {"time", {{"end", 2.0}, {"frame_interval", 2.0}}},
      {"materials", {{"water", {{"type", "water"}, {"density", 1000}, {"bulk_modulus", 1e8}}}}},
      {"bodies", {{{"material", "water"}, {"particles_per_cell", 4},
                   {"shape", {{"type", "box"}, {"min", {40.0, 0.0}}, {"max", {100.0, 40.0}}}}}}},
      {"boundaries", {{{"type", "walls"}, {"condition", "slip"}},
                      {{"type", "box"}, {"condition", "slip"}, {"min", {0.0, 0.0}}, {"max", {40.0, 60.0}}}}},
      {"output", {{"frames", false}}}};
  const Scene scene = scene_from_json(j, "pool.json");
  Simulation<2> sim(scene);
  sim.run_until(scene.time.end);
  const double rho_g_h = 1000 * 9.81 * 40;
  // Mean deviation from hydrostatic of the three particle columns next to each side (depth 5..38 m).
  double box[3] = {0, 0, 0}, wall[3] = {0, 0, 0};
  int nb[3] = {0, 0, 0}, nw[3] = {0, 0, 0};
  const double h = 1.25;
  for (size_t q = 0; q < sim.particles.size(); ++q) {
    const auto& x = sim.particles.x[q];
    if (x[1] < 2 || x[1] > 35) continue;
    const double dev = particle_pressure(sim.materials[0], sim.particles, q) - 1000 * 9.81 * (40 - x[1]);
    for (int c = 0; c < 3; ++c) {
      if (x[0] > 40 + h * c && x[0] < 40 + h * (c + 1)) box[c] += dev, ++nb[c];
      if (x[0] < 100 - h * c && x[0] > 100 - h * (c + 1)) wall[c] += dev, ++nw[c];
    }
  }
  for (int c = 0; c < 3; ++c) {
    ASSERT_GT(nb[c], 0);
    ASSERT_GT(nw[c], 0);
    EXPECT_NEAR(box[c] / nb[c], wall[c] / nw[c], 1e-3 * rho_g_h) << "column " << c;
    EXPECT_LT(std::abs(box[c] / nb[c]), 0.02 * rho_g_h) << "column " << c;
  }
}

}  // namespace
}  // namespace cdmpm
