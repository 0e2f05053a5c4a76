// cohesive_cam_clay.h - cohesive non-associative Cam-Clay plasticity with softening/hardening, the plastic
// part of the ice model (Wolper et al. 2019, CD-MPM, ACM TOG 38(4), sec. 4; Wolper et al. 2021 for ice).
// The elastic part is material/neo_hookean_split.h; F below is always the ELASTIC deformation gradient.
//
// Stress invariants of the Kirchhoff stress tau (d = dim):
//   p = -tr(tau)/d                       pressure, POSITIVE IN COMPRESSION,
//   q = sqrt(3/2) |dev(tau)|             von Mises stress (Frobenius norm of the deviator),
//   of the full 3x3 state in 3D and in 2D, where the body is in plane strain (F_zz = 1 in total; the elastic
//   state diag(F, Fz), return_mapping_plane_strain), so one set of parameters is one material in 2D and 3D.
//   The reference implementation's 2D convention (use_reference_2d) instead takes the invariants of the 2x2
//   state with q^2 = (6 - d)/2 |dev tau|^2 = 2 |dev tau|^2, d = 2 in p, and its own softening measure and floor.
// Yield function (ellipse in the p-q plane through p = -beta p0 and p = p0, centre p_c = (1 - beta) p0 / 2):
//   y(p, q) = (1 + 2 beta) q^2 + M^2 (p + beta p0)(p - p0) <= 0.
//   p0 is the compressive strength (hydrostatic), beta p0 the hydrostatic tensile strength (cohesion).
//
// Return mapping (non-associative, CD-MPM), from the trial elastic F = U diag(s) V^T (math/svd.h: U, V
// rotations, an inverted F has a negative last s):
//   * y <= 0: elastic, F untouched (bitwise). Most particles of a glacier are elastic in most steps, so in 3D
//             (where the SVD is iterative) this case is decided BEFORE the SVD, from invariants of F alone
//             (trial_is_elastic; 2D goes straight to its closed-form SVD): J = det F and
//             b = F F^T, whose eigenvalues are s_i^2, give p = p(J) and |dev(bhat)| = J^(-2/d) |dev b|
//             (Frobenius norms), and a lower bound on the smallest singular value, s_min^2 >=
//             J^2 / (tr(b) / (d - 1))^(d - 1) (the other d - 1 eigenvalues of b have a product at most their
//             mean to the power d - 1), rules out the clamp below. States it cannot clear take the SVD path.
//   * p > p0: project to the compressive tip (p0, 0): s_i = J^(1/d), kappa/2 (J^2 - 1) = -p0
//             => J = sqrt(1 - 2 p0 / kappa) (closed form; tau = J sigma is the Kirchhoff stress).
//   * p < -beta p0: project to the tensile tip (-beta p0, 0): J = sqrt(1 + 2 beta p0 / kappa).
//   * otherwise: keep p (i.e. keep J; the Kirchhoff pressure depends on J only) and scale the deviatoric
//             stress by c = q_target / q_trial, q_target = sqrt(M^2 (p0 - p)(p + beta p0) / (1 + 2 beta)).
//             With bhat_i = J^(-2/d) s_i^2 (prod bhat_i = 1) the deviatoric stress is mu dev(bhat). The new
//             bhat'_i = m + c dev(bhat)_i has deviator exactly c dev(bhat); m is the unique root of
//             prod_i (m + c dev(bhat)_i) = 1 (unimodular, so J is unchanged). f(m) = prod(...) - 1 is
//             increasing and convex right of its largest pole, and f(mean(bhat)) >= 0 (log-concavity and
//             AM-GM), so Newton from m = mean(bhat) decreases monotonically to the root. s'_i = J^(1/d) sqrt(bhat'_i).
//   F <- U diag(s') V^T.
//
// Hardening/softening (if `hardening`). alpha is a signed accumulated plastic strain; p0 depends on it through
//   p0(alpha) = kappa (eps + sinh(xi max(-alpha, 0))),  eps = p0_floor = 1e-4 (1e-5 in the reference 2D convention),
// so p0 DECREASES as alpha INCREASES (down to kappa eps once alpha >= 0) and increases as alpha decreases.
//   * q-branch (the specification's rule: driven by the DEVIATORIC plastic strain). With the Hencky (log)
//     strains of the trial and projected elastic states, coaxial in U, the plastic strain increment is
//     d eps^p = ln(s_trial) - ln(s_new) (componentwise, principal values); it is purely deviatoric because J
//     is kept (sum_i d eps^p_i = ln(J_trial / J_new) = 0). Its equivalent (von Mises) measure is
//         delta_eps = sqrt(2/3) |ln(s_trial) - ln(s_new)|   (Euclidean norm over the d principal values),
//     the normalisation work-conjugate to q = sqrt(3/2) |dev tau| (q delta_eps = dev(tau) : d eps^p for a
//     flow along dev tau; in 3D incompressible uniaxial flow (1, -1/2, -1/2) e gives delta_eps = |e|).
//     Sign by the side of the ellipse centre p_c = (1 - beta) p0 / 2 (p = trial pressure = new pressure):
//         p < p_c (tensile side):     alpha += delta_eps   (softening: p0 decreases),
//         p > p_c (compressive side): alpha -= delta_eps   (hardening: p0 increases),
//         p = p_c exactly:            alpha unchanged.
//   * tips (unchanged, volumetric): alpha += ln(J_trial / J_new). At the tensile tip J_new < J_trial, so
//     alpha increases (softening); at the compressive tip J_new > J_trial, alpha decreases (hardening).
//   * the reference 2D convention (use_reference_2d) measures the q-branch's increment as the reference
//     implementation does, by the change of the deviatoric strain: delta_eps = ln(z_trial / z_new),
//     z = sqrt(1 + |dev b|) with b = J^(2/d) bhat, i.e. |dev eps_trial| - |dev eps_new| at small strain (a factor
//     sqrt(3/2) faster than the measure above), and takes eps = 1e-5.
//   * elastic steps, and hardening == false: alpha is left untouched (bitwise).
// SIGN CONVENTION, in short: alpha UP = weaker. TENSION SOFTENS (damages) the ice toward p0 = kappa eps,
// beta p0 -> beta kappa eps (near-zero cohesion); COMPRESSION HARDENS it.
// Initialise alpha with alpha_of_p0(p0_initial, kappa) (< 0) for a given initial strength p0_initial.
// damage = 1 - p0 / p0_initial, clamped to [0, 1]; its maximum is 1 - kappa eps / p0_initial.
//
// Robustness: singular values are clamped to at least min_singular_value = 1e-6 (U, V are proper rotations,
// so the sign of an inverted F is on the last singular value, which the clamp then replaces). A degenerate or
// inverted F is therefore mapped to a nearby non-inverted F with J >= 1e-6^d and never yields NaN; such an F
// is always rewritten (the function then returns true even if the clamped state is elastic). s_trial, J_trial
// above mean the values after this clamp.
// All tolerances are relative (dimensionless stretches, or stresses relative to kappa/p0), so the same code
// works for E = 1e4 Pa and E = 9e9 Pa.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/types.h"
#include "math/powers.h"
#include "math/svd.h"
#include "material/neo_hookean_split.h"

namespace cdmpm {

struct CohesiveCamClay {
  Real M = Real(1.85), beta = Real(0.3), xi = Real(3);
  bool hardening = true;
  // The invariant and softening conventions (see the header): q^2 = q_factor |dev tau|^2, the floor eps of
  // p0(alpha) and the plastic strain measure of the softening. The defaults are the von Mises stress of the full
  // (3x3) state; reference_2d() gives the reference implementation's 2D convention.
  enum class Softening { hencky_mises, deviatoric_strain };
  Real q_factor = Real(1.5);
  Real p0_floor = Real(1e-4);  // eps in p0(alpha): residual strength / kappa
  Softening softening = Softening::hencky_mises;

  static constexpr Real min_singular_value = Real(1e-6);  // clamp for degenerate / inverted F

  // The 2D convention of the CD-MPM reference implementation (Wolper et al. 2019; ziran2020,
  // Lib/Ziran/Physics/PlasticityApplier.cpp, NonAssociativeCamClay), on the 2x2 state: q^2 = (6 - d)/2 |dev tau|^2
  // = 2 |dev tau|^2, eps = 1e-5, the softening increment the change of |dev eps| (ln z, z = sqrt(1 + |dev b|)).
  void use_reference_2d() {
    q_factor = Real(2);
    p0_floor = Real(1e-5);
    softening = Softening::deviatoric_strain;
  }

  Real p0_of_alpha(Real alpha, Real kappa) const {
    return kappa * (p0_floor + std::sinh(xi * std::max(-alpha, Real(0))));
  }
  // Inverse of p0_of_alpha on alpha <= 0 (for initialisation); p0 <= kappa eps gives alpha = 0.
  Real alpha_of_p0(Real p0, Real kappa) const {
    return -std::asinh(std::max(p0 / kappa - p0_floor, Real(0))) / xi;
  }
  static Real damage(Real p0, Real p0_initial) {
    return std::clamp(Real(1) - p0 / p0_initial, Real(0), Real(1));
  }

  Real yield(Real p, Real q, Real p0) const {
    return (Real(1) + Real(2) * beta) * q * q + M * M * (p + beta * p0) * (p - p0);
  }

  // Invariants of a Kirchhoff stress given as principal values or as a full matrix, in this convention
  // (q^2 = q_factor |dev tau|^2; pass the 3x3 state of a plane-strain body).
  template <int dim>
  static Real pressure(const Vec<dim>& tau) { return -tau.sum() / Real(dim); }
  template <int dim>
  Real mises(const Vec<dim>& tau) const {
    return std::sqrt(q_factor) * (tau.array() - tau.sum() / Real(dim)).matrix().norm();
  }
  template <int dim>
  static Real pressure(const Mat<dim>& tau) { return -tau.trace() / Real(dim); }
  template <int dim>
  Real mises(const Mat<dim>& tau) const {
    return std::sqrt(q_factor) * (tau - (tau.trace() / Real(dim)) * Mat<dim>::Identity()).norm();
  }

  // Uniaxial strength magnitude sigma > 0 predicted by the yield surface for a stress diag(+-sigma, 0, ...) with n
  // principal values (n = 3: the laboratory's uniaxial test, also for a plane-strain body, whose material it is;
  // n = 2: the reference 2D convention's 2x2 state): p = -+sigma/n, q^2 = q_factor (n-1)/n sigma^2 (= sigma^2 in
  // 3D, and in the reference 2D convention).
  // y = 0 is a quadratic A s^2 + B s + C = 0 with C = -M^2 beta p0^2 <= 0: exactly one root s >= 0.
  // Tension is weaker than compression iff beta < 1.
  template <int n>
  Real uniaxial_strength(Real p0, bool tension) const {
    const Real t = (tension ? Real(-1) : Real(1)) / Real(n);   // p = t sigma
    const Real cq2 = q_factor * Real(n - 1) / Real(n);         // q^2 = cq2 sigma^2
    const Real A = (Real(1) + Real(2) * beta) * cq2 + M * M * t * t;
    const Real B = M * M * t * (beta - Real(1)) * p0;
    const Real C = -M * M * beta * p0 * p0;
    const Real disc = std::sqrt(B * B - Real(4) * A * C);
    // Cancellation-free form of the non-negative root.
    return B > 0 ? (Real(-2) * C) / (B + disc) : (-B + disc) / (Real(2) * A);
  }

  // Pure-shear strength tau_s > 0 of the yield surface: the shear stress tau of tau_xy = tau_yx = tau (all else 0),
  // for which p = 0 and |dev tau| = sqrt(2) tau, so q^2 = 2 q_factor tau^2 (3 tau^2 in 3D and plane strain).
  // y(0, q) = 0 gives (1 + 2 beta) q^2 = M^2 beta p0^2:
  //   tau_s = M p0 sqrt(beta / (2 q_factor (1 + 2 beta))).
  // Against the uniaxial tensile strength sigma_t = uniaxial_strength<3>(p0, true): in the von Mises limit
  // (M small, so that the strengths, of order M p0, leave |p| << beta p0 and << p0, where the ellipse is the line
  // q = M p0 sqrt(beta / (1 + 2 beta))), q is the same in shear and in tension, so tau_s / sigma_t -> 1/sqrt(3).
  // Away from that limit the ellipse narrows towards its tensile tip, sigma_t falls faster than tau_s and the
  // ratio rises (docs/ice.md).
  Real shear_strength(Real p0) const {
    return M * p0 * std::sqrt(beta / (Real(2) * q_factor * (Real(1) + Real(2) * beta)));
  }

  // True if F is certainly an elastic trial state that the return mapping leaves untouched (see the header):
  // not inverted, smallest singular value certainly above the clamp, and y(p, q) <= 0. Without a root:
  // with q^2 = 3/2 mu^2 J^(-4/d) |dev b|^2, y <= 0 reads X J^(-4/d) <= R for X = (1 + 2 beta) 3/2 mu^2 |dev b|^2
  // and R = M^2 (p + beta p0)(p0 - p) >= 0, i.e. X <= R J^2 (2D) or X^3 <= R^3 J^4 (3D). X and R are scaled
  // by 1/kappa^2 so that the cubes stay within single precision's range (an underflow only sends the state to
  // the full return mapping). One division: every yielding particle pays for this check.
  template <int dim>
  bool trial_is_elastic(const Mat<dim>& F, Real p0, const NeoHookeanSplit& e) const {
    const Real J = F.determinant();
    if (!(J > 0)) return false;
    const Real p = e.pressure_of_J(J);
    if (p > p0 || p < -beta * p0) return false;  // beyond a tip: plastic
    const Mat<dim> b = F * F.transpose();
    const Real trb = b.trace();
    const Real others = trb / Real(dim - 1);  // bound on the mean of the other eigenvalues
    constexpr Real clamp2 = Real(4) * min_singular_value * min_singular_value;  // factor 4: rounding margin
    if (!(J * J >= clamp2 * (dim == 2 ? others : others * others))) return false;
    const Real inv_kappa = Real(1) / e.kappa;
    const Real mu_k = e.mu * inv_kappa, p_k = p * inv_kappa, p0_k = p0 * inv_kappa;
    const Real X = (Real(1) + Real(2) * beta) * q_factor * mu_k * mu_k *
                   (b - (trb / Real(dim)) * Mat<dim>::Identity()).squaredNorm();
    const Real R = M * M * (p_k + beta * p0_k) * (p0_k - p_k);
    if constexpr (dim == 2) return X <= R * J * J;
    else return X * X * X <= R * R * R * (J * J) * (J * J);
  }

  // Plastic projection of the elastic deformation gradient F (in place). p0 is the current compressive
  // strength (normally p0_of_alpha(alpha, e.kappa)); alpha is updated if `hardening`.
  // Returns true iff F was modified (plastic projection, or the degenerate/inverted-F safeguard).
  // dim = 3, and dim = 2 in the reference implementation's 2D convention (2x2 invariants); a plane-strain 2D body
  // takes return_mapping_plane_strain.
  template <int dim>
  bool return_mapping(Mat<dim>& F, Real& alpha, Real p0, const NeoHookeanSplit& e) const {
    // In 3D the check saves the iterative SVD of an elastic particle. The 2D SVD is closed-form and costs
    // about what the check does, and the check, paid again by every yielding particle, slowed the all-yielding
    // 2D ice benchmark by 12 %: so 3D only (docs/performance.md).
    if constexpr (dim == 3)
      if (trial_is_elastic<dim>(F, p0, e)) return false;
    Mat<dim> U, V;
    Vec<dim> s;
    svd<dim>(F, U, s, V);  // U, V rotations; an inverted F has s(dim - 1) < 0
    if (!project<dim>(s, alpha, p0, e)) return false;
    F = U * s.asDiagonal() * V.transpose();
    return true;
  }

  // Plane strain (Hill 1950, The Mathematical Theory of Plasticity, ch. VII): the elastic state of a 2D body is
  // the 3x3 F_e = diag(F, fz), F the in-plane 2x2 and fz the out-of-plane stretch. F = U diag(s0, s1) V^T
  // makes F_e = diag(U, 1) diag(s0, s1, fz) diag(V, 1)^T, so the 3D return mapping acts on the principal
  // values (s0, s1, fz) and keeps the out-of-plane axis a principal axis: the result is again of the form
  // diag(F', fz'), the same to round-off as return_mapping<3> of diag(F, fz) (tests/unit/test_plane_strain.cpp).
  bool return_mapping_plane_strain(Mat<2>& F, Real& fz, Real& alpha, Real p0, const NeoHookeanSplit& e) const {
    Mat<2> U, V;
    Vec<2> s2;
    svd<2>(F, U, s2, V);
    Vec<3> s(s2(0), s2(1), fz);
    if (!project<3>(s, alpha, p0, e)) return false;
    F = U * s.head<2>().asDiagonal() * V.transpose();
    fz = s(2);
    return true;
  }

  // The return mapping on the n principal stretches s of the trial elastic state (see the header; n = 3 in 3D
  // and plane strain, n = 2 in the reference implementation's 2D convention), in place. Returns true iff s was
  // changed (projected, or clamped).
  template <int n>
  bool project(Vec<n>& s, Real& alpha, Real p0, const NeoHookeanSplit& e) const {
    bool clamped = false;
    for (int i = 0; i < n; ++i)
      if (!(s(i) >= min_singular_value)) {  // also catches a negative (inverted) last value
        s(i) = min_singular_value;
        clamped = true;
      }

    const Real J = s.prod();
    const Real Jd = root_dim<n>(J);  // J^(1/n), and J^(-2/n) from it: one root per call
    const Real Jm2d = Real(1) / (Jd * Jd);
    Vec<n> bhat = (Jm2d * s.array().square()).matrix();  // unimodular stretch, prod = 1
    const Real bmean = bhat.sum() / Real(n);
    const Vec<n> bdev = (bhat.array() - bmean).matrix();
    const Real p = e.pressure_of_J(J);
    const Real q = std::sqrt(q_factor) * e.mu * bdev.norm();
    const Real y = yield(p, q, p0);

    if (y <= 0) return clamped;

    if (p > p0 || p < -beta * p0) {  // tips: hydrostatic state at the tip pressure
      const Real p_tip = p > p0 ? p0 : -beta * p0;
      // kappa/2 (J^2 - 1) = -p_tip. p_tip = p0 >= kappa/2 is unreachable (p < kappa/2); guard anyway.
      const Real J2 = std::max(Real(1) - Real(2) * p_tip / e.kappa, std::pow(min_singular_value, Real(2 * n)));
      const Real J_new = std::sqrt(J2);
      if (hardening) alpha += std::log(J / J_new);
      s = Vec<n>::Constant(root_dim<n>(J_new));
      return true;
    }

    // q-branch: here -beta p0 <= p <= p0 and y > 0 imply q > 0.
    const Real q_target =
        std::sqrt(std::max(M * M * (p0 - p) * (p + beta * p0) / (Real(1) + Real(2) * beta), Real(0)));
    const Real c = q_target / q;
    const Vec<n> cd = c * bdev;
    // Newton on f(m) = prod(m + cd_i) - 1 from m = bmean (f >= 0 there): monotone decrease to the root.
    Real m = bmean;
    for (int it = 0; it < 100; ++it) {
      Real f = 1, df = 0;
      for (int i = 0; i < n; ++i) {
        df = df * (m + cd(i)) + f;  // product rule accumulated
        f *= (m + cd(i));
      }
      f -= Real(1);
      if (!(f > 0) || !(df > 0)) break;
      const Real m_new = m - f / df;
      if (!(m_new < m)) break;  // converged to machine precision
      m = m_new;
    }
    if (hardening) {
      // The plastic strain increment, signed by the side of the ellipse centre (see the header).
      const Real p_c = (Real(1) - beta) * p0 / Real(2);
      Real delta_eps = 0;
      if (softening == Softening::hencky_mises) {
        // sqrt(2/3) |ln s - ln s_new|, ln(s_i / s_new_i) = ln(bhat_i / bhat'_i) / 2.
        Real sq = 0;
        for (int i = 0; i < n; ++i) {
          const Real l = Real(0.5) * std::log(bhat(i) / (m + cd(i)));
          sq += l * l;
        }
        delta_eps = std::sqrt(Real(2) / Real(3) * sq);
      } else {
        // ln(z_trial / z_new), z = sqrt(1 + |dev b|), b = J^(2/n) bhat: the change of |dev eps| (small strain).
        const Real dev_b = Jd * Jd * bdev.norm();
        delta_eps = Real(0.5) * std::log((Real(1) + dev_b) / (Real(1) + c * dev_b));
      }
      if (std::isfinite(delta_eps)) {
        if (p < p_c) alpha += delta_eps;
        else if (p > p_c) alpha -= delta_eps;
      }
    }
    for (int i = 0; i < n; ++i) s(i) = Jd * std::sqrt(std::max(m + cd(i), Real(0)));
    return true;
  }
};

}  // namespace cdmpm
