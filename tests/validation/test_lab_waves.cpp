// test_lab_waves.cpp - the laboratory calving-wave scenes end to end, coarse (cells_per_h = 10; the validation
// resolution is the scenes' 25, tools/validate_lab): scenes/lab_gf_2d.json, lab_bf_2d.json, lab_cs_2d.json.
// What must hold at any resolution: each run completes and writes waves.csv for its five gauges; water mass is
// conserved (to 0.1 %; the transfers conserve it exactly); the gravity-dominated fall raises the largest first
// crest of the three mechanisms (as in Heller et al. 2019); the GF leading crest travels at the long-wave
// celerity sqrt(g h) within 10 % between every gauge pair beyond x/h = 4; the buoyancy-dominated fall's wave leads
// with a trough. (At this resolution the crest runs
// 3-7 % below sqrt(g h) and up to 11 % below the solitary-wave celerity sqrt(g (h + a)); the 10 % band
// around sqrt(g (h + a)) is checked at the validation resolution by tools/validate_lab.)
// Resumed and on two threads: tests/end_to_end/test_lab_waves_resume.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>

#include "cli_helpers.h"

namespace cdmpm::testing {
namespace {

struct LabRun {
  nlohmann::json summary;
  std::map<std::string, std::vector<double>> probes;
  CsvTable waves;
};

LabRun run_lab(const TempDir& dir, const std::string& mechanism) {
  const std::string out = dir / mechanism;
  const auto r = run_cdmpm({"run", source_path("scenes/lab_" + mechanism + "_2d.json"), "--out", out, "--quiet",
                            "--threads", "1", "--set", "parameters.cells_per_h=10", "--set", "time.end=6"});
  EXPECT_EQ(r.exit_code, 0) << r.output;
  LabRun run;
  run.summary = read_json(out + "/summary.json");
  run.probes = read_probes(out + "/probes.csv");
  run.waves = read_csv_table(out + "/waves.csv");
  return run;
}

TEST(LabWaves, CoarseMechanismsConserveWaterAndFallMakesTheLargestWave) {
  TempDir dir;
  std::map<std::string, LabRun> runs;
  for (const char* m : {"gf", "bf", "cs"}) {
    runs[m] = run_lab(dir, m);
    const LabRun& r = runs[m];
    ASSERT_EQ(r.summary["status"], "completed") << m;
    EXPECT_EQ(r.waves.header, (std::vector<std::string>{"gauge", "x", "amplitude", "arrival_time", "earliest_arrival",
                                                      "noise_floor", "reason"})) << m;
    ASSERT_EQ(r.waves.rows.size(), 5u) << m;
    const auto& mass = r.probes.at("water_mass");
    EXPECT_LE(std::abs(mass.back() - mass.front()), 1e-3 * mass.front()) << m;
    ASSERT_TRUE(r.summary["max_amplitude"].is_number()) << m;
    // The block's probes are there (dim columns for position and velocity).
    for (const char* c : {"block_position_x", "block_position_y", "block_velocity_y", "block_angle"})
      EXPECT_EQ(r.probes.count(c), 1u) << m << ": " << c;
  }
  const double a_gf = runs["gf"].summary["max_amplitude"], a_bf = runs["bf"].summary["max_amplitude"],
               a_cs = runs["cs"].summary["max_amplitude"];
  EXPECT_GT(a_gf, a_bf);
  EXPECT_GT(a_gf, a_cs);
  // BF leads with a trough at every gauge: the block rising through the surface displaces less water than when
  // it was submerged, so the long-wave part of its wave is a depression (the crest behind it is the dispersive
  // second half-wave, docs/validation.md). The first sample beyond a quarter of the record's largest |eta| is
  // negative.
  for (const char* gauge : {"gauge_2h", "gauge_4h", "gauge_6h", "gauge_8h", "gauge_12h"}) {
    const auto& eta = runs["bf"].probes.at(gauge);
    double largest = 0;
    for (double e : eta) largest = std::max(largest, std::abs(e));
    ASSERT_GT(largest, 0) << gauge;
    size_t i = 0;
    while (std::abs(eta[i]) < 0.25 * largest) ++i;
    EXPECT_LT(eta[i], 0) << gauge << ": the BF wave's first excursion is a crest";
  }
  // GF leading crest: pairs (x/h 4 -> 6, 6 -> 8, 8 -> 12) at sqrt(g h).
  const double g = 9.81, h = runs["gf"].summary["parameters"]["h"];
  const auto gauge = runs["gf"].waves.strings("gauge");
  const auto x = runs["gf"].waves.numbers("x"), t = runs["gf"].waves.numbers("arrival_time");
  for (size_t i = 1; i + 1 < x.size(); ++i) {
    const double c = (x[i + 1] - x[i]) / (t[i + 1] - t[i]);
    EXPECT_NEAR(c, std::sqrt(g * h), 0.1 * std::sqrt(g * h)) << gauge[i] << " -> " << gauge[i + 1];
  }
}

}  // namespace
}  // namespace cdmpm::testing
