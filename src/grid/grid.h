// grid.h - the background Eulerian grid: node masses and momenta/velocities on a regular lattice.
//
// Nodes sit at i*dx for i in [-ghost, n_cells + ghost] along each axis, so the quadratic B-spline stencil
// of any particle inside the domain [0, size] (and up to one cell outside it) lands on allocated nodes.
// Nodes on or beyond a domain face are where wall boundary conditions act. The grid is cut into blocks of
// 4^dim nodes; the particle-to-grid scatter processes blocks in 2^dim colours so that blocks of one colour
// never write the same node (see transfer/p2g.h).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/types.h"

namespace cdmpm {

template <int dim>
struct Grid {
  static constexpr int ghost = 3;
  static constexpr int block_shift = 2;  // blocks of 4 nodes per axis

  Real dx = 1, inv_dx = 1;
  IVec<dim> n_nodes;   // allocated nodes per axis, ghosts included
  IVec<dim> n_blocks;  // blocks per axis
  std::vector<Real> mass;
  std::vector<Vec<dim>> momentum;  // momentum after p2g, velocity after grid_update

  Grid() = default;
  Grid(const Vec<dim>& size, Real dx_) : dx(dx_), inv_dx(Real(1) / dx_) {
    for (int a = 0; a < dim; ++a) {
      const int cells = static_cast<int>(std::ceil(size[a] / dx - Real(1e-9)));
      n_nodes[a] = cells + 1 + 2 * ghost;
      n_blocks[a] = (n_nodes[a] + (1 << block_shift) - 1) >> block_shift;
    }
    mass.assign(node_count(), Real(0));
    momentum.assign(node_count(), Vec<dim>::Zero());
  }

  size_t node_count() const {
    size_t n = 1;
    for (int a = 0; a < dim; ++a) n *= static_cast<size_t>(n_nodes[a]);
    return n;
  }
  size_t block_count() const {
    size_t n = 1;
    for (int a = 0; a < dim; ++a) n *= static_cast<size_t>(n_blocks[a]);
    return n;
  }

  // Linear index of node i (physical index, may be negative down to -ghost). Last axis fastest.
  size_t index(const IVec<dim>& i) const {
    size_t k = static_cast<size_t>(i[0] + ghost);
    for (int a = 1; a < dim; ++a) k = k * n_nodes[a] + static_cast<size_t>(i[a] + ghost);
    return k;
  }
  // Physical node index of linear index k.
  IVec<dim> node(size_t k) const {
    IVec<dim> i;
    for (int a = dim - 1; a >= 0; --a) {
      i[a] = static_cast<int>(k % n_nodes[a]) - ghost;
      k /= n_nodes[a];
    }
    return i;
  }
  Vec<dim> position(const IVec<dim>& i) const { return i.template cast<Real>() * dx; }

  // Block containing node i, and the block's colour (parity of the block coordinates).
  IVec<dim> block_of(const IVec<dim>& i) const {
    IVec<dim> b;
    for (int a = 0; a < dim; ++a) b[a] = (i[a] + ghost) >> block_shift;
    return b;
  }
  size_t block_index(const IVec<dim>& b) const {
    size_t k = static_cast<size_t>(b[0]);
    for (int a = 1; a < dim; ++a) k = k * n_blocks[a] + static_cast<size_t>(b[a]);
    return k;
  }
  int block_colour(size_t block) const {
    int c = 0;
    for (int a = dim - 1, bit = 0; a >= 0; --a, ++bit) {
      c |= static_cast<int>((block % n_blocks[a]) & 1) << bit;
      block /= n_blocks[a];
    }
    return c;
  }

  // True if the 3^dim stencil starting at base lies on allocated nodes.
  bool stencil_inside(const IVec<dim>& base) const {
    for (int a = 0; a < dim; ++a)
      if (base[a] + ghost < 0 || base[a] + ghost + 2 >= n_nodes[a]) return false;
    return true;
  }

  void clear() {
    const size_t n = node_count();
#pragma omp parallel for schedule(static)
    for (size_t k = 0; k < n; ++k) {
      mass[k] = Real(0);
      momentum[k].setZero();
    }
  }
};

}  // namespace cdmpm
