// test_settle_cli.cpp - the settling before t = 0 (time.settle) through the program: a run resumed from a
// checkpoint gives the straight run's results.
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

// A run resumed from a checkpoint settles again before loading it, so its results, and the initial energies of its
// summary, are those of the straight run (bit for bit; docs/scenes.md, time.settle).
TEST(SettleCli, ResumeGivesTheStraightRunsResults) {
  testing::TempDir dir;
  auto j = testing::settle_block(1.0, 1.0);
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
