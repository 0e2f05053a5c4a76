// test_calving_front.cpp - the default scene of the README, scenes/calving_front_2d.json, coarse (dx = 10 m
// instead of 5 m): a grounded ice cliff of thickness H whose face is undercut at the water line (a notch of
// depth u and height h_n) must calve the overhang and raise a wave in the fjord.
//   * Beam theory: the overhang is a cantilever of length u and thickness t = H - h_n under its own weight;
//     its root stress 3 rho_i g u^2 / t exceeds the tensile strength, so it must break off. The berg is
//     the overhang: thickness t within two cells, length between u - 2 dx (crack at the notch root) and
//     u + t (a crack inclined at up to 45 degrees behind the root).
//   * Mass conservation: once afloat, the berg displaces rho_i / rho_w of its volume; spread over the fjord
//     that is a permanent rise of the mean level, so the gauge 200 m from the front must see at least that.
#include <gtest/gtest.h>

#include <algorithm>

#include "cli_helpers.h"

namespace cdmpm::testing {
namespace {

TEST(CalvingFront, UndercutCliffCalvesAndRaisesAWave) {
  TempDir dir;
  const double dx = 10;
  const auto r = run_cdmpm({"run", source_path("scenes/calving_front_2d.json"), "--out", dir / "out", "--quiet",
                            "--set", "parameters.dx=10", "--set", "time.end=30", "--set", "output.frames=false"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto scene = read_json(source_path("scenes/calving_front_2d.json"));
  const auto& p = scene["parameters"];
  const double H = p["H"], h_n = p["notch_height"], u = p["notch_depth"], front = p["front"], end = p["fjord_end"];
  const double rho_i = scene["materials"]["ice"]["density"], rho_w = scene["materials"]["water"]["density"];
  const double sigma_t = scene["materials"]["ice"]["tensile_strength"], g = 9.81, t = H - h_n;
  ASSERT_GT(3 * rho_i * g * u * u / t, sigma_t) << "the scene's overhang must be beyond its bending strength";

  const auto s = read_json(dir / "out/summary.json");
  ASSERT_TRUE(s["first_iceberg"].is_object()) << s.dump(2);
  const auto& berg = s["first_iceberg"];
  EXPECT_NEAR(berg["height"].get<double>(), t, 2 * dx);
  EXPECT_GE(berg["length"].get<double>(), u - 2 * dx);
  EXPECT_LE(berg["length"].get<double>(), u + t);

  const auto probes = read_probes(dir / "out/probes.csv");
  const auto& eta = probes.at("gauge_200m");
  const double eta_max = *std::max_element(eta.begin(), eta.end());
  const double mean_rise = rho_i / rho_w * berg["volume"].get<double>() / (end - front);
  EXPECT_GT(eta_max, mean_rise);
}

}  // namespace
}  // namespace cdmpm::testing
