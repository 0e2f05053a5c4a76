// test_calving_3d.cpp - the 3D scale scene, scenes/calving_3d.json, at its small setting (8 cells per ice
// thickness H instead of 50: about 100k particles instead of 25M).
//   * Seeding: the crevasse field is cut out of the ice (no ice particle inside a crevasse), so the ice holds
//     fewer particles than its box by at least the crevasses' whole cells.
//   * Sparse grid: the active grid covers the ice and the water, not the air above the ice behind the front
//     or above the fjord: at most the nodes of the bodies' bounding boxes grown by two blocks on every side.
// The program on it: tests/end_to_end/test_calving_3d_cli.cpp.
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

}  // namespace
}  // namespace cdmpm::testing
