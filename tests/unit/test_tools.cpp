// test_tools.cpp - the post-processing tools in tools/ behave as a user of a report expects (issue 21): a missing
// or wrong input gives one line naming it and exit status 2, never a Python traceback; no tool writes into a
// folder that holds committed files unless told to (--force); a plot goes where the user names.
#include <gtest/gtest.h>

#include <fstream>

#include "cli_helpers.h"

namespace cdmpm::testing {
namespace {

const char* kPython = "/usr/bin/python3";

// One line, naming the tool, exit 2, no traceback.
void expect_one_line_error(const CliResult& r, const std::string& tool, const std::string& names) {
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(r.output.find("Traceback"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.rfind(tool + ": ", 0), 0u) << r.output;
  EXPECT_NE(r.output.find(names), std::string::npos) << r.output;
  EXPECT_LE(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

TEST(Tools, MissingInputsAreOneLineErrors) {
  TempDir dir;
  const std::string none = dir / "no_such_run";
  expect_one_line_error(run_program(kPython, {source_path("tools/plot_frames.py"), none}), "plot_frames", none);
  expect_one_line_error(run_program(kPython, {source_path("tools/plot_probes.py"), none}), "plot_probes", none);
  expect_one_line_error(run_program(kPython, {source_path("tools/plot_hazard.py"), none}), "plot_hazard", none);
  expect_one_line_error(run_program(kPython, {source_path("tools/validate_lab"), "--skip-run", "--out", none}),
                        "validate_lab", none);
  expect_one_line_error(run_program(kPython, {source_path("tools/validate_dam_break.py"), "--no-run", "--out", none}),
                        "validate_dam_break", none);
}

TEST(Tools, PlotsGoWhereTheUserSaysAndNeverOverCommittedFiles) {
  TempDir dir;
  {
    std::ofstream csv(dir / "probes.csv");
    csv << "time,gauge\n0,0\n0.5,0.1\n1,0.05\n";
  }
  // Into a folder holding committed figures: refused, nothing written there.
  const std::string committed = source_path("docs/validation/lab");
  const auto before = fs::last_write_time(committed + "/lab_gauges.png");
  const auto refused = run_program(kPython, {source_path("tools/plot_probes.py"), dir.path.string(), "--out", committed});
  expect_one_line_error(refused, "plot_probes", "committed");
  EXPECT_FALSE(fs::exists(committed + "/probes.png"));
  EXPECT_EQ(fs::last_write_time(committed + "/lab_gauges.png"), before);
  // By default into the run's plots/ folder; --out elsewhere.
  const auto ok = run_program(kPython, {source_path("tools/plot_probes.py"), dir.path.string()});
  ASSERT_EQ(ok.exit_code, 0) << ok.output;
  EXPECT_TRUE(fs::exists(dir / "plots/probes.png"));
  const auto named = run_program(kPython, {source_path("tools/plot_probes.py"), dir.path.string(), "--out", dir / "mine"});
  ASSERT_EQ(named.exit_code, 0) << named.output;
  EXPECT_TRUE(fs::exists(dir / "mine/probes.png"));
}

}  // namespace
}  // namespace cdmpm::testing
