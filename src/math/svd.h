// svd.h - fast "rotation-variant" singular value decomposition of small (2x2, 3x3) matrices for MPM.
//
//   template <int dim> void svd(const Mat<dim>& F, Mat<dim>& U, Vec<dim>& sigma, Mat<dim>& V);
//
// Result: F = U diag(sigma) V^T up to roundoff, with U and V proper ROTATIONS (det = +1) and
// sigma(0) >= sigma(1) >= ... >= sigma(dim-1), where only the last entry may be negative and
// |sigma(dim-1)| <= sigma(dim-2) (up to roundoff). An inverted F (det F < 0) therefore shows up as a
// negative last singular value (Irving, Teran & Fedkiw 2004; Stomakhin et al. 2012): det F = prod(sigma).
// The |sigma| are the ordinary singular values. Works for any F, including 0, rank-deficient, repeated
// singular values and reflections; a matrix whose largest entry is outside [2^-20, 2^20] is first scaled by
// an exact power of two, so squared column norms never overflow or underflow prematurely (also in float).
//
// 2D, closed form: polar decomposition F = R S with R the rotation by theta = atan2(F10 - F01, F00 + F11),
// which makes S = R^T F symmetric with tr S = |(F00 + F11, F10 - F01)| >= 0; then S = W diag(d) W^T by one
// exact Jacobi rotation (the symmetric Schur decomposition, Golub & Van Loan, Matrix Computations, 4th ed.,
// alg. 8.5.1), d sorted descending by a quarter turn of W. U = R W, V = W, sigma = d. tr S >= 0 gives
// d0 >= |d1|, so only d1 can be negative (exactly when det F < 0).
//
// 3D, one-sided (Hestenes 1958) Jacobi: orthogonalise the columns of B = F V by plane rotations
// V <- V J(p, q), each chosen to make columns p and q of B orthogonal (the same rotation that the two-sided
// cyclic Jacobi method would apply to F^T F, but computed from B itself, so that the backward error is
// O(eps |F|) and small singular values are not lost to the squaring of F^T F; Demmel & Veselic 1992,
// "Jacobi's method is more accurate than QR"). Cyclic sweeps over (0,1), (0,2), (1,2) until every pair
// satisfies |b_p . b_q| <= dim * eps |b_p| |b_q| (quadratic convergence: 3-6 sweeps including the final
// check sweep that rotates nothing, for random F of any condition; at most kMaxSweeps). Rotation angles from
// svd_detail::jacobi_rotation (2 square roots and 2 divisions, or 2 divisions for the small angles of the
// later sweeps). Then the columns are sorted by norm (a transposition is paired with a sign change of one
// column so that det V stays +1), u_0 = b_0 / |b_0|, u_1 = the Gram-Schmidt (twice) orthonormalised b_1
// (any unit vector orthogonal to u_0 if b_1 is numerically zero: rank deficiency), u_2 = u_0 x u_1 (so U is a
// rotation by construction), sigma_i = u_i . b_i. The last one carries the sign of det F.
// Cost (development machine, one thread, double, -O3): ~40 ns in 2D and ~480 ns in 3D per call, against
// ~110 ns and ~810 ns for Eigen::JacobiSVD with full U and V (which then also needs the sign fix-up).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "core/types.h"

namespace cdmpm {

namespace svd_detail {

// Smaller-angle Jacobi rotation J = [[c, s], [-s, c]] (c = cos theta >= 1/sqrt(2), s = sin theta) that
// diagonalises the symmetric 2x2 [[app, apq], [apq, aqq]] (apq != 0): J^T A J = diag(app - t apq, aqq + t apq),
// t = s / c. Equivalently, [b_p b_q] J has orthogonal columns when app = |b_p|^2, aqq = |b_q|^2,
// apq = b_p . b_q. Golub & Van Loan's zeta = (aqq - app) / (2 apq), t = sign(zeta) / (|zeta| + rho),
// rho = sqrt(1 + zeta^2), in the algebraically identical form c = (rho + |zeta|) r, s = sign(zeta) r,
// r = 1 / sqrt(2 rho (rho + |zeta|)) (sign(0) = +1): two square roots and two divisions, and scale-invariant
// (no squares of the possibly tiny app, aqq, apq, which would underflow in float). For |zeta| > 1/sqrt(eps),
// t < sqrt(eps)/2 and c = 1/sqrt(1 + t^2) rounds to 1: then c = 1, s = t = 1 / (2 zeta) (the small angles of
// the later sweeps).
inline void jacobi_rotation(Real app, Real aqq, Real apq, Real& c, Real& s) {
  const Real zeta = (aqq - app) / (Real(2) * apq);
  const Real az = std::abs(zeta);
  if (az * az * std::numeric_limits<Real>::epsilon() > Real(1)) {
    c = 1;
    s = Real(0.5) / zeta;
    return;
  }
  const Real rho = std::sqrt(Real(1) + az * az);
  const Real r = Real(1) / std::sqrt(Real(2) * rho * (rho + az));
  c = (rho + az) * r;
  s = zeta < 0 ? -r : r;
}

// Exact power-of-two scale factor bringing max|F_ij| into [0.5, 1) when it is outside [2^-20, 2^20]; 1
// otherwise (and for F = 0). Returns the factor to multiply F by; sigma is divided by it afterwards.
template <int dim>
Real power_of_two_scale(const Mat<dim>& F) {
  const Real m = F.cwiseAbs().maxCoeff();
  if (!(m > 0) || (m >= std::ldexp(Real(1), -20) && m <= std::ldexp(Real(1), 20))) return Real(1);
  int e = 0;
  std::frexp(m, &e);
  // Subnormal m: a factor above 2^-min_exponent would overflow; the scaled F is then still far from overflow.
  return std::ldexp(Real(1), -std::max(e, std::numeric_limits<Real>::min_exponent));
}

inline void svd2(const Mat<2>& F, Mat<2>& U, Vec<2>& sigma, Mat<2>& V) {
  // Polar part: rotation R(theta) with theta = atan2(F10 - F01, F00 + F11) makes R^T F symmetric.
  Real a = F(0, 0) + F(1, 1), b = F(1, 0) - F(0, 1), r2 = a * a + b * b;
  if (r2 < std::numeric_limits<Real>::min() / std::numeric_limits<Real>::epsilon()) {
    // (a, b) tiny next to F (nearly symmetric traceless F): a^2 + b^2 would lose precision to underflow and
    // (cr, sr) would not be a unit vector. Only the direction of (a, b) matters: normalise it first.
    const Real m = std::max(std::abs(a), std::abs(b));
    if (m > 0) {
      a /= m;
      b /= m;
      r2 = a * a + b * b;
    }
  }
  const Real r = std::sqrt(r2);
  const Real cr = r > 0 ? a / r : Real(1), sr = r > 0 ? b / r : Real(0);
  const Real s00 = cr * F(0, 0) + sr * F(1, 0);
  const Real s11 = cr * F(1, 1) - sr * F(0, 1);
  const Real s01 = Real(0.5) * ((cr * F(0, 1) + sr * F(1, 1)) + (cr * F(1, 0) - sr * F(0, 0)));
  // Symmetric eigen-decomposition S = W diag(d) W^T, W = [[cw, sw], [-sw, cw]], d0 >= d1.
  Real cw = 1, sw = 0, d0 = s00, d1 = s11;
  bool turn = s00 < s11;
  if (s01 != 0) {
    jacobi_rotation(s00, s11, s01, cw, sw);
    // Eigenvalues m +- h (h computed independently of the rotation: no division on the critical path; its
    // possible underflow in float only concerns h < sqrt(min) << eps |S|).
    const Real m = Real(0.5) * (s00 + s11), dx = Real(0.5) * (s00 - s11);
    const Real h = std::sqrt(dx * dx + s01 * s01);
    d0 = m + h;
    d1 = m - h;
    // J^T S J = diag(s00 - t s01, s11 + t s01), t = sw / cw; the difference of the two is
    // (s00 - s11) + sign(s00 - s11) 2 |t s01|, or -2 s01 when s00 = s11 (then t = 1): the first is the larger
    // iff s00 > s11, or s00 = s11 and s01 < 0. Otherwise W's columns must be exchanged.
    turn = s00 < s11 || (s00 == s11 && s01 > 0);
  } else if (turn) {
    std::swap(d0, d1);
  }
  if (turn) {  // W <- W [[0, -1], [1, 0]] (quarter turn, det stays +1): exchanges the columns up to a sign
    const Real c_old = cw;
    cw = -sw;
    sw = c_old;
  }
  d0 = std::max(d0, Real(0));  // d0 >= (d0 + d1) / 2 = tr S / 2 >= 0 up to roundoff
  V << cw, sw, -sw, cw;
  // U = R W with R = [[cr, -sr], [sr, cr]]: again a rotation, by theta + angle(W).
  const Real cu = cr * cw + sr * sw, su = cr * sw - sr * cw;
  U << cu, su, -su, cu;
  sigma << d0, d1;
}

inline constexpr int kMaxSweeps = 12;  // never reached in the tests (at most 6 sweeps observed)

inline void svd3(const Mat<3>& F, Mat<3>& U, Vec<3>& sigma, Mat<3>& V) {
  constexpr Real eps = std::numeric_limits<Real>::epsilon();
  const Real tol = Real(3) * eps;  // dim eps
  Mat<3> B = F;
  V.setIdentity();
  for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
    bool rotated = false;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        const Real app = B.col(p).squaredNorm(), aqq = B.col(q).squaredNorm(), apq = B.col(p).dot(B.col(q));
        // Converged pair: |apq| <= tol |b_p| |b_q| (with roots, not squares: app aqq may underflow in float).
        // Also skips NaN.
        if (!(std::abs(apq) > tol * std::sqrt(app) * std::sqrt(aqq))) continue;
        rotated = true;
        Real c, s;
        jacobi_rotation(app, aqq, apq, c, s);  // small-angle fast path for most rotations after sweep 2
        for (int i = 0; i < 3; ++i) {
          const Real bp = B(i, p), bq = B(i, q);
          B(i, p) = c * bp - s * bq;
          B(i, q) = s * bp + c * bq;
          const Real vp = V(i, p), vq = V(i, q);
          V(i, p) = c * vp - s * vq;
          V(i, q) = s * vp + c * vq;
        }
      }
    if (!rotated) break;
  }

  // Sort columns by norm, descending; every transposition also negates one column (of B and V alike, so
  // F V = B still holds) to keep det V = +1.
  Vec<3> n(B.col(0).squaredNorm(), B.col(1).squaredNorm(), B.col(2).squaredNorm());
  auto swap_cols = [&](int i, int j) {
    B.col(i).swap(B.col(j));
    V.col(i).swap(V.col(j));
    std::swap(n(i), n(j));
    B.col(j) *= Real(-1);
    V.col(j) *= Real(-1);
  };
  if (n(0) < n(1)) swap_cols(0, 1);
  if (n(0) < n(2)) swap_cols(0, 2);
  if (n(1) < n(2)) swap_cols(1, 2);

  if (!(n(0) > 0)) {  // F = 0 (or NaN): any rotations will do
    U.setIdentity();
    sigma = B.colwise().norm().transpose();  // 0 (or NaN, propagated)
    return;
  }
  const Vec<3> u0 = B.col(0) / std::sqrt(n(0));
  Vec<3> w = B.col(1);
  for (int k = 0; k < 2; ++k) w -= u0.dot(w) * u0;  // Gram-Schmidt, twice ("twice is enough")
  Real wn = w.norm();
  if (!(wn > std::numeric_limits<Real>::min() / eps)) {
    // b_1 numerically zero (rank <= 1): complete u0 by the coordinate axis least aligned with it.
    int k = 0;
    u0.cwiseAbs().minCoeff(&k);
    w = Vec<3>::Unit(k);
    for (int it = 0; it < 2; ++it) w -= u0.dot(w) * u0;
    wn = w.norm();
  }
  const Vec<3> u1 = w / wn;
  const Vec<3> u2(u0(1) * u1(2) - u0(2) * u1(1), u0(2) * u1(0) - u0(0) * u1(2),
                  u0(0) * u1(1) - u0(1) * u1(0));  // u0 x u1 (no <Eigen/Geometry> needed)
  U.col(0) = u0;
  U.col(1) = u1;
  U.col(2) = u2;
  sigma(0) = u0.dot(B.col(0));
  sigma(1) = std::clamp(u1.dot(B.col(1)), Real(0), sigma(0));  // >= 0 also in the rank-deficient fallback
  sigma(2) = std::min(u2.dot(B.col(2)), sigma(1));  // carries the sign of det F
}

}  // namespace svd_detail

template <int dim>
void svd(const Mat<dim>& F, Mat<dim>& U, Vec<dim>& sigma, Mat<dim>& V) {
  static_assert(dim == 2 || dim == 3, "svd: dim must be 2 or 3");
  const Real scale = svd_detail::power_of_two_scale<dim>(F);
  if (scale == Real(1)) {
    if constexpr (dim == 2) svd_detail::svd2(F, U, sigma, V);
    else svd_detail::svd3(F, U, sigma, V);
    return;
  }
  const Mat<dim> Fs = scale * F;  // exact (power of two), barring subnormals
  if constexpr (dim == 2) svd_detail::svd2(Fs, U, sigma, V);
  else svd_detail::svd3(Fs, U, sigma, V);
  sigma /= scale;
}

}  // namespace cdmpm
