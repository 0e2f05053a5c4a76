// test_field_contact_rule.cpp - the frictionless contact of the deformable solids' own velocity field with the
// shared field (sim/field_contact.h; ice key `contact`), node by node on a hand-made pair of fields, an ice field
// filling x < 0.5 m and a water field filling x > 0.5 m (node masses ramping over the three nodes x = 0.4, 0.5,
// 0.6 m), no gravity, no boundary. Bardenhagen et al. (2000): where the two approach along the solid's outward normal
// (+x here), both normal velocities become the node's centre-of-mass velocity (at full share), the tangential ones
// are untouched, and the node's momentum is conserved; where they separate nothing changes. Tolerances: a handful of
// floating-point operations on numbers of order 10, so 1e-12.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "rise_reference.h"
#include "scene/scene_loader.h"
#include "sim/field_contact.h"
#include "sim/simulation.h"

namespace cdmpm {
namespace {

const std::string kScene = std::string(CDMPM_SOURCE_DIR) + "/scenes/ice_rise_contact_2d.json";

struct TwoFields {
  Scene scene = load_scene(kScene, {"parameters.dx=0.1"});
  Grid<2> shared{Vec<2>(1.0, 1.0), Real(0.1)};
  FieldContact<2> contact;
  double full_ice = 920 * 0.01, full_water = 1000 * 0.01;

  // Ice moving with v_ice, water with v_water (velocities in the shared field, momenta in the ice field, as after
  // the shared field's grid update and before the solids' own).
  TwoFields(const Vec<2>& v_ice, const Vec<2>& v_water) {
    std::vector<uint32_t> all(shared.block_count());
    for (size_t b = 0; b < all.size(); ++b) all[b] = static_cast<uint32_t>(b);
    shared.activate(all);
    contact.configure(scene.materials, shared);
    contact.activate(all);
    shared.for_each_node([&](size_t k, const IVec<2>& i) {
      const double x = i[0] * 0.1;
      const double fi = x < 0.35 ? 1 : x < 0.45 ? 1 : x < 0.55 ? 0.5 : x < 0.65 ? 0.1 : 0;
      const double fw = x > 0.65 ? 1 : x > 0.55 ? 1 : x > 0.45 ? 0.5 : x > 0.35 ? 0.1 : 0;
      contact.field.mass[k] = static_cast<Real>(fi * full_ice);
      contact.field.momentum[k] = contact.field.mass[k] * v_ice;
      shared.mass[k] = static_cast<Real>(fw * full_water);
      shared.momentum[k] = v_water;
    });
  }
  void update() { contact.update(shared, Vec<2>::Zero(), Real(1e-3), {}); }
  Vec<2> momentum() const {
    Vec<2> p = Vec<2>::Zero();
    for (size_t k = 0; k < shared.node_count(); ++k)
      p += contact.field.mass[k] * contact.field.momentum[k] + shared.mass[k] * shared.momentum[k];
    return p;
  }
  size_t node_at(double x, double y) const { return shared.find(IVec<2>(int(std::lround(x / 0.1)), int(std::lround(y / 0.1)))); }
};

TEST(FieldContact, ApproachingFieldsTakeTheCentreOfMassNormalVelocityAndKeepMomentum) {
  const Vec<2> v_ice(1.0, 0.3), v_water(-0.5, -0.2);
  TwoFields f(v_ice, v_water);
  Vec<2> before = Vec<2>::Zero();
  for (size_t k = 0; k < f.shared.node_count(); ++k)
    before += f.contact.field.momentum[k] + f.shared.mass[k] * f.shared.momentum[k];  // ice: momentum still
  f.update();
  const Vec<2> after = f.momentum();
  EXPECT_NEAR(after[0], before[0], 1e-12 * before.norm());
  EXPECT_NEAR(after[1], before[1], 1e-12 * before.norm());
  // Full share (ice node mass >= 0.2 of a full node): x = 0.4 and 0.5 m.
  for (const double x : {0.4, 0.5}) {
    const size_t k = f.node_at(x, 0.5);
    const double ms = f.contact.field.mass[k], mo = f.shared.mass[k];
    const double v_cm = (ms * v_ice[0] + mo * v_water[0]) / (ms + mo);
    EXPECT_NEAR(f.contact.field.momentum[k][0], v_cm, 1e-12) << "x = " << x;
    EXPECT_NEAR(f.shared.momentum[k][0], v_cm, 1e-12) << "x = " << x;
    EXPECT_NEAR(f.contact.field.momentum[k][1], v_ice[1], 1e-12) << "x = " << x;  // no friction
    EXPECT_NEAR(f.shared.momentum[k][1], v_water[1], 1e-12) << "x = " << x;
  }
  // A third of the share at x = 0.6 m (ice node mass 0.1 of a full node): a third of the relative normal velocity.
  const size_t k = f.node_at(0.6, 0.5);
  const double rel = f.contact.field.momentum[k][0] - f.shared.momentum[k][0];
  EXPECT_NEAR(rel, (1.0 - 1.0 / 3.0) * (v_ice[0] - v_water[0]), 1e-12);
  // Nodes of one field alone keep their velocity.
  EXPECT_NEAR(f.contact.field.momentum[f.node_at(0.2, 0.5)][0], v_ice[0], 1e-12);
  EXPECT_NEAR(f.shared.momentum[f.node_at(0.8, 0.5)][0], v_water[0], 1e-12);
}

TEST(FieldContact, SeparatingFieldsKeepTheirVelocities) {
  const Vec<2> v_ice(-1.0, 0.3), v_water(0.5, -0.2);
  TwoFields f(v_ice, v_water);
  f.update();
  for (const double x : {0.4, 0.5, 0.6}) {
    const size_t k = f.node_at(x, 0.5);
    EXPECT_NEAR((f.contact.field.momentum[k] - v_ice).norm(), 0, 1e-12) << "x = " << x;
    EXPECT_NEAR((f.shared.momentum[k] - v_water).norm(), 0, 1e-12) << "x = " << x;
  }
}

}  // namespace
}  // namespace cdmpm
