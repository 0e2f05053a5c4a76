// test_terrain_file.cpp - terrain from files (src/terrain/terrain_file.h): CSV profiles and ESRI ASCII grids
// parse to the right numbers (rows flipped northwards, xllcorner and xllcenter giving the same nodes), are
// placed in the domain with the file origin and cropped to it, and every malformed file of tests/bad_terrain/
// is refused with a message naming the file and the line. Through the program: tests/engine/test_terrain_cli.cpp.
#include <gtest/gtest.h>

#include <fstream>

#include "cli_helpers.h"
#include "boundary/boundary.h"
#include "scene/scene_loader.h"
#include "terrain/terrain_file.h"

namespace cdmpm::testing {
namespace {

std::string terrain_dir(const std::string& file) { return source_path("tests/terrain/" + file); }

// The message of the SceneError that `f` throws, or "" if it throws none.
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(TerrainFile, ReadsCsvProfileWithHeaderCommentsBlankLinesAndCrlf) {
  const TerrainProfile p = read_profile_csv(terrain_dir("profile.csv"));
  ASSERT_EQ(p.points.size(), 3u);
  EXPECT_EQ(p.points[0], (std::array<double, 2>{0, -100}));
  EXPECT_EQ(p.points[1], (std::array<double, 2>{400, -120.5}));
  EXPECT_EQ(p.points[2], (std::array<double, 2>{1000, -40}));
  EXPECT_EQ(p.lines, (std::vector<int>{4, 5, 8}));
}

// grid_corner.asc: xllcorner = yllcorner = -25, cellsize 50, 8 x 6 values -10 (r + 1) - i in file row r (the
// first row the northernmost), NODATA in the north-east corner.
void expect_test_grid(const TerrainGrid& g) {
  EXPECT_DOUBLE_EQ(g.x0, 0);
  EXPECT_DOUBLE_EQ(g.y0, 0);
  EXPECT_DOUBLE_EQ(g.cellsize, 50);
  ASSERT_EQ(g.nrows(), 6u);
  ASSERT_EQ(g.ncols(), 8u);
  for (std::size_t j = 0; j < 6; ++j)
    for (std::size_t i = 0; i < 8; ++i) {
      const bool corner = j == 5 && i == 7;
      EXPECT_EQ(g.nodata[j][i], corner) << j << " " << i;
      EXPECT_DOUBLE_EQ(g.heights[j][i], corner ? -9999 : -10.0 * double(6 - j) - double(i)) << j << " " << i;
    }
  EXPECT_EQ(g.row_line.front(), 12);  // j = 0 (south) is the last line of the file
  EXPECT_EQ(g.row_line.back(), 7);
}

TEST(TerrainFile, ReadsEsriAsciiFlippingRowsNorthwards) {
  expect_test_grid(read_esri_ascii(terrain_dir("grid_corner.asc")));
}

TEST(TerrainFile, EsriAsciiCenterHeaderInAnyOrderAndCaseGivesTheSameNodes) {
  expect_test_grid(read_esri_ascii(terrain_dir("grid_center.asc")));
}

TEST(TerrainFile, FillsAProfileShiftedByTheFileOrigin) {
  TerrainSurface spec;
  bathymetry_from_file(spec, terrain_dir("profile.csv"), {0, -150}, {1000, 200});
  ASSERT_EQ(spec.points.size(), 3u);
  EXPECT_EQ(spec.points[1], (std::array<double, 2>{400, 29.5}));
  // The domain's x = 0 at distance 100 in the file: the profile must reach 1100, it stops at 1000.
  const std::string msg =
      error_of([&] { bathymetry_from_file(spec, terrain_dir("profile.csv"), {100, 0}, {1000, 200}); });
  EXPECT_NE(msg.find("profile.csv:8: expected a profile spanning the domain, distance [100, 1100]"), std::string::npos)
      << msg;
}

TEST(TerrainFile, FillsAGridShiftedByTheFileOriginAndCroppedToTheDomain) {
  TerrainSurface spec;
  // Domain x in [50, 250], y in [0, 150] of the file: nodes i = 1..5, j = 0..3 (the NODATA corner is unused).
  bathymetry_from_file(spec, terrain_dir("grid_corner.asc"), {50, 0, -100}, {200, 150, 100});
  EXPECT_EQ(spec.origin, (std::vector<double>{0, 0}));
  EXPECT_EQ(spec.spacing, (std::vector<double>{50, 50}));
  ASSERT_EQ(spec.heights.size(), 4u);
  ASSERT_EQ(spec.heights[0].size(), 5u);
  for (std::size_t j = 0; j < 4; ++j)
    for (std::size_t i = 0; i < 5; ++i)
      EXPECT_DOUBLE_EQ(spec.heights[j][i], 100 - 10.0 * double(6 - j) - double(i + 1)) << j << " " << i;
}

TEST(TerrainFile, BadFilesAreRefusedNamingTheFileAndLine) {
  const auto expected = read_json(source_path("tests/bad_terrain/expected.json"));
  ASSERT_GE(expected.size(), 20u);
  for (const auto& [file, want] : expected.items()) {
    const std::string path = source_path("tests/bad_terrain/" + file);
    const bool grid = file.ends_with(".asc");
    const std::vector<double> domain = grid ? std::vector<double>{300, 200, 100} : std::vector<double>{1000, 200};
    TerrainSurface spec;
    const std::vector<double> origin(domain.size(), 0.0);
    const std::string msg = error_of([&] { bathymetry_from_file(spec, path, origin, domain); });
    const std::string where = path + ":" + std::to_string(want["line"].get<int>()) + ": ";
    EXPECT_EQ(msg.rfind(where, 0), 0u) << file << ": expected to start with " << where << ", got: " << msg;
    EXPECT_NE(msg.find(want["message"].get<std::string>()), std::string::npos) << file << ": " << msg;
  }
}

TEST(TerrainFile, MissingFileDirectoryAndOverlongLineAreRefused) {
  TempDir dir;
  std::string msg = error_of([&] { read_profile_csv(dir / "none.csv"); });
  EXPECT_EQ(msg, dir / "none.csv" + ": cannot open terrain file (no such file)");
  msg = error_of([&] { read_esri_ascii(dir.path.string()); });
  EXPECT_EQ(msg, dir.path.string() + ": expected a terrain file, got a directory");
  {
    std::ofstream out(dir / "long.csv");
    out << "distance,elevation\n0,1\n" << std::string(kMaxLineLength + 1, '1') << ",2\n";
  }
  msg = error_of([&] { read_profile_csv(dir / "long.csv"); });
  EXPECT_EQ(msg, dir / "long.csv" + ":3: expected a line of at most 16777216 characters, got a longer line");
}

TEST(TerrainFile, AGridIn2DOrAProfileIn3DIsRefused) {
  TerrainSurface spec;
  std::string msg = error_of([&] { bathymetry_from_file(spec, terrain_dir("grid_corner.asc"), {0, 0}, {300, 100}); });
  EXPECT_EQ(msg, terrain_dir("grid_corner.asc") + ": expected a CSV profile in a 2D scene, got an .asc grid (3D)");
  msg = error_of([&] { bathymetry_from_file(spec, terrain_dir("profile.csv"), {0, 0, 0}, {300, 100, 100}); });
  EXPECT_EQ(msg, terrain_dir("profile.csv") + ": expected an .asc grid in a 3D scene, got a .csv profile (2D)");
}

TEST(TerrainFile, SceneLoaderReadsTheFileRelativeToTheScene) {
  // The bathymetry built from the scene has the file's terrain: solid just below it, free just above.
  const Scene s2 = load_scene(terrain_dir("scene_2d.json"));
  ASSERT_EQ(s2.boundaries.size(), 2u);
  const auto bed2 = make_boundary<2>(s2, s2.boundaries[1], BoundaryContext<2>{Vec<2>(s2.domain.size[0], s2.domain.size[1]), Real(s2.domain.dx)});
  EXPECT_TRUE(bed2->is_solid(Vec<2>(1000, 109.9)));  // the profile's last point, (1000, 110) in the domain
  EXPECT_FALSE(bed2->is_solid(Vec<2>(1000, 110.1)));
  const Scene s3 = load_scene(terrain_dir("scene_3d.json"));
  const auto bed3 = make_boundary<3>(s3, s3.boundaries[1], BoundaryContext<3>{Vec<3>(s3.domain.size[0], s3.domain.size[1], s3.domain.size[2]), Real(s3.domain.dx)});
  EXPECT_TRUE(bed3->is_solid(Vec<3>(0, 0, 39.9)));  // the grid's node at the domain's origin: 40 m
  EXPECT_FALSE(bed3->is_solid(Vec<3>(0, 0, 40.1)));
}

TEST(TerrainFile, SceneWithFileAndInlinePointsIsRefused) {
  const std::string msg = error_of([] { load_scene(terrain_dir("scene_file_and_points_2d.json")); });
  EXPECT_NE(msg.find("scene_file_and_points_2d.json: boundaries[1].points: not allowed together with \"file\""),
            std::string::npos) << msg;
}

// scenes/data/eqip_sermia_profile.csv keeps the published numbers (docs/eqip_sermia.md): the front in 100 m
// of water, depths 35-135 m up to the slope of the opposite shore, the shoreline at 4000 m, the shore up to +60 m.
TEST(TerrainFile, EqipSermiaProfileKeepsThePublishedNumbers) {
  const TerrainProfile p = read_profile_csv(source_path("scenes/data/eqip_sermia_profile.csv"));
  double deepest = 0, shallowest = 1e9, top = -1e9;
  for (const auto& [x, z] : p.points) {
    if (x == 0) {
      EXPECT_EQ(z, -100);
    }
    if (x >= 0 && x <= 3850) deepest = std::max(deepest, -z), shallowest = std::min(shallowest, -z);
    if (x == 4000) {
      EXPECT_EQ(z, 0);
    }
    top = std::max(top, z);
  }
  EXPECT_EQ(deepest, 135);
  EXPECT_EQ(shallowest, 35);
  EXPECT_EQ(top, 60);
}

}  // namespace
}  // namespace cdmpm::testing
