// test_calving_3d_cli.cpp - the 3D scale scene, scenes/calving_3d.json, at its small setting (8 cells per ice
// thickness H instead of 50): the program runs 20 steps (--steps 20), stops with status completed and says why,
// conserves mass to rounding, and reports its memory per particle.
#include <gtest/gtest.h>

#include <cmath>

#include "cli_helpers.h"
#include "scene/scene_loader.h"
#include "sim/simulation.h"

namespace cdmpm::testing {
namespace {

const std::vector<std::string> kSmall = {"parameters.cells_per_H=8"};

TEST(Calving3D, SmallSettingRunsTwentyStepsAndReportsMemory) {
  TempDir dir;
  std::vector<std::string> args = {"run", source_path("scenes/calving_3d.json"), "--out", dir / "out", "--quiet",
                                   "--steps", "20", "--set", "output.frames=false"};
  for (const auto& s : kSmall) args.insert(args.end(), {"--set", s});
  const auto r = run_cdmpm(args);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto s = read_json(dir / "out/summary.json");
  EXPECT_EQ(s["status"], "completed");
  EXPECT_EQ(s["steps"], 20);
  EXPECT_NE(s["reason"].get<std::string>().find("--steps"), std::string::npos) << s["reason"];
  EXPECT_LT(std::abs(s["mass_change"].get<double>()), 1e-12);
  // The peak resident memory holds at least every particle's own arrays (core/particles.h: x, v, C, mass, J,
  // material; F and alpha of the ice), so per particle it is at least the fluids' share.
  EXPECT_GE(s["bytes_per_particle"].get<double>(),
            2 * sizeof(Vec<3>) + sizeof(Mat<3>) + 2 * sizeof(Real) + sizeof(MaterialId));
  // The stepping loop is part of the run's wall time, so its rate is at least the whole run's.
  EXPECT_GE(s["stepping_particle_steps_per_second"].get<double>(), s["particle_steps_per_second"].get<double>());
}

}  // namespace
}  // namespace cdmpm::testing
