// test_cli.cpp - the cdmpm program end to end: bad input is refused with a message naming the key and
// nothing written; an unstable run stops with status "unstable" and keeps its frames; a resumed run and
// runs on 1 and 2 threads give bitwise identical particle states; --help, --version and check work.
#include <gtest/gtest.h>

#include <cstring>

#include "bad_scenes.h"
#include "cli_helpers.h"
#include "io/checkpoint.h"

namespace cdmpm::testing {
namespace {

TEST(Cli, VersionHelpAndCheck) {
  auto r = run_cdmpm({"--version"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.output.find("cdmpm"), std::string::npos);
  r = run_cdmpm({"--help"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.output.find("run"), std::string::npos);
  for (const char* s : {"hydrostatic_2d", "dam_break_2d", "dam_break_3d"}) {
    r = run_cdmpm({"check", source_path(std::string("scenes/") + s + ".json")});
    EXPECT_EQ(r.exit_code, 0) << s << ": " << r.output;
  }
  r = run_cdmpm({"run"});
  EXPECT_EQ(r.exit_code, 2);
}

TEST(Cli, BadScenesExitNonZeroNameTheKeyAndWriteNothing) {
  TempDir scenes;
  const std::vector<BadScene> bad = write_bad_scenes(scenes.path);
  ASSERT_GE(bad.size(), 15u);
  for (const BadScene& s : bad) {
    TempDir dir;
    const auto r = run_cdmpm({"run", s.path, "--out", dir / "out"});
    EXPECT_EQ(r.exit_code, s.exit_code) << s.name << ": " << r.output;
    EXPECT_NE(r.output.find(s.message), std::string::npos) << s.name << ": " << r.output;
    EXPECT_NE(r.output.find(s.name + ".json"), std::string::npos) << s.name << " not named in: " << r.output;
    EXPECT_FALSE(fs::exists(dir / "out")) << s.name << ": output directory was created";
  }
  // The base scenes the rows patch are valid.
  for (const std::string& base : bad_scene_bases()) {
    const auto r = run_cdmpm({"check", base});
    EXPECT_EQ(r.exit_code, 0) << base << ": " << r.output;
  }
  // A bad --set override is bad input too.
  TempDir dir;
  const auto r = run_cdmpm({"run", source_path("scenes/hydrostatic_2d.json"), "--out", dir / "out", "--set", "domain.dx=-1"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("domain.dx"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(Cli, UnstableRunStopsWithReasonAndKeepsFrames) {
  TempDir dir;
  // Water launched at 1e5 m/s: the CFL time step collapses far below the acoustic one.
  const auto r = run_cdmpm({"run", source_path("scenes/hydrostatic_2d.json"), "--out", dir / "out", "--quiet", "--set",
                            "bodies.0.velocity=[1e5,0]"});
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("unstable"), std::string::npos) << r.output;
  const auto s = read_json(dir / "out/summary.json");
  EXPECT_EQ(s["status"], "unstable");
  EXPECT_NE(s["reason"].get<std::string>().find("time step collapsed"), std::string::npos) << s["reason"];
  EXPECT_NE(s["reason"].get<std::string>().find("t = "), std::string::npos) << s["reason"];
  SKIP_IN_MPI_BUILD_LAYOUT();
  // Frame 0 is intact (complete XML).
  const std::string f0 = read_bytes(dir / "out/particles_0000.vtu");
  EXPECT_NE(f0.find("</VTKFile>"), std::string::npos);
  // The collection lists the frame that was written.
  EXPECT_NE(read_bytes(dir / "out/particles.pvd").find("particles_0000.vtu"), std::string::npos);
}

TEST(Cli, ResumeGivesBitwiseIdenticalState) {
  TempDir dir;
  const std::string scene = source_path("scenes/dam_break_2d.json");
  const std::vector<std::string> common = {"--quiet", "--set", "domain.dx=0.003571875", "--set",
                                           "time.frame_interval=0.01"};
  auto args = [&](std::vector<std::string> a) { a.insert(a.end(), common.begin(), common.end()); return a; };
  auto r = run_cdmpm(args({"run", scene, "--out", dir / "full", "--set", "time.end=0.08"}));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = run_cdmpm(args({"run", scene, "--out", dir / "half", "--set", "time.end=0.04"}));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = run_cdmpm(args({"run", scene, "--resume", dir / "half", "--set", "time.end=0.08"}));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  expect_same_particles<2>(dir / "full/checkpoint.bin", dir / "half/checkpoint.bin");
  EXPECT_EQ(read_bytes(dir / "full/probes.csv"), read_bytes(dir / "half/probes.csv"));
  EXPECT_EQ(read_bytes(dir / "full/particles.pvd"), read_bytes(dir / "half/particles.pvd"));
  EXPECT_EQ(read_json(dir / "half/summary.json")["steps"], read_json(dir / "full/summary.json")["steps"]);
  // Resuming from a directory without a checkpoint is a clear error.
  r = run_cdmpm(args({"run", scene, "--resume", dir / "nothing"}));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("checkpoint"), std::string::npos) << r.output;
}

// `--resume DIR` alone: the scene and --set values come from DIR/run.json, which records them with the command
// line, version and commit (also in summary.json, beside scene.resolved.json, the scene as loaded). The resumed
// run ends in the same state as the straight one, bit for bit. A folder that is not a run's is refused.
TEST(Cli, ResumeNeedsNoRepeatedSetValues) {
  TempDir dir;
  const std::string scene = source_path("scenes/dam_break_2d.json");
  const std::vector<std::string> sets = {"--set", "domain.dx=0.003571875", "--set", "time.frame_interval=0.01"};
  auto args = [&](std::vector<std::string> a, const std::string& end) {
    a.insert(a.end(), sets.begin(), sets.end());
    a.insert(a.end(), {"--set", "time.end=" + end, "--quiet"});
    return a;
  };
  auto r = run_cdmpm(args({"run", scene, "--out", dir / "full"}, "0.06"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = run_cdmpm(args({"run", scene, "--out", dir / "half"}, "0.03"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto run = read_json(dir / "half/run.json");
  EXPECT_EQ(run["overrides"].size(), 3u);
  EXPECT_EQ(run["overrides"][0], "domain.dx=0.003571875");
  EXPECT_TRUE(fs::exists(dir / "half/scene.resolved.json"));
  EXPECT_EQ(read_json(dir / "half/summary.json")["command_line"][1], "run");
  r = run_cdmpm({"run", "--resume", dir / "half", "--set", "time.end=0.06", "--quiet"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  expect_same_particles<2>(dir / "full/checkpoint.bin", dir / "half/checkpoint.bin");
  EXPECT_EQ(read_bytes(dir / "full/probes.csv"), read_bytes(dir / "half/probes.csv"));
  // A folder without run.json (and no scene given), and a run.json that is not one, are refused with exit 2.
  fs::create_directories(dir / "foreign");
  r = run_cdmpm({"run", "--resume", dir / "foreign"});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("not the output folder of a cdmpm run"), std::string::npos) << r.output;
  std::ofstream(dir / "foreign/run.json") << "{\"scene_file\": 3}";
  r = run_cdmpm({"run", "--resume", dir / "foreign"});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("run.json: expected an object"), std::string::npos) << r.output;
}

// Resuming with another frame or probe interval (--set time.frame_interval / probes.interval) continues on a
// grid of the new interval from the resume time. The first version kept the index grid, (k + 1) dt: with a
// shorter interval it put the next output in the past, the run stepped with a negative dt and blew up.
TEST(Cli, ResumeWithAnotherOutputIntervalContinuesFromTheResumeTime) {
  TempDir dir;
  const std::string scene = source_path("scenes/dam_break_2d.json");
  auto r = run_cdmpm({"run", scene, "--out", dir / "run", "--quiet", "--set", "domain.dx=0.003571875", "--set",
                      "time.end=0.04", "--set", "time.frame_interval=0.01"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* interval : {"0.0025", "0.02"}) {  // shorter, then longer than the checkpoint's 0.01 s
    const double dt = std::stod(interval), t0 = read_json(dir / "run/summary.json")["sim_time"];
    r = run_cdmpm({"run", scene, "--resume", dir / "run", "--quiet", "--set", "domain.dx=0.003571875", "--set",
                   "time.end=" + std::to_string(t0 + 2 * dt), "--set", std::string("time.frame_interval=") + interval,
                   "--set", std::string("probes.interval=") + interval});
    ASSERT_EQ(r.exit_code, 0) << interval << ": " << r.output;
    const auto s = read_json(dir / "run/summary.json");
    EXPECT_EQ(s["status"], "completed") << interval;
    EXPECT_NEAR(s["sim_time"].get<double>(), t0 + 2 * dt, 1e-12) << interval;
    // The last two frames in particles.pvd are at t0 + dt and t0 + 2 dt.
    const std::string pvd = read_bytes(dir / "run/particles.pvd");
    std::vector<double> times;
    for (size_t p = pvd.find("timestep=\""); p != std::string::npos; p = pvd.find("timestep=\"", p + 1))
      times.push_back(std::stod(pvd.substr(p + 10)));
    ASSERT_GE(times.size(), 2u);
    EXPECT_NEAR(times[times.size() - 2], t0 + dt, 1e-9) << interval;
    EXPECT_NEAR(times.back(), t0 + 2 * dt, 1e-9) << interval;
  }
}

// The same for ice (elastic F, hardening alpha, icebergs.csv, the first-iceberg record in the checkpoint):
// the coarse sliding block pushed hard enough to break before half time (a block breaks off near the pusher
// at about 6 s), resumed at half time, and on 1 thread. (At a push of 10 m/s the first break was a fragment
// at the front just above the debris size, which came at 9 s or not before 30 s depending on rounding-level
// changes such as the order of the particles in memory.)
TEST(Cli, IceResumeAndThreadCountGiveBitwiseIdenticalState) {
  TempDir dir;
  const std::string scene = source_path("scenes/sliding_block_2d.json");
  const std::vector<std::string> common = {"--quiet", "--set", "parameters.cells_per_H=8", "--set",
                                           "parameters.push_speed=20", "--set", "parameters.push_ramp=5", "--set",
                                           "output.icebergs.stop_after_first=1000"};
  const std::string failed = run_straight_other_threads_and_resumed(dir, scene, common, "2", "1", "8", "16");
  ASSERT_EQ(failed, "");
  expect_same_particles<2>(dir / "full/checkpoint.bin", dir / "half/checkpoint.bin");
  expect_same_particles<2>(dir / "full/checkpoint.bin", dir / "other/checkpoint.bin");
  for (const char* f : {"probes.csv", "icebergs.csv"}) {
    EXPECT_EQ(read_bytes(dir / ("full/" + std::string(f))), read_bytes(dir / ("half/" + std::string(f)))) << f;
    EXPECT_EQ(read_bytes(dir / ("full/" + std::string(f))), read_bytes(dir / ("other/" + std::string(f)))) << f;
  }
  const auto full = read_json(dir / "full/summary.json");
  EXPECT_EQ(read_json(dir / "half/summary.json")["first_iceberg"], full["first_iceberg"]);
  ASSERT_TRUE(full["first_iceberg"].is_object()) << "the run should break the slab before t = 8 s";
  EXPECT_LT(full["first_iceberg"]["time"].get<double>(), 8) << "the half run's checkpoint should hold the first iceberg";
}

TEST(Cli, OneAndTwoThreadsGiveBitwiseIdenticalState) {
  TempDir dir;
  for (const char* t : {"1", "2"}) {
    const auto r = run_cdmpm({"run", source_path("scenes/dam_break_3d.json"), "--out", dir / t, "--threads", t, "--quiet",
                              "--set", "domain.dx=0.00714375", "--set", "time.end=0.03", "--set", "output.frames=false"});
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  expect_same_particles<3>(dir / "1/checkpoint.bin", dir / "2/checkpoint.bin");
}

}  // namespace
}  // namespace cdmpm::testing
