// Tests of the rotation-variant SVD (math/svd.h) against Eigen::JacobiSVD, in 2D and 3D, on ~10000 random
// matrices per dimension (random rotations times random stretches: generic, wide-range, near-identity,
// near-degenerate, rank-deficient, repeated and nearly repeated, inverted, tiny and huge scales) plus
// special exact matrices (0, I, -I, reflections, permutations, rank 1, shears).
//
// Tolerances, with eps = std::numeric_limits<Real>::epsilon() (so the same test runs in float):
//   c = 50. The 3D one-sided Jacobi applies a handful of rotations that are not already negligible (3 per
//   sweep, quadratic convergence leaves ~3 sweeps of significant ones); each changes two columns of B and V
//   by a backward error of ~2 eps |F| (Frobenius), so <= ~20 eps after accumulation; the normalisation,
//   Gram-Schmidt and cross product add a few eps, and evaluating U diag(sigma) V^T - F in the test costs up to
//   2 dim eps |F|. The 2D closed form has ~10 eps. The Eigen reference (computed in double from the same
//   matrix) contributes a few eps(double), and by Weyl's inequality singular values move by at most the
//   backward error |dF|_2 <= |dF|_F, so all |sigma_i| agree with the reference to ~30 eps sigma_max < 50 eps.
//   * reconstruction: |U diag(sigma) V^T - F|_F <= c eps |F|_F;
//   * orthogonality: |U^T U - I|_F, |V^T V - I|_F <= c eps; det U, det V within c eps of +1;
//   * singular values: ||sigma_i| - sigma_i^Eigen| <= c eps sigma_max;
//   * sign: sigma_last < 0 iff det F < 0, checked where sigma_min > c eps sigma_max (there the backward
//     errors of both SVDs cannot change the sign); sign(det F) is taken as det(U_ref) det(V_ref);
//   * order: sigma_0 >= ... >= sigma_last exactly, sigma_i >= 0 for i < last, |sigma_last| <= sigma_(last-1)
//     + c eps sigma_max.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "math/svd.h"

using namespace cdmpm;

namespace {

constexpr Real kEps = std::numeric_limits<Real>::epsilon();
constexpr double kC = 50;

template <int dim>
Mat<dim> random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> n(0, 1);
  Eigen::Matrix<double, dim, dim> A;
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) A(i, j) = n(rng);
  Eigen::Matrix<double, dim, dim> Q = Eigen::HouseholderQR<Eigen::Matrix<double, dim, dim>>(A).householderQ();
  if (Q.determinant() < 0) Q.col(0) *= -1;
  return Q.template cast<Real>();
}

template <int dim>
struct Stats {
  double recon = 0, orth = 0, det = 0, sv = 0;  // worst observed error / (eps * scale)
  int n = 0, n_negative = 0;
};

template <int dim>
void check_one(const Mat<dim>& F, const std::string& what, Stats<dim>& st) {
  Mat<dim> U, V;
  Vec<dim> s;
  svd<dim>(F, U, s, V);
  ++st.n;
  if (s(dim - 1) < 0) ++st.n_negative;

  using Md = Eigen::Matrix<double, dim, dim>;
  const Md Fd = F.template cast<double>();
  Eigen::JacobiSVD<Md> ref(Fd, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Matrix<double, dim, 1> sref = ref.singularValues();
  const double smax = sref(0), eps = kEps;

  ASSERT_TRUE(U.array().isFinite().all() && V.array().isFinite().all() && s.array().isFinite().all()) << what;

  // stableNorm: |F|^2 would overflow / underflow in float for the huge and tiny scales.
  const double fnorm = double(F.stableNorm());
  const double recon = double(Mat<dim>(U * s.asDiagonal() * V.transpose() - F).stableNorm());
  EXPECT_LE(recon, kC * eps * fnorm) << what;
  if (fnorm > 0) st.recon = std::max(st.recon, recon / (eps * fnorm));

  const Mat<dim> I = Mat<dim>::Identity();
  const double ou = double((U.transpose() * U - I).norm()), ov = double((V.transpose() * V - I).norm());
  EXPECT_LE(ou, kC * eps) << what;
  EXPECT_LE(ov, kC * eps) << what;
  st.orth = std::max(st.orth, std::max(ou, ov) / eps);
  const double du = std::abs(double(U.determinant()) - 1), dv = std::abs(double(V.determinant()) - 1);
  EXPECT_LE(du, kC * eps) << what;
  EXPECT_LE(dv, kC * eps) << what;
  st.det = std::max(st.det, std::max(du, dv) / eps);

  for (int i = 0; i < dim; ++i) {
    const double e = std::abs(std::abs(double(s(i))) - sref(i));
    EXPECT_LE(e, kC * eps * smax) << what << " i " << i << " sigma " << s.transpose() << " ref "
                                  << sref.transpose();
    if (smax > 0) st.sv = std::max(st.sv, e / (eps * smax));
  }
  for (int i = 0; i + 1 < dim; ++i) {
    EXPECT_GE(s(i), s(i + 1)) << what;
    EXPECT_GE(s(i), 0) << what;
  }
  EXPECT_LE(std::abs(double(s(dim - 1))), double(s(dim - 2)) + kC * eps * smax) << what;
  if (sref(dim - 1) > kC * eps * smax) {
    // sign(det F) = det(U_ref) det(V_ref) (each +-1): backward stable, unlike a cofactor determinant, whose
    // error ~ eps sigma_max^dim can exceed |det F| = prod sigma_i when sigma_min is small.
    const double sign_ref = ref.matrixU().determinant() * ref.matrixV().determinant();
    EXPECT_EQ(s(dim - 1) < 0, sign_ref < 0) << what << " sigma " << s.transpose();
  }
}

// Random singular values of the given kind (all > 0 here; signs/inversion are applied separately).
template <int dim>
Vec<dim> random_stretch(std::mt19937& rng, int kind) {
  std::uniform_real_distribution<double> u(0, 1);
  Vec<dim> s;
  auto logu = [&](double lo, double hi) { return Real(std::pow(10.0, lo + (hi - lo) * u(rng))); };
  switch (kind) {
    case 0:  // generic, moderate
      for (int i = 0; i < dim; ++i) s(i) = logu(-1, 1);
      break;
    case 1:  // wide range (condition number up to 1e8)
      for (int i = 0; i < dim; ++i) s(i) = logu(-4, 4);
      break;
    case 2:  // near identity (typical MPM elastic F)
      for (int i = 0; i < dim; ++i) s(i) = Real(1 + 1e-3 * (2 * u(rng) - 1));
      break;
    case 3:  // near-degenerate: one tiny singular value
      for (int i = 0; i < dim; ++i) s(i) = logu(-0.5, 0.5);
      s(int(u(rng) * dim) % dim) = logu(-12, -4);
      break;
    case 4:  // rank-deficient: one (or, in 3D, two) exactly zero before rotation
      for (int i = 0; i < dim; ++i) s(i) = logu(-0.5, 0.5);
      s(0) = 0;
      if (dim == 3 && u(rng) < 0.5) s(1) = 0;
      break;
    case 5: {  // repeated: two or all equal
      const Real a = logu(-1, 1);
      for (int i = 0; i < dim; ++i) s(i) = a;
      if (dim == 3 && u(rng) < 0.5) s(int(u(rng) * 3) % 3) = logu(-1, 1);
      break;
    }
    case 6: {  // nearly repeated (relative gaps 1e-12 .. 1e-4)
      const Real a = logu(-1, 1);
      for (int i = 0; i < dim; ++i) s(i) = a * Real(1 + std::pow(10.0, -12 + 8 * u(rng)));
      break;
    }
    default:  // near-degenerate pair in 3D / tiny-but-equal
      for (int i = 0; i < dim; ++i) s(i) = logu(-0.5, 0.5);
      s(0) = logu(-9, -5);
      s(dim - 1) = s(0);
      break;
  }
  return s;
}

template <int dim>
void run_random(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  Stats<dim> st;
  int n_inverted = 0;
  for (int k = 0; k < n; ++k) {
    const int kind = k % 8;
    Vec<dim> s = random_stretch<dim>(rng, kind);
    const bool invert = u(rng) < 0.3;
    if (invert) {
      s(int(u(rng) * dim) % dim) *= Real(-1);
      ++n_inverted;
    }
    Mat<dim> F = random_rotation<dim>(rng) * s.asDiagonal() * random_rotation<dim>(rng);
    const double r = u(rng);
    if (r < 0.05) F *= Real(1e-25);  // tiny and huge overall scales (exercise the power-of-two scaling)
    else if (r < 0.1) F *= Real(1e25);
    check_one<dim>(F, "random kind " + std::to_string(kind) + " #" + std::to_string(k), st);
    if (::testing::Test::HasFailure()) return;  // one report is enough
  }
  // The inverted cases must show up as negative last singular values (not all: near-singular ones may
  // legitimately round either way, and a rank-deficient F has det 0).
  EXPECT_GT(st.n_negative, n_inverted / 2);
  std::printf("svd<%d>: %d matrices; worst errors / eps: reconstruction %.1f, orthogonality %.1f, det %.1f, "
              "singular values %.1f (bound %.0f)\n",
              dim, st.n, st.recon, st.orth, st.det, st.sv, kC);
}

template <int dim>
std::vector<Mat<dim>> special_matrices() {
  std::vector<Mat<dim>> m;
  const Mat<dim> I = Mat<dim>::Identity();
  m.push_back(Mat<dim>::Zero());
  m.push_back(I);
  m.push_back(-I);
  m.push_back(Real(2) * I);
  for (int i = 0; i < dim; ++i) {
    Mat<dim> R = I;
    R(i, i) = -1;  // reflection
    m.push_back(R);
    Mat<dim> Z = I;
    Z(i, i) = 0;  // rank dim - 1
    m.push_back(Z);
    Mat<dim> E = Mat<dim>::Zero();
    E(i, (i + 1) % dim) = Real(3);  // rank 1, off-diagonal
    m.push_back(E);
  }
  // Permutations (even and odd).
  Mat<dim> P = Mat<dim>::Zero();
  for (int i = 0; i < dim; ++i) P(i, (i + 1) % dim) = 1;
  m.push_back(P);
  Mat<dim> T = I;
  T.row(0).swap(T.row(1));
  m.push_back(T);
  m.push_back(Mat<dim>(Vec<dim>::Ones() * Vec<dim>::Ones().transpose()));  // rank 1, repeated zeros
  Mat<dim> Sh = I;
  Sh(0, dim - 1) = 1;  // simple shear
  m.push_back(Sh);
  Mat<dim> D = I;
  for (int i = 0; i < dim; ++i) D(i, i) = Real(i + 1);  // unsorted diagonal
  m.push_back(D);
  m.push_back(Mat<dim>(-D));
  m.push_back(Mat<dim>(Real(1e-30) * D));
  m.push_back(Mat<dim>(Real(1e30) * D));
  if constexpr (dim == 2) {
    Mat<dim> A;
    A << 1, 0, 0, -1;  // symmetric traceless: the polar angle is undefined
    m.push_back(A);
    A << 0, 1, 1, 0;
    m.push_back(A);
    // Nearly symmetric traceless: (F00 + F11, F10 - F01) = (0, -4e-21), whose squared norm is subnormal in
    // float; the polar angle must still come out as a unit vector.
    A << 1, Real(3e-21), Real(-1e-21), -1;
    m.push_back(A);
    A << Real(1e-20), 1, 1, Real(-2e-20);
    m.push_back(A);
  }
  return m;
}

template <int dim>
void run_special() {
  Stats<dim> st;
  int k = 0;
  for (const Mat<dim>& F : special_matrices<dim>()) check_one<dim>(F, "special #" + std::to_string(k++), st);
  // Exact results where they are determined: F = I and F = 0.
  Mat<dim> U, V;
  Vec<dim> s;
  svd<dim>(Mat<dim>::Identity(), U, s, V);
  EXPECT_EQ((U * s.asDiagonal() * V.transpose() - Mat<dim>::Identity()).norm(), Real(0));
  svd<dim>(Mat<dim>::Zero(), U, s, V);
  EXPECT_EQ(s.norm(), Real(0));
  // A reflection has singular values (1, ..., 1, -1).
  Mat<dim> R = Mat<dim>::Identity();
  R(0, 0) = -1;
  svd<dim>(R, U, s, V);
  for (int i = 0; i + 1 < dim; ++i) EXPECT_NEAR(s(i), 1, kC * kEps);
  EXPECT_NEAR(s(dim - 1), -1, kC * kEps);
}

}  // namespace

TEST(Svd, RandomMatrices2D) { run_random<2>(10000, 1); }
TEST(Svd, RandomMatrices3D) { run_random<3>(10000, 2); }
TEST(Svd, SpecialMatrices2D) { run_special<2>(); }
TEST(Svd, SpecialMatrices3D) { run_special<3>(); }
