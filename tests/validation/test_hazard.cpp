// test_hazard.cpp - the hazard products (hazard/hazard_map.h, hazard/hazard_report.h) and the georeference:
//   HazardSolitary (validation): scenes/solitary_runup_2d.json, a Boussinesq solitary wave of H/h = 0.1 on a
//     plane beach of cot(beta) = 2.5, against theory: the maximum elevation along the constant-depth part, the
//     arrival time of the wave front (speed c = sqrt(g (h + H))), the run-up and the inundation extent that goes
//     with it against Synolakis's (1987) exact linear solution (against his law: disabled, see the test), and the run-up
//     and inundation extent of the same wave at a vertical wall (Su & Mirie 1980);
//   HazardProducts: tests/end_to_end/test_hazard_products.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "cli_helpers.h"
#include "terrain/terrain_file.h"

namespace cdmpm::testing {
// Named, not anonymous: its constants (g, dx, h, ...) have the names of other test files' constants, and a unity
// batch shares the anonymous namespace of its files.
namespace hazard_test {

// The solitary scene's parameters (scenes/solitary_runup_2d.json).
constexpr double g = 9.81, h = 1.0, H = 0.1, cot_beta = 2.5, x0 = 7.5, toe = 20.0, threshold = 0.5 * H;
// The surface's resolution: a column's water top is its highest particle plus half the particle spacing, so it
// lies within half a spacing, dx/4, of the true surface (12 cells per h: dx/4 = 0.21 H).
constexpr double dx = h / 12, surface_resolution = dx / 4;

class HazardSolitary : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir;
    const CliResult r = run_cdmpm({"run", source_path("scenes/solitary_runup_2d.json"), "--out", *dir_ / "run", "--quiet"});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    table_ = new CsvTable(read_csv_table(*dir_ / "run/hazard.csv"));
    summary_ = new nlohmann::json(read_json(*dir_ / "run/summary.json"));
  }
  static void TearDownTestSuite() {
    delete summary_;
    delete table_;
    delete dir_;
  }
  // The value of column `name` in the column whose centre is nearest x.
  static double at(const std::string& name, double x) {
    const std::vector<double> xs = table_->numbers("x"), v = table_->numbers(name);
    size_t best = 0;
    for (size_t k = 1; k < xs.size(); ++k)
      if (std::abs(xs[k] - x) < std::abs(xs[best] - x)) best = k;
    return v[best];
  }
  static inline TempDir* dir_ = nullptr;
  static inline CsvTable* table_ = nullptr;
  static inline nlohmann::json* summary_ = nullptr;
};

// A solitary wave keeps its form in constant depth (Boussinesq 1872): along the tank the largest elevation is
// H, within the surface's resolution dx/4 = 0.21 H (the Boussinesq initial state adjusts its amplitude by a few %
// of H in the Euler equations, Grimshaw 1971, well inside that). Checked from 2.5 h after the crest's start to
// x = 14 h, before the shoaling over the beach from x = 20 h reaches back (docs/validation.md#solitary-wave-run-up).
//
// One test for both products, so that ctest (one process per test) runs the scene once.
TEST_F(HazardSolitary, MaxElevationAndArrivalTimeAlongTheConstantDepthPart) {
  for (double x = 10.0; x <= 14.0; x += 0.5) {
    const double eta = at("max_elevation", x);
    EXPECT_NEAR(eta, H, surface_resolution) << "x = " << x;
  }

  // The front where eta = threshold (H/2) lies d = arccosh(sqrt(H / threshold)) / k ahead of the crest, k =
  // sqrt(3 H / (4 h^3)), and travels at c = sqrt(g (h + H)): it reaches x at (x - x0 - d) / c. Tolerance: the
  // time the front takes to rise by the surface's resolution there, dx/4 / (c |d eta/dx|), |d eta/dx| = 2 k eta
  // tanh(k d) (0.33 s; the travel times are 0.6 .. 1.6 s).
  const double k = std::sqrt(3 * H / (4 * h * h * h)), c = std::sqrt(g * (h + H));
  const double d = std::acosh(std::sqrt(H / threshold)) / k;
  const double tolerance = surface_resolution / (c * 2 * k * threshold * std::tanh(k * d));
  for (double x : {13.0, 14.5, 16.0}) {
    const double expected = (x - x0 - d) / c;
    EXPECT_NEAR(at("arrival_time", x), expected, tolerance) << "x = " << x;
  }
}

// Synolakis (1987): R / h = 2.831 sqrt(cot beta) (H / h)^(5/4) for a non-breaking solitary wave (H/h = 0.1 <
// 0.288 (tan beta)^(10/9) = 0.104); within 15 %. The inundation extent goes with it: the waterline at the run-up
// height lies R cot(beta) beyond the still shoreline.
// Disabled: the run-up is 0.295 h at 12 cells per h and 0.313 h at 24 against the law's 0.252 h (+17 %, +24 %);
// the law is the asymptote of the exact linear solution (below) for 2 gamma cot beta >> 1, here 1.37, and lies
// 10 % below it (docs/validation.md#solitary-wave-run-up).
TEST_F(HazardSolitary, DISABLED_RunupAndInundationExtentFollowSynolakis) {
  const double R = h * 2.831 * std::sqrt(cot_beta) * std::pow(H / h, 1.25);
  const auto& shores = (*summary_)["hazard"]["shores"];
  ASSERT_EQ(shores.size(), 1u);
  EXPECT_NEAR(shores[0]["runup"].get<double>(), R, 0.15 * R);
  EXPECT_NEAR(shores[0]["extent_x"].get<double>(), toe + (h + R) * cot_beta, 0.15 * R * cot_beta);
}

// The run-up against the exact linear solution the law approximates (Synolakis 1987, J. Fluid Mech. 185, with its J0 - i J1
// denominator; `tools/runup_linear.py 0.1:2.5` gives R/h = 0.2786, test Tools.RunupLinearTheoryTendsToTheRunupLaw),
// within the issue's 15 %, and the inundation extent that goes with it. Nonlinear shallow-water theory has the same
// largest run-up (Carrier & Greenspan 1958). Without the slip condition on the particles that end a step below the
// bed (boundary/bathymetry.cpp, keep_inside) the run-up was 0.327 h, +17 %.
TEST_F(HazardSolitary, RunupAndInundationExtentFollowTheExactLinearTheory) {
  const double R = 0.2786 * h;
  const auto& shores = (*summary_)["hazard"]["shores"];
  ASSERT_EQ(shores.size(), 1u);
  EXPECT_NEAR(shores[0]["runup"].get<double>(), R, 0.15 * R);
  EXPECT_NEAR(shores[0]["extent_x"].get<double>(), toe + (h + R) * cot_beta, 0.15 * R * cot_beta);
}

// The same wave against a vertical wall (a static slip box on grid planes from the toe, as high as the domain,
// whose face holds still water hydrostatic): the maximum run-up of a solitary wave on a vertical wall is
// R/h = 2 (H/h) + (H/h)^2 / 2 + 3/4 (H/h)^3 (Su & Mirie 1980), 0.2058 h here, within the surface's resolution
// dx/4; the inundation extent is the wall's face, within the same.
TEST(HazardWall, SolitaryWaveRunupAndInundationExtentAtAVerticalWall) {
  TempDir dir;
  const CliResult r = run_cdmpm({"run", source_path("scenes/solitary_runup_2d.json"), "--out", dir / "wall", "--quiet",
                                 "--set", R"(boundaries.1={"type": "box", "condition": "slip", "min": [20, 0], "max": [23.75, 1.5]})",
                                 "--set", "time.end=4.6"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const double e = H / h, R = h * (2 * e + e * e / 2 + 0.75 * e * e * e);
  const nlohmann::json summary = read_json(dir / "wall/summary.json");
  const auto& shores = summary["hazard"]["shores"];
  ASSERT_EQ(shores.size(), 1u);
  EXPECT_NEAR(shores[0]["runup"].get<double>(), R, surface_resolution);
  EXPECT_NEAR(shores[0]["extent_x"].get<double>(), toe, surface_resolution);
}

}  // namespace hazard_test
}  // namespace cdmpm::testing
