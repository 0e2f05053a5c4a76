// test_settle.cpp - the seeded lithostatic state of ice with a lateral stress ratio k (body key
// lateral_stress_ratio, material/neo_hookean_split.h vertical_load_stretches) and the settling before t = 0
// (time.settle, sim/simulation.h), on an ice block of height H = 50 m and width 100 m resting on a slip bed.
//   * Seeding: every ice particle starts with sigma_yy = -rho g d (d its depth below the block's top) and
//     sigma_xx = k sigma_yy, to the Newton solve's tolerance (64 machine epsilons of kappa; asserted at 1e-6 of
//     rho g H, far above it).
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

namespace cdmpm {
namespace {

constexpr double H = 50, W = 400, rho = 917, g = 9.81;

nlohmann::json block(double k, double settle) {
  nlohmann::json time = {{"end", 1.0}, {"frame_interval", 1.0}};
  if (settle > 0) time["settle"] = settle;
  return {{"dim", 2},
          {"domain", {{"size", {W + 200.0, 100.0}}, {"dx", 5.0}}},
          {"time", time},
          {"materials", {{"ice", {{"type", "ice"}, {"density", rho}, {"youngs_modulus", 1e9}, {"poissons_ratio", 0.3},
                                  {"M", 1.85}, {"beta", 0.1}, {"xi", 5}, {"tensile_strength", 1e6}}}}},
          {"bodies", {{{"material", "ice"}, {"particles_per_cell", 4}, {"lateral_stress_ratio", k},
                       {"shape", {{"type", "box"}, {"min", {100.0, 0.0}}, {"max", {100.0 + W, H}}}}}}},
          {"boundaries", {{{"type", "walls"}, {"condition", "slip"}, {"faces", {"y-"}}}}}};
}

TEST(Settle, LateralStressRatioSetsTheSeededHorizontalStress) {
  for (double k : {0.0, 0.5, 1.0}) {
    const Scene s = scene_from_json(block(k, 0), "block.json");
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

TEST(Settle, CryostaticBlockSettlesToTheElasticEquilibriumOnItsBed) {
  // Slowest mode: the block's horizontal extension, period about 2 W / c_p = 0.66 s; 4 s is 6 periods with the
  // default damping 10 / settle = 2.5 1/s.
  auto j = block(1.0, 4.0);
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
  const Scene unsettled = scene_from_json(block(1.0, 0), "block.json");
  const Simulation<2> seeded(unsettled);
  for (size_t q = 0; q < P.size(); ++q) EXPECT_EQ(P.alpha[q], seeded.particles.alpha[0]) << "settling must not yield";
}

TEST(Settle, UnsettledCryostaticBlockMovesAtTheReleaseSpeed) {
  const Scene s = scene_from_json(block(1.0, 0), "block.json");
  Simulation<2> sim(s);
  double max_speed = 0;
  while (sim.time() < 0.05) {
    sim.step(sim.stable_dt());
    for (const auto& v : sim.particles.v) max_speed = std::max(max_speed, double(v.norm()));
  }
  const double c_p = std::sqrt(1e9 * 0.7 / (1.3 * 0.4 * rho));
  EXPECT_GT(max_speed, 0.1 * g * H / c_p);
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
  auto j = block(1.0, 0);
  j["bodies"][0]["lateral_stress_ratio"] = 1.5;
  bad(j, "lateral_stress_ratio");
  j = block(0.5, 0);
  j["bodies"][0]["hydrostatic"] = false;
  bad(j, "lateral_stress_ratio");
  j = block(0, 0);
  j["time"]["settle_damping"] = 2;
  bad(j, "settle_damping");
  j = block(0, 0);
  j["time"]["settle"] = -1;
  bad(j, "time.settle");
}

// A run resumed from a checkpoint settles again before loading it, so its results, and the initial energies of its
// summary, are those of the straight run (bit for bit; docs/scenes.md, time.settle).
TEST(SettleCli, ResumeGivesTheStraightRunsResults) {
  testing::TempDir dir;
  auto j = block(1.0, 1.0);
  j["time"]["end"] = 0.4;
  j["time"]["frame_interval"] = 0.1;
  j["output"] = {{"checkpoint_every", 2}};  // frames
  const std::string scene = dir / "block.json";
  std::ofstream(scene) << j.dump();
  const auto full = testing::run_cdmpm({"run", scene, "--out", dir / "full", "--quiet"});
  ASSERT_EQ(full.exit_code, 0) << full.output;
  const auto half = testing::run_cdmpm({"run", scene, "--out", dir / "half", "--quiet", "--set", "time.end=0.2"});
  ASSERT_EQ(half.exit_code, 0) << half.output;
  const auto resumed = testing::run_cdmpm({"run", "--resume", dir / "half", "--quiet", "--set", "time.end=0.4"});
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  const auto a = testing::read_json(dir / "full/summary.json"), b = testing::read_json(dir / "half/summary.json");
  EXPECT_EQ(a["energy_initial"], b["energy_initial"]);
  EXPECT_EQ(a["energy"], b["energy"]);
  EXPECT_EQ(testing::read_bytes(dir / "full/particles_0004.vtu"), testing::read_bytes(dir / "half/particles_0004.vtu"));
}

}  // namespace
}  // namespace cdmpm
