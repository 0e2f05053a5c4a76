// test_replay_cli.cpp - a run with a replayed source (rigid key `track`, sim/rigid_bodies.h) keeps the program's
// bitwise promises: the same particles and gauge record on 1 and 2 threads and after a resume half-way (the replayed
// particles' seeded positions come again from the seeding that precedes the checkpoint's load, not from the
// checkpoint). The recorded Eqip Sermia calving (scenes/eqip_sermia_replay_2d.json) at dx = 40 m over the first
// 1.16 km of the fjord, to t = 12 s: the source is moving (it slides out between 2 and 20 s).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "cli_helpers.h"

namespace cdmpm::testing {
namespace {

TEST(ReplayCli, RunIsTheSameOnOtherThreadsAndAfterResume) {
  TempDir dir;
  ASSERT_EQ(run_straight_other_threads_and_resumed(
                dir, source_path("scenes/eqip_sermia_replay_2d.json"),
                {"--quiet", "--set", "parameters.dx=40", "--set", "parameters.fjord_end=1400", "--set",
                 "output.frames=false", "--set",
                 R"(probes.list=[{"name": "gauge_250m", "type": "wave_gauge", "material": "water", "position": [490], )"
                 R"("still_level": 160}])"},
                "1", "2", "6", "12"),
            "");
  const std::string full = read_bytes(dir / "full/probes.csv");
  EXPECT_EQ(full, read_bytes(dir / "other/probes.csv"));
  EXPECT_EQ(full, read_bytes(dir / "half/probes.csv"));
  expect_same_particles<2>(dir / "full/checkpoint.bin", dir / "other/checkpoint.bin");
  expect_same_particles<2>(dir / "full/checkpoint.bin", dir / "half/checkpoint.bin");
  const auto p = read_probes(dir / "full/probes.csv");
  EXPECT_GT(*std::max_element(p.at("gauge_250m").begin(), p.at("gauge_250m").end()), 1.0);  // the wave reached it
}

}  // namespace
}  // namespace cdmpm::testing
