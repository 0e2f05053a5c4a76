// test_buoyancy_one_step.cpp - the buoyancy a coupling passes to a body in one step, wherever the body's faces lie
// between grid planes. A neutrally buoyant block (the density of the water it displaces) released at rest in water at
// rest must take no net impulse: its weight M g dt and the pressure the water exerts on its faces cancel. The net
// vertical impulse of the first step, M V_y, is asserted under 0.5 % of the displaced weight times dt for faces at
// 0, 1/4, 1/2 and 3/4 of a cell above a grid plane. A coupling that passes a fraction Phi(s) of a face's pressure, s
// the face's offset (tools/contact_share_phi.py: 0.755-0.995 for the shares of sim/rigid_contact.h), takes
// (1 - Phi) of that face's force away; 0.5 % of the displaced weight is 6 % of the net buoyancy of the 920 block
// (8.9 % of its displaced weight; docs/validation.md, "Buoyancy-driven motions").
//
// The rigid block in contact (scenes/rigid_rise_contact_2d.json: a 0.4 m square centred 1 m under the still level of
// Tait water, K = 1e6 Pa) at D/16, moved up by s dx, with 16 particles per cell in every body (a lattice of dx/4, on
// whose cell edges every offset's faces lie, so that water and block fill the space between them exactly); its
// density is the water's where its centre is (hydrostatic_column.h: the column's density is linear in depth to a part
// in 1e6 over the block's 0.4 m, so that is the displaced mass's mean).
// The elastic block in its own field (sim/field_contact.h) is not asserted here: its exchange gives both fields a
// node's centre-of-mass normal velocity, so in one step the block takes its node-mass share of each contact node's
// push (48-61 % of the displaced weight at these offsets, measured) and the water at the node moves with it; the rest
// reaches the block over the following steps, which its neutral test measures (test_field_contact.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "hydrostatic_column.h"
#include "rise_reference.h"
#include "scene/scene_loader.h"
#include "sim/simulation.h"

namespace cdmpm {
namespace {

using namespace cdmpm::testing;

constexpr double dx = 0.025;  // D/16

struct OneStep {
  double impulse;  // the block's net vertical impulse over the first step [N s / m]
  double scale;    // its displaced weight times dt
};

// The first step of the scene with the block's faces s cells above the scene's: the block's net vertical impulse.
OneStep first_step(double s) {
  const double y0 = 1.0 - 0.5 * rise_block_size + s * dx, y1 = y0 + rise_block_size;
  const double rho_w = tait_column_density(rise_water_rho0, rise_g, rise_block_depth - s * dx, rise_scene_K);
  const std::vector<std::string> sets = {"parameters.dx=" + std::to_string(dx),
                                         "parameters.block_density=" + std::to_string(rho_w),
                                         "bodies.0.particles_per_cell=16",
                                         "bodies.1.particles_per_cell=16",
                                         "bodies.0.shape.min.1=" + std::to_string(y0),
                                         "bodies.0.shape.max.1=" + std::to_string(y1)};
  const Scene scene = load_scene(std::string(CDMPM_SOURCE_DIR) + "/scenes/rigid_rise_contact_2d.json", sets);
  Simulation<2> sim(scene);
  const Real dt = sim.stable_dt();
  sim.step(dt);
  const auto& B = sim.rigid.bodies[0];
  // The block's mass is its density times its volume (the displaced water's mass; rho_w as printed, to 1e-6).
  EXPECT_NEAR(B.mass, rho_w * rise_block_size * rise_block_size, 1e-6 * B.mass) << "offset " << s;
  return {B.mass * static_cast<double>(B.velocity[1]), B.mass * rise_g * static_cast<double>(dt)};
}

// Not met: the shipped share gives -7.8, +36.0, -12.7 and -58.1 % at the four offsets; the share 1 at every node the
// body reaches passes (-0.14 to +0.21 %) but holds the water a kernel width out, and the 920 block then rises at 0.236
// instead of 0.337 m/s^2 at D/16 (docs/changelog.md, "Buoyancy coupling", 2026-12-07). Run with
// --gtest_also_run_disabled_tests.
TEST(BuoyancyOneStep, DISABLED_RigidBlockInContactTakesNoNetImpulseAtAnyOffset) {
  for (const double s : {0.0, 0.25, 0.5, 0.75}) {
    const OneStep r = first_step(s);
    std::printf("faces at %.2f of a cell: net impulse %+.4f %% of the displaced weight times dt\n", s,
                100 * r.impulse / r.scale);
    EXPECT_LT(std::abs(r.impulse), 0.005 * r.scale) << "faces at " << s << " of a cell";
  }
}

}  // namespace
}  // namespace cdmpm
