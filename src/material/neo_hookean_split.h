// neo_hookean_split.h - compressible Neo-Hookean elasticity with a volumetric/deviatoric split, the elastic
// part of the ice model (Wolper et al. 2019, CD-MPM, ACM TOG 38(4), eq. for psi; Wolper et al. 2021).
//
// Stored energy per reference volume, with J = det F, b = F F^T, d = dim:
//   psi(F) = mu/2 (tr(J^(-2/d) b) - d) + kappa/2 ((J^2 - 1)/2 - ln J).
// Derivation of the Kirchhoff stress tau = P F^T, P = dpsi/dF:
//   d tr(J^(-2/d) F F^T)/dF = J^(-2/d) (2 F - (2/d) tr(b) F^-T)        (using dJ/dF = J F^-T)
//     => deviatoric part  tau_dev = mu J^(-2/d) (b - tr(b)/d I) = mu J^(-2/d) dev(b),
//   d/dJ [(J^2 - 1)/2 - ln J] = J - 1/J, times dJ/dF F^T = J I
//     => volumetric part  tau_vol = kappa/2 (J^2 - 1) I.
//   tau = mu J^(-2/d) dev(b) + kappa/2 (J^2 - 1) I.
// The Kirchhoff pressure p = -tr(tau)/d = -kappa/2 (J^2 - 1) (positive in compression) depends on J only;
// it is bounded above by kappa/2 (reached as J -> 0).
// In principal axes (F = U diag(s) V^T, b = U diag(s^2) U^T) tau = U diag(tau_i) U^T with
//   tau_i = mu J^(-2/d) (s_i^2 - sum_k s_k^2 / d) + kappa/2 (J^2 - 1),  J = prod s_k.
// Small-strain limit (F = I + grad u, eps = sym grad u): tau ~ 2 mu dev(eps) + kappa tr(eps) I.
//
// Elastic constants from (E, nu), see from_young_poisson: mu = E / (2 (1 + nu)), kappa = E / (3 (1 - 2 nu)) (the
// bulk modulus, lambda + 2/3 mu). A 2D body in plane strain evaluates the 3D energy at diag(F, Fz)
// (material/ice.h), which linearises to plane-strain Hooke's law sigma = lambda tr(eps) I + 2 mu eps; the d = 2
// form of the energy with this kappa is the reference implementation's 2D convention.
// Preconditions: J = det F > 0 (the energy contains ln J). The plastic return mapping
// (material/cohesive_cam_clay.h) guarantees this for the stored elastic F.
#pragma once

#include <Eigen/LU>
#include <cmath>
#include <limits>

#include "core/types.h"
#include "math/powers.h"

namespace cdmpm {

struct NeoHookeanSplit {
  Real mu = 0, kappa = 0;

  // mu, kappa from Young's modulus and Poisson's ratio (see above).
  static NeoHookeanSplit from_young_poisson(Real E, Real nu) {
    NeoHookeanSplit e;
    e.mu = E / (Real(2) * (Real(1) + nu));
    e.kappa = E / (Real(3) * (Real(1) - Real(2) * nu));
    return e;
  }

  // Small-strain P-wave (uniaxial-strain) modulus kappa + 2 mu (1 - 1/d) of the d-dimensional energy: lambda + 2 mu
  // in 3D (and so in plane strain). Gives the elastic wave speed sqrt(modulus / rho) for the time-step restriction.
  template <int dim>
  Real p_wave_modulus() const { return kappa + Real(2) * mu * (Real(1) - Real(1) / Real(dim)); }

  // Kirchhoff pressure as a function of J, and its inverse (the J giving pressure p; requires p < kappa/2).
  Real pressure_of_J(Real J) const { return -Real(0.5) * kappa * (J * J - Real(1)); }
  Real J_of_pressure(Real p) const { return std::sqrt(Real(1) - Real(2) * p / kappa); }

  template <int dim>
  Real energy_density(const Mat<dim>& F) const {
    const Real J = F.determinant();
    const Real Jm2d = pow_minus_two_over_dim<dim>(J);
    return Real(0.5) * mu * (Jm2d * F.squaredNorm() - Real(dim)) +
           Real(0.5) * kappa * (Real(0.5) * (J * J - Real(1)) - std::log(J));
  }

  template <int dim>
  Mat<dim> kirchhoff(const Mat<dim>& F) const {
    const Real J = F.determinant();
    const Real Jm2d = pow_minus_two_over_dim<dim>(J);
    const Mat<dim> b = F * F.transpose();
    Mat<dim> tau = (mu * Jm2d) * (b - (b.trace() / Real(dim)) * Mat<dim>::Identity());
    tau.diagonal().array() += Real(0.5) * kappa * (J * J - Real(1));
    return tau;
  }

  // First Piola-Kirchhoff stress P = tau F^-T.
  template <int dim>
  Mat<dim> first_piola(const Mat<dim>& F) const {
    return kirchhoff<dim>(F) * F.inverse().transpose();
  }

  // Diagonal F (stretches: horizontal axes equal, vertical axis last) of the vertical Cauchy stress sigma_v
  // with the horizontal stress k sigma_v: the lithostatic state of an ice body under its own weight
  // (sigma_v = -rho g depth), laterally free for k = 0 (uniaxial), cryostatic for k = 1 (isotropic, no
  // deviatoric stress: the state creep relaxes glacier ice to). Newton on (ln s_h, ln s_v) with the residual
  // (tau_h - J k sigma_v, tau_v - J sigma_v) / kappa; converges in a few iterations for |sigma_v| << kappa.
  template <int dim>
  Vec<dim> vertical_load_stretches(Real sigma_v, Real k = 0) const {
    Real lh = 0, lv = 0;
    auto residual = [&](Real a, Real b) {
      Vec<dim> s = Vec<dim>::Constant(std::exp(a));
      s[dim - 1] = std::exp(b);
      const Vec<dim> tau = kirchhoff_from_singular_values<dim>(s);
      return Eigen::Matrix<Real, 2, 1>((tau[0] - s.prod() * k * sigma_v) / kappa, (tau[dim - 1] - s.prod() * sigma_v) / kappa);
    };
    for (int it = 0; it < 50; ++it) {
      const auto r = residual(lh, lv);
      if (r.norm() < Real(64) * std::numeric_limits<Real>::epsilon()) break;
      const Real h = std::sqrt(std::numeric_limits<Real>::epsilon());
      Eigen::Matrix<Real, 2, 2> Jac;
      Jac.col(0) = (residual(lh + h, lv) - r) / h;
      Jac.col(1) = (residual(lh, lv + h) - r) / h;
      const Eigen::Matrix<Real, 2, 1> d = Jac.partialPivLu().solve(-r);
      lh += d[0];
      lv += d[1];
    }
    Vec<dim> s = Vec<dim>::Constant(std::exp(lh));
    s[dim - 1] = std::exp(lv);
    return s;
  }

  // Principal Kirchhoff stresses tau_i for singular values s (all > 0) of F, in the principal axes U.
  template <int dim>
  Vec<dim> kirchhoff_from_singular_values(const Vec<dim>& s) const {
    const Real J = s.prod();
    const Real Jm2d = pow_minus_two_over_dim<dim>(J);
    const Vec<dim> s2 = s.array().square().matrix();
    Vec<dim> tau = (mu * Jm2d) * (s2.array() - s2.sum() / Real(dim)).matrix();
    tau.array() += Real(0.5) * kappa * (J * J - Real(1));
    return tau;
  }
};

}  // namespace cdmpm
