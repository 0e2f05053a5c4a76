// test_terrain_cli.cpp - terrain from files (src/terrain/terrain_file.h) through the program: `cdmpm check` and
// `cdmpm run` on a scene with a bad terrain file (tests/bad_terrain/) exit with code 2, name the file and line and
// write nothing.
#include <gtest/gtest.h>

#include <fstream>

#include "cli_helpers.h"
#include "boundary/boundary.h"
#include "scene/scene_loader.h"
#include "terrain/terrain_file.h"

namespace cdmpm::testing {
namespace {

std::string terrain_dir(const std::string& file) { return source_path("tests/terrain/" + file); }

TEST(TerrainCli, BadTerrainFileExitsWithCode2NamingFileAndLineAndWritesNothing) {
  TempDir dir;
  const std::string scene = terrain_dir("scene_bad_profile_2d.json");
  for (const std::vector<std::string>& args : {std::vector<std::string>{"check", scene},
                                               std::vector<std::string>{"run", scene, "--out", dir / "out"}}) {
    const CliResult r = run_cdmpm(args);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("scene_bad_profile_2d.json: boundaries[1].file: "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("bad_terrain/profile_nan.csv:4: expected a finite number (elevation), got 'nan'"),
              std::string::npos) << r.output;
  }
  EXPECT_TRUE(fs::is_empty(dir.path)) << "something was written";
}

}  // namespace
}  // namespace cdmpm::testing
