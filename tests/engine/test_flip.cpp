// test_flip.cpp - the FLIP share of the velocity update and its XPIC filter (transfer/flip.h), against their
// definitions on fields whose transfers are known in closed form.
//
// On a lattice of 2 x 2 particles per cell (at 1/4 and 3/4 of each cell, equal masses) the round trip S+ S of
// quadratic B-splines acts on a grid mode c_i = cos(theta i_x) as a multiplication by its symbol
//   lambda(theta) = a0 + a1 cos(theta) + a2 cos(2 theta),  a0 = 0.552734375, a1 = 0.4296875, a2 = 0.017578125
// (sums of products of the weights 0.6875, 0.28125, 0.03125 of particles a quarter, three quarters and five
// quarters of a cell from a node; xpic_mode_factor below). For particle velocities V = S c of such a mode
// (C_p = 0), v^n = S+ V = lambda c, so
//   FLIP:     u_p = V_p - (S v^n)_p = (1 - lambda) V_p = A V_p,
//   XPIC(m):  v* = (1 - A^m) c, u_p = (S v*)_p - (S v^n)_p = (A - A^m) V_p,
// with A = 1 - lambda, in the lattice's interior (a transfer reaches 3 nodes, so m transfers reach 3m cells from
// the lattice's edge).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "grid/grid_update.h"
#include "grid/particle_bins.h"
#include "transfer/flip.h"
#include "transfer/p2g.h"

namespace cdmpm {
namespace {

// The quadratic B-spline, N(r) for |r| in cells.
double bspline(double r) {
  r = std::abs(r);
  if (r < 0.5) return 0.75 - r * r;
  if (r < 1.5) return 0.5 * (1.5 - r) * (1.5 - r);
  return 0;
}

// A = 1 - lambda(theta) for the 2-per-cell lattice: lambda = sum over the particles p around node 0 of
// N_0(x_p) sum_j N_j(x_p) cos(theta j), over sum_p N_0(x_p) = 2 (offsets +-1/4, +-3/4, +-5/4 of a cell).
double xpic_mode_factor(double theta) {
  double lambda = 0;
  for (double xp : {-1.25, -0.75, -0.25, 0.25, 0.75, 1.25}) {
    double Sc = 0;
    for (int j = -3; j <= 3; ++j) Sc += bspline(xp - j) * std::cos(theta * j);
    lambda += bspline(xp) * Sc;
  }
  return 1 - lambda / 2;
}

struct FlipSetup {
  static constexpr double dx = 1.0 / 16;
  static constexpr int cells_x = 96, first_cell = 4, last_cell = 92;  // the lattice along x
  Grid<2> g{Vec<2>(Real(cells_x * dx), Real(0.5)), Real(dx)};
  Particles<2> p;
  std::vector<Material> mats;
  ParticleBins bins;
  std::vector<Vec<2>> u;
  XpicScratch<2> scratch;

  // Particles at 1/4 and 3/4 of each cell of x-cells [first_cell, last_cell) and y-cells [2, 6), with
  // velocity v(x) along x and C_p = 0; one water material with flip = 1 and the XPIC order xpic (0: plain FLIP).
  template <class V>
  FlipSetup(int xpic, V&& v) {
    Water w;
    w.flip.a = 1;
    w.flip.xpic = xpic;
    mats.push_back(Material{"water", w});
    for (int i = 2 * first_cell; i < 2 * last_cell; ++i)
      for (int k = 4; k < 12; ++k) {
        const Vec<2> x(Real((i + 0.5) * dx / 2), Real((k + 0.5) * dx / 2));
        p.add_fluid(x, Vec<2>(Real(v(x[0] / dx)), 0), Real(1), Real(1), 0);
      }
    bins.build(p, g);
    g.activate(bins.blocks);
  }
  void transfer() {  // S+ of the particles' velocities (dt = 0: no force), as the step's flip_transfer
    g.clear();
    p2g(p, mats, bins, g, Real(0));
    grid_update<2>(g, Vec<2>::Zero(), Real(0), {});
  }
  // u_p of flip_transfer: FLIP's residual, then XPIC's terms up to the material's order.
  void residual() {
    transfer();
    flip_residual(p, mats, g, bins, u);
    if (const int m = mats[0].xpic(); m > 0) xpic_filter(p, mats, g, bins, m, [&] { transfer(); }, scratch, u);
  }
  bool interior(size_t q) const {  // 40 cells or more from the lattice's ends: beyond the reach of 8 orders
    const double c = p.x[q][0] / dx;
    return c > first_cell + 40 && c < last_cell - 40;
  }
};

// V = S c for the grid mode c_i = cos(pi i_x / 2) (4 cells long): V(x) = sum_j N(x - j) cos(pi j / 2).
double mode_velocity(double x_cells) {
  double v = 0;
  for (int j = static_cast<int>(std::floor(x_cells)) - 2; j <= static_cast<int>(std::floor(x_cells)) + 2; ++j)
    v += bspline(x_cells - j) * std::cos(std::numbers::pi / 2 * j);
  return v;
}

const double kTol = 1e3 * std::numeric_limits<Real>::epsilon();

// Plain FLIP keeps A V_p of a grid-scale mode; XPIC(m) keeps (A - A^m) V_p: PIC at m = 1, FLIP's share of it as
// m grows, to the closed form of the symbol (A = 0.46484375 for the 4-cell mode).
TEST(Flip, XpicKeepsTheModesShareOfTheClosedForm) {
  const double A = xpic_mode_factor(std::numbers::pi / 2);
  ASSERT_NEAR(A, 0.46484375, 1e-15);  // 1 - (a0 - a2), the header's coefficients
  for (int m = 0; m <= 8; ++m) {
    FlipSetup s(m, mode_velocity);
    s.residual();
    const double share = m == 0 ? A : A - std::pow(A, m);
    size_t checked = 0;
    for (size_t q = 0; q < s.p.size(); ++q) {
      if (!s.interior(q)) continue;
      ++checked;
      EXPECT_NEAR(s.u[q][0], share * s.p.v[q][0], kTol) << "xpic " << m << ", particle at x = " << s.p.x[q][0];
      EXPECT_NEAR(s.u[q][1], 0, kTol);
    }
    EXPECT_EQ(checked, 8u * 2 * 8);  // 8 cells of 2 x 8 particles
  }
}

// A velocity the grid cannot hold at all: two particles at each lattice point moving in opposite directions.
// p2g sees no momentum (S^T W V = 0), so FLIP keeps all of V and XPIC none of it, at every order.
TEST(Flip, XpicDropsWhatTheTransferCannotSee) {
  for (int m = 0; m <= 8; m += 2) {
    FlipSetup s(m, [](double) { return 1.0; });
    const size_t n = s.p.size();
    for (size_t q = 0; q < n; ++q) s.p.add_fluid(s.p.x[q], -s.p.v[q], Real(1), Real(1), 0);
    s.bins.build(s.p, s.g);
    s.residual();
    for (size_t q = 0; q < s.p.size(); ++q) {
      const Vec<2> expected = m == 0 ? s.p.v[q] : Vec<2>::Zero();
      EXPECT_LT((s.u[q] - expected).norm(), kTol) << "xpic " << m << ", particle " << q;
    }
  }
}

}  // namespace
}  // namespace cdmpm
