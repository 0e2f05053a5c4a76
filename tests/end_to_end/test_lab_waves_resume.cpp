// test_lab_waves_resume.cpp - a laboratory calving-wave scene with a rigid body (coarse, cells_per_h = 10),
// resumed from a checkpoint or run on two threads, is bitwise identical to one straight run on one thread.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>

#include "cli_helpers.h"

namespace cdmpm::testing {
namespace {

// The capsizing block (hinge, tilt) resumed at half time and on two threads gives the same state bit for bit.
TEST(LabWaves, RigidResumeAndThreadCountGiveBitwiseIdenticalState) {
  TempDir dir;
  const std::string scene = source_path("scenes/lab_cs_2d.json");
  const std::vector<std::string> common = {"--quiet", "--set", "parameters.cells_per_h=10", "--set",
                                           "time.frame_interval=0.25", "--set", "output.checkpoint_every=1"};
  ASSERT_EQ(run_straight_other_threads_and_resumed(dir, scene, common, "1", "2", "0.5", "1"), "");
  for (const char* other : {"other", "half"}) {
    EXPECT_EQ(read_bytes(dir / "full/probes.csv"), read_bytes(dir / (std::string(other) + "/probes.csv"))) << other;
    EXPECT_EQ(read_bytes(dir / "full/waves.csv"), read_bytes(dir / (std::string(other) + "/waves.csv"))) << other;
  }
  // The block turned (the angle probe changed), so the rigid state was exercised.
  const auto p = read_probes(dir / "full/probes.csv");
  EXPECT_NE(p.at("block_angle").front(), p.at("block_angle").back());
  SKIP_IN_MPI_BUILD_LAYOUT();  // the checkpoint's index names its pieces after the run's alternation
  for (const char* other : {"other", "half"})
    EXPECT_EQ(read_bytes(dir / "full/checkpoint.bin"), read_bytes(dir / (std::string(other) + "/checkpoint.bin"))) << other;
}

}  // namespace
}  // namespace cdmpm::testing
