// Tests of the ice constitutive model: split Neo-Hookean elasticity (material/neo_hookean_split.h) and the
// cohesive Cam-Clay return mapping (material/cohesive_cam_clay.h), in 2D and 3D, for lab-scale (E = 1e6 Pa)
// and glacier-scale (E = 9e9 Pa) parameters.
//
// Tolerances (double precision, unit roundoff u ~ 1.1e-16):
//  * central finite differences of psi with step h: truncation O(h^2 |P'''|) and roundoff
//    O(u psi / h); with h = 1e-5 and stretches O(1) both are <= ~1e-9 relative to |P|, so 1e-6 is safe.
//  * objectivity / principal-axes consistency: pure roundoff, O(10 u) relative -> 1e-12.
//  * return mapping: stresses are recomputed from the new F by an independent path (full-matrix tau);
//    their roundoff is O(u kappa), i.e. O(u kappa / p0) <= 1e-11 relative to p0 for p0 >= 1e-4 kappa,
//    so the specification's 1e-8 holds with margin.
#include <gtest/gtest.h>

#include <Eigen/QR>
#include <Eigen/SVD>
#include <cmath>
#include <limits>
#include <random>
#include <type_traits>
#include <vector>

#include "material/cohesive_cam_clay.h"
#include "material/neo_hookean_split.h"

using namespace cdmpm;

namespace {

constexpr bool kDouble = std::is_same_v<Real, double>;
#define SKIP_IF_FLOAT() \
  if constexpr (!kDouble) GTEST_SKIP() << "tolerances require double precision"

struct Scale {
  const char* name;
  Real E, nu;
};
const Scale kScales[] = {{"lab", Real(1e6), Real(0.3)}, {"glacier", Real(9e9), Real(0.3)}};

template <int dim>
Mat<dim> random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> n(0, 1);
  Mat<dim> A;
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) A(i, j) = Real(n(rng));
  Mat<dim> Q = Eigen::HouseholderQR<Mat<dim>>(A).householderQ();
  if (Q.determinant() < 0) Q.col(0) *= Real(-1);
  return Q;
}

// F = R1 diag(exp(strain_i)) R2 with strain_i uniform in [-scale, scale].
template <int dim>
Mat<dim> random_F(std::mt19937& rng, Real scale) {
  std::uniform_real_distribution<double> u(-1, 1);
  Vec<dim> s;
  for (int i = 0; i < dim; ++i) s(i) = std::exp(scale * Real(u(rng)));
  return random_rotation<dim>(rng) * s.asDiagonal() * random_rotation<dim>(rng);
}

template <int dim>
void check_energy_derivative() {
  std::mt19937 rng(12345 + dim);
  for (const Scale& sc : kScales) {
    const NeoHookeanSplit e = NeoHookeanSplit::from_young_poisson(sc.E, sc.nu);
    for (int trial = 0; trial < 50; ++trial) {
      const Mat<dim> F = random_F<dim>(rng, Real(0.3));
      const Real h = Real(1e-5);
      Mat<dim> P_fd;
      for (int i = 0; i < dim; ++i)
        for (int j = 0; j < dim; ++j) {
          Mat<dim> Fp = F, Fm = F;
          Fp(i, j) += h;
          Fm(i, j) -= h;
          P_fd(i, j) = (e.energy_density<dim>(Fp) - e.energy_density<dim>(Fm)) / (Real(2) * h);
        }
      const Mat<dim> tau = e.kirchhoff<dim>(F);
      const Mat<dim> tau_fd = P_fd * F.transpose();
      EXPECT_LT((tau - tau_fd).norm(), Real(1e-6) * tau.norm()) << sc.name << " dim " << dim;
      EXPECT_LT((e.first_piola<dim>(F) - P_fd).norm(), Real(1e-6) * P_fd.norm()) << sc.name;
    }
  }
}

template <int dim>
void check_zero_stress_and_objectivity() {
  std::mt19937 rng(777 + dim);
  for (const Scale& sc : kScales) {
    const NeoHookeanSplit e = NeoHookeanSplit::from_young_poisson(sc.E, sc.nu);
    EXPECT_EQ(e.kirchhoff<dim>(Mat<dim>::Identity()).norm(), Real(0));
    EXPECT_EQ(e.energy_density<dim>(Mat<dim>::Identity()), Real(0));
    for (int trial = 0; trial < 50; ++trial) {
      const Mat<dim> F = random_F<dim>(rng, Real(0.5));
      const Mat<dim> R = random_rotation<dim>(rng);
      const Mat<dim> tau = e.kirchhoff<dim>(F);
      const Mat<dim> tau_rot = e.kirchhoff<dim>(Mat<dim>(R * F));
      EXPECT_LT((tau_rot - R * tau * R.transpose()).norm(), Real(1e-12) * tau.norm()) << sc.name;
      // A rotation applied on the right (reference frame) changes nothing.
      const Mat<dim> tau_right = e.kirchhoff<dim>(Mat<dim>(F * R));
      EXPECT_LT((tau_right - tau).norm(), Real(1e-12) * tau.norm()) << sc.name;
      // Principal-axes formula agrees with the full-matrix one.
      Eigen::JacobiSVD<Mat<dim>> svd(F, Eigen::ComputeFullU | Eigen::ComputeFullV);
      const Vec<dim> tp = e.kirchhoff_from_singular_values<dim>(svd.singularValues());
      const Mat<dim> U = svd.matrixU();
      EXPECT_LT((U * tp.asDiagonal() * U.transpose() - tau).norm(), Real(1e-12) * tau.norm()) << sc.name;
    }
  }
}

// Small-strain limit of the d-dimensional energy: 2 mu dev(eps) + kappa tr(eps) I with kappa the bulk modulus
// lambda + 2/3 mu: linear elasticity in 3D (tau -> lambda tr(eps) I + 2 mu eps, lambda = E nu / ((1 + nu)(1 - 2 nu))),
// and the reference 2D convention's law in 2D (plane strain, the 3D energy at diag(F, Fz), is tested in
// test_plane_strain.cpp). Error O(h) relative.
template <int dim>
void check_linearisation() {
  std::mt19937 rng(99 + dim);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const Scale& sc : kScales) {
    const NeoHookeanSplit e = NeoHookeanSplit::from_young_poisson(sc.E, sc.nu);
    const Real lambda = sc.E * sc.nu / ((1 + sc.nu) * (1 - 2 * sc.nu));
    EXPECT_NEAR(e.mu, sc.E / (2 * (1 + sc.nu)), 1e-12 * sc.E);
    EXPECT_NEAR(e.kappa, lambda + 2 * e.mu / 3, 1e-12 * sc.E);
    EXPECT_NEAR(e.p_wave_modulus<dim>(), e.kappa + 2 * e.mu * (1 - Real(1) / dim), 1e-12 * sc.E);
    const Real h = Real(1e-7);
    Mat<dim> G;
    for (int i = 0; i < dim; ++i)
      for (int j = 0; j < dim; ++j) G(i, j) = Real(u(rng));
    const Mat<dim> eps = Real(0.5) * (G + G.transpose());
    const Mat<dim> tau = e.kirchhoff<dim>(Mat<dim>(Mat<dim>::Identity() + h * G)) / h;
    const Mat<dim> hooke = e.kappa * eps.trace() * Mat<dim>::Identity() +
                           2 * e.mu * (eps - eps.trace() / dim * Mat<dim>::Identity());
    EXPECT_LT((tau - hooke).norm(), Real(1e-5) * hooke.norm()) << sc.name << " dim " << dim;
  }
}

template <int dim>
struct Invariants {
  Real p, q;
};
template <int dim>
Invariants<dim> invariants(const NeoHookeanSplit& e, const Mat<dim>& F) {
  const Mat<dim> tau = e.kirchhoff<dim>(F);
  return {CohesiveCamClay::pressure<dim>(tau), CohesiveCamClay{}.mises<dim>(tau)};
}

bool all_finite(const auto& A) { return A.array().isFinite().all(); }

template <int dim>
void check_return_mapping() {
  std::mt19937 rng(2024 + dim);
  const Real p0_ratios[] = {Real(1e-2), Real(1e-3), CohesiveCamClay{}.p0_floor};
  const Real strain_scales[] = {0.1, 0.3, 1, 3, 10, 30};
  for (const Scale& sc : kScales) {
    const NeoHookeanSplit e = NeoHookeanSplit::from_young_poisson(sc.E, sc.nu);
    for (bool hard : {false, true}) {
      CohesiveCamClay cc;
      cc.M = Real(1.85);
      cc.beta = Real(0.3);
      cc.xi = Real(3);
      cc.hardening = hard;
      for (Real ratio : p0_ratios) {
        const Real p0 = ratio * e.kappa;
        const Real alpha0 = cc.alpha_of_p0(p0, e.kappa);
        EXPECT_NEAR(cc.p0_of_alpha(alpha0, e.kappa), p0, 1e-12 * p0);
        int n_elastic = 0, n_q = 0, n_tip_c = 0, n_tip_t = 0;
        for (Real ss : strain_scales) {
          for (int trial = 0; trial < 200; ++trial) {
            // Volumetric strain up to ss * p0/kappa, deviatoric up to ss * p0/mu.
            Mat<dim> F = random_F<dim>(rng, ss * p0 / e.mu);
            const Real vol = ss * p0 / e.kappa * Real(std::uniform_real_distribution<double>(-1, 1)(rng));
            F *= std::exp(vol / dim);
            const Mat<dim> F_trial = F;
            const auto [p_tr, q_tr] = invariants<dim>(e, F_trial);
            const Real y_tr = cc.yield(p_tr, q_tr, p0);
            Real alpha = alpha0;
            const bool plastic = cc.return_mapping<dim>(F, alpha, p0, e);
            const Real scale_y = cc.M * cc.M * p0 * p0;
            ASSERT_TRUE(all_finite(F));
            if (y_tr < -Real(1e-10) * scale_y) {  // clearly elastic (margin against classification roundoff)
              ++n_elastic;
              EXPECT_FALSE(plastic);
              for (int i = 0; i < dim; ++i)
                for (int j = 0; j < dim; ++j) EXPECT_EQ(F(i, j), F_trial(i, j));  // bitwise
              EXPECT_EQ(alpha, alpha0);
              continue;
            }
            if (y_tr <= Real(1e-10) * scale_y) continue;  // on the surface: either outcome is right
            EXPECT_TRUE(plastic);
            const auto [p, q] = invariants<dim>(e, F);
            EXPECT_LT(std::abs(cc.yield(p, q, p0)), Real(1e-8) * scale_y)
                << sc.name << " p0/kappa " << ratio << " p_tr/p0 " << p_tr / p0 << " q_tr/p0 " << q_tr / p0;
            if (p_tr > p0) {
              ++n_tip_c;
              EXPECT_LT(q, Real(1e-8) * p0);
              EXPECT_NEAR(p, p0, Real(1e-8) * p0);
              if (hard) { EXPECT_LT(alpha, alpha0); }  // compression hardens
            } else if (p_tr < -cc.beta * p0) {
              ++n_tip_t;
              EXPECT_LT(q, Real(1e-8) * p0);
              EXPECT_NEAR(p, -cc.beta * p0, Real(1e-8) * p0);
              if (hard) { EXPECT_GT(alpha, alpha0); }  // tension softens
            } else {
              ++n_q;
              EXPECT_NEAR(p, p_tr, Real(1e-8) * p0);
              EXPECT_LT(q, q_tr);
              // Only the deviatoric stretch changed: det F is kept and the principal axes are kept.
              EXPECT_NEAR(F.determinant(), F_trial.determinant(), Real(1e-12) * F_trial.determinant());
              const Mat<dim> tau_tr = e.kirchhoff<dim>(F_trial), tau = e.kirchhoff<dim>(F);
              EXPECT_LT((tau * tau_tr - tau_tr * tau).norm(), Real(1e-10) * tau.norm() * tau_tr.norm());
              const Real p_c = (1 - cc.beta) * p0 / 2;
              if (hard && std::abs(p_tr - p_c) > Real(1e-6) * p0) {
                if (p_tr > p_c) { EXPECT_LT(alpha, alpha0); }
                else { EXPECT_GT(alpha, alpha0); }
              }
            }
            if (!hard) { EXPECT_EQ(alpha, alpha0); }
            const Real p0_new = cc.p0_of_alpha(alpha, e.kappa);
            const Real D = CohesiveCamClay::damage(p0_new, p0);
            EXPECT_GE(D, 0);
            EXPECT_LE(D, 1);
            // Idempotence: a projected state is (up to roundoff) on the surface; projecting again with the
            // same p0 moves F by at most roundoff.
            Mat<dim> F2 = F;
            Real a2 = alpha;
            cc.return_mapping<dim>(F2, a2, p0, e);
            EXPECT_LT((F2 - F).norm(), Real(1e-10) * F.norm());
          }
        }
        EXPECT_GT(n_elastic, 0) << sc.name << " dim " << dim;
        EXPECT_GT(n_q, 0) << sc.name << " dim " << dim;
        EXPECT_GT(n_tip_t, 0) << sc.name << " dim " << dim;
        if (ratio < Real(0.5)) { EXPECT_GT(n_tip_c, 0) << sc.name << " dim " << dim; }
      }
    }
  }
}

template <int dim>
void check_degenerate() {
  std::mt19937 rng(31 + dim);
  for (const Scale& sc : kScales) {
    const NeoHookeanSplit e = NeoHookeanSplit::from_young_poisson(sc.E, sc.nu);
    CohesiveCamClay cc;
    const Real p0 = Real(1e-3) * e.kappa;
    std::vector<Mat<dim>> cases;
    Mat<dim> refl = Mat<dim>::Identity();
    refl(0, 0) = -1;
    cases.push_back(refl);                                               // inverted, det = -1
    cases.push_back(Mat<dim>(random_F<dim>(rng, Real(0.2)) * refl));   // inverted, generic
    Mat<dim> flat = Mat<dim>::Identity();
    flat(dim - 1, dim - 1) = 0;
    cases.push_back(flat);                                               // zero singular value
    cases.push_back(Mat<dim>::Zero());                                   // all zero
    Mat<dim> rank1 = Vec<dim>::Ones() * Vec<dim>::Ones().transpose();
    cases.push_back(rank1);
    for (Mat<dim> F : cases) {
      for (bool hard : {false, true}) {
        cc.hardening = hard;
        Mat<dim> G = F;
        Real alpha = cc.alpha_of_p0(p0, e.kappa);
        EXPECT_TRUE(cc.return_mapping<dim>(G, alpha, p0, e));
        EXPECT_TRUE(all_finite(G));
        EXPECT_GT(G.determinant(), 0);
        EXPECT_TRUE(std::isfinite(alpha));
        EXPECT_TRUE(all_finite(e.kirchhoff<dim>(G)));
        const Real D = CohesiveCamClay::damage(cc.p0_of_alpha(alpha, e.kappa), p0);
        EXPECT_TRUE(D >= 0 && D <= 1);
        const auto [p, q] = invariants<dim>(e, G);
        EXPECT_LT(std::abs(cc.yield(p, q, p0)), Real(1e-8) * cc.M * cc.M * p0 * p0);
      }
    }
  }
}

template <int dim>
void check_uniaxial() {
  for (const Scale& sc : kScales) {
    const NeoHookeanSplit e = NeoHookeanSplit::from_young_poisson(sc.E, sc.nu);
    CohesiveCamClay cc;
    for (Real beta : {Real(0), Real(0.1), Real(0.3), Real(0.9)}) {
      cc.beta = beta;
      const Real p0 = Real(1e-3) * e.kappa;
      const Real st = cc.uniaxial_strength<dim>(p0, true), sc_ = cc.uniaxial_strength<dim>(p0, false);
      for (auto [s, sign] : {std::pair{st, Real(1)}, std::pair{sc_, Real(-1)}}) {
        Vec<dim> tau = Vec<dim>::Zero();
        tau(0) = sign * s;
        const Real p = CohesiveCamClay::pressure<dim>(tau), q = CohesiveCamClay{}.mises<dim>(tau);
        EXPECT_NEAR(p, -sign * s / dim, 1e-14 * s);
        if (dim == 3) { EXPECT_NEAR(q, s, 1e-14 * s); }
        EXPECT_LT(std::abs(cc.yield(p, q, p0)), Real(1e-12) * cc.M * cc.M * p0 * p0);
      }
      if (beta == 0) {
        EXPECT_EQ(st, 0);  // no cohesion, no tensile strength
      } else {
        EXPECT_GT(st, 0);
      }
      EXPECT_LT(st, sc_) << "beta " << beta;
      EXPECT_LT(st, sc_);
    }
  }
}

}  // namespace

// The return mapping decides most elastic states before the SVD (CohesiveCamClay::trial_is_elastic, from J and
// b = F F^T without a root). It must agree with the yield function evaluated on the stress: a clearly elastic
// state is cleared, a clearly plastic one is not (a false "elastic" would skip a projection). "Clearly": |y|
// beyond the round-off of y computed two ways, O(u kappa^2 / (M p0)^2 * |strain|) relative to (M p0)^2: 1e-8
// in double; in single precision 5 %, the relative round-off of dev(b) at the smallest strains here
// (b - tr(b)/d I loses the digits of strains of 1e-5 against 1).
template <int dim>
void check_elastic_precheck() {
  std::mt19937 rng(77 + dim);
  const Real margin = kDouble ? Real(1e-8) : Real(5e-2);
  for (const Scale& sc : kScales) {
    const NeoHookeanSplit e = NeoHookeanSplit::from_young_poisson(sc.E, sc.nu);
    CohesiveCamClay cc;
    // p0 = 0.3 kappa: strong enough for elastic states with J down to 0.63, where q's factor J^(-4/d) counts.
    for (Real ratio : {Real(0.3), Real(1e-2), Real(1e-3)}) {
      const Real p0 = ratio * e.kappa, scale_y = cc.M * cc.M * p0 * p0;
      int cleared = 0, plastic = 0;
      for (Real ss : {Real(0.1), Real(0.5), Real(1), Real(2), Real(10)}) {
        for (int trial = 0; trial < 400; ++trial) {
          Mat<dim> F = random_F<dim>(rng, ss * p0 / e.mu);
          F *= std::exp(ss * p0 / e.kappa * Real(std::uniform_real_distribution<double>(-1, 1)(rng)) / dim);
          const auto [p, q] = invariants<dim>(e, F);
          const Real y = cc.yield(p, q, p0);
          const bool fast = cc.trial_is_elastic<dim>(F, p0, e);
          if (y < -margin * scale_y) {
            EXPECT_TRUE(fast) << sc.name << " y/scale " << y / scale_y;
            cleared += fast;
          } else if (y > margin * scale_y) {
            EXPECT_FALSE(fast) << sc.name << " y/scale " << y / scale_y;
            ++plastic;
          }
        }
      }
      EXPECT_GT(cleared, 100);  // both outcomes were exercised
      EXPECT_GT(plastic, 100);
    }
  }
  // Inverted and nearly degenerate F are never cleared: they need the SVD's clamp.
  const NeoHookeanSplit e = NeoHookeanSplit::from_young_poisson(Real(9e9), Real(0.3));
  CohesiveCamClay cc;
  Mat<dim> inverted = Mat<dim>::Identity();
  inverted(0, 0) = -1;
  EXPECT_FALSE(cc.trial_is_elastic<dim>(inverted, e.kappa, e));
  Mat<dim> thin = Mat<dim>::Identity();
  thin(0, 0) = Real(1e-7);
  EXPECT_FALSE(cc.trial_is_elastic<dim>(thin, Real(1e3) * e.kappa, e));
}

TEST(IceConstitutive, ElasticPrecheckAgreesWithYieldFunction2D) { check_elastic_precheck<2>(); }
TEST(IceConstitutive, ElasticPrecheckAgreesWithYieldFunction3D) { check_elastic_precheck<3>(); }

TEST(IceConstitutive, KirchhoffIsEnergyDerivative2D) { SKIP_IF_FLOAT(); check_energy_derivative<2>(); }
TEST(IceConstitutive, KirchhoffIsEnergyDerivative3D) { SKIP_IF_FLOAT(); check_energy_derivative<3>(); }
TEST(IceConstitutive, ZeroStressAndObjectivity2D) { SKIP_IF_FLOAT(); check_zero_stress_and_objectivity<2>(); }
TEST(IceConstitutive, ZeroStressAndObjectivity3D) { SKIP_IF_FLOAT(); check_zero_stress_and_objectivity<3>(); }
TEST(IceConstitutive, SmallStrainLimitIsLinearElasticity2D) { SKIP_IF_FLOAT(); check_linearisation<2>(); }
TEST(IceConstitutive, SmallStrainLimitIsLinearElasticity3D) { SKIP_IF_FLOAT(); check_linearisation<3>(); }
TEST(IceConstitutive, ReturnMapping2D) { SKIP_IF_FLOAT(); check_return_mapping<2>(); }
TEST(IceConstitutive, ReturnMapping3D) { SKIP_IF_FLOAT(); check_return_mapping<3>(); }
TEST(IceConstitutive, DegenerateAndInvertedF2D) { SKIP_IF_FLOAT(); check_degenerate<2>(); }
TEST(IceConstitutive, DegenerateAndInvertedF3D) { SKIP_IF_FLOAT(); check_degenerate<3>(); }
TEST(IceConstitutive, UniaxialTensionWeakerThanCompression2D) { SKIP_IF_FLOAT(); check_uniaxial<2>(); }
TEST(IceConstitutive, UniaxialTensionWeakerThanCompression3D) { SKIP_IF_FLOAT(); check_uniaxial<3>(); }

TEST(IceConstitutive, SofteningSignConvention) {
  CohesiveCamClay cc;
  const Real kappa = Real(7.5e9), p0i = Real(1e-3) * kappa;
  const Real a0 = cc.alpha_of_p0(p0i, kappa);
  EXPECT_LT(a0, 0);
  EXPECT_LT(cc.p0_of_alpha(a0 + Real(0.01), kappa), p0i);  // alpha up (tension) -> weaker
  EXPECT_GT(cc.p0_of_alpha(a0 - Real(0.01), kappa), p0i);  // alpha down (compression) -> stronger
  EXPECT_EQ(cc.p0_of_alpha(Real(1), kappa), CohesiveCamClay{}.p0_floor * kappa);
  EXPECT_EQ(CohesiveCamClay::damage(p0i, p0i), 0);
  EXPECT_EQ(CohesiveCamClay::damage(2 * p0i, p0i), 0);
  EXPECT_EQ(CohesiveCamClay::damage(0, p0i), 1);
  EXPECT_NEAR(CohesiveCamClay::damage(Real(0.25) * p0i, p0i), 0.75, 1e-15);
}

// ---- Hardening rule (q-branch driven by the deviatoric plastic strain; see cohesive_cam_clay.h) ----------
//
// A diagonal elastic F is driven through repeated isochoric shear increments (+dg on axis 0, -dg on axis 1)
// with J reset every step so that the trial pressure is p = ratio * p0 for the CURRENT p0 = p0(alpha):
// ratio = -0.1 lies on the tensile side of the centre (p_c / p0 = (1 - beta) / 2 = 0.35) and inside
// (-beta p0, p0), ratio = 0.8 on the compressive side; both are in the q-branch. The SVD of a diagonal matrix
// is a signed permutation, so F stays diagonal and its diagonal holds the principal stretches of each axis.
// Per step: elastic -> alpha bitwise unchanged; plastic -> alpha changes by exactly
// +-sqrt(2/3) |ln diag(F_trial) - ln diag(F_new)| (+ tensile side, - compressive side).
// Tolerance of that identity: each log of a stretch ratio carries a few eps of absolute roundoff (stretches
// O(1)), the norm adds ~eps relative and alpha + delta rounds at eps |alpha| (|alpha| < 1): 64 eps absolute,
// against typical increments sqrt(2/3) sqrt(2) dg ~ 2.3e-4 (tolerance / increment ~ 3e-2 in float, 6e-11 in
// double).
namespace {

template <int dim>
struct PathOutcome {
  Real p0_final = 0, alpha_initial = 0, alpha_final = 0;
  int n_elastic = 0, n_plastic = 0;
};

template <int dim>
PathOutcome<dim> drive_shear_path(const CohesiveCamClay& cc, const NeoHookeanSplit& e, Real p0_initial,
                                  Real ratio, int steps) {
  constexpr Real eps = std::numeric_limits<Real>::epsilon();
  const Real tol = 64 * eps;
  const Real dg = Real(2e-4);
  const bool tensile = ratio * p0_initial < (1 - cc.beta) * p0_initial / 2;
  Real alpha = cc.alpha_of_p0(p0_initial, e.kappa);
  Real p0 = cc.p0_of_alpha(alpha, e.kappa);  // = p0_initial up to roundoff; the path compares p0(alpha) only
  Vec<dim> log_s = Vec<dim>::Zero();  // elastic log stretches, axis by axis
  PathOutcome<dim> out;
  out.alpha_initial = alpha;
  for (int step = 0; step < steps; ++step) {
    Vec<dim> ls = log_s;
    ls(0) += dg;
    ls(1) -= dg;
    ls.array() += std::log(e.J_of_pressure(ratio * p0)) / Real(dim) - ls.mean();  // prescribe J
    Mat<dim> F = Mat<dim>(ls.array().exp().matrix().asDiagonal());
    const Mat<dim> F_trial = F;
    const Real alpha_old = alpha;
    const bool plastic = cc.return_mapping<dim>(F, alpha, p0, e);
    EXPECT_LE((F - Mat<dim>(F.diagonal().asDiagonal())).norm(), tol) << "F must stay diagonal";
    if (!plastic) {
      ++out.n_elastic;
      EXPECT_EQ(alpha, alpha_old) << "step " << step;  // bitwise
    } else {
      ++out.n_plastic;
      const Vec<dim> dlog = (F_trial.diagonal().array() / F.diagonal().array()).log().matrix();
      EXPECT_LT(std::abs(dlog.sum()), tol) << "q-branch plastic strain must be deviatoric";
      const Real delta = std::sqrt(Real(2) / Real(3)) * dlog.norm();
      EXPECT_GT(delta, 0);
      if (cc.hardening) {
        EXPECT_NEAR(alpha - alpha_old, tensile ? delta : -delta, tol) << "step " << step;
      } else {
        EXPECT_EQ(alpha, alpha_old);
      }
    }
    const Real p0_new = cc.p0_of_alpha(alpha, e.kappa);
    if (tensile) {
      EXPECT_LE(p0_new, p0) << "step " << step;  // monotone softening
      if (plastic && cc.hardening && alpha_old < 0) { EXPECT_LT(p0_new, p0) << "step " << step; }
    } else {
      EXPECT_GE(p0_new, p0) << "step " << step;  // monotone hardening
      if (plastic && cc.hardening) { EXPECT_GT(p0_new, p0) << "step " << step; }
    }
    log_s = F.diagonal().array().log().matrix();
    p0 = p0_new;
  }
  out.p0_final = p0;
  out.alpha_final = alpha;
  return out;
}

template <int dim>
void check_tensile_softening() {
  const NeoHookeanSplit e = NeoHookeanSplit::from_young_poisson(Real(9e9), Real(0.3));
  CohesiveCamClay cc;
  const Real p0_initial = Real(1e-2) * e.kappa;
  const auto out = drive_shear_path<dim>(cc, e, p0_initial, Real(-0.1), 400);
  EXPECT_GT(out.n_elastic, 0);
  EXPECT_GT(out.n_plastic, 10);
  // p0(alpha) = kappa (eps + sinh(xi max(-alpha, 0))) is exactly kappa eps once alpha >= 0.
  EXPECT_GE(out.alpha_final, 0);
  EXPECT_EQ(out.p0_final, cc.p0_of_alpha(Real(0), e.kappa));
  EXPECT_NEAR(out.p0_final, CohesiveCamClay{}.p0_floor * e.kappa, 4 * std::numeric_limits<Real>::epsilon() * out.p0_final);
  // Damage reaches its maximum 1 - kappa eps / p0_initial = 1 - 1e-4 / 1e-2 = 0.99 (near-zero cohesion).
  EXPECT_NEAR(CohesiveCamClay::damage(out.p0_final, p0_initial), Real(1) - CohesiveCamClay{}.p0_floor / Real(1e-2),
              8 * std::numeric_limits<Real>::epsilon());
}

template <int dim>
void check_compressive_hardening() {
  const NeoHookeanSplit e = NeoHookeanSplit::from_young_poisson(Real(9e9), Real(0.3));
  CohesiveCamClay cc;
  const Real p0_initial = Real(1e-2) * e.kappa;
  const auto out = drive_shear_path<dim>(cc, e, p0_initial, Real(0.8), 200);
  EXPECT_GT(out.n_elastic, 0);
  EXPECT_GT(out.n_plastic, 0);
  EXPECT_GT(out.p0_final, p0_initial);
  EXPECT_LT(out.alpha_final, out.alpha_initial);
}

template <int dim>
void check_no_hardening_leaves_alpha() {
  const NeoHookeanSplit e = NeoHookeanSplit::from_young_poisson(Real(9e9), Real(0.3));
  CohesiveCamClay cc;
  cc.hardening = false;
  const Real p0 = Real(1e-2) * e.kappa;
  for (Real ratio : {Real(-0.1), Real(0.8)}) {
    const auto out = drive_shear_path<dim>(cc, e, p0, ratio, 100);  // checks alpha bitwise every step
    EXPECT_GT(out.n_plastic, 0);
    // Bitwise against the path's own start value (a separately evaluated alpha_of_p0 / p0_of_alpha may be
    // constant-folded by the compiler and differ from the run-time libm result in the last bit).
    EXPECT_EQ(out.alpha_final, out.alpha_initial);
  }
  // Tips: hydrostatic trial states beyond p0 and beyond -beta p0.
  for (Real p_trial : {Real(1.5) * p0, Real(-0.6) * p0}) {
    Mat<dim> F = std::pow(e.J_of_pressure(p_trial), Real(1) / Real(dim)) * Mat<dim>::Identity();
    const Real alpha0 = cc.alpha_of_p0(p0, e.kappa);
    Real alpha = alpha0;
    EXPECT_TRUE(cc.return_mapping<dim>(F, alpha, p0, e));
    EXPECT_EQ(alpha, alpha0);
  }
}

// Tip branches keep the volumetric rule alpha += ln(J_trial / J_new) (roundoff of two determinants and a log:
// 64 eps absolute, against increments >= 1e-3).
template <int dim>
void check_tip_rule() {
  const NeoHookeanSplit e = NeoHookeanSplit::from_young_poisson(Real(9e9), Real(0.3));
  CohesiveCamClay cc;
  const Real p0 = Real(1e-2) * e.kappa;
  for (Real p_trial : {Real(1.5) * p0, Real(-0.6) * p0}) {
    Mat<dim> F = std::pow(e.J_of_pressure(p_trial), Real(1) / Real(dim)) * Mat<dim>::Identity();
    const Real J_trial = F.determinant();
    const Real alpha0 = cc.alpha_of_p0(p0, e.kappa);
    Real alpha = alpha0;
    EXPECT_TRUE(cc.return_mapping<dim>(F, alpha, p0, e));
    const Real expected = std::log(J_trial / F.determinant());
    EXPECT_NEAR(alpha - alpha0, expected, 64 * std::numeric_limits<Real>::epsilon());
    if (p_trial > 0) { EXPECT_LT(alpha, alpha0); } else { EXPECT_GT(alpha, alpha0); }
  }
}

}  // namespace

TEST(IceConstitutive, TensileShearSoftensToFloor2D) { check_tensile_softening<2>(); }
TEST(IceConstitutive, TensileShearSoftensToFloor3D) { check_tensile_softening<3>(); }
TEST(IceConstitutive, CompressiveShearHardens2D) { check_compressive_hardening<2>(); }
TEST(IceConstitutive, CompressiveShearHardens3D) { check_compressive_hardening<3>(); }
TEST(IceConstitutive, NoHardeningLeavesAlpha2D) { check_no_hardening_leaves_alpha<2>(); }
TEST(IceConstitutive, NoHardeningLeavesAlpha3D) { check_no_hardening_leaves_alpha<3>(); }
TEST(IceConstitutive, TipsKeepVolumetricRule2D) { check_tip_rule<2>(); }
TEST(IceConstitutive, TipsKeepVolumetricRule3D) { check_tip_rule<3>(); }
