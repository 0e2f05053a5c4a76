// grid.h - the background Eulerian grid: a sparse set of blocks of 4^dim nodes holding node masses and
// momenta/velocities.
//
// Nodes sit at i*dx for i in [-ghost, n_cells + ghost] along each axis, so the quadratic B-spline stencil
// of any particle inside the domain [0, size] (and up to one cell outside it) lands on the lattice. Nodes on
// or beyond a domain face are where wall boundary conditions act. The lattice is cut into blocks of 4^dim
// nodes; only the blocks that particle stencils touch are allocated ("active"), so memory and the cost of
// the grid phases grow with the volume the material occupies, not with the domain's bounding box. A fjord
// 10 km long costs what its water and ice cost, plus a table of one 4-byte slot per block of the lattice
// (1/64 of a node's size per node in 3D, 1/16 in 2D).
//
// Storage: the active blocks are numbered by slot in increasing block index; slot s holds its 4^dim nodes
// contiguously (mass[s * block_nodes + local], last axis fastest within the block), so a block's nodes are
// one cache-friendly run. activate() rebuilds the active set every step from the particle bins
// (grid/particle_bins.h): a particle whose stencil base node lies in block b touches b + {0,1}^dim.
// The particle-to-grid scatter processes blocks in 2^dim colours so that blocks of one colour never write
// the same node (transfer/p2g.h).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/types.h"

namespace cdmpm {

template <int dim>
struct Grid {
  static constexpr int ghost = 3;
  static constexpr int block_shift = 2;  // blocks of 4 nodes per axis
  static constexpr int block_width = 1 << block_shift;
  static constexpr size_t block_nodes = size_t(1) << (block_shift * dim);
  static constexpr size_t npos = std::numeric_limits<size_t>::max();

  Real dx = 1, inv_dx = 1;
  IVec<dim> n_nodes;   // nodes per axis of the lattice, ghosts included
  IVec<dim> n_blocks;  // blocks per axis of the lattice
  std::vector<Real> mass;          // per active node (slot-major)
  std::vector<Vec<dim>> momentum;  // momentum after p2g, velocity after grid_update

  Grid() = default;
  Grid(const Vec<dim>& size, Real dx_) : dx(dx_), inv_dx(Real(1) / dx_) {
    for (int a = 0; a < dim; ++a) {
      const int cells = static_cast<int>(std::ceil(size[a] / dx - Real(1e-9)));
      n_nodes[a] = cells + 1 + 2 * ghost;
      n_blocks[a] = (n_nodes[a] + block_width - 1) >> block_shift;
    }
    slot_.assign(block_count(), -1);
  }

  // Nodes held in storage (active blocks x block_nodes); storage index k runs over [0, node_count()).
  size_t node_count() const { return active_.size() * block_nodes; }
  // Blocks of the whole lattice.
  size_t block_count() const {
    size_t n = 1;
    for (int a = 0; a < dim; ++a) n *= static_cast<size_t>(n_blocks[a]);
    return n;
  }

  // Block coordinates of node i (physical index, may be negative down to -ghost), and its place in the block.
  IVec<dim> block_of(const IVec<dim>& i) const {
    IVec<dim> b;
    for (int a = 0; a < dim; ++a) b[a] = (i[a] + ghost) >> block_shift;
    return b;
  }
  static size_t local_index(const IVec<dim>& i) {
    size_t l = 0;
    for (int a = 0; a < dim; ++a) l = (l << block_shift) | static_cast<size_t>((i[a] + ghost) & (block_width - 1));
    return l;
  }
  size_t block_index(const IVec<dim>& b) const {
    size_t k = static_cast<size_t>(b[0]);
    for (int a = 1; a < dim; ++a) k = k * n_blocks[a] + static_cast<size_t>(b[a]);
    return k;
  }
  IVec<dim> block_coords(size_t block) const {
    IVec<dim> b;
    for (int a = dim - 1; a >= 0; --a) {
      b[a] = static_cast<int>(block % n_blocks[a]);
      block /= n_blocks[a];
    }
    return b;
  }
  // Colour of a block: the parity of its coordinates, one bit per axis.
  int block_colour(size_t block) const {
    const IVec<dim> b = block_coords(block);
    int c = 0;
    for (int a = 0; a < dim; ++a) c = (c << 1) | (b[a] & 1);
    return c;
  }
  // Storage index of the first node of a block, or npos if the block is not active.
  size_t block_storage(size_t block) const {
    const int32_t s = slot_[block];
    return s < 0 ? npos : static_cast<size_t>(s) * block_nodes;
  }
  // Block index of the neighbour c + offset of block coordinates c, where bit (dim - 1 - a) of m is the offset
  // (0 or 1) along axis a; npos if that neighbour is off the lattice. m = 0 .. 2^dim - 1 runs over the blocks
  // that the stencils of block c's particles touch.
  size_t upper_neighbour(const IVec<dim>& c, int m) const {
    IVec<dim> d = c;
    for (int a = 0; a < dim; ++a) {
      d[a] += (m >> (dim - 1 - a)) & 1;
      if (d[a] >= n_blocks[a]) return npos;
    }
    return block_index(d);
  }
  // Storage index of node i, or npos if it is off the lattice or its block is not active.
  size_t find(const IVec<dim>& i) const {
    for (int a = 0; a < dim; ++a)
      if (i[a] + ghost < 0 || i[a] + ghost >= n_nodes[a]) return npos;
    const size_t s = block_storage(block_index(block_of(i)));
    return s == npos ? npos : s + local_index(i);
  }
  // Physical node index of storage index k.
  IVec<dim> node(size_t k) const {
    const IVec<dim> b = block_coords(active_[k / block_nodes]);
    size_t l = k % block_nodes;
    IVec<dim> i;
    for (int a = dim - 1; a >= 0; --a) {
      i[a] = (b[a] << block_shift) + static_cast<int>(l & (block_width - 1)) - ghost;
      l >>= block_shift;
    }
    return i;
  }
  Vec<dim> position(const IVec<dim>& i) const { return i.template cast<Real>() * dx; }

  // Calls f(k, i) for every node of every active block, with storage index k and physical index i; blocks
  // run in parallel (f must only touch node k).
  template <class F>
  void for_each_node(F&& f) const {
    const size_t nb = active_.size();
#pragma omp parallel for schedule(static)
    for (size_t s = 0; s < nb; ++s) {
      const IVec<dim> origin = block_coords(active_[s]) * block_width - IVec<dim>::Constant(ghost);
      size_t k = s * block_nodes;
      IVec<dim> o = IVec<dim>::Zero();
      for (size_t l = 0; l < block_nodes; ++l, ++k) {
        f(k, IVec<dim>(origin + o));
        for (int a = dim - 1; a >= 0; --a) {  // next local offset, last axis fastest
          if (++o[a] < block_width) break;
          o[a] = 0;
        }
      }
    }
  }

  // Calls f(k, i) for every node of an active block with i[axis] == plane; blocks run in parallel.
  template <class F>
  void for_each_node_on_plane(int axis, int plane, F&& f) const {
    const int pb = (plane + ghost) >> block_shift;
    if (plane + ghost < 0 || pb >= n_blocks[axis]) return;
    const size_t nb = active_.size();
#pragma omp parallel for schedule(static)
    for (size_t s = 0; s < nb; ++s) {
      const IVec<dim> c = block_coords(active_[s]);
      if (c[axis] != pb) continue;
      const IVec<dim> origin = c * block_width - IVec<dim>::Constant(ghost);
      IVec<dim> o = IVec<dim>::Zero();
      o[axis] = plane - origin[axis];
      for (size_t l = 0; l < block_nodes / block_width; ++l) {
        const IVec<dim> i = origin + o;
        f(s * block_nodes + local_index(i), i);
        for (int a = dim - 1; a >= 0; --a) {  // next offset in the plane
          if (a == axis) continue;
          if (++o[a] < block_width) break;
          o[a] = 0;
        }
      }
    }
  }

  // Makes active exactly the blocks touched by particles whose stencil base lies in one of
  // `particle_blocks` (block indices, ascending): each such block b and b + {0,1}^dim. Then zeroes the
  // active nodes. Deterministic: slots follow block index order. `extra_blocks` are made active as they are (a
  // distributed run's own blocks that only other ranks' particles touch, parallel/halo_exchange.h).
  void activate(const std::vector<uint32_t>& particle_blocks, const std::vector<uint32_t>& extra_blocks = {}) {
    for (const uint32_t b : active_) slot_[b] = -1;
    active_.clear();
    for (const uint32_t b : particle_blocks) {
      const IVec<dim> c = block_coords(b);
      for (int m = 0; m < (1 << dim); ++m) {
        const size_t nb = upper_neighbour(c, m);
        if (nb == npos) continue;
        if (slot_[nb] < 0) {
          slot_[nb] = 0;
          active_.push_back(static_cast<uint32_t>(nb));
        }
      }
    }
    for (const uint32_t b : extra_blocks)
      if (slot_[b] < 0) {
        slot_[b] = 0;
        active_.push_back(b);
      }
    std::sort(active_.begin(), active_.end());
    for (size_t s = 0; s < active_.size(); ++s) slot_[active_[s]] = static_cast<int32_t>(s);
    mass.resize(node_count());
    momentum.resize(node_count());
    clear();
  }

  void clear() {
    const size_t n = node_count();
#pragma omp parallel for schedule(static)
    for (size_t k = 0; k < n; ++k) {
      mass[k] = Real(0);
      momentum[k].setZero();
    }
  }

 private:
  std::vector<int32_t> slot_;     // per lattice block: its slot, or -1 if not active
  std::vector<uint32_t> active_;  // block index of each slot, ascending
};

}  // namespace cdmpm
