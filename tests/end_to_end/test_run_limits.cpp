// test_run_limits.cpp - inputs that used to run for minutes, eat the machine's memory or overflow the grid now
// stop before the run starts, with exit code 2, a message naming the key and what was expected (or the run's
// estimate), and nothing written: physical ranges of material keys and gravity, the up-front estimate of memory
// and frames (run/run_estimate.h, with --force as the override), the grid lattice bound, and a body that seeds
// no particle. `cdmpm check` takes several scenes and reports each one's estimate and seeded particles.
#include <gtest/gtest.h>

#include "bad_scenes.h"
#include "cli_helpers.h"
#include "run/run_estimate.h"
#include "scene/scene_loader.h"

namespace cdmpm::testing {
namespace {

const std::string kScene = source_path("scenes/calving_front_2d.json");

// `cdmpm run` of the default scene with `sets` exits 2 naming `what` and writes no output folder.
void expect_refused(const std::vector<std::string>& sets, const std::string& what) {
  TempDir dir;
  std::vector<std::string> args = {"run", kScene, "--out", dir / "out", "--quiet"};
  for (const auto& s : sets) args.insert(args.end(), {"--set", s});
  const auto r = run_cdmpm(args);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(what), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "out")) << "output written for a refused run";
}

TEST(RunLimits, NonPhysicalMaterialValuesAreInputErrors) {
  expect_refused({"materials.water.density=1e-300"}, "materials.water.density: expected a number in [1, 100000] kg/m^3");
  expect_refused({"materials.water.density=1e308"}, "materials.water.density: expected a number in [1, 100000]");
  expect_refused({"materials.water.bulk_modulus=1e20"}, "materials.water.bulk_modulus: expected a number in (0, 1e+12] Pa");
  expect_refused({"materials.ice.youngs_modulus=1e300"}, "materials.ice.youngs_modulus: expected a number in (0, 1e+12] Pa");
  expect_refused({"materials.ice.poissons_ratio=0.4999999999"}, "materials.ice.poissons_ratio: expected a number in (-1, 0.49]");
  expect_refused({"gravity=[0,-1e30]"}, "gravity[1]: expected a number in [-1000, 1000]");
}

TEST(RunLimits, RunsTooBigForTheMachineAreRefusedWithTheirEstimate) {
  expect_refused({"parameters.dx=0.01"}, "of memory, the machine has");     // ~1e9 particles
  expect_refused({"bodies.0.particles_per_cell=1000000"}, "of memory, the machine has");
  expect_refused({"domain.dx=1e-300"}, "domain.dx");                       // lattice overflow, even with --force
  expect_refused({"time.frame_interval=1e-12"}, "time.frame_interval: the run would write");
  TempDir dir;
  const auto forced = run_cdmpm({"run", kScene, "--out", dir / "out", "--quiet", "--force", "--set", "domain.dx=1e-300"});
  EXPECT_EQ(forced.exit_code, 2) << "the lattice bound holds with --force: " << forced.output;
}

TEST(RunLimits, ForceRunsPastTheFrameLimit) {
  TempDir dir;
  const auto r = run_cdmpm({"run", kScene, "--out", dir / "out", "--quiet", "--force", "--set", "time.end=0.002",
                            "--set", "time.frame_interval=1e-7", "--set", "output.frames=false", "--steps", "2"});
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

TEST(RunLimits, ABodyThatSeedsNoParticleIsAnInputError) {
  // The water body made smaller than the particle spacing (its box lies between two lattice points).
  expect_refused({"bodies.1.shape.max.1=0.1", "bodies.1.shape.min.1=0.05"}, "bodies[1]: seeds no particle");
}

TEST(RunLimits, CheckReportsEachScenesEstimate) {
  const auto r = run_cdmpm({"check", kScene, source_path("scenes/dam_break_2d.json")});
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("calving_front_2d.json: valid 2D scene"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("dam_break_2d.json: valid 2D scene"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("particles <= "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("first dt "), std::string::npos) << r.output;
  TempDir dir;
  const auto bad = run_cdmpm({"check", kScene, write_bad_scenes(dir.path, "dx_negative").at(0).path});
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("calving_front_2d.json: valid"), std::string::npos) << "the good scene is still reported";
}

// `cdmpm check` seeds the scene keeping no particle: it counts exactly the particles a run seeds, and refuses what
// seeding refuses (a body that seeds nothing; material within a cell of a wall face off the grid), naming the key.
TEST(RunLimits, CheckSeedsTheSceneAndRefusesWhatSeedingRefuses) {
  TempDir dir;
  const auto run = run_cdmpm({"run", kScene, "--out", dir / "out", "--quiet", "--steps", "1", "--set", "output.frames=false"});
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const uint64_t seeded = read_json(dir / "out/summary.json").at("particles").get<uint64_t>();
  const auto r = run_cdmpm({"check", kScene});
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("seeded: " + std::to_string(seeded) + " particles\n"), std::string::npos)
      << seeded << " seeded by the run; " << r.output;
  const auto empty = run_cdmpm({"check", kScene, "--set", "bodies.1.shape.max.1=0.1", "--set", "bodies.1.shape.min.1=0.05"});
  EXPECT_EQ(empty.exit_code, 2) << empty.output;
  EXPECT_NE(empty.output.find("bodies[1]: seeds no particle"), std::string::npos) << empty.output;
  // The fjord's end wall (x+) half a cell past a grid plane, with the water against it.
  const auto off = run_cdmpm({"check", kScene, "--set", "parameters.fjord_end=2002.5"});
  EXPECT_EQ(off.exit_code, 2) << off.output;
  EXPECT_NE(off.output.find("calving_front_2d.json: boundaries[0].faces[1]: the wall face \"x+\" lies at domain.size[0] = "
                            "2002.5 m, 400.5 cells"), std::string::npos) << off.output;
  EXPECT_EQ(off.output.find("valid"), std::string::npos) << "a refused scene is not called valid: " << off.output;
}

// A distributed run's machine holds only its ranks' share of the particles (run/run_estimate.h): a scene too big
// for one machine is refused on one rank and accepted as 1 rank of 64 (its lattice tables and program counted
// once per rank here).
TEST(RunLimits, ADistributedRunNeedsItsMachinesShare) {
  const double machine = machine_memory_bytes();
  if (machine <= 0) GTEST_SKIP() << "no /proc/meminfo";
  const Scene scene = load_scene(kScene, {"parameters.dx=0.05"});
  const RunEstimate e = estimate_run(scene);
  ASSERT_GT(e.memory_bytes, 0.9 * machine) << "the scene must be too big for this machine";
  ASSERT_LT(e.memory_bytes / 64, 0.5 * machine);
  EXPECT_THROW(check_run_fits(scene, e), SceneError);
  EXPECT_THROW(check_run_fits(scene, e, false, 64, 64), SceneError);  // all 64 ranks on this machine
  EXPECT_NO_THROW(check_run_fits(scene, e, false, 1, 64));
}

// `cdmpm run --dry-run --ranks N` (run/run_plan.h): the plan as JSON, the particles of the ranks adding up to the
// scene's, and nothing written; a scene over the machine's limits (here the frame limit) is planned all the same.
TEST(RunLimits, DryRunPlansWithoutRunning) {
  TempDir dir;
  const auto r = run_cdmpm({"run", kScene, "--out", dir / "out", "--dry-run", "--ranks", "3", "--set", "parameters.dx=40"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json plan = nlohmann::json::parse(r.output.substr(r.output.find('{')));
  EXPECT_EQ(plan["ranks"], 3);
  ASSERT_EQ(plan["per_rank"].size(), 3u);
  uint64_t sum = 0;
  for (const auto& rank : plan["per_rank"]) sum += rank["particles"].get<uint64_t>();
  EXPECT_EQ(sum, plan["particles"].get<uint64_t>());
  EXPECT_GT(sum, 0u);
  EXPECT_FALSE(fs::exists(dir / "out")) << "a dry run writes nothing";
  const auto big = run_cdmpm({"run", kScene, "--out", dir / "out", "--dry-run", "--ranks", "64", "--set",
                              "parameters.dx=40", "--set", "time.frame_interval=1e-12"});
  EXPECT_EQ(big.exit_code, 0) << big.output;
}

}  // namespace
}  // namespace cdmpm::testing
