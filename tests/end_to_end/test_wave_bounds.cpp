// test_wave_bounds.cpp - numbers a hazard modeller can quote: what a run reports about its waves is physically
// possible, or absent with a reason (probe/wave_bounds.h, probe/wave_analysis.h, hazard/hazard_map.h):
//   WaveBounds: tests/unit/test_wave_bounds_arrival.cpp;
//   SetUpTraps (end-to-end): a run's set-up never silently differs from what the user wrote: an unknown
//     parameter in --set, the still level of water whose depth is not a whole number of particle spacings, a
//     frame interval beyond the end without frames, thread counts and memory beyond the machine;
//   HostileOutputs (end-to-end): short and coarse runs of the shipped scenes report no phantom crest, no
//     impossible celerity, no negative run-up.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "cli_helpers.h"
#include "probe/wave_analysis.h"
#include "probe/wave_bounds.h"
#include "scene/scene_loader.h"

namespace cdmpm::testing {
namespace {

constexpr double kG = 9.81;  // [m/s^2]

// Runs scenes/SCENE.json into dir/run, quietly and without frames, with the given --set values.
CliResult run_short(const TempDir& dir, const std::string& scene, const std::vector<std::string>& sets) {
  std::vector<std::string> args = {"run", source_path("scenes/" + scene + ".json"), "--out", dir / "run", "--quiet",
                                   "--set", "output.frames=false"};
  for (const std::string& v : sets) args.insert(args.end(), {"--set", v});
  return run_cdmpm(args);
}

// An unknown parameter in --set is refused with the list of the scene's parameters, like an unknown key.
TEST(SetUpTraps, UnknownParameterInSetIsRefusedWithTheKnownOnes) {
  TempDir dir;
  const CliResult r = run_cdmpm({"run", source_path("scenes/calving_front_2d.json"), "--out", dir / "run", "--set",
                                 "parameters.dX=5", "--steps", "1", "--quiet"});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("no parameter 'dX'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("notch_depth"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "run"));
  const CliResult c = run_cdmpm({"check", source_path("scenes/calving_front_2d.json"), "--set", "parameters.dX=5"});
  EXPECT_EQ(c.exit_code, 2) << c.output;
}

// Water 197 m deep seeded at 4 particles per 10 m cell (a spacing of 5 m: 39.4 spacings) stands at 197 m, not at
// 195 or 200: the gauge, measuring from the scene's still level, starts at 0 within rounding and the lake
// (a well-balanced bed of the Eqip Sermia profile) stays within dx/20 over 5 s.
TEST(SetUpTraps, WaterIsSeededToItsStillLevel) {
  TempDir dir;
  const CliResult r = run_cdmpm({"run", source_path("scenes/lake_at_rest_2d.json"), "--out", dir / "run", "--quiet",
                                 "--set", "parameters.sea_level=197", "--set", "time.end=5", "--set",
                                 "time.frame_interval=5", "--set", "output.frames=false"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto probes = read_probes(dir / "run/probes.csv");
  const auto& eta = probes.at("gauge_2000");
  EXPECT_NEAR(eta.front(), 0.0, 1e-9);
  for (double e : eta) EXPECT_LE(std::abs(e), 10.0 / 20);
}

// What would move the still water before any wave is said by check: water seeded without its hydrostatic state
// settles by rho0 g H^2 / (2K), for the calving front's 40 m of water at K = 1e8 Pa 1000 x 9.81 x 40^2 / 2e8 =
// 0.07848 m, more than dx/20 at dx = 1 m; and a gauge whose still level is not the water's.
TEST(SetUpTraps, CheckWarnsOfWaterThatWouldSettle) {
  const CliResult quiet = run_cdmpm({"check", source_path("scenes/calving_front_2d.json")});
  EXPECT_EQ(quiet.exit_code, 0) << quiet.output;
  EXPECT_EQ(quiet.output.find("warning"), std::string::npos) << quiet.output;
  const CliResult r = run_cdmpm({"check", source_path("scenes/calving_front_2d.json"), "--set",
                                 "bodies.1.hydrostatic=false", "--set", "parameters.dx=1"});
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("warning: bodies[1]: hydrostatic is false"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("0.07848 m"), std::string::npos) << r.output;
  // A gauge measuring from a level 1 m off the water's.
  const CliResult g2 = run_cdmpm({"check", source_path("scenes/lake_at_rest_2d.json"), "--set",
                                  "probes.list.2.still_level=201"});
  EXPECT_NE(g2.output.find("warning: probes.list[2]: still_level 201 m differs"), std::string::npos) << g2.output;
}

// Without frames, a frame interval longer than the run only paces checkpoints: accepted; with frames, refused.
TEST(SetUpTraps, FrameIntervalBeyondTheEndIsAcceptedWithoutFrames) {
  TempDir dir;
  const std::vector<std::string> common = {"--quiet", "--set", "time.end=0.02", "--set", "time.frame_interval=1"};
  auto args = [&](const std::string& out, bool frames) {
    std::vector<std::string> a = {"run", source_path("scenes/dam_break_2d.json"), "--out", dir / out};
    a.insert(a.end(), common.begin(), common.end());
    a.insert(a.end(), {"--set", std::string("output.frames=") + (frames ? "true" : "false")});
    return a;
  };
  const CliResult off = run_cdmpm(args("off", false));
  EXPECT_EQ(off.exit_code, 0) << off.output;
  const CliResult on = run_cdmpm(args("on", true));
  EXPECT_EQ(on.exit_code, 2) << on.output;
  EXPECT_NE(on.output.find("time.frame_interval"), std::string::npos) << on.output;
}

// Thread counts no machine runs well and a scene too big for the memory this process may use (its address-space
// limit, ulimit -v 1.1 GB: 4.1 M particles of 1e6 per cell need about 1.6 GB with their frames) are refused up
// front with exit 2 and a message, not left to the OpenMP runtime or a bad_alloc.
TEST(SetUpTraps, AbsurdThreadsAndTooLittleMemoryAreRefusedUpFront) {
  TempDir dir;
  for (const char* threads : {"10000", "2e9"}) {
    const CliResult r = run_cdmpm({"run", source_path("scenes/dam_break_2d.json"), "--out", dir / "t", "--threads",
                                   threads, "--steps", "1", "--quiet"});
    EXPECT_EQ(r.exit_code, 2) << threads << ": " << r.output;
    EXPECT_NE(r.output.find("--threads"), std::string::npos) << r.output;
  }
  const std::string cmd = "ulimit -v 1100000; exec " + quote(CDMPM_BINARY) + " run " +
                          quote(source_path("scenes/dam_break_2d.json")) + " --out " + quote(dir / "m") +
                          " --set domain.dx=0.04 --set bodies.0.particles_per_cell=1000000 --steps 2 --quiet";
  const CliResult m = run_program("/bin/sh", {"-c", cmd});
  EXPECT_EQ(m.exit_code, 2) << m.output;
  EXPECT_NE(m.output.find("ulimit -v"), std::string::npos) << m.output;
  EXPECT_FALSE(fs::exists(dir / "m"));
}

// The calving front at dx = 10 m, stopped at 6 s: the iceberg has fallen, the wave has not reached the 600 m
// gauge (no wave can before 15 s): no crest there, with its reason; no celerity from one gauge; no shore, said.
TEST(HostileOutputs, ShortCoarseCalvingRunReportsNoPhantomCrest) {
  TempDir dir;
  const CliResult r = run_short(dir, "calving_front_2d", {"parameters.dx=10", "time.end=6"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const CsvTable waves = read_csv_table(dir / "run/waves.csv");
  const auto gauge = waves.strings("gauge"), reason = waves.strings("reason");
  const auto amplitude = waves.numbers("amplitude"), earliest = waves.numbers("earliest_arrival");
  for (size_t i = 0; i < gauge.size(); ++i)
    if (gauge[i] == "gauge_600m") {
      EXPECT_TRUE(std::isnan(amplitude[i])) << amplitude[i];
      EXPECT_EQ(reason[i].rfind("not arrived: ", 0), 0u) << reason[i];
      EXPECT_NEAR(earliest[i], 600 / (2 * std::sqrt(kG * 40)), 1e-6);
    }
  const nlohmann::json s = read_json(dir / "run/summary.json");
  EXPECT_TRUE(s["celerity"].is_null()) << s["celerity"];
  EXPECT_TRUE(s["hazard"]["shores"].empty());
  EXPECT_TRUE(s["hazard"].contains("shores_reason"));
  EXPECT_FALSE(fs::exists(dir / "run/runup.csv"));
}

// The Eqip Sermia fjord in 3D at dx = 40 m for 40 s: the block has toppled into the fjord and its wave has run
// 1.2 km (at about 36 m/s, sqrt(g D) over the fjord's 120 m). No run-up below the still level (the columns the
// block vacates were ice at t = 0, not land: it was -100 m); an arrival time in at least half of the wet columns
// within 1 km of the front, all of which the wave has passed (a fixed dx/4 gave 3 of 3,570 columns one); no crest
// before its earliest arrival; a celerity in (0, 2 sqrt(g h_max)] (it was -79 m/s, and 67,766 m/s for a pair).
TEST(HostileOutputs, Eqip3DCoarseRunHasNoNegativeRunupAndAnArrivalMap) {
  TempDir dir;
  const CliResult r = run_short(dir, "eqip_sermia_3d", {"parameters.dx=40", "time.end=40"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json s = read_json(dir / "run/summary.json");
  const nlohmann::json& h = s["hazard"];
  EXPECT_TRUE(h["runup"].is_null() || h["runup"].get<double>() >= 0) << h.dump();
  const double c_max = s["wave_bounds"]["c_max"].get<double>();
  ASSERT_TRUE(s["celerity"].is_number()) << s.dump();
  EXPECT_GT(s["celerity"].get<double>(), 0);
  EXPECT_LE(s["celerity"].get<double>(), c_max);
  for (const auto& p : s["celerity_pairs"]) EXPECT_TRUE(p["celerity"].is_null() || p["celerity"].get<double>() <= c_max);
  const CsvTable waves = read_csv_table(dir / "run/waves.csv");
  const auto arrival = waves.numbers("arrival_time"), earliest = waves.numbers("earliest_arrival");
  for (size_t i = 0; i < arrival.size(); ++i)
    if (!std::isnan(arrival[i])) {
      EXPECT_GE(arrival[i], earliest[i]) << waves.rows[i][0];
    }
  // The rasters: rows from the north, columns from x = 0; cell centres at (i + 1/2) dx.
  auto raster = [&](const std::string& name) {
    std::ifstream in(dir / ("run/" + name));
    std::string key;
    double v = 0;
    int ncols = 0;
    for (int k = 0; k < 6 && in >> key >> v; ++k)
      if (key == "ncols") ncols = static_cast<int>(v);
    std::vector<double> all;
    while (in >> v) all.push_back(v);
    return std::make_pair(ncols, all);
  };
  const auto [ncols, arrive] = raster("arrival_time.asc");
  const auto [ncols2, top] = raster("max_elevation.asc");
  ASSERT_EQ(ncols, ncols2);
  ASSERT_EQ(arrive.size(), top.size());
  const double front = 160, dx = 40;
  size_t wet = 0, reached = 0;
  for (size_t k = 0; k < top.size(); ++k) {
    const double x = (static_cast<double>(k % static_cast<size_t>(ncols)) + 0.5) * dx;
    if (x > front + 1000 || top[k] == -9999) continue;
    ++wet;
    reached += arrive[k] != -9999;
  }
  EXPECT_GT(wet, 500u);
  EXPECT_GE(2 * reached, wet) << reached << " of " << wet;
}

// Every shipped scene with water, run short and coarse as users try them first: what summary.json and waves.csv
// report is physically possible, or absent with a reason. Bounds from theory: a first crest no earlier than the
// earliest arrival (distance from the sources over c_max = 2 sqrt(g h_max)) and no higher than the domain's top
// (water cannot leave it); a celerity in (0, c_max]; a 3D run-up never negative (a maximum height of inundated
// land above the still level); a 2D run-up no lower than the still level by more than the surface's resolution
// (dx/4: at t = 0 the shoreline is at the still level).
struct ShortRun {
  const char* scene;
  std::vector<std::string> sets;
};

class HostileOutputsOfShippedScenes : public ::testing::TestWithParam<ShortRun> {};

TEST_P(HostileOutputsOfShippedScenes, AreAbsentOrPhysicallyPossible) {
  const ShortRun& c = GetParam();
  TempDir dir;
  const CliResult r = run_short(dir, c.scene, c.sets);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json s = read_json(dir / "run/summary.json");
  const nlohmann::json resolved = read_json(dir / "run/scene.resolved.json");
  const double top = resolved["domain"]["size"].back().get<double>(), dx = resolved["domain"]["dx"].get<double>();
  if (s.contains("wave_bounds")) {
    const double c_max = s["wave_bounds"]["c_max"].get<double>();
    auto possible = [&](const nlohmann::json& v) { return v.is_null() || (v.get<double>() > 0 && v.get<double>() <= c_max); };
    EXPECT_TRUE(possible(s["celerity"])) << s["celerity"];
    for (const auto& p : s["celerity_pairs"]) EXPECT_TRUE(possible(p["celerity"])) << p.dump();
    const CsvTable waves = read_csv_table(dir / "run/waves.csv");
    const auto amplitude = waves.numbers("amplitude"), arrival = waves.numbers("arrival_time"),
               earliest = waves.numbers("earliest_arrival");
    const auto reason = waves.strings("reason");
    for (size_t i = 0; i < amplitude.size(); ++i) {
      if (std::isnan(amplitude[i])) {
        EXPECT_EQ(reason[i].rfind("not arrived: ", 0), 0u) << waves.rows[i][0];
        continue;
      }
      EXPECT_GE(arrival[i], earliest[i]) << waves.rows[i][0];
      EXPECT_GT(amplitude[i], 0) << waves.rows[i][0];
      EXPECT_LT(amplitude[i], top) << waves.rows[i][0];
    }
  }
  if (s.contains("hazard")) {
    const nlohmann::json& h = s["hazard"];
    if (h.contains("runup")) {
      EXPECT_TRUE(h["runup"].is_null() || h["runup"].get<double>() >= 0) << h["runup"];
    }
    if (h.contains("shores")) {
      for (const auto& shore : h["shores"])
        EXPECT_TRUE(shore["runup"].is_null() || shore["runup"].get<double>() >= -dx / 4) << shore.dump();
    }
    if (!h["max_elevation"].is_null()) {
      EXPECT_LT(h["max_elevation"]["elevation"].get<double>(), top);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    ShortAndCoarse, HostileOutputsOfShippedScenes,
    ::testing::Values(ShortRun{"calving_front_2d", {"parameters.dx=10", "time.end=8"}},
                      ShortRun{"eqip_sermia_block_2d", {"parameters.dx=20", "time.end=12"}},
                      ShortRun{"eqip_sermia_wedge_2d", {"parameters.dx=20", "time.end=6"}},
                      ShortRun{"lab_gf_2d", {"parameters.cells_per_h=6", "time.end=1"}},
                      ShortRun{"lab_cs_2d", {"parameters.cells_per_h=6", "time.end=1"}},
                      ShortRun{"wave_celerity_2d", {"parameters.cells_per_h=8", "time.end=1.5"}},
                      ShortRun{"solitary_runup_2d", {"parameters.cells_per_h=6", "time.end=3"}},
                      ShortRun{"absorbing_packet_2d", {"parameters.cells_per_h=6", "time.end=4"}},
                      ShortRun{"lake_at_rest_2d", {"parameters.dx=20", "time.end=5"}},
                      ShortRun{"sliding_block_2d", {"time.end=2"}},
                      ShortRun{"calving_3d", {"parameters.cells_per_H=6", "time.end=1"}}),
    [](const ::testing::TestParamInfo<ShortRun>& info) { return std::string(info.param.scene); });

}  // namespace
}  // namespace cdmpm::testing
