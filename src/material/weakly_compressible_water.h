// weakly_compressible_water.h - water as a weakly compressible fluid (Tait equation of state).
//
// Pressure from the volume ratio J = V/V0 = rho0/rho (Monaghan 1994; Becker & Teschner 2007):
//   p(J) = K/gamma (J^-gamma - 1),
// with bulk modulus K (the slope dp/d(rho/rho0) at rest) and gamma = 7, cut off at p >= 0: water does not
// sustain tension (a free surface or a body pulling away from the water opens a gap instead of pulling the
// water with it through the shared grid; the standard cavitation cut-off of free-surface MPM/SPH). Acoustic speed
//   c(J) = sqrt(dp/drho) = sqrt(K/rho0 J^(1-gamma)).
// Optional Newtonian viscosity adds the deviatoric Cauchy stress 2 mu dev(D), D = sym(grad v).
// Kirchhoff stress tau = J sigma = -J p I + 2 mu J dev(D).
// Stored energy per reference volume, psi(J) = -int_1^J p dJ' = K/gamma [(J^(1-gamma) - 1)/(gamma - 1) + J - 1]
// for J < 1 and 0 for J >= 1, so that p = -dpsi/dJ. See docs/water.md for how to choose K.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/types.h"
#include "math/powers.h"

namespace cdmpm {

struct WeaklyCompressibleWater {
  Real rho0 = 1000, K = 2e5, gamma = 7, mu = 0;

  Real pressure(Real J) const { return J < Real(1) ? K / gamma * (real_pow(J, -gamma) - Real(1)) : Real(0); }

  // J at which the equation of state gives pressure p (used for the hydrostatic pre-compression).
  Real volume_ratio_at_pressure(Real p) const { return std::pow(Real(1) + gamma * p / K, Real(-1) / gamma); }

  Real wave_speed(Real J) const { return std::sqrt(K / rho0 * real_pow(J, Real(1) - gamma)); }

  Real energy_density(Real J) const {
    if (J >= Real(1)) return 0;
    return K / gamma * ((real_pow(J, Real(1) - gamma) - Real(1)) / (gamma - Real(1)) + J - Real(1));
  }

  // Kirchhoff stress from J and the velocity gradient estimate C.
  template <int dim>
  Mat<dim> kirchhoff(Real J, const Mat<dim>& C) const {
    Mat<dim> tau = Mat<dim>::Identity() * (-J * pressure(J));
    if (mu > 0) {
      const Mat<dim> D = Real(0.5) * (C + C.transpose());
      tau += (Real(2) * mu * J) * (D - D.trace() / Real(dim) * Mat<dim>::Identity());
    }
    return tau;
  }
};

}  // namespace cdmpm
