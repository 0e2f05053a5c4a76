// test_hazard.cpp - the hazard products (hazard/hazard_map.h, hazard/hazard_report.h) and the georeference:
//   HazardSolitary (validation): scenes/solitary_runup_2d.json, a Boussinesq solitary wave of H/h = 0.1 on a
//     plane beach of cot(beta) = 2.5, against theory: the maximum elevation along the constant-depth part, the
//     arrival time of the wave front (speed c = sqrt(g (h + H))), the run-up and the inundation extent that goes
//     with it against Synolakis's (1987) exact linear solution (against his law: disabled, see the test), and the run-up
//     and inundation extent of the same wave at a vertical wall (Su & Mirie 1980);
//   HazardProducts (end-to-end): a still 3D lake beside a raised shelf (rasters, georeferenced corner, no
//     inundation, elevation ~ 0), and the products bit for bit across a checkpoint/resume and thread counts.
#include <gtest/gtest.h>

#include <cmath>

#include "cli_helpers.h"
#include "terrain/terrain_file.h"

namespace cdmpm::testing {
namespace {

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

// A still 3D lake (0.6 m of the 1 m long domain, 0.15 m deep) beside a shelf 0.2 m high (a static slip box on
// grid planes, so the water against it stays hydrostatic), georeferenced.
std::string lake_scene() {
  return R"({
  "name": "lake", "dim": 3,
  "domain": {"size": [1.0, 0.5, 0.3], "dx": 0.05},
  "time": {"end": 0.4, "frame_interval": 0.2},
  "materials": {"water": {"type": "water", "density": 1000, "bulk_modulus": 2e5}},
  "bodies": [{"material": "water", "particles_per_cell": 8,
              "shape": {"type": "box", "min": [0, 0, 0], "max": [1.0, 0.5, 0.15]}}],
  "boundaries": [{"type": "walls", "condition": "slip"},
                 {"type": "box", "condition": "slip", "min": [0.6, 0, 0], "max": [1.0, 0.5, 0.2]}],
  "georeference": {"easting": 612345.5, "northing": 7654321.25},
  "output": {"frames": false, "checkpoint_every": 1}
})";
}

std::string write_lake(const TempDir& dir) {
  const std::string path = dir / "lake.json";
  std::ofstream(path) << lake_scene();
  return path;
}

// Rasters exist and parse as ESRI ASCII grids (the terrain reader), one cell per grid column with the corner at
// the georeference; the lake's maximum elevation is 0 within a quarter of the particle spacing (the surface's
// resolution; the lake starts in hydrostatic equilibrium), the shelf is never inundated (depth 0, area 0) and
// the lake's cells are NODATA in the inundation raster.
TEST(HazardProducts, StillLakeRastersAreGeoreferencedFlatAndDry) {
  TempDir dir;
  const CliResult r = run_cdmpm({"run", write_lake(dir), "--out", dir / "run", "--quiet"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const double dx = 0.05, spacing = dx / 2;
  for (const char* name : {"max_elevation.asc", "max_elevation_time.asc", "arrival_time.asc", "inundation_depth.asc"}) {
    const TerrainGrid grid = read_esri_ascii(dir / ("run/" + std::string(name)));
    EXPECT_EQ(grid.ncols(), 20u) << name;
    EXPECT_EQ(grid.nrows(), 10u) << name;
    EXPECT_DOUBLE_EQ(grid.cellsize, dx) << name;
    EXPECT_DOUBLE_EQ(grid.x0, 612345.5 + dx / 2) << name;  // the reader gives the centre of the south-west cell
    EXPECT_DOUBLE_EQ(grid.y0, 7654321.25 + dx / 2) << name;
  }
  const TerrainGrid eta = read_esri_ascii(dir / "run/max_elevation.asc");
  const TerrainGrid depth = read_esri_ascii(dir / "run/inundation_depth.asc");
  const TerrainGrid arrival = read_esri_ascii(dir / "run/arrival_time.asc");
  for (size_t j = 0; j < 10; ++j)
    for (size_t i = 0; i < 20; ++i) {
      const bool lake = i < 12;
      EXPECT_EQ(eta.nodata[j][i], !lake) << i << "," << j;
      EXPECT_EQ(depth.nodata[j][i], lake) << i << "," << j;
      EXPECT_TRUE(arrival.nodata[j][i]) << i << "," << j;  // nothing exceeds the threshold (dx/4)
      if (lake) EXPECT_NEAR(eta.heights[j][i], 0.0, spacing / 4) << i << "," << j;
      else EXPECT_EQ(depth.heights[j][i], 0.0) << i << "," << j;
    }
  const nlohmann::json s = read_json(dir / "run/summary.json");
  EXPECT_EQ(s["hazard"]["inundated_area"].get<double>(), 0.0);
  EXPECT_TRUE(s["hazard"]["runup"].is_null());
  EXPECT_EQ(s["georeference"]["easting"].get<double>(), 612345.5);
  EXPECT_EQ(s["georeference"]["northing"].get<double>(), 7654321.25);
  EXPECT_FALSE(s["georeference"].contains("azimuth"));
}

void expect_same_hazard(const TempDir& dir, const std::vector<std::string>& files) {
  for (const std::string other : {"other", "half"})
    for (const std::string& f : files)
      EXPECT_EQ(read_bytes(dir / ("full/" + f)), read_bytes(dir / (other + "/" + f))) << other << "/" << f;
  const nlohmann::json full = read_json(dir / "full/summary.json")["hazard"];
  EXPECT_EQ(full, read_json(dir / "half/summary.json")["hazard"]);
  EXPECT_EQ(full, read_json(dir / "other/summary.json")["hazard"]);
}

// The hazard record is kept in checkpoints: a run resumed at half time writes the same products bit for bit as
// the straight run, and so does a run on another number of threads (maxima, minima and first times only). The
// half time is an output time of the straight run (frames every 0.25 s), so both take the same steps.
TEST(HazardProducts, ResumeAndThreadCountGiveBitIdenticalProducts) {
  TempDir dir;
  const std::string failed = run_straight_other_threads_and_resumed(
      dir, source_path("scenes/solitary_runup_2d.json"),
      {"--quiet", "--set", "parameters.cells_per_h=6", "--set", "time.frame_interval=0.25", "--set", "probes.interval=0.125"},
      "2", "1", "2.25", "4.5");
  ASSERT_EQ(failed, "");
  expect_same_hazard(dir, {"hazard.csv", "runup.csv"});
  EXPECT_FALSE(read_json(dir / "full/summary.json")["hazard"]["shores"][0]["runup"].is_null());

  TempDir lake;
  const std::string failed3 = run_straight_other_threads_and_resumed(lake, write_lake(lake), {"--quiet"}, "2", "1",
                                                                     "0.2", "0.4");
  ASSERT_EQ(failed3, "");
  expect_same_hazard(lake, {"max_elevation.asc", "max_elevation_time.asc", "arrival_time.asc", "inundation_depth.asc"});
}

// Checked keys: an azimuth outside [0, 360), an azimuth in 3D, an unknown hazard key and a negative threshold
// stop the program with exit code 2 and a message naming the key.
TEST(HazardProducts, BadGeoreferenceAndHazardKeysAreInputErrors) {
  const std::string scene = source_path("scenes/solitary_runup_2d.json");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"georeference.azimuth=360", "georeference.azimuth"},
      {"georeference.northing=\"north\"", "georeference.northing"},
      {"hazard.arrival_threshold=-0.1", "hazard.arrival_threshold"},
      {"hazard.interval=1e9", "hazard.interval"},
      {"hazard.window=1", "hazard.window"},
      {"bodies.0.solitary_wave.height=0.9", "bodies[0].solitary_wave.height"}};
  for (const auto& [set, key] : cases) {
    const CliResult r = run_cdmpm({"check", scene, "--set", set});
    EXPECT_EQ(r.exit_code, 2) << set;
    EXPECT_NE(r.output.find(key), std::string::npos) << r.output;
  }
  TempDir dir;
  std::string lake = lake_scene();
  lake.replace(lake.find("\"northing\": 7654321.25"), 22, "\"northing\": 1, \"azimuth\": 10");
  std::ofstream(dir / "lake.json") << lake;
  const CliResult r = run_cdmpm({"check", dir / "lake.json"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("georeference.azimuth: unknown key"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace cdmpm::testing
