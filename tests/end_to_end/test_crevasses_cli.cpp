// test_crevasses_cli.cpp - surface crevasses (the body key "crevasses") through the program: it exits with 2 on a
// bad key, and writes crevasses.csv.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "cli_helpers.h"
#include "hydrostatic_column.h"
#include "material/stress.h"
#include "scene/scene_loader.h"
#include "shape/crevasse_field.h"
#include "shape/simplex_noise.h"
#include "sim/simulation.h"
#include "scene_builders.h"

namespace cdmpm {
namespace {

TEST(CrevassesCli, BadKeyExitsWithTwoAndAGoodSceneWritesCrevassesCsv) {
  using testing::CliResult, testing::TempDir, testing::run_cdmpm;
  TempDir dir;
  nlohmann::json c = {{"seed", 1}, {"spacing", 40}, {"depth", -5}, {"width", 4}};
  std::ofstream(dir / "bad.json") << testing::crevassed_ice_scene(2, c).dump();
  const CliResult bad = run_cdmpm({"run", dir / "bad.json", "--out", dir / "bad", "--quiet"});
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("bodies[0].crevasses.depth"), std::string::npos) << bad.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "bad"));
  c["depth"] = 30;
  nlohmann::json scene = testing::crevassed_ice_scene(2, c);
  scene["output"] = {{"frames", false}};
  std::ofstream(dir / "good.json") << scene.dump();
  const CliResult good = run_cdmpm({"run", dir / "good.json", "--out", dir / "good", "--quiet", "--steps", "1"});
  ASSERT_EQ(good.exit_code, 0) << good.output;
  const CsvTable t = read_csv_table(dir / "good/crevasses.csv");
  EXPECT_EQ(t.header, (std::vector<std::string>{"body", "crevasse", "x", "depth", "width", "clipped", "water_depth"}));
  ASSERT_EQ(t.rows.size(), 10u);
  for (double d : t.numbers("depth")) EXPECT_NEAR(d, 30, 1e-9);  // no depth_std: every crevasse at the mean
  for (double w : t.numbers("width")) EXPECT_EQ(w, 4);
}

}  // namespace
}  // namespace cdmpm
