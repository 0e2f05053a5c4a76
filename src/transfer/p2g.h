// p2g.h - particle-to-grid transfer of mass and momentum (APIC) with the internal-force impulse.
//
// For each particle p and stencil node i with weight w_ip (Jiang et al. 2015, eq. 8; Hu et al. 2018,
// MLS-MPM eq. 17-18):
//   m_i   += w_ip m_p
//   (mv)_i += w_ip [ m_p v_p + (m_p C_p - dt V0_p D^-1 tau_p) (x_i - x_p) ]
// where C_p is the APIC affine matrix, tau_p the Kirchhoff stress, V0_p the reference volume and
// D^-1 = 4/dx^2 for quadratic B-splines. The stress term is the explicit force -dt sum_p V0_p tau_p grad w_ip
// in its moving-least-squares form. With dt = 0 this is the pure APIC transfer, which conserves mass,
// linear and angular momentum exactly.
//
// Race-free and deterministic: blocks of one colour run in parallel, colours in sequence (particle_bins.h).
#pragma once

#include <vector>

#include "core/bspline.h"
#include "core/particles.h"
#include "grid/grid.h"
#include "grid/particle_bins.h"
#include "material/stress.h"

namespace cdmpm {

template <int dim>
void p2g(const Particles<dim>& p, const std::vector<Material>& materials, const ParticleBins& bins, Grid<dim>& g,
         Real dt) {
  const Real Dinv = Real(4) * g.inv_dx * g.inv_dx;
  for (const auto& blocks : bins.colour_blocks) {
#pragma omp parallel for schedule(dynamic, 4)
    for (size_t bi = 0; bi < blocks.size(); ++bi) {
      const uint32_t b = blocks[bi];
      for (uint32_t k = bins.block_start[b]; k < bins.block_start[b + 1]; ++k) {
        const uint32_t q = bins.order[k];
        const BSplineStencil<dim> s(p.x[q] * g.inv_dx);
        const Real m = p.mass[q];
        Mat<dim> affine = m * p.C[q];
        if (dt != 0) affine -= (dt * p.volume0[q] * Dinv) * kirchhoff_stress(materials[p.material[q]], p, q);
        // Affine term in units of dx: (x_i - x_p) = dx * offset.
        affine *= g.dx;
        const Vec<dim> mv = m * p.v[q];
        for_each_stencil_node<dim>([&](const IVec<dim>& o) {
          const Real w = s.weight(o);
          const size_t n = g.index(s.base + o);
          g.mass[n] += w * m;
          g.momentum[n] += w * (mv + affine * s.offset(o));
        });
      }
    }
  }
}

}  // namespace cdmpm
