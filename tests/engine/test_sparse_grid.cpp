// test_sparse_grid.cpp - the sparse blocked grid (grid/grid.h): only the blocks that particle stencils reach
// are allocated, so the grid of a body costs the same in a domain ten times longer, and the state it
// computes does not depend on the empty part of the domain.
#include <gtest/gtest.h>

#include <cstring>
#include <nlohmann/json.hpp>

#include "scene/scene_loader.h"
#include "sim/simulation.h"

namespace cdmpm {
namespace {

// A dam break: a water column 0.4 m wide and 0.4 m high against the left wall of a tank `length` long.
template <int dim>
Scene dam_break(double length) {
  std::vector<double> size(dim, 0.6), hi(dim, 0.4), lo(dim, 0.0);
  size[0] = length;
  std::vector<double> g(dim, 0.0);
  g[dim - 1] = -9.81;
  const nlohmann::json j = {
      {"name", "sparse"},
      {"dim", dim},
      {"domain", {{"size", size}, {"dx", 0.02}}},
      {"time", {{"end", 1.0}, {"frame_interval", 0.1}}},
      {"gravity", g},
      {"materials", {{"water", {{"type", "water"}, {"density", 1000}, {"bulk_modulus", 1.0e5}}}}},
      {"bodies", {{{"material", "water"}, {"particles_per_cell", dim == 2 ? 4 : 8},
                   {"shape", {{"type", "box"}, {"min", lo}, {"max", hi}}}}}},
      {"boundaries", {{{"type", "walls"}, {"condition", "slip"}}}},
      {"output", {{"frames", false}}}};
  return scene_from_json(j, "<sparse>");
}

template <int dim>
void check_grid_follows_the_material() {
  const Scene short_tank = dam_break<dim>(1.0), long_tank = dam_break<dim>(10.0);
  Simulation<dim> a(short_tank), b(long_tank);
  // 20 steps: the surge front moves about sqrt(g h) t = 2 m/s * 20 dt, far less than the 0.6 m gap to the
  // short tank's right wall, so the two runs see the same walls.
  for (int s = 0; s < 20; ++s) {
    const Real dt = a.stable_dt();
    ASSERT_EQ(dt, b.stable_dt());
    a.step(dt);
    b.step(dt);
  }
  // The same blocks are active: the grid's storage does not grow with the domain.
  EXPECT_EQ(a.grid.node_count(), b.grid.node_count());
  // At most the body's bounding box plus one block per side is allocated (the body spans 20 cells per axis,
  // that is 21 nodes, plus the 3 ghost nodes below the walls; the stencil reaches 2 nodes beyond).
  size_t bound = 1;
  for (int a_ = 0; a_ < dim; ++a_) bound *= (21 + 3 + 2 + 2 * Grid<dim>::block_width);
  EXPECT_LE(a.grid.node_count(), bound);
  // The lattice is ten times longer, but the state is bitwise the same.
  ASSERT_EQ(a.particles.size(), b.particles.size());
  EXPECT_EQ(0, std::memcmp(a.particles.x.data(), b.particles.x.data(), a.particles.x.size() * sizeof(Vec<dim>)));
  EXPECT_EQ(0, std::memcmp(a.particles.v.data(), b.particles.v.data(), a.particles.v.size() * sizeof(Vec<dim>)));
}

TEST(SparseGrid, StorageAndStateIndependentOfEmptyDomain2D) { check_grid_follows_the_material<2>(); }
TEST(SparseGrid, StorageAndStateIndependentOfEmptyDomain3D) { check_grid_follows_the_material<3>(); }

}  // namespace
}  // namespace cdmpm
