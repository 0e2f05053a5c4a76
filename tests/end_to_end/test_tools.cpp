// test_tools.cpp - the post-processing tools in tools/ behave as a user of a report expects: a missing
// or wrong input gives one line naming it and exit status 2, never a Python traceback; no tool writes into a
// folder that holds committed files unless told to (--force); a plot goes where the user names.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

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
  expect_one_line_error(run_program(kPython, {source_path("tools/validate_eqip"), "--skip-run", "--out", none}),
                        "validate_eqip", none);
  const std::string no_pair = dir / "no_such_pair";
  expect_one_line_error(run_program(kPython, {source_path("tools/eqip_2d_to_3d"), "--skip-run", "--out", no_pair}),
                        "eqip_2d_to_3d", no_pair);
  EXPECT_FALSE(std::filesystem::exists(no_pair)) << "eqip_2d_to_3d wrote into " << no_pair;
  expect_one_line_error(run_program(kPython, {source_path("tools/validate_runup"), "--skip-run", "--out", none}),
                        "validate_runup", none);
  expect_one_line_error(run_program(kPython, {source_path("tools/runup_linear.py"), "0.1-2.5"}), "runup_linear", "0.1-2.5");
  expect_one_line_error(run_program(kPython, {source_path("tools/cliff_stress.py"), none, "0"}), "cliff_stress", none);
  expect_one_line_error(run_program(kPython, {source_path("tools/resolved_shear.py"), none, "0"}), "resolved_shear", none);
}

// tools/yield_surfaces_2d.py draws both 2D conventions from one tensile strength: in the reference implementation's
// convention (`cd_mpm`) the in-plane uniaxial tension it finds on its surface is that strength (the convention
// defines it so: the loader's p0, src/material/ice.h), within the bisection's and the printout's 4 digits; a
// non-physical parameter is a one-line error.
TEST(Tools, YieldSurfacesOfBothConventionsHoldTheirTensileStrength) {
  TempDir dir;
  for (const char* st : {"0.7e6", "1.5e6"}) {
    const auto r = run_program(kPython, {source_path("tools/yield_surfaces_2d.py"), "--tensile-strength", st,
                                         "--out", dir / "fig"});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto at = r.output.find("cd_mpm:");
    ASSERT_NE(at, std::string::npos) << r.output;
    const auto key = r.output.find("uniaxial tension ", at);
    ASSERT_NE(key, std::string::npos) << r.output;
    const double found = std::stod(r.output.substr(key + 17)) * 1e6;
    EXPECT_NEAR(found, std::stod(st), 1e-3 * std::stod(st)) << r.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "fig/yield_surfaces_2d.png"));
  }
  const auto bad = run_program(kPython, {source_path("tools/yield_surfaces_2d.py"), "--beta", "-1", "--out", dir / "x"});
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_EQ(bad.output.rfind("yield_surfaces_2d: ", 0), 0u) << bad.output;
}

// tools/runup_linear.py against the theory it evaluates (Synolakis 1987): its asymptotic column is the run-up law
// 2.831 sqrt(cot beta) (H/d)^(5/4) (same closed form, so within the quadrature's 0.5 %), and the exact linear
// run-up tends to the law when 2 gamma cot beta >> 1: within 5 % at 4.9, where the Bessel functions' next
// asymptotic term is 1 / (8 z) = 2.6 %.
TEST(Tools, RunupLinearTheoryTendsToTheRunupLaw) {
  const auto r = run_program(kPython, {source_path("tools/runup_linear.py"), "0.1:2.5", "0.02:19.85"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::istringstream lines(r.output);
  std::string line;
  std::getline(lines, line);  // header
  for (int i = 0; i < 2; ++i) {
    ASSERT_TRUE(std::getline(lines, line)) << r.output;
    std::vector<double> v;
    std::istringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) v.push_back(std::stod(cell));
    ASSERT_EQ(v.size(), 7u) << line;
    const double law = 2.831 * std::sqrt(v[1]) * std::pow(v[0], 1.25);
    EXPECT_NEAR(v[5], law, 0.005 * law) << line;
    EXPECT_NEAR(v[4], v[5], 0.005 * law) << line;
    if (v[2] > 4) {
      EXPECT_NEAR(v[3] / law, 1.0, 0.05) << line;
    }
  }
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
