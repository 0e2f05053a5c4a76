// block_patch.h - a dense scratch copy of the grid nodes that the particles of one block touch.
//
// A particle whose stencil base node lies in block b touches nodes base + {0,1,2}^dim, all inside the
// (4 + 2)^dim nodes starting at b's first node: the block and one and two nodes beyond it on every axis
// (blocks b + {0,1}^dim, see grid/grid.h). The transfers work block by block on this patch: p2g scatters a
// block's particles into the patch and adds the patch to the grid once; g2p copies the patch from the grid
// once and gathers from it. The inner loops then touch a few kilobytes with fixed strides instead of
// looking up sparse storage per node (the "shared-memory" blocking of Gao et al. 2018 and Wang et al. 2020,
// on CPU caches).
#pragma once

#include <array>

#include "core/bspline.h"
#include "grid/grid.h"

namespace cdmpm {

template <int dim>
struct BlockPatch {
  static constexpr int width = Grid<dim>::block_width + 2;
  static constexpr int size = dim == 2 ? width * width : width * width * width;

  IVec<dim> origin;                       // physical index of the patch's first node
  std::array<size_t, (1 << dim)> store;   // storage index of the first node of blocks b + {0,1}^dim (npos: none)

  BlockPatch(const Grid<dim>& g, uint32_t block) {
    const IVec<dim> c = g.block_coords(block);
    origin = c * Grid<dim>::block_width - IVec<dim>::Constant(Grid<dim>::ghost);
    for (int m = 0; m < (1 << dim); ++m) {
      const size_t nb = g.upper_neighbour(c, m);
      store[m] = nb == Grid<dim>::npos ? Grid<dim>::npos : g.block_storage(nb);
    }
  }

  // Patch index of the stencil base node of s (in the patch, last axis fastest).
  int base_index(const BSplineStencil<dim>& s) const {
    int k = 0;
    for (int a = 0; a < dim; ++a) k = k * width + (s.base[a] - origin[a]);
    return k;
  }

  // Calls f(patch_index, storage_index) for every patch node that lies on the lattice.
  template <class F>
  void for_each_node(F&& f) const {
    constexpr int W = Grid<dim>::block_width;
    IVec<dim> o = IVec<dim>::Zero();
    for (int k = 0; k < size; ++k) {
      int m = 0;
      IVec<dim> local;
      for (int a = 0; a < dim; ++a) {
        const int hi = o[a] >= W;
        m = (m << 1) | hi;
        local[a] = o[a] - hi * W;
      }
      if (store[m] != Grid<dim>::npos) {
        size_t l = 0;
        for (int a = 0; a < dim; ++a) l = (l << Grid<dim>::block_shift) | static_cast<size_t>(local[a]);
        f(k, store[m] + l);
      }
      for (int a = dim - 1; a >= 0; --a) {
        if (++o[a] < width) break;
        o[a] = 0;
      }
    }
  }
};

// One patch node as four reals, so that a node's update is one 4-wide vector operation (in double one AVX
// register, or two SSE2 registers on the x86-64 baseline; in float one SSE register): in p2g
// [mass, momentum (dim components), 0...], in g2p [velocity (dim components), 0...].
using NodeRecord = Eigen::Matrix<Real, 4, 1>;
template <int dim>
using PatchRecords = std::array<NodeRecord, BlockPatch<dim>::size>;

// The p2g record [first, v, 0...]: `first` in slot 0, the dim-vector v in the next dim slots.
template <int dim>
inline NodeRecord to_record(Real first, const Vec<dim>& v) {
  NodeRecord r = NodeRecord::Zero();
  r[0] = first;
  r.template segment<dim>(1) = v;
  return r;
}

// The patch's accumulators for one block's scatter: node masses and momenta as records
// [m, (m v)_0 .. (m v)_dim-1, 0...].
template <int dim>
struct PatchAccumulator {
  PatchRecords<dim> node;
  PatchAccumulator() {
    for (auto& r : node) r.setZero();
  }
  Real mass(int n) const { return node[n][0]; }
  Vec<dim> momentum(int n) const { return node[n].template segment<dim>(1); }
};

// Scatters one particle into the patch: node i of the stencil (offset o from the base node, in cells) gets
// w_i m and w_i (a + A o), the affine momentum field a + A o evaluated at the node (a and A from p2g.h).
// The record [m, a + A o] is built per axis by adding A's columns (which carry 0 in the mass slot), so the
// inner loop is one 4-wide multiply-add per node, with no integer-to-real conversion and no matrix-vector
// product.
template <int dim>
inline void scatter_to_patch(PatchAccumulator<dim>& acc, const BSplineStencil<dim>& s, int k0, Real m,
                             const Vec<dim>& a, const Mat<dim>& A) {
  constexpr int W = BlockPatch<dim>::width;
  NodeRecord col[dim];
  for (int c = 0; c < dim; ++c) col[c] = to_record<dim>(0, A.col(c));
  NodeRecord u0 = to_record<dim>(m, a);
  for (int i = 0; i < 3; ++i, u0 += col[0]) {
    if constexpr (dim == 2) {
      NodeRecord u = u0;
      for (int j = 0; j < 3; ++j, u += col[1]) acc.node[k0 + i * W + j] += (s.w[0][i] * s.w[1][j]) * u;
    } else {
      NodeRecord u1 = u0;
      for (int j = 0; j < 3; ++j, u1 += col[1]) {
        const Real wij = s.w[0][i] * s.w[1][j];
        NodeRecord u = u1;
        for (int l = 0; l < 3; ++l, u += col[2]) acc.node[k0 + (i * W + j) * W + l] += (wij * s.w[2][l]) * u;
      }
    }
  }
}

// Gathers one particle from the patch velocities pv (records [v, 0...]): v = sum_i w_i v_i and
// B = sum_i w_i v_i o_i^T (o_i the node's offset from the base node, in cells), summed per axis so that B's
// columns are weighted sums of partial sums.
template <int dim>
inline void gather_from_patch(const PatchRecords<dim>& pv, const BSplineStencil<dim>& s, int k0, Vec<dim>& v,
                              Mat<dim>& B) {
  constexpr int W = BlockPatch<dim>::width;
  NodeRecord sum = NodeRecord::Zero(), col[dim];
  for (auto& c : col) c.setZero();
  for (int i = 0; i < 3; ++i) {
    NodeRecord vi = NodeRecord::Zero();  // sum over the stencil plane at offset i along axis 0
    if constexpr (dim == 2) {
      for (int j = 0; j < 3; ++j) {
        const NodeRecord wv = (s.w[0][i] * s.w[1][j]) * pv[k0 + i * W + j];
        vi += wv;
        col[1] += Real(j) * wv;
      }
    } else {
      for (int j = 0; j < 3; ++j) {
        NodeRecord vij = NodeRecord::Zero();
        const Real wij = s.w[0][i] * s.w[1][j];
        for (int l = 0; l < 3; ++l) {
          const NodeRecord wv = (wij * s.w[2][l]) * pv[k0 + (i * W + j) * W + l];
          vij += wv;
          col[2] += Real(l) * wv;
        }
        vi += vij;
        col[1] += Real(j) * vij;
      }
    }
    sum += vi;
    col[0] += Real(i) * vi;
  }
  v = sum.template head<dim>();
  for (int c = 0; c < dim; ++c) B.col(c) = col[c].template head<dim>();
}

// The divergence of the interpolated velocity v(x) = sum_i w_i(x) v_i at the particle, from the patch velocities:
//   div v(x_p) = sum_i v_i . grad w_ip,  grad w_ip = (w'_a(f_a) prod_{c != a} w_c(f_c))_a / dx,
// with the quadratic B-spline's derivatives for the nodes at offsets 0, 1, 2 from the base node:
//   w'(f) = (f - 3/2, 2 (1 - f), f - 1/2)   (f = s.fx, the particle's offset from the base node, in cells).
template <int dim>
inline Real divergence_from_patch(const PatchRecords<dim>& pv, const BSplineStencil<dim>& s, int k0, Real inv_dx) {
  constexpr int W = BlockPatch<dim>::width;
  Real d[dim][3];
  for (int a = 0; a < dim; ++a) {
    const Real f = s.fx[a];
    d[a][0] = f - Real(1.5), d[a][1] = Real(2) * (Real(1) - f), d[a][2] = f - Real(0.5);
  }
  Real div = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      if constexpr (dim == 2) {
        const NodeRecord& v = pv[k0 + i * W + j];
        div += v[0] * d[0][i] * s.w[1][j] + v[1] * s.w[0][i] * d[1][j];
      } else {
        for (int l = 0; l < 3; ++l) {
          const NodeRecord& v = pv[k0 + (i * W + j) * W + l];
          div += v[0] * d[0][i] * s.w[1][j] * s.w[2][l] + v[1] * s.w[0][i] * d[1][j] * s.w[2][l] +
                 v[2] * s.w[0][i] * s.w[1][j] * d[2][l];
        }
      }
    }
  return div * inv_dx;
}

}  // namespace cdmpm
