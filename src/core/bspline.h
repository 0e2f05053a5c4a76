// bspline.h - quadratic B-spline interpolation weights, computed once per particle and per axis.
//
// N(x) = 3/4 - x^2 for |x| < 1/2, 1/2 (3/2 - |x|)^2 for 1/2 <= |x| < 3/2, 0 otherwise
// (Steffen, Kirby & Berzins 2008; Jiang et al. 2016 course notes, eq. 123). A particle at x (in units of
// dx) touches the 3 nodes base, base+1, base+2 per axis with base = floor(x - 1/2). The weights form a
// partition of unity and reproduce linear functions: sum_i w_i = 1, sum_i w_i x_i = x.
#pragma once

#include <cmath>

#include "core/types.h"

namespace cdmpm {

// floor(v) for |v| < 2^31, by truncation and a correction: std::floor is a library call on the x86-64
// baseline (no SSE4.1 rounding instruction), and was a sixth of the particle-to-grid transfer.
inline int floor_to_int(Real v) {
  const int i = static_cast<int>(v);
  return i - (v < static_cast<Real>(i));
}

template <int dim>
struct BSplineStencil {
  IVec<dim> base;    // lowest node index of the 3^dim stencil
  Real w[dim][3];    // per-axis weights
  Vec<dim> fx;       // particle position relative to the base node, in units of dx (in [0.5, 1.5))

  // x: particle position divided by dx.
  explicit BSplineStencil(const Vec<dim>& x) {
    for (int a = 0; a < dim; ++a) {
      base[a] = floor_to_int(x[a] - Real(0.5));
      const Real f = x[a] - Real(base[a]);
      fx[a] = f;
      const Real d0 = Real(1.5) - f, d1 = f - Real(1), d2 = f - Real(0.5);
      w[a][0] = Real(0.5) * d0 * d0;
      w[a][1] = Real(0.75) - d1 * d1;
      w[a][2] = Real(0.5) * d2 * d2;
    }
  }

  // Weight of stencil node offset o (each component in 0..2).
  Real weight(const IVec<dim>& o) const {
    Real r = w[0][o[0]];
    for (int a = 1; a < dim; ++a) r *= w[a][o[a]];
    return r;
  }
  // Position of stencil node o relative to the particle, in units of dx.
  Vec<dim> offset(const IVec<dim>& o) const { return o.template cast<Real>() - fx; }
};

// Calls f(o) for every node offset o of the 3^dim stencil, last axis fastest.
template <int dim, class F>
inline void for_each_stencil_node(F&& f) {
  IVec<dim> o;
  if constexpr (dim == 2) {
    for (o[0] = 0; o[0] < 3; ++o[0])
      for (o[1] = 0; o[1] < 3; ++o[1]) f(o);
  } else {
    for (o[0] = 0; o[0] < 3; ++o[0])
      for (o[1] = 0; o[1] < 3; ++o[1])
        for (o[2] = 0; o[2] < 3; ++o[2]) f(o);
  }
}

// Quadratic B-spline kernel value N(r) for a scalar distance r in units of dx.
inline Real bspline_kernel(Real r) {
  r = std::abs(r);
  if (r < Real(0.5)) return Real(0.75) - r * r;
  if (r < Real(1.5)) return Real(0.5) * (Real(1.5) - r) * (Real(1.5) - r);
  return Real(0);
}

}  // namespace cdmpm
