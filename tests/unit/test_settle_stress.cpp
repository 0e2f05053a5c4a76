// test_settle_stress.cpp - the seeded lithostatic state of ice with a lateral stress ratio k (body key
// lateral_stress_ratio, material/neo_hookean_split.h vertical_load_stretches): every ice particle starts with
// sigma_yy = -rho g d (d its depth below the block's top) and sigma_xx = k sigma_yy, to the Newton solve's tolerance
// (64 machine epsilons of kappa; asserted at 1e-6 of rho g H, far above it); bad settling keys are refused. The
// settling itself: tests/engine/test_settle.cpp.
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
namespace {

constexpr double H = 50, W = 400, rho = 917, g = 9.81;

TEST(Settle, LateralStressRatioSetsTheSeededHorizontalStress) {
  for (double k : {0.0, 0.5, 1.0}) {
    const Scene s = scene_from_json(testing::settle_block(k, 0), "block.json");
    Simulation<2> sim(s);
    const auto& P = sim.particles;
    ASSERT_EQ(P.size(), size_t(W / 5 * H / 5 * 4));
    for (size_t q = 0; q < P.size(); ++q) {
      const Mat<2> sigma = cauchy_stress(sim.materials[P.material[q]], P, q);
      const double depth = H - P.x[q][1];
      EXPECT_NEAR(sigma(1, 1), -rho * g * depth, 1e-6 * rho * g * H) << "k " << k << " particle " << q;
      EXPECT_NEAR(sigma(0, 0), k * sigma(1, 1), 1e-6 * rho * g * H) << "k " << k << " particle " << q;
    }
  }
}

TEST(Settle, BadKeysAreRefused) {
  auto bad = [](nlohmann::json j, const std::string& what) {
    try {
      scene_from_json(j, "bad.json");
      ADD_FAILURE() << "accepted: " << what;
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  auto j = testing::settle_block(1.0, 0);
  j["bodies"][0]["lateral_stress_ratio"] = 1.5;
  bad(j, "lateral_stress_ratio");
  j = testing::settle_block(0.5, 0);
  j["bodies"][0]["hydrostatic"] = false;
  bad(j, "lateral_stress_ratio");
  j = testing::settle_block(0, 0);
  j["time"]["settle_damping"] = 2;
  bad(j, "settle_damping");
  j = testing::settle_block(0, 0);
  j["time"]["settle"] = -1;
  bad(j, "time.settle");
}

}  // namespace
}  // namespace cdmpm
