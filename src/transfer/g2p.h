// g2p.h - grid-to-particle transfer (APIC).
//
//   v_p = sum_i w_ip v_i,   C_p = D^-1 sum_i w_ip v_i (x_i - x_p)^T
// (Jiang et al. 2015, eq. 9-10; D^-1 = 4/dx^2 for quadratic B-splines). C_p is both the APIC affine
// matrix and the particle's velocity gradient used by the constitutive update. Positions are advected
// after the constitutive update (material/constitutive_update.h).
#pragma once

#include "core/bspline.h"
#include "core/particles.h"
#include "grid/grid.h"

namespace cdmpm {

template <int dim>
void g2p(Particles<dim>& p, const Grid<dim>& g) {
  const Real Dinv_dx = Real(4) * g.inv_dx;  // D^-1 * dx, since offsets are in units of dx
  const size_t n = p.size();
#pragma omp parallel for schedule(static)
  for (size_t q = 0; q < n; ++q) {
    const BSplineStencil<dim> s(p.x[q] * g.inv_dx);
    Vec<dim> v = Vec<dim>::Zero();
    Mat<dim> B = Mat<dim>::Zero();
    for_each_stencil_node<dim>([&](const IVec<dim>& o) {
      const Real w = s.weight(o);
      const Vec<dim>& vi = g.momentum[g.index(s.base + o)];
      v += w * vi;
      B += (w * vi) * s.offset(o).transpose();
    });
    p.v[q] = v;
    p.C[q] = Dinv_dx * B;
  }
}

}  // namespace cdmpm
