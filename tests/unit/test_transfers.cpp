// test_transfers.cpp - APIC particle-to-grid and grid-to-particle transfers (Jiang et al. 2015):
// exact conservation of mass, linear and angular momentum, and exact transport of affine velocity fields; and
// water's `continuity` "interpolated": tr C_p the divergence of the interpolated velocity (transfer/g2p.h).
#include <gtest/gtest.h>

#include <omp.h>

#include <cstring>
#include <random>

#include <Eigen/Geometry>

#include "grid/grid_update.h"
#include "grid/particle_bins.h"
#include "transfer/g2p.h"
#include "transfer/p2g.h"

namespace cdmpm {
namespace {

template <int dim>
struct TransferSetup {
  Particles<dim> p;
  Grid<dim> g{Vec<dim>::Ones(), Real(1) / 16};
  std::vector<Material> mats{Material{}};
  ParticleBins bins;

  explicit TransferSetup(int n, unsigned seed = 3) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.2, 0.8), s(-1, 1);
    for (int k = 0; k < n; ++k) {
      Vec<dim> x, v;
      for (int a = 0; a < dim; ++a) { x[a] = Real(u(rng)); v[a] = Real(s(rng)); }
      p.add_fluid(x, v, Real(0.5 + 0.5 * u(rng)), Real(1), 0);
      for (int a = 0; a < dim; ++a)
        for (int b = 0; b < dim; ++b) p.C.back()(a, b) = Real(3 * s(rng));
    }
    bins.build(p, g);
  }
  void to_grid() {  // pure APIC transfer (dt = 0: no stress impulse), then momentum -> velocity
    g.activate(bins.blocks);
    p2g(p, mats, bins, g, Real(0));
    grid_update<dim>(g, Vec<dim>::Zero(), Real(0), {});
  }
};

// Angular momentum about the origin, including the APIC affine part m D eps_abc C_cb with D = dx^2/4.
template <int dim>
Eigen::Vector3d particle_angular_momentum(const TransferSetup<dim>& s) {
  Eigen::Vector3d L = Eigen::Vector3d::Zero();
  const double D = s.g.dx * s.g.dx / 4.0;
  for (size_t q = 0; q < s.p.size(); ++q) {
    Eigen::Vector3d x = Eigen::Vector3d::Zero(), v = Eigen::Vector3d::Zero();
    Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
    x.head<dim>() = s.p.x[q].template cast<double>();
    v.head<dim>() = s.p.v[q].template cast<double>();
    C.topLeftCorner<dim, dim>() = s.p.C[q].template cast<double>();
    const double m = s.p.mass[q];
    L += m * x.cross(v);
    L += m * D * Eigen::Vector3d(C(2, 1) - C(1, 2), C(0, 2) - C(2, 0), C(1, 0) - C(0, 1));
  }
  return L;
}

template <int dim>
Eigen::Vector3d grid_angular_momentum(const Grid<dim>& g) {
  Eigen::Vector3d L = Eigen::Vector3d::Zero();
  for (size_t k = 0; k < g.node_count(); ++k) {
    if (g.mass[k] <= 0) continue;
    Eigen::Vector3d x = Eigen::Vector3d::Zero(), v = Eigen::Vector3d::Zero();
    x.head<dim>() = g.position(g.node(k)).template cast<double>();
    v.head<dim>() = g.momentum[k].template cast<double>();  // velocity after grid_update
    L += g.mass[k] * x.cross(v);
  }
  return L;
}

// Relative tolerance: round-off of the floating-point type over a few thousand additions.
const double kTol = std::numeric_limits<Real>::epsilon() * 1e3;

template <int dim>
void check_conservation(const std::vector<uint8_t>& interpolated_divergence = {}) {
  TransferSetup<dim> s(3000);
  double m = 0;
  Vec<dim> P = Vec<dim>::Zero();
  for (size_t q = 0; q < s.p.size(); ++q) { m += s.p.mass[q]; P += s.p.mass[q] * s.p.v[q]; }
  const Eigen::Vector3d L0 = particle_angular_momentum(s);
  s.to_grid();
  double mg = 0;
  Vec<dim> Pg = Vec<dim>::Zero();
  for (size_t k = 0; k < s.g.node_count(); ++k) { mg += s.g.mass[k]; Pg += s.g.mass[k] * s.g.momentum[k]; }
  EXPECT_NEAR(mg, m, kTol * m);
  EXPECT_LT((Pg - P).norm(), kTol * s.p.size());
  const Eigen::Vector3d Lg = grid_angular_momentum(s.g);
  EXPECT_LT((Lg - L0).norm(), kTol * L0.norm() + kTol) << "grid " << Lg.transpose() << " particles " << L0.transpose();
  g2p(s.p, s.g, s.bins, interpolated_divergence);
  const Eigen::Vector3d L1 = particle_angular_momentum(s);
  EXPECT_LT((L1 - L0).norm(), kTol * L0.norm() + kTol) << "after g2p " << L1.transpose() << " before " << L0.transpose();
  Vec<dim> P1 = Vec<dim>::Zero();
  for (size_t q = 0; q < s.p.size(); ++q) P1 += s.p.mass[q] * s.p.v[q];
  EXPECT_LT((P1 - P).norm(), kTol * s.p.size());
}

TEST(Transfers, ConserveMassMomentumAngularMomentum2D) { check_conservation<2>(); }
TEST(Transfers, ConserveMassMomentumAngularMomentum3D) { check_conservation<3>(); }
// The divergence of the interpolated velocity replaces C_p's isotropic part only, which has no skew part.
TEST(Transfers, InterpolatedDivergenceConservesAngularMomentum2D) { check_conservation<2>({1}); }
TEST(Transfers, InterpolatedDivergenceConservesAngularMomentum3D) { check_conservation<3>({1}); }

// Water's `continuity` "interpolated": tr C_p is the divergence of v(x) = sum_i w_i(x) v_i, the velocity that moves
// the particles. For a quadratic field v_i = (a x^2 + b y^2, c x y [, e x z]) at the nodes, the quadratic B-spline
// interpolant is that field plus constants (sum_i w_i x_i^2 = x^2 + dx^2/4, sum_i w_i x_i y_j = x y), so
// div v(x_p) = 2 a x + c x [+ e x] exactly. APIC's own trace differs by O(dx), varying with the particle's place in
// its cell (by 4 a m3 / dx^2, m3 the weights' third central moment along x): the default is checked to differ.
template <int dim>
void check_interpolated_divergence() {
  TransferSetup<dim> s(2000);
  s.to_grid();  // activates the particles' nodes
  const Real a = 0.8, b = -0.6, c = 1.3, e = 0.7;
  auto field = [&](const Vec<dim>& x) {
    Vec<dim> v;
    v[0] = a * x[0] * x[0] + b * x[1] * x[1];
    v[1] = c * x[0] * x[1];
    if constexpr (dim == 3) v[2] = e * x[0] * x[2];
    return v;
  };
  for (size_t k = 0; k < s.g.node_count(); ++k) s.g.momentum[k] = field(s.g.position(s.g.node(k)));
  Particles<dim> apic = s.p;
  g2p(s.p, s.g, s.bins, {1});
  g2p(apic, s.g, s.bins);
  double apic_error = 0;
  for (size_t q = 0; q < s.p.size(); ++q) {
    const Real x = s.p.x[q][0];
    const Real div = 2 * a * x + c * x + (dim == 3 ? e * x : 0);
    EXPECT_NEAR(s.p.C[q].trace(), div, kTol * 4) << "particle " << q;
    // Only the isotropic part changes: C_p's deviatoric part is APIC's.
    const Mat<dim> dev = s.p.C[q] - s.p.C[q].trace() / dim * Mat<dim>::Identity();
    const Mat<dim> dev_apic = apic.C[q] - apic.C[q].trace() / dim * Mat<dim>::Identity();
    EXPECT_LT((dev - dev_apic).norm(), kTol * 16) << "particle " << q;
    EXPECT_EQ(s.p.v[q], apic.v[q]);
    apic_error = std::max(apic_error, std::abs(double(apic.C[q].trace() - div)));
  }
  // APIC's trace misses the divergence by 4 a m3 / dx^2: m3 = -3/64 dx^3 at f = 0.75 (0 at f = 0.5 and 1), so by
  // up to 0.1875 a dx = 0.0094 here; 2000 particles spread over their cells come close to it.
  EXPECT_GT(apic_error, 0.1 * a * s.g.dx);
}

TEST(Transfers, InterpolatedDivergenceIsTheDivergenceOfTheVelocityThatMovesParticles2D) {
  check_interpolated_divergence<2>();
}
TEST(Transfers, InterpolatedDivergenceIsTheDivergenceOfTheVelocityThatMovesParticles3D) {
  check_interpolated_divergence<3>();
}

template <int dim>
void check_affine() {
  TransferSetup<dim> s(2000);
  Mat<dim> A;
  Vec<dim> b;
  for (int i = 0; i < dim; ++i) {
    b[i] = Real(0.3 * (i + 1));
    for (int j = 0; j < dim; ++j) A(i, j) = Real(0.7 * i - 0.4 * j + 0.1 * i * j + 0.25);
  }
  for (size_t q = 0; q < s.p.size(); ++q) {
    s.p.v[q] = A * s.p.x[q] + b;
    s.p.C[q] = A;
  }
  s.to_grid();
  g2p(s.p, s.g, s.bins);
  for (size_t q = 0; q < s.p.size(); ++q) {
    EXPECT_LT((s.p.v[q] - (A * s.p.x[q] + b)).norm(), kTol) << "particle " << q;
    EXPECT_LT((s.p.C[q] - A).norm(), kTol * 16) << "particle " << q;
  }
}

TEST(Transfers, AffineFieldSurvivesRoundTrip2D) { check_affine<2>(); }
TEST(Transfers, AffineFieldSurvivesRoundTrip3D) { check_affine<3>(); }

// The coloured scatter gives the same grid whatever the thread count (bitwise).
TEST(Transfers, ScatterIsDeterministicAcrossThreadCounts) {
  TransferSetup<3> a(5000), b(5000);
  omp_set_num_threads(1);
  a.to_grid();
  omp_set_num_threads(2);
  b.to_grid();
  EXPECT_EQ(0, std::memcmp(a.g.mass.data(), b.g.mass.data(), a.g.mass.size() * sizeof(Real)));
  EXPECT_EQ(0, std::memcmp(a.g.momentum.data(), b.g.momentum.data(), a.g.momentum.size() * sizeof(Vec<3>)));
}

}  // namespace
}  // namespace cdmpm
