// test_calving_3d.cpp - the 3D scale scene, scenes/calving_3d.json, at its small setting (8 cells per ice
// thickness H instead of 50: about 100k particles instead of 25M).
//   * Seeding: the crevasse field is cut out of the ice (no ice particle inside a crevasse), so the ice holds
//     fewer particles than its box by at least the crevasses' whole cells.
//   * Sparse grid: the active grid covers the ice and the water, not the air above the ice behind the front
//     or above the fjord: at most the nodes of the bodies' bounding boxes grown by two blocks on every side.
//   * The program runs 20 steps (--steps 20), stops with status completed and says why, conserves mass to
//     rounding, and reports its memory per particle.
#include <gtest/gtest.h>

#include <cmath>

#include "cli_helpers.h"
#include "scene/scene_loader.h"
#include "sim/simulation.h"

namespace cdmpm::testing {
namespace {

const std::vector<std::string> kSmall = {"parameters.cells_per_H=8"};

TEST(Calving3D, CrevassesAreCutAndTheSparseGridCoversOnlyTheBodies) {
  const Scene scene = load_scene(source_path("scenes/calving_3d.json"), kSmall);
  Simulation<3> sim(scene);
  const BodySpec& ice = scene.bodies[0];
  ASSERT_GE(ice.holes.size(), 5u) << "a crevasse field";
  for (size_t q = 0; q < sim.particles.solid_count(); ++q)
    for (const auto& h : ice.holes) ASSERT_FALSE(h.contains(sim.particles.x[q].cast<double>())) << "ice particle " << q;

  // Whole cells inside the crevasses hold no ice: the count falls short of the box by at least that.
  const double dx = scene.domain.dx;
  double box_cells = 1, hole_cells = 0;
  for (int a = 0; a < 3; ++a) box_cells *= std::round((ice.shape.upper(a) - ice.shape.lower(a)) / dx);
  for (const auto& h : ice.holes) {
    double c = 1;
    for (int a = 0; a < 3; ++a) c *= std::floor((h.upper(a) - h.lower(a)) / dx);
    hole_cells += c;
  }
  ASSERT_GT(hole_cells, 0) << "crevasses at least a cell wide and deep at the small setting";
  EXPECT_LE(double(sim.particles.solid_count()), (box_cells - hole_cells) * ice.particles_per_cell);

  sim.step(sim.stable_dt());
  size_t bound = 0;  // nodes of each body's bounding box grown by two blocks per side (overlaps counted twice)
  for (const auto& b : scene.bodies) {
    size_t n = 1;
    for (int a = 0; a < 3; ++a)
      n *= static_cast<size_t>(std::ceil((b.shape.upper(a) - b.shape.lower(a)) / dx)) + 1 + 4 * Grid<3>::block_width;
    bound += n;
  }
  size_t lattice = 1;
  for (int a = 0; a < 3; ++a) lattice *= static_cast<size_t>(sim.grid.n_nodes[a]);
  EXPECT_LE(sim.grid.node_count(), bound);
  EXPECT_LT(sim.grid.node_count(), lattice);
}

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
