// test_hazard_products.cpp - the hazard products (hazard/hazard_map.h, hazard/hazard_report.h) and the
// georeference through the program: a still 3D lake beside a raised shelf (rasters, georeferenced corner, no
// inundation, elevation ~ 0), the products bit for bit across a checkpoint/resume and thread counts, and bad
// georeference and hazard keys refused as input errors. Against theory: tests/validation/test_hazard.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "cli_helpers.h"
#include "terrain/terrain_file.h"

namespace cdmpm::testing {
namespace {

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
