// test_section_probe_cli.cpp - the "section" probe (probe/section.cpp) through the program: a section outside the
// domain is refused with exit code 2, and probes.csv is the same bytes on 1 and 2 threads and after a resume.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <bit>
#include <cstdio>
#include <cmath>
#include <fstream>

#include "cli_helpers.h"
#include "probe/probes.h"
#include "scene/scene_loader.h"
#include "sim/simulation.h"
#include "scene_builders.h"

namespace cdmpm::testing {
namespace {

// The program refuses a section outside the domain with exit code 2, naming file and key.
TEST(SectionProbe, CliRefusesASectionOutsideTheDomainWithExit2) {
  TempDir dir;
  const std::string file = dir / "section.json";
  std::ofstream(file) << section_tank(2, 1, 0.1, 1, 4, 0, 0.1, {{"position", {4.5}}}).dump();
  const CliResult r = run_cdmpm({"check", file});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("probes.list[0].position"), std::string::npos) << r.output;
}

// The record is the same bytes on 1 and 2 threads and after a resume half-way (the still level measured at t = 0
// comes back from the checkpoint, not from the state at the resume).
TEST(SectionProbe, CliRecordIsTheSameOnOtherThreadsAndAfterResume) {
  TempDir dir;
  const std::string file = dir / "section.json";
  nlohmann::json j = section_tank(2, 0.5, 0.0625, 1, 3, 0, 0.0625, {{"position", {1.25}}});
  j["time"] = {{"end", 0.4}, {"frame_interval", 0.1}};
  j["probes"]["interval"] = 0.01;
  std::ofstream(file) << j.dump();
  ASSERT_EQ(run_straight_other_threads_and_resumed(dir, file, {"--quiet"}, "1", "2", "0.2", "0.4"), "");
  const std::string full = read_bytes(dir / "full/probes.csv");
  EXPECT_EQ(full, read_bytes(dir / "other/probes.csv"));
  EXPECT_EQ(full, read_bytes(dir / "half/probes.csv"));
  const auto p = read_probes(dir / "full/probes.csv");
  EXPECT_EQ(p.at("s_eta").front(), 0);
  EXPECT_GT(*std::max_element(p.at("s_eta").begin(), p.at("s_eta").end()), 0.01);  // the wave reached it
}

}  // namespace
}  // namespace cdmpm::testing
