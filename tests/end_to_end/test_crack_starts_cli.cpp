// test_crack_starts_cli.cpp - the crack-start record (crack_starts.csv, summary.json; probe/crack_starts.h) is the
// same on 1 and 2 threads and after a resume.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <string>

#include "cli_helpers.h"
#include "material/stress.h"
#include "probe/crack_starts.h"
#include "scene/scene_loader.h"
#include "sim/simulation.h"

namespace cdmpm {
namespace {

// ---- the program: threads and resume ---------------------------------------------------------------------------

TEST(CrackStartsCli, SameRecordOnOneAndTwoThreadsAndAfterAResume) {
  testing::TempDir dir;
  // Pulled at 0.3 /s the bar breaks from t = 3.33 ms on, and the record of 64 events is full at 4.3 ms. The half
  // run stops at the frame time 4 ms (an output time of the straight run too, so both take the same steps) with
  // 40 events: the resumed run must continue the record it loaded from the checkpoint.
  const std::string err = testing::run_straight_other_threads_and_resumed(
      dir, testing::source_path("scenes/ice_bar_2d.json"),
      {"--quiet", "--set", "output.frames=false", "--set", "parameters.strain_rate=0.3"}, "1", "2", "0.004", "0.006");
  ASSERT_EQ(err, "");
  const std::string full = testing::read_bytes(dir / "full/crack_starts.csv");
  ASSERT_NE(full.find('\n'), std::string::npos);
  ASSERT_GT(std::count(full.begin(), full.end(), '\n'), 1) << "no crack start recorded";
  EXPECT_EQ(full, testing::read_bytes(dir / "other/crack_starts.csv")) << "differs between 1 and 2 threads";
  EXPECT_EQ(full, testing::read_bytes(dir / "half/crack_starts.csv")) << "differs after a resume";
  const auto a = testing::read_json(dir / "full/summary.json"), b = testing::read_json(dir / "other/summary.json"),
             c = testing::read_json(dir / "half/summary.json");
  ASSERT_TRUE(a["first_iceberg"].is_object());
  ASSERT_TRUE(a["first_iceberg"]["crack_start"].is_object());
  EXPECT_EQ(a["first_iceberg"]["crack_start"]["mode"], "tension");
  EXPECT_EQ(a["first_iceberg"], b["first_iceberg"]);
  EXPECT_EQ(a["first_iceberg"], c["first_iceberg"]);
}

}  // namespace
}  // namespace cdmpm
