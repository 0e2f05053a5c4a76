// test_settle.cpp - the seeded lithostatic state of ice with a lateral stress ratio k (body key
// lateral_stress_ratio, material/neo_hookean_split.h vertical_load_stretches) and the settling before t = 0
// (time.settle, sim/simulation.h), on an ice block of height H = 50 m and width 100 m resting on a slip bed.
//   * Seeding (the stress it sets, and bad keys: tests/unit/test_settle_stress.cpp; a resume through the program:
//     tests/end_to_end/test_settle_cli.cpp).
//   * Settling: started cryostatic (k = 1), a long block (W = 8 H) is out of balance at its free ends by the
//     whole overburden. Away from the ends (the middle 2 H) its settled elastic equilibrium on a slip bed, which
//     holds the bed line straight, is analytic: sigma_yy = -rho g d (each column carries its weight), and a
//     horizontal strain uniform in depth (plane sections stay plane, the bed forbids curvature) changes
//     sigma_xx by a constant that makes the section's net horizontal force zero (the ends are free):
//     sigma_xx = k rho g (H/2 - d). Tolerance 2 % of rho g H: the damped settling leaves e^-5 = 0.7 % of the
//     released amplitude (at most rho g H / 2), and quadratic B-splines carry a linear stress field exactly in
//     the interior. Every speed must be under 1 % of the release speed g H / c_p of the unsettled block
//     (0.4 m/s), and no particle may yield while settling. Without settling the block moves at a sizeable
//     fraction of the release speed within 0.05 s (the last test; it is the settling's reason).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "cli_helpers.h"
#include "material/stress.h"
#include "scene/scene_loader.h"
#include "sim/simulation.h"
#include "scene_builders.h"

namespace cdmpm {

// Named, not anonymous: its constants (g, dx, h, ...) have the names of other test files' constants, and a unity
// batch shares the anonymous namespace of its files.
namespace settle_test {

constexpr double H = 50, W = 400, rho = 917, g = 9.81;

TEST(Settle, CryostaticBlockSettlesToTheElasticEquilibriumOnItsBed) {
  // Slowest mode: the block's horizontal extension, period about 2 W / c_p = 0.66 s; 4 s is 6 periods with the
  // default damping 10 / settle = 2.5 1/s.
  auto j = testing::settle_block(1.0, 4.0);
  const Scene s = scene_from_json(j, "block.json");
  Simulation<2> sim(s);
  EXPECT_EQ(sim.time(), 0.0);
  EXPECT_EQ(sim.steps(), 0);
  const auto& P = sim.particles;
  const double c_p = std::sqrt(1e9 * 0.7 / (1.3 * 0.4 * rho)), centre = 100 + W / 2;
  int middle = 0;
  for (size_t q = 0; q < P.size(); ++q) {
    EXPECT_LT(P.v[q].norm(), 0.01 * g * H / c_p) << "particle " << q;
    if (std::abs(P.x[q][0] - centre) > H) continue;
    ++middle;
    const Mat<2> sigma = cauchy_stress(sim.materials[P.material[q]], P, q);
    const double d = H - P.x[q][1];
    EXPECT_NEAR(sigma(1, 1), -rho * g * d, 0.02 * rho * g * H) << "at " << P.x[q].transpose();
    EXPECT_NEAR(sigma(0, 0), rho * g * (H / 2 - d), 0.02 * rho * g * H) << "at " << P.x[q].transpose();
  }
  EXPECT_EQ(middle, 40 * 20);  // 2 H = 100 m of 2.5 m columns, H / 2.5 m rows
  const Scene unsettled = scene_from_json(testing::settle_block(1.0, 0), "block.json");
  const Simulation<2> seeded(unsettled);
  for (size_t q = 0; q < P.size(); ++q) EXPECT_EQ(P.alpha[q], seeded.particles.alpha[0]) << "settling must not yield";
}

TEST(Settle, UnsettledCryostaticBlockMovesAtTheReleaseSpeed) {
  const Scene s = scene_from_json(testing::settle_block(1.0, 0), "block.json");
  Simulation<2> sim(s);
  double max_speed = 0;
  while (sim.time() < 0.05) {
    sim.step(sim.stable_dt());
    for (const auto& v : sim.particles.v) max_speed = std::max(max_speed, double(v.norm()));
  }
  const double c_p = std::sqrt(1e9 * 0.7 / (1.3 * 0.4 * rho));
  EXPECT_GT(max_speed, 0.1 * g * H / c_p);
}

}  // namespace settle_test
}  // namespace cdmpm
