// flip.h - a FLIP share in the velocity update of g2p (Brackbill & Ruppel 1986; in MPM with APIC's affine
// transfer: Fei et al. 2021, "Revisiting integration in the material point method").
//
// APIC replaces a particle's velocity at every step by the grid's, v_p = sum_i w_ip v_i^{n+1} (g2p.h): what the
// grid cannot represent (a shear layer a cell thick, a kink at a material interface) is smoothed away once per
// step, a numerical viscosity of order dx^2 / dt. At the acoustic time step of weakly compressible water, dt ~
// dx / c, that is of order c dx: a 0.4 m block in a pool at dx = 5 cm rises through a creeping (Stokes) flow
// that fills the pool (docs/water.md, "Buoyancy: J-bar and FLIP"). FLIP adds only the grid's change of velocity:
//   v_p <- (1 - a) sum_i w_ip v_i^{n+1} + a [v_p + sum_i w_ip (v_i^{n+1} - v_i^n)]
//        = sum_i w_ip v_i^{n+1} + a u_p,   u_p = v_p - sum_i w_ip v_i^n,
// with a = the material's `flip` and v_i^n the grid velocity of the transfer alone (p2g with dt = 0, the
// boundaries' fold and unfold, no force). u_p is what the grid did not see of the particle's velocity; it is taken
// before g2p (flip_residual) and added after it (flip_blend). C_p stays APIC's. a = 0 is APIC unchanged.
// Momentum: p2g conserves it, so sum_p m_p u_p = sum_p m_p v_p - sum_i m_i v_i^n = 0 (up to the boundaries'
// fold and unfold): the FLIP share adds no momentum, it keeps on the particles what the grid smoothed away.
#pragma once

#include <vector>

#include "core/particles.h"
#include "grid/grid.h"
#include "grid/particle_bins.h"
#include "material/material.h"
#include "transfer/g2p.h"

namespace cdmpm {

// u_p = v_p - sum_i w_ip v_i for the particles of materials with a FLIP share (0 for the others), v_i the grid
// velocity now held in g.momentum.
template <int dim>
void flip_residual(const Particles<dim>& p, const std::vector<Material>& materials, const Grid<dim>& g,
                   const ParticleBins& bins, std::vector<Vec<dim>>& u) {
  u.assign(p.size(), Vec<dim>::Zero());
  gather_velocity(p, g, bins, [&](uint32_t q, const Vec<dim>& v, const Mat<dim>&) {
    if (materials[p.material[q]].flip() > 0) u[q] = p.v[q] - v;
  });
}

// After g2p: v_p += a u_p.
template <int dim>
void flip_blend(Particles<dim>& p, const std::vector<Material>& materials, const std::vector<Vec<dim>>& u) {
  const size_t n = p.size();
#pragma omp parallel for schedule(static)
  for (size_t q = 0; q < n; ++q)
    if (const Real a = materials[p.material[q]].flip(); a > 0) p.v[q] += a * u[q];
}

}  // namespace cdmpm
