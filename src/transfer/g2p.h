// g2p.h - grid-to-particle transfer (APIC).
//
//   v_p = sum_i w_ip v_i,   C_p = D^-1 sum_i w_ip v_i (x_i - x_p)^T
// (Jiang et al. 2015, eq. 9-10; D^-1 = 4/dx^2 for quadratic B-splines). C_p is both the APIC affine
// matrix and the particle's velocity gradient used by the constitutive update (the next phase of the step,
// material/constitutive_update.h). Particles are processed block by block:
// a block's grid velocities are copied once into a dense patch and gathered from there (block_patch.h).
#pragma once

#include <array>

#include "core/bspline.h"
#include "core/particles.h"
#include "grid/grid.h"
#include "grid/particle_bins.h"
#include "transfer/block_patch.h"

namespace cdmpm {

// Visits every particle q, block by block, with the grid velocity at it and the matrix of APIC's C,
//   f(q, v, B),   v = sum_i w_ip v_i,   B = sum_i w_ip v_i (x_i - x_p)^T / dx,
// the nodes' velocities v_i being in g.momentum (after grid_update). Also used by transfer/flip.h.
template <int dim, class F>
void gather_velocity(const Particles<dim>& p, const Grid<dim>& g, const ParticleBins& bins, F&& f) {
  const size_t nb = bins.bin_count();
#pragma omp parallel for schedule(dynamic, 4)
  for (size_t j = 0; j < nb; ++j) {
    const BlockPatch<dim> patch(g, bins.blocks[j]);
    PatchRecords<dim> pv;
    for (auto& r : pv) r.setZero();
    patch.for_each_node([&](int n, size_t k) { pv[n].template head<dim>() = g.momentum[k]; });
    for (uint32_t k = bins.start[j]; k < bins.start[j + 1]; ++k) {
      const uint32_t q = bins.order[k];
      const BSplineStencil<dim> s(p.x[q] * g.inv_dx);
      Vec<dim> v;
      Mat<dim> B;  // sum_i w_i v_i o_i^T; the node's offset from the particle is o_i - fx
      gather_from_patch<dim>(pv, s, patch.base_index(s), v, B);
      B -= v * s.fx.transpose();
      f(q, v, B);
    }
  }
}

template <int dim>
void g2p(Particles<dim>& p, const Grid<dim>& g, const ParticleBins& bins) {
  const Real Dinv_dx = Real(4) * g.inv_dx;  // D^-1 * dx, since offsets are in units of dx
  gather_velocity(p, g, bins, [&](uint32_t q, const Vec<dim>& v, const Mat<dim>& B) {
    p.v[q] = v;
    p.C[q] = Dinv_dx * B;
  });
}

}  // namespace cdmpm
