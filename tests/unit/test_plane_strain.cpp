// test_plane_strain.cpp - a 2D ice body is in plane strain (material/ice.h): its elastic state is the 3x3
// F_e = diag(F, Fz), so the same parameters are the same ice in 2D and in 3D.
//   PlaneStrain.StressAndEnergyAreThoseOfThe3DStateWithFzzOne   the 2D particle's Kirchhoff stress is the in-plane
//       block of the 3D model's at diag(F, 1), its energy and pressure the 3D ones, its out-of-plane block zero;
//   PlaneStrain.SmallStrainIsPlaneStrainHooke   tau -> lambda tr(eps) I + 2 mu eps in the plane (Hill 1950, ch. VII);
//   PlaneStrain.ReturnMappingIsThe3DOneWithFzzOne   over random trial states on both sides of the yield surface, at
//       tips and on the q-branch: the 2D return mapping gives the 3D one's in-plane F, its F_zz (the new Fz) and
//       alpha, and the 3D state stays block-diagonal; the yield value after it is <= 0 as in 3D;
//   PlaneStrain.SceneConventions   a 2D scene's ice is in plane strain with the bulk modulus E / (3 (1 - 2 nu)) and the
//       3D uniaxial strength; "convention_2d": "cd_mpm" gives the reference 2D convention (q^2 = 2 |dev tau|^2, its
//       M of a friction angle, floor 1e-5), refused in 3D and for an unknown value;
//   PlaneStrain.CryostaticSeedingIsIsotropicIn3D   a body seeded under lateral stress ratio 1 has no deviatoric stress
//       (tau_xx = tau_yy = tau_zz), which needs Fz = the horizontal stretch.
// Tolerances: the two paths do the same arithmetic in a different order (a closed-form 2x2 SVD against a Jacobi 3x3
// one), so they agree to a few hundred ulps of the stretches: 1e-12 relative in double precision.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <type_traits>

#include "material/ice.h"
#include "material/stress.h"
#include "scene/scene_loader.h"

namespace cdmpm {
namespace {

constexpr bool kPsDouble = std::is_same_v<Real, double>;
constexpr double kPsRel = kPsDouble ? 1e-12 : 2e-5;

nlohmann::json ps_scene(int dim, const nlohmann::json& extra = nlohmann::json::object()) {
  nlohmann::json ice = {{"type", "ice"}, {"density", 917}, {"youngs_modulus", 9e9}, {"poissons_ratio", 0.3},
                        {"friction_angle", 40}, {"beta", 0.3}, {"xi", 5}, {"tensile_strength", 1e6}};
  ice.update(extra);
  nlohmann::json size = dim == 2 ? nlohmann::json{400.0, 300.0} : nlohmann::json{400.0, 100.0, 300.0};
  nlohmann::json lo = dim == 2 ? nlohmann::json{100, 50} : nlohmann::json{100, 20, 50};
  nlohmann::json hi = dim == 2 ? nlohmann::json{300, 250} : nlohmann::json{300, 80, 250};
  nlohmann::json g = dim == 2 ? nlohmann::json{0.0, -9.81} : nlohmann::json{0.0, 0.0, -9.81};
  return {{"dim", dim},
          {"domain", {{"size", size}, {"dx", 10.0}}},
          {"time", {{"end", 0.1}, {"frame_interval", 0.1}}},
          {"gravity", g},
          {"materials", {{"ice", ice}}},
          {"bodies", {{{"material", "ice"}, {"particles_per_cell", 1}, {"lateral_stress_ratio", 1},
                       {"shape", {{"type", "box"}, {"min", lo}, {"max", hi}}}}}},
          {"boundaries", {{{"type", "walls"}}}}};
}

const Ice& ps_ice(const Scene& s) { return std::get<Ice>(s.materials.at(0).model); }

Mat<3> ps_embed(const Mat<2>& F, Real fz) {
  Mat<3> F3 = Mat<3>::Zero();
  F3.topLeftCorner<2, 2>() = F;
  F3(2, 2) = fz;
  return F3;
}

Particles<2> ps_particle(const Mat<2>& F, Real alpha, Real fz = 1) {
  Particles<2> p;
  p.add_solid(Vec<2>::Zero(), Vec<2>::Zero(), Real(1), F.determinant() * fz, 0, Mat<2>::Zero(), F, alpha, fz);
  return p;
}

TEST(PlaneStrain, StressAndEnergyAreThoseOfThe3DStateWithFzzOne) {
  const Scene s = scene_from_json(ps_scene(2), "ps.json");
  const Ice& ice = ps_ice(s);
  ASSERT_TRUE(ice.plane_strain);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  for (int k = 0; k < 100; ++k) {
    Mat<2> F;
    F << 1 + u(rng), u(rng), u(rng), 1 + u(rng);
    const Particles<2> p = ps_particle(F, ice.alpha_initial);
    const Mat<3> tau3 = ice.elastic.kirchhoff<3>(ps_embed(F, 1));
    const Mat<2> tau2 = ice.kirchhoff<2>(p, 0);
    EXPECT_LT((tau2 - tau3.topLeftCorner<2, 2>()).norm(), kPsRel * tau3.norm());
    EXPECT_LT(tau3.col(2).head<2>().norm() + tau3.row(2).head<2>().norm(), kPsRel * tau3.norm());
    EXPECT_NEAR(ice.energy_density<2>(p, 0), ice.elastic.energy_density<3>(ps_embed(F, 1)),
                kPsRel * std::abs(ice.elastic.energy_density<3>(ps_embed(F, 1))));
    EXPECT_NEAR(ice.pressure<2>(p, 0), -tau3.trace() / 3 / F.determinant(), kPsRel * tau3.norm());
  }
}

TEST(PlaneStrain, SmallStrainIsPlaneStrainHooke) {
  if constexpr (!kPsDouble) GTEST_SKIP() << "a finite difference of 1e-7 needs double precision";
  const Scene s = scene_from_json(ps_scene(2), "ps.json");
  const Ice& ice = ps_ice(s);
  const double E = 9e9, nu = 0.3, lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const Real h = Real(1e-7);
  Mat<2> G;
  G << 0.3, -0.7, 0.2, -0.4;
  const Mat<2> eps = Real(0.5) * (G + G.transpose());
  const Particles<2> p = ps_particle(Mat<2>::Identity() + h * G, ice.alpha_initial);
  const Mat<2> tau = ice.kirchhoff<2>(p, 0) / h;
  const Mat<2> hooke = lambda * eps.trace() * Mat<2>::Identity() + 2 * mu * eps;
  EXPECT_LT((tau - hooke).norm(), 1e-5 * hooke.norm());
  // and its fastest wave is the P wave of lambda + 2 mu, as in 3D
  EXPECT_NEAR(ice.wave_speed<2>(1), std::sqrt((lambda + 2 * mu) / 917), 1e-9 * std::sqrt((lambda + 2 * mu) / 917));
}

TEST(PlaneStrain, ReturnMappingIsThe3DOneWithFzzOne) {
  const Scene s = scene_from_json(ps_scene(2), "ps.json");
  const Ice& ice = ps_ice(s);
  const CohesiveCamClay& cc = ice.plastic;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  int plastic = 0, tips = 0;
  for (int k = 0; k < 4000; ++k) {
    // Strains up to 3e-3 (the ice yields near 1e-4): elastic states, the q-branch and both tips.
    const double a = std::pow(10.0, -5 + 2.5 * (u(rng) + 1) / 2);
    Mat<2> F;
    F << 1 + a * u(rng), a * u(rng), a * u(rng), 1 + a * u(rng);
    const Real fz = Real(1 + a * u(rng) * (k % 2));  // also an out-of-plane stretch left by earlier plastic flow
    const Real alpha0 = ice.alpha_initial * Real(k % 3 == 0 ? 1.0 : 0.5);  // intact and partly softened
    Mat<2> F2 = F;
    Real fz2 = fz, alpha2 = alpha0;
    const bool changed2 = cc.return_mapping_plane_strain(F2, fz2, alpha2, ice.p0(alpha0), ice.elastic);
    Mat<3> F3 = ps_embed(F, fz);
    Real alpha3 = alpha0;
    const bool changed3 = cc.return_mapping<3>(F3, alpha3, ice.p0(alpha0), ice.elastic);
    ASSERT_EQ(changed2, changed3) << "state " << k;
    if (!changed3) {
      EXPECT_EQ(F2, F);
      EXPECT_EQ(fz2, fz);
      continue;
    }
    ++plastic;
    tips += std::abs(F3.determinant() - ps_embed(F, fz).determinant()) > 1e-9 * F3.determinant();
    EXPECT_LT((F2 - F3.topLeftCorner<2, 2>()).norm(), kPsRel) << "state " << k;
    EXPECT_NEAR(fz2, F3(2, 2), kPsRel) << "state " << k;
    EXPECT_LT(F3.col(2).head<2>().norm() + F3.row(2).head<2>().norm(), kPsRel) << "state " << k;
    EXPECT_NEAR(alpha2, alpha3, kPsRel * std::max(Real(1), std::abs(alpha3))) << "state " << k;
    const Mat<3> tau = ice.elastic.kirchhoff<3>(ps_embed(F2, fz2));
    const Real y = cc.yield(CohesiveCamClay::pressure<3>(tau), cc.mises<3>(tau), ice.p0(alpha0));
    const Real scale = cc.M * cc.M * ice.p0(alpha0) * ice.p0(alpha0);
    EXPECT_LT(y, 1e-9 * scale) << "state " << k;
  }
  EXPECT_GT(plastic, 1000);  // the sample reaches the surface, and its tips
  EXPECT_GT(tips, 50);
}

TEST(PlaneStrain, SceneConventions) {
  const double E = 9e9, nu = 0.3;
  const Scene s2 = scene_from_json(ps_scene(2), "ps.json");
  const Scene s3 = scene_from_json(ps_scene(3), "ps3.json");
  const Ice &a = ps_ice(s2), &b = ps_ice(s3);
  EXPECT_TRUE(a.plane_strain);
  EXPECT_FALSE(b.plane_strain);
  EXPECT_NEAR(a.elastic.kappa, E / (3 * (1 - 2 * nu)), 1e-6);
  // One material in 2D and 3D: the same constants, strength and M.
  EXPECT_EQ(a.elastic.kappa, b.elastic.kappa);
  EXPECT_EQ(a.plastic.M, b.plastic.M);
  EXPECT_EQ(a.p0_initial, b.p0_initial);
  EXPECT_NEAR(a.plastic.uniaxial_strength<3>(a.p0_initial, true), 1e6, 1e-6 * 1e6);

  const Scene r = scene_from_json(ps_scene(2, {{"convention_2d", "cd_mpm"}}), "cd.json");
  const Ice& c = ps_ice(r);
  EXPECT_FALSE(c.plane_strain);
  EXPECT_EQ(c.plastic.q_factor, Real(2));
  EXPECT_EQ(c.plastic.p0_floor, Real(1e-5));
  const double sphi = std::sin(40 * std::acos(-1.0) / 180);
  // ziran2020's M: sqrt(2/3) 2 sin(phi) / (3 - sin(phi)) d / sqrt(2 / (6 - d)), d = 2.
  EXPECT_NEAR(c.plastic.M, std::sqrt(2.0 / 3) * 2 * sphi / (3 - sphi) * 2 / std::sqrt(2.0 / 4), 1e-12);
  // its tensile strength is that of the 2x2 state: tau = diag(sigma, 0), p = -sigma/2, q^2 = 2 |dev tau|^2 = sigma^2
  const double st = 1e6, p = -st / 2, q = st;
  EXPECT_NEAR(c.plastic.yield(p, q, c.p0_initial), 0, 1e-9 * c.plastic.M * c.plastic.M * c.p0_initial * c.p0_initial);
  Mat<2> F = Mat<2>::Identity();
  const Particles<2> pc = ps_particle(F, c.alpha_initial);
  EXPECT_EQ(c.energy_density<2>(pc, 0), 0);

  auto refused = [](const nlohmann::json& j, const std::string& what) {
    try {
      scene_from_json(j, "bad.json");
      ADD_FAILURE() << "accepted: " << what;
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("convention_2d"), std::string::npos) << e.what();
    }
  };
  refused(ps_scene(3, {{"convention_2d", "plane_strain"}}), "a 3D convention_2d");
  refused(ps_scene(2, {{"convention_2d", "in_plane"}}), "an unknown convention");
}

TEST(PlaneStrain, CryostaticSeedingIsIsotropicIn3D) {
  const Scene s = scene_from_json(ps_scene(2), "ps.json");
  const Ice& ice = ps_ice(s);
  const Real pressure = Real(917 * 9.81 * 150);  // 150 m of ice
  const InitialState<2> st = ice.initial_state<2>(pressure, 1);
  Particles<2> p;
  p.add_solid(Vec<2>::Zero(), Vec<2>::Zero(), Real(1), st.J, 0, Mat<2>::Zero(), st.F, st.alpha, st.Fz);
  const Mat<3> tau = ice.elastic.kirchhoff<3>(ps_embed(p.F[0], p.Fz[0]));
  const Real J3 = tau.trace() == 0 ? 1 : p.F[0].determinant() * p.Fz[0];
  EXPECT_NEAR(tau(0, 0) / J3, -pressure, 1e-9 * pressure);
  EXPECT_NEAR(tau(1, 1) / J3, -pressure, 1e-9 * pressure);
  EXPECT_NEAR(tau(2, 2) / J3, -pressure, 1e-9 * pressure);
  EXPECT_NE(p.Fz[0], Real(1));
  EXPECT_EQ(st.J, p.F[0].determinant());
}

}  // namespace
}  // namespace cdmpm
