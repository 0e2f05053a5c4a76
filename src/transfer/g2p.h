// g2p.h - grid-to-particle transfer (APIC).
//
//   v_p = sum_i w_ip v_i,   C_p = D^-1 sum_i w_ip v_i (x_i - x_p)^T
// (Jiang et al. 2015, eq. 9-10; D^-1 = 4/dx^2 for quadratic B-splines). C_p is both the APIC affine
// matrix and the particle's velocity gradient used by the constitutive update (the next phase of the step,
// material/constitutive_update.h). For the materials that ask for it (water's `continuity` "interpolated",
// material/water.h) C_p's isotropic part is replaced so that its trace is the divergence of the interpolated
// velocity, the field that moves the particles (sim/advect.h):
//   C_p <- C_p + (div v(x_p) - tr C_p) / dim I,   div v(x_p) = sum_i v_i . grad w_ip   (block_patch.h)
// APIC's C_p is a gradient exact for a velocity linear across the stencil only; where the velocity curves, its
// trace differs from the divergence of v(x) by O(dx) and depends on where the particle sits in its cell, so J
// drifts from the volume the particles actually leave each other. An isotropic matrix has no skew part, so the
// change leaves the transfer's linear and angular momentum as they are. Particles are processed block by block:
// a block's grid velocities are copied once into a dense patch and gathered from there (block_patch.h).
#pragma once

#include <algorithm>
#include <array>
#include <vector>

#include "core/bspline.h"
#include "core/particles.h"
#include "grid/grid.h"
#include "grid/particle_bins.h"
#include "transfer/block_patch.h"

namespace cdmpm {

// Every particle (see gather_velocity).
struct AllParticles {
  bool operator()(uint32_t) const { return true; }
};

// Visits every particle q for which select(q) holds, block by block, with the grid velocity at it and the matrix
// of APIC's C,
//   f(q, v, B, div),   v = sum_i w_ip v_i,   B = sum_i w_ip v_i (x_i - x_p)^T / dx,
// the nodes' velocities v_i being in g.momentum (after grid_update); div() returns div v(x_p), computed on demand.
// Also used by transfer/flip.h.
template <int dim, class F, class Select = AllParticles>
void gather_velocity(const Particles<dim>& p, const Grid<dim>& g, const ParticleBins& bins, F&& f, Select select = {}) {
  const size_t nb = bins.bin_count();
#pragma omp parallel for schedule(dynamic, 4)
  for (size_t j = 0; j < nb; ++j) {
    const BlockPatch<dim> patch(g, bins.blocks[j]);
    PatchRecords<dim> pv;
    for (auto& r : pv) r.setZero();
    patch.for_each_node([&](int n, size_t k) { pv[n].template head<dim>() = g.momentum[k]; });
    for (uint32_t k = bins.start[j]; k < bins.start[j + 1]; ++k) {
      const uint32_t q = bins.order[k];
      if (!select(q)) continue;
      const BSplineStencil<dim> s(p.x[q] * g.inv_dx);
      Vec<dim> v;
      Mat<dim> B;  // sum_i w_i v_i o_i^T; the node's offset from the particle is o_i - fx
      const int k0 = patch.base_index(s);
      gather_from_patch<dim>(pv, s, k0, v, B);
      B -= v * s.fx.transpose();
      f(q, v, B, [&] { return divergence_from_patch<dim>(pv, s, k0, g.inv_dx); });
    }
  }
}

// `interpolated_divergence`: per material, whether tr C_p is the divergence of the interpolated velocity (above);
// empty: none. `only`: per material, whether its particles read this grid (empty: all of them; the solids' own
// field of sim/field_contact.h is read by its materials' particles alone).
template <int dim>
void g2p(Particles<dim>& p, const Grid<dim>& g, const ParticleBins& bins,
         const std::vector<uint8_t>& interpolated_divergence = {}, const std::vector<uint8_t>& only = {}) {
  const Real Dinv_dx = Real(4) * g.inv_dx;  // D^-1 * dx, since offsets are in units of dx
  const bool any = std::find(interpolated_divergence.begin(), interpolated_divergence.end(), 1) !=
                   interpolated_divergence.end();
  const auto write = [&](uint32_t q, const Vec<dim>& v, const Mat<dim>& B, const auto& div) {
    p.v[q] = v;
    p.C[q] = Dinv_dx * B;
    if (any && interpolated_divergence[p.material[q]])
      p.C[q].diagonal().array() += (div() - p.C[q].trace()) / Real(dim);
  };
  if (only.empty()) gather_velocity(p, g, bins, write);
  else gather_velocity(p, g, bins, write, [&](uint32_t q) { return only[p.material[q]] != 0; });
}

}  // namespace cdmpm
