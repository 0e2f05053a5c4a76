// test_hydrofracture.cpp - water pressure in damaged ice (poro-damage; material/ice.h, the material key
// "hydrofracture"; Duddu, Jimenez & Bassis 2020): sigma = sigma_ice(F) - d p_w I, p_w = rho_w g max(z_w - z, 0).
//   Hydrofracture     a damaged particle below z_w carries sigma_ice - d p_w I (with F = I, sigma_ice = 0 exactly, so
//                     sigma = -d p_w I; a fully damaged one -p_w I up to its residual strength kappa 1e-4 / p0_initial);
//                     above z_w, outside the region, with d = 0 and without the key the stress is the skeleton's, bit
//                     for bit; the pressure field agrees with the stress; g comes from the scene's gravity; bad keys
//                     are refused naming the key;
// Through the program: tests/end_to_end/test_hydrofracture_cli.cpp.
// Tolerances: tau and sigma are a handful of floating-point operations on p_w and the elastic stress, so they agree
// with the formula to a few ulps of the largest term: 1e-12 relative (double precision).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <type_traits>

#include "cli_helpers.h"
#include "material/stress.h"
#include "scene/scene_loader.h"
#include "scene_builders.h"

namespace cdmpm {
namespace {

constexpr double kRel = std::is_same_v<Real, double> ? 1e-12 : 1e-5;

const Ice& ice_of(const Scene& s) { return std::get<Ice>(s.materials.at(0).model); }

// One ice particle at x with elastic F and hardening variable alpha.
Particles<2> one_particle(const Vec<2>& x, const Mat<2>& F, Real alpha) {
  Particles<2> p;
  p.add_solid(x, Vec<2>::Zero(), Real(1), F.determinant(), 0, Mat<2>::Zero(), F, alpha);
  return p;
}

const nlohmann::json kKey = {{"water_level", 250}, {"water_density", 1025}};

// A fully damaged particle (alpha = 0: p0 at its floor kappa 1e-4) at F = I, 100 m below z_w: the skeleton carries
// nothing (tau_ice(I) = 0 exactly), so sigma = -d p_w I with p_w = rho_w g 100 m = 1.0055 MPa and d = 1 - 1e-4 kappa /
// p0_initial (0.987 for this ice): -p_w I to that residual, and to round-off once d is accounted for.
TEST(Hydrofracture, FullyDamagedParticleBelowTheWaterCarriesMinusTheWaterPressure) {
  const Scene s = scene_from_json(testing::hydrofracture_ice_scene(kKey), "hf.json");
  const Ice& ice = ice_of(s);
  ASSERT_TRUE(ice.hydrofracture.on);
  EXPECT_EQ(ice.hydrofracture.gravity, Real(9.81));
  const Particles<2> p = one_particle(Vec<2>(200, 150), Mat<2>::Identity(), Real(0));
  const Real d = ice.damage(p.alpha[0]);
  EXPECT_NEAR(d, 1 - CohesiveCamClay{}.p0_floor * ice.elastic.kappa / ice.p0_initial, 1e-15);
  ASSERT_GT(d, 0.95);  // fully damaged: the residual strength is a few per cent of the intact one
  const Real pw = Real(1025 * 9.81 * 100.0);
  const Mat<2> sigma = cauchy_stress(s.materials[0], p, 0);
  EXPECT_NEAR(sigma(0, 0), -d * pw, kRel * pw);
  EXPECT_NEAR(sigma(1, 1), -d * pw, kRel * pw);
  EXPECT_EQ(sigma(0, 1), 0);
  EXPECT_EQ(sigma(1, 0), 0);
  EXPECT_NEAR(sigma(1, 1), -pw, (1 - d) * pw + kRel * pw);  // -p_w I up to the residual strength
  EXPECT_NEAR(particle_pressure(s.materials[0], p, 0), d * pw, kRel * pw);
}

// Partly damaged ice under a general elastic F: sigma - sigma_ice = -d p_w I to round-off, whatever F; the Kirchhoff
// stress p2g uses is J = det F_e times it; the pressure is the skeleton's (plane strain: -tr(sigma_3x3)/3) plus d p_w.
TEST(Hydrofracture, DamagedParticleAddsMinusDamageTimesWaterPressureToTheSkeletonsStress) {
  const Scene s = scene_from_json(testing::hydrofracture_ice_scene(kKey), "hf.json");
  const Ice& ice = ice_of(s);
  Mat<2> F;
  F << 1.0004, 0.0003, -0.0002, 0.9993;
  const Real alpha = Real(0.5) * ice.alpha_initial;  // p0 = kappa (1e-4 + sinh(xi alpha_initial / 2)): part damaged
  for (const double z : {60.0, 120.0, 249.0}) {
    const Particles<2> p = one_particle(Vec<2>(150, z), F, alpha);
    const Real d = ice.damage(alpha);
    ASSERT_GT(d, 0.1);
    ASSERT_LT(d, 0.99);
    const Real pw = Real(1025 * 9.81 * (250 - z));
    const Real J = ice.volume_ratio<2>(p, 0);  // det F Fz (plane strain)
    const Mat<2> tau_ice = ice.skeleton_kirchhoff<2>(p, 0);
    const Mat<2> tau = kirchhoff_stress(s.materials[0], p, 0);
    const Real scale = tau_ice.norm() + pw;
    EXPECT_LT((tau - (tau_ice - J * d * pw * Mat<2>::Identity())).norm(), kRel * scale) << "z = " << z;
    const Mat<2> sigma = cauchy_stress(s.materials[0], p, 0);
    EXPECT_LT((sigma - (tau_ice / J - d * pw * Mat<2>::Identity())).norm(), kRel * scale) << "z = " << z;
    EXPECT_NEAR(particle_pressure(s.materials[0], p, 0), ice.elastic.pressure_of_J(J) / J + d * pw, kRel * scale) << "z = " << z;
  }
}

// Above z_w (and at it), outside the region, in intact ice (d = 0) and with the key absent, the stress is the
// skeleton's bit for bit.
TEST(Hydrofracture, AboveTheWaterOutsideTheRegionIntactOrOffTheStressIsTheSkeletons) {
  nlohmann::json key = kKey;
  key["region"] = {120, 280};
  const Scene s = scene_from_json(testing::hydrofracture_ice_scene(key), "hf.json");
  const Scene off = scene_from_json(testing::hydrofracture_ice_scene(nullptr), "off.json");
  EXPECT_FALSE(ice_of(off).hydrofracture.on);
  const Ice& ice = ice_of(s);
  Mat<2> F;
  F << 1.0004, 0.0003, -0.0002, 0.9993;
  auto same = [&](const Scene& sc, const Vec<2>& x, Real alpha, const char* what) {
    const Particles<2> p = one_particle(x, F, alpha);
    const Mat<2> tau_ice = ice.skeleton_kirchhoff<2>(p, 0);
    const Mat<2> tau = kirchhoff_stress(sc.materials[0], p, 0);
    EXPECT_TRUE((tau.array() == tau_ice.array()).all()) << what;
    const Real Je = ice.volume_ratio<2>(p, 0);
    EXPECT_EQ(particle_pressure(sc.materials[0], p, 0), ice.elastic.pressure_of_J(Je) / Je) << what;
  };
  same(s, Vec<2>(200, 251), Real(0), "damaged, 1 m above z_w");
  same(s, Vec<2>(200, 250), Real(0), "damaged, at z_w");
  same(s, Vec<2>(110, 100), Real(0), "damaged, below z_w, before the region");
  same(s, Vec<2>(290, 100), Real(0), "damaged, below z_w, beyond the region");
  same(s, Vec<2>(200, 100), ice.alpha_initial, "intact (d = 0), below z_w");
  same(off, Vec<2>(200, 100), Real(0), "damaged, below z_w, no hydrofracture key");
  // Inside the region it acts.
  const Particles<2> p = one_particle(Vec<2>(200, 100), F, Real(0));
  EXPECT_LT(kirchhoff_stress(s.materials[0], p, 0)(0, 0), ice.elastic.kirchhoff<2>(F)(0, 0) - Real(1e6));
}

// p_w = rho_w g (z_w - z) with g the scene's gravity and rho_w the key's density.
TEST(Hydrofracture, WaterPressureUsesTheScenesGravityAndTheWatersDensity) {
  nlohmann::json key = kKey;
  key["water_density"] = 1000;
  const Scene s = scene_from_json(testing::hydrofracture_ice_scene(key, -3.7), "mars.json");
  const Ice& ice = ice_of(s);
  EXPECT_EQ(ice.hydrofracture.gravity, Real(3.7));
  EXPECT_NEAR(ice.hydrofracture.water_pressure<2>(Vec<2>(200, 50)), 1000 * 3.7 * 200, kRel * 1000 * 3.7 * 200);
  EXPECT_EQ(ice.hydrofracture.water_pressure<2>(Vec<2>(200, 260)), 0);
}

// Each non-physical or inconsistent value is refused with its path in the message.
TEST(Hydrofracture, BadKeysAreRefusedNamingTheKey) {
  struct Case {
    nlohmann::json key;
    double gravity;
    bool plastic;
    std::string path;
  };
  const std::vector<Case> cases = {
      {{{"water_density", 1025}}, -9.81, true, "materials.ice.hydrofracture"},  // no water_level
      {{{"water_level", 250}, {"water_density", 0}}, -9.81, true, "materials.ice.hydrofracture.water_density"},
      {{{"water_level", 250}, {"water_density", -1025}}, -9.81, true, "materials.ice.hydrofracture.water_density"},
      {{{"water_level", 250}, {"water_density", 1.025e6}}, -9.81, true, "materials.ice.hydrofracture.water_density"},
      {{{"water_level", "high"}}, -9.81, true, "materials.ice.hydrofracture.water_level"},
      {{{"water_level", 1e9}}, -9.81, true, "materials.ice.hydrofracture.water_level"},
      {{{"water_level", 250}, {"region", {300, 100}}}, -9.81, true, "materials.ice.hydrofracture.region"},
      {{{"water_level", 250}, {"colour", "blue"}}, -9.81, true, "materials.ice.hydrofracture"},
      {{{"water_level", 250}}, 9.81, true, "materials.ice.hydrofracture"},  // gravity pointing up
      {{{"water_level", 250}}, -9.81, false, "materials.ice.hydrofracture"},  // no damage without plasticity
      {250, -9.81, true, "materials.ice.hydrofracture"}};                     // not an object
  for (const auto& c : cases) {
    try {
      scene_from_json(testing::hydrofracture_ice_scene(c.key, c.gravity, c.plastic), "bad.json");
      ADD_FAILURE() << c.key.dump() << " accepted";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("bad.json: " + c.path), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace cdmpm
