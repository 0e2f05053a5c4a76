// test_rigid_body.cpp - rigid bodies (sim/rigid_bodies.h) against mechanics: free fall in air with g, exact
// conservation of linear and angular momentum of an isolated spinning block (2D and 3D), a hinged bar's
// initial angular acceleration m g d / I_o, a block sliding down a frictionless support plane at g sin(theta)
// and falling freely where the plane is bounded away (half-plane `within`), a held block at rest until its release (a block lighter than
// water floating at the draft of Archimedes' principle: tests/validation/test_rigid_body_float.cpp), and the initial rise of a submerged block against potential
// flow, a = (rho_w - rho_b) V g / (m + m_a), m_a = C_A rho_w pi (D/2)^2, C_A = 1.51 for a square (DNV-RP-C205
// table A-1; Brennen 1982: m_a = 4.754 rho_w (D/2)^2), rho_w the water's density at the block (rise_reference.h):
// closer under refinement, and within 15 % at D/16 in the shared field. The buoyancy criteria not met yet
// (docs/validation.md, "Buoyancy-driven motions") are disabled tests: 15 % at D/16 in contact, a neutrally buoyant
// block at rest, and floating at the draft after rising.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>

#include "cli_helpers.h"
#include "rise_reference.h"
#include "scene/scene_loader.h"
#include "sim/simulation.h"
#include "scene_builders.h"

namespace cdmpm {
namespace {

using json = nlohmann::json;
constexpr double g = 9.81;

// Quantities that are exact in exact arithmetic (momenta, symmetry) are asserted to round-off: the bound
// written for double, or in a single-precision build (CDMPM_SINGLE_PRECISION) a few float epsilons per step,
// 16 eps per step, accumulated over the run's steps (each step's transfers and projection round every sum).
double roundoff(double double_bound, long long steps) {
  return std::max(double_bound, 16.0 * std::numeric_limits<Real>::epsilon() * static_cast<double>(steps));
}
// Round-off of a position of magnitude x (a few ulps).
double position_roundoff(double double_bound, double x) {
  return std::max(double_bound, 8.0 * std::numeric_limits<Real>::epsilon() * x);
}

// A rigid block alone in an empty 4 m box (no walls), 2D (dx = 0.05 m) or 3D (dx = 0.1 m). In air the body's
// pressure stays zero, so its bulk modulus only sets the time step; it starts unstressed (not hydrostatic), so
// its particles have equal masses and its centre of mass is the box's centre.
json block_scene(int dim, const std::vector<double>& lo, const std::vector<double>& hi, double gravity) {
  json s;
  s["dim"] = dim;
  s["domain"] = {{"size", std::vector<double>(dim, 4.0)}, {"dx", dim == 2 ? 0.05 : 0.1}};
  s["time"] = {{"end", 1.0}, {"frame_interval", 0.1}};
  std::vector<double> gv(dim, 0.0);
  gv.back() = -gravity;
  s["gravity"] = gv;
  s["materials"] = {{"block", {{"type", "rigid"}, {"density", 920}, {"bulk_modulus", 1e5}}}};
  s["bodies"] = json::array({{{"material", "block"}, {"particles_per_cell", dim == 2 ? 4 : 8},
                              {"hydrostatic", false}, {"shape", {{"type", "box"}, {"min", lo}, {"max", hi}}}}});
  return s;
}

template <int dim>
void run_until(Simulation<dim>& sim, double t_end) {
  sim.run_until(t_end);
}

template <int dim>
void expect_free_fall() {
  std::vector<double> lo(dim, 1.6), hi(dim, 2.4);
  lo.back() = 3.0, hi.back() = 3.5;
  const Scene scene = scene_from_json(block_scene(dim, lo, hi, g), "fall.json");
  Simulation<dim> sim(scene);
  const double z0 = sim.rigid.bodies[0].centre[dim - 1];
  const double t = 0.6;
  run_until(sim, t);
  const auto& b = sim.rigid.bodies[0];
  // Falls with g: v = -g t and drop g t^2 / 2, both within 1 %; no horizontal motion, no spin.
  EXPECT_NEAR(b.velocity[dim - 1], -g * t, 0.01 * g * t);
  EXPECT_NEAR(z0 - b.centre[dim - 1], 0.5 * g * t * t, 0.01 * 0.5 * g * t * t);
  const double tol = roundoff(1e-9, sim.steps());
  for (int a = 0; a < dim - 1; ++a) EXPECT_NEAR(b.velocity[a], 0, tol * g * t);
  EXPECT_NEAR(b.omega.norm(), 0, tol * g * t / 0.4);  // 0.4 m: half the block's width
}

TEST(RigidBody, FallsWithGravityInAir2D) { expect_free_fall<2>(); }
TEST(RigidBody, FallsWithGravityInAir3D) { expect_free_fall<3>(); }

// Linear momentum, angular momentum (with the APIC term m D axial(C - C^T), D = dx^2/4) and the body's
// inertia about its centre of mass, summed over its particles.
// Summed in double, so that the measurement adds no round-off of its own in a single-precision build.
template <int dim>
struct Momenta {
  Eigen::Matrix<double, dim, 1> P;
  Eigen::Matrix<double, RigidBody<dim>::rot, 1> L;
  double inertia;
};
template <int dim>
Momenta<dim> momenta(const Simulation<dim>& sim) {
  const auto& p = sim.particles;
  const Real D = sim.grid.dx * sim.grid.dx / 4;
  Momenta<dim> m{Eigen::Matrix<double, dim, 1>::Zero(), Eigen::Matrix<double, RigidBody<dim>::rot, 1>::Zero(), 0};
  const Vec<dim> c = sim.rigid.bodies[0].centre;
  for (size_t q = 0; q < p.size(); ++q) {
    m.P += (p.mass[q] * p.v[q]).template cast<double>();
    m.L += (p.mass[q] * (RigidAlgebra<dim>::cross(p.x[q], p.v[q]) + D * RigidAlgebra<dim>::axial2(p.C[q])))
               .template cast<double>();
    m.inertia += static_cast<double>(p.mass[q] * (p.x[q] - c).squaredNorm());
  }
  return m;
}

template <int dim>
void expect_spin_conserved() {
  std::vector<double> lo(dim, 1.5), hi(dim, 2.3);
  hi[0] = 2.7;
  json j = block_scene(dim, lo, hi, 0.0);
  std::vector<double> v(dim, 0.3);
  v[0] = 0.5;
  j["bodies"][0]["velocity"] = v;
  // Spin 3 rad/s about the out-of-plane axis (2D) or about (0.2, 0.5, 1) (3D): G = [omega]_x.
  json G = json::array();
  if (dim == 2) G = {{0, -3}, {3, 0}};
  else G = {{0, -3, 1.5}, {3, 0, -0.6}, {-1.5, 0.6, 0}};
  j["bodies"][0]["velocity_gradient"] = G;
  const Scene scene = scene_from_json(j, "spin.json");
  Simulation<dim> sim(scene);
  const Momenta<dim> m0 = momenta(sim);
  ASSERT_GT(m0.L.norm(), 0);
  run_until(sim, 0.4);
  const Momenta<dim> m1 = momenta(sim);
  // Exact up to round-off (sums over ~10^3 particles, ~10^2 steps). L is about the origin, so a round-off
  // dP of the momentum moves it by up to |x_c| dP (x_c: the centre, about 2 m from the origin).
  const double tol = roundoff(1e-9, sim.steps());
  const double arm = sim.rigid.bodies[0].centre.norm();
  EXPECT_LE((m1.P - m0.P).norm(), tol * m0.P.norm());
  EXPECT_LE((m1.L - m0.L).norm(), tol * (m0.L.norm() + arm * m0.P.norm()));
  // Rigid: the inertia about the centre of mass (the particles' spread) is unchanged.
  EXPECT_NEAR(m1.inertia, m0.inertia, tol * m0.inertia);
  // 2D: the spin is unchanged, omega = 3 rad/s, and the angle turned is 3 t. (In 3D omega precesses about the
  // fixed L, as the spin axis is not a principal axis of the block.)
  if (dim == 2) {
    EXPECT_NEAR(sim.rigid.bodies[0].omega[0], 3.0, tol * 3.0);
    EXPECT_NEAR(sim.rigid.bodies[0].angle, 3 * 0.4, tol * 3 * 0.4);
  }
}

// A 0.6 m x 0.3 m block lying on a slip half-plane that dips 30 degrees towards +x (the plane through (1, 2)),
// bounded by `within` to x in [0, 1.8] m (to the box [0, 0] - [1.8, 4]). On a frictionless incline the block
// slides with a = g sin(theta) along the plane and does not turn; with the plane's box moved away from it
// (`within` x in [3, 4] m) nothing holds it and it falls with g.
// With `contact` the body is in a field of its own and the plane holds it through the contact's boundary rows
// (sim/rigid_contact.h) instead of the shared field's nodes.
void expect_slide_down_support_plane(bool contact) {
  const double theta = std::numbers::pi / 6, L = 0.6, T = 0.3;
  const double c = std::cos(theta), sn = std::sin(theta);
  const std::array<double, 2> a{1.0, 2.0}, b{a[0] + L * c, a[1] - L * sn};
  json scene = block_scene(2, {0, 0}, {1, 1}, g);
  scene["materials"]["block"]["contact"] = contact;
  scene["bodies"][0]["shape"] = {{"type", "polygon"},
                                 {"vertices", {{a[0], a[1]}, {b[0], b[1]}, {b[0] + T * sn, b[1] + T * c},
                                               {a[0] + T * sn, a[1] + T * c}}}};
  json plane = {{"type", "half_plane"}, {"condition", "slip"}, {"point", {a[0], a[1]}}, {"normal", {sn, c}},
                {"within", {{"min", {0, 0}}, {"max", {1.8, 4}}}}};
  scene["boundaries"] = json::array({plane});
  const double t = 0.25;  // slides 0.15 m, well before its front reaches x = 1.8
  {
    Simulation<2> sim(scene_from_json(scene, "incline.json"));
    run_until(sim, t);
    const auto& body = sim.rigid.bodies[0];
    const double along = body.velocity[0] * c - body.velocity[1] * sn;  // down the slope
    const double across = body.velocity[0] * sn + body.velocity[1] * c;  // along the plane's normal
    // The acceleration of a frictionless incline, g sin(theta) (5 %: the first node layer inside the plane
    // carries the slip condition half a cell below the contact, so the body may sink into it at a few per cent
    // of its speed); no spin.
    EXPECT_NEAR(along, g * sn * t, 0.05 * g * sn * t);
    EXPECT_NEAR(across, 0, 0.05 * g * sn * t);
    EXPECT_NEAR(body.omega.norm(), 0, 0.02 * g * sn * t / L);
  }
  plane["within"] = {{"min", {3, 0}}, {"max", {4, 4}}};
  scene["boundaries"] = json::array({plane});
  Simulation<2> sim(scene_from_json(scene, "no_support.json"));
  run_until(sim, t);
  const auto& body = sim.rigid.bodies[0];
  EXPECT_NEAR(body.velocity[1], -g * t, 0.01 * g * t);
  EXPECT_NEAR(body.velocity[0], 0, 0.01 * g * t);
}
TEST(RigidBody, SlidesDownABoundedSupportPlaneAtGSinTheta) { expect_slide_down_support_plane(false); }
TEST(RigidBody, BlockInContactSlidesDownABoundedSupportPlaneAtGSinTheta) { expect_slide_down_support_plane(true); }

// The submerged block of scenes/lab_bf_2d.json (coarse: 10 cells per depth) stands against the tank's x- wall in a
// field of its own (`contact`): the water presses it against the wall, which holds it (its centre stays at
// x = 0.2 m within a thousandth of its 0.4 m thickness: without the contact's boundary rows it moved 16 mm into
// the wall by 0.5 s), and buoyancy lifts it along the wall once it is released at 0.2 s.
TEST(RigidBody, BlockInContactIsHeldByTheWallTheWaterPressesItAgainst) {
  const Scene scene = load_scene(std::string(CDMPM_SOURCE_DIR) + "/scenes/lab_bf_2d.json",
                                 {"parameters.cells_per_h=10", "materials.block.contact=true"});
  Simulation<2> sim(scene);
  const double x0 = sim.rigid.bodies[0].centre[0], y0 = sim.rigid.bodies[0].centre[1];
  double drift = 0;
  for (int k = 1; k <= 12; ++k) {
    run_until(sim, 0.05 * k);
    drift = std::max(drift, std::abs(static_cast<double>(sim.rigid.bodies[0].centre[0]) - x0));
  }
  std::printf("largest drift across the wall %.3g m, rise %.4f m at 0.6 s\n", drift, sim.rigid.bodies[0].centre[1] - y0);
  EXPECT_LT(drift, 1e-3 * 0.4);
  EXPECT_GT(sim.rigid.bodies[0].velocity[1], 0);
  EXPECT_GT(sim.rigid.bodies[0].centre[1], y0);
}

TEST(RigidBody, IsolatedSpinningBlockConservesMomentum2D) { expect_spin_conserved<2>(); }
TEST(RigidBody, IsolatedSpinningBlockConservesMomentum3D) { expect_spin_conserved<3>(); }

// A horizontal bar (length a, thickness b) hinged at its left end starts turning with angular acceleration
// m g d / I_o, d = a/2, I_o = m (a^2 + b^2)/12 + m d^2 (clockwise, so omega < 0); the centre stays at distance d.
TEST(RigidBody, HingedBarTurnsAboutItsPivot) {
  const double a = 1.0, b = 0.2, x0 = 1.0, y0 = 2.0;
  json j = block_scene(2, {x0, y0}, {x0 + a, y0 + b}, g);
  j["bodies"][0]["rigid"] = {{"hinge", {x0, y0 + b / 2}}};
  const Scene scene = scene_from_json(j, "hinge.json");
  Simulation<2> sim(scene);
  const double r0 = (sim.rigid.bodies[0].centre - sim.rigid.bodies[0].pivot).norm();
  ASSERT_NEAR(r0, a / 2, position_roundoff(1e-12, x0 + a));
  const double t = 0.03;
  run_until(sim, t);
  const double d = a / 2, I_o = (a * a + b * b) / 12 + d * d;  // per unit mass
  const double alpha = g * d / I_o;
  const auto& B = sim.rigid.bodies[0];
  EXPECT_NEAR(B.omega[0], -alpha * t, 0.01 * alpha * t);
  EXPECT_NEAR((B.centre - B.pivot).norm(), d, position_roundoff(1e-12, x0 + a) * std::max(1LL, sim.steps()));
  // Symplectic Euler turns by sum_k omega_k dt = alpha dt^2 n (n + 1) / 2 over n = t / dt steps of the (here
  // constant) time step: alpha t^2 / 2 (1 + dt / t).
  const double dt = sim.stable_dt();
  EXPECT_NEAR(B.angle, -0.5 * alpha * t * t * (1 + dt / t), 0.01 * 0.5 * alpha * t * t);
}

// A driven body (rigid key "motion": a prescribed tilt about its hinge) follows its motion whatever the forces:
// under gravity, a bar hinged at its left end turns from 0 to -30 degrees over 0.5 s and then holds, its angle
// a(t) at every step equal to the piecewise-linear motion (exact: each step turns by a(t + dt) - a(t)), its centre
// at a fixed distance from the pivot, in 2D and in 3D (tilt in the x-z plane: about -y). Without the motion the
// bar would fall the other way first (-30 degrees is clockwise, gravity turns it clockwise too, but at
// alpha t^2 / 2 = 0.22 rad by 0.5 s, not 0.52).
template <int dim>
void expect_driven_motion() {
  std::vector<double> lo(dim, 1.9), hi(dim, 2.1);
  lo[0] = 1.0, hi[0] = 2.0, lo.back() = 2.0, hi.back() = 2.2;
  json j = block_scene(dim, lo, hi, g);
  std::vector<double> pivot(dim, 2.0);
  pivot[0] = 1.0, pivot.back() = 2.1;
  j["bodies"][0]["rigid"] = {{"hinge", pivot}, {"motion", {{0, 0}, {0.5, -30}, {1.0, -30}}}};
  const Scene scene = scene_from_json(j, "driven.json");
  Simulation<dim> sim(scene);
  const auto& B = sim.rigid.bodies[0];
  const double r0 = (B.centre - B.pivot).norm();
  const double deg = std::numbers::pi / 180;
  for (double t : {0.1, 0.25, 0.5, 0.8}) {
    run_until(sim, t);
    const double expected = -30 * deg * std::min(1.0, t / 0.5);
    const double tol = roundoff(1e-9, sim.steps());
    if constexpr (dim == 2) EXPECT_NEAR(B.angle, expected, tol) << "t = " << t;
    else EXPECT_NEAR(B.angle, std::abs(expected), tol) << "t = " << t;  // 3D: the rotation's angle, >= 0
    // The x axis turned by the tilt: towards -z for a negative (clockwise) tilt.
    EXPECT_NEAR(B.rotation(dim - 1, 0), std::sin(expected), tol) << "t = " << t;
    EXPECT_NEAR((B.centre - B.pivot).norm(), r0, position_roundoff(1e-12, 2.0) * std::max(1LL, sim.steps()));
  }
  EXPECT_EQ(B.omega.norm(), 0) << "held at the last angle";
}
TEST(RigidBody, DrivenBodyFollowsItsMotion2D) { expect_driven_motion<2>(); }
TEST(RigidBody, DrivenBodyFollowsItsMotion3D) { expect_driven_motion<3>(); }

TEST(RigidBody, MotionInputErrors) {
  auto refused = [](json rigid, const std::string& expected) {
    json j = block_scene(2, {1.0, 2.0}, {2.0, 2.2}, g);
    j["bodies"][0]["rigid"] = std::move(rigid);
    try {
      scene_from_json(j, "bad.json");
      ADD_FAILURE() << "accepted; expected: " << expected;
    } catch (const std::exception& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  };
  const json hinge = {1.0, 2.1};
  refused({{"motion", {{0, 0}, {1, 10}}}}, "bodies[0].rigid.motion: expected no motion on a body without a hinge");
  refused({{"hinge", hinge}, {"tilt", 5}, {"motion", {{0, 0}, {1, 10}}}}, "without \"tilt\"");
  refused({{"hinge", hinge}, {"motion", {{0.5, 0}, {1, 10}}}}, "bodies[0].rigid.motion[0]: expected a first time of 0 s");
  refused({{"hinge", hinge}, {"motion", {{0, 0}, {1, 10}, {1, 20}}}}, "motion[2]: expected times increasing");
  refused({{"hinge", hinge}, {"motion", {{0, 0}, {1, 190}}}}, "motion[1]: expected an angle in (-180, 180)");
  refused({{"hinge", hinge}, {"motion", {{0, 0}}}}, "bodies[0].rigid.motion");
}

// A held block stays at rest until hold_until, then falls with g from rest.
TEST(RigidBody, HeldBlockIsReleasedAtHoldTime) {
  json j = block_scene(2, {1.6, 3.0}, {2.4, 3.5}, g);
  const double hold = 0.2, t = 0.5;
  j["bodies"][0]["rigid"] = {{"hold_until", hold}};
  const Scene scene = scene_from_json(j, "hold.json");
  Simulation<2> sim(scene);
  const double z0 = sim.rigid.bodies[0].centre[1];
  run_until(sim, hold);
  EXPECT_NEAR(sim.rigid.bodies[0].centre[1], z0, position_roundoff(1e-12, z0));
  EXPECT_EQ(sim.rigid.bodies[0].velocity.norm(), 0);
  run_until(sim, t);
  const double s = t - hold;
  EXPECT_NEAR(sim.rigid.bodies[0].velocity[1], -g * s, 0.01 * g * s);
  EXPECT_NEAR(z0 - sim.rigid.bodies[0].centre[1], 0.5 * g * s * s, 0.02 * 0.5 * g * s * s);
}

// The submerged block of scenes/rigid_rise_2d.json (0.4 m square, density 920, centred 1 m deep in a 4 m x 2 m
// pool) released at rest: its acceleration, the slope of its velocity over [0.1, 0.3] s (after the acoustic
// start-up: sqrt(K / rho) = 32 m/s crosses the block in 0.013 s), at cell size dx.
double rise_acceleration(double dx, std::vector<std::string> sets = {}) {
  sets.push_back("parameters.dx=" + std::to_string(dx));
  const Scene scene = load_scene(std::string(CDMPM_SOURCE_DIR) + "/scenes/rigid_rise_2d.json", sets);
  Simulation<2> sim(scene);
  double st = 0, sv = 0, stt = 0, stv = 0, n = 0;
  for (int k = 1; k <= 30; ++k) {
    run_until(sim, 0.01 * k);
    const double t = sim.time(), v = sim.rigid.bodies[0].velocity[1];
    if (t < 0.1 - 1e-9) continue;
    st += t, sv += v, stt += t * t, stv += t * v, ++n;
  }
  return (n * stv - st * sv) / (n * stt - st * st);
}
// The initial rise approaches potential flow under refinement: closer at D/16 than at D/8, and upwards.
TEST(RigidBody, SubmergedBlockRiseApproachesPotentialFlowUnderRefinement) {
  const double a_theory = testing::scene_rise_reference();
  const double a8 = rise_acceleration(0.05), a16 = rise_acceleration(0.025);
  std::printf("rise acceleration %.4f (D/8), %.4f (D/16) m/s^2, potential flow %.4f m/s^2\n", a8, a16, a_theory);
  EXPECT_GT(a16, 0);
  EXPECT_LT(std::abs(a16 - a_theory), std::abs(a8 - a_theory));
}

// The rise criterion: within 15 % of potential flow at D/16. The scene's water and block take their stress at
// the cell-mean J and a pure FLIP velocity update (j_bar, flip = 1: docs/water.md, "Buoyancy: J-bar and FLIP");
// without them the block rises at 0.17 m/s^2 (D/16), with flip = 0.99 at 0.31 m/s^2 (the block's velocity is
// noisy after 0.2 s with flip = 1). Met since the block is seeded at its own density (0.375 m/s^2, 9.7 % short of
// the reference at the water's density where the block is); seeded 1 % heavy it rose at 0.346, 17 % short.
TEST(RigidBody, SubmergedBlockStartsRisingAtPotentialFlowAcceleration) {
  const double a_theory = testing::scene_rise_reference(), a16 = rise_acceleration(0.025);
  std::printf("rise acceleration %.4f (D/16) m/s^2, potential flow %.4f m/s^2\n", a16, a_theory);
  EXPECT_NEAR(a16, a_theory, 0.15 * a_theory);
}

// The block in a field of its own, in frictionless contact with the water (rigid key `contact`,
// sim/rigid_contact.h), with XPIC(4) filtering the FLIP share of both (docs/water.md, "XPIC").
const std::vector<std::string> contact_sets = {"materials.block.contact=true", "materials.water.xpic=4",
                                               "materials.block.xpic=4"};

// In contact the rise approaches potential flow under refinement: closer at D/16 than at D/8 (0.317 and 0.337 m/s^2
// against 0.415). In the shared field the same XPIC(4) gives 0.165 and 0.241 m/s^2 (D/8, D/16), the contact with
// APIC's transfer 0.26 and 0.29 m/s^2 (docs/changelog.md, "Buoyancy coupling").
TEST(RigidBody, BlockInContactWithXpicRiseApproachesPotentialFlowUnderRefinement) {
  const double a_theory = testing::scene_rise_reference();
  const double a8 = rise_acceleration(0.05, contact_sets), a16 = rise_acceleration(0.025, contact_sets);
  std::printf("rise acceleration in contact, XPIC(4): %.4f (D/8), %.4f (D/16) m/s^2, potential flow %.4f m/s^2\n", a8,
              a16, a_theory);
  EXPECT_GT(a16, 0);
  EXPECT_LT(std::abs(a16 - a_theory), std::abs(a8 - a_theory));
}

// The rise criterion for the block in contact: within 15 % of potential flow at D/16. Not met: 0.337 m/s^2, 19 %
// short (it passed against 0.373 until 2026-12-06). What is short is the buoyancy the contact passes: the next test.
TEST(RigidBody, DISABLED_BlockInContactWithXpicRisesAtPotentialFlowAcceleration) {
  const double a_theory = testing::scene_rise_reference(), a16 = rise_acceleration(0.025, contact_sets);
  std::printf("rise acceleration in contact, XPIC(4): %.4f (D/16) m/s^2, potential flow %.4f m/s^2\n", a16, a_theory);
  EXPECT_NEAR(a16, a_theory, 0.15 * a_theory);
}

// A block of the water's density where it is (1009.6 kg/m^3) is neutrally buoyant: whatever its added mass it must
// not accelerate. Bound: the acceleration band of the rise criterion for the block of density 920, 15 % of its
// reference (0.062 m/s^2). Not met: in contact it sinks at 0.12 m/s^2 at D/8 and D/16; the contact passes it
// 97.5-98.4 % of the displaced water's weight, and the missing 1.6-2.5 % is a fifth to a quarter of the net buoyancy
// of the block of density 920 (docs/validation.md, "Buoyancy-driven motions"). Full contact (share 1) keeps it at
// rest (0.0000 m/s^2) but holds the water a kernel width out: the 920 block then rises at 0.236 m/s^2 (docs/changelog.md,
// "Buoyancy coupling", 2026-12-07).
TEST(RigidBody, DISABLED_NeutrallyBuoyantBlockInContactStaysAtRest) {
  std::vector<std::string> sets = contact_sets;
  sets.push_back(testing::neutral_block_density_set());
  const double band = 0.15 * testing::scene_rise_reference(), a16 = rise_acceleration(0.025, sets);
  std::printf("neutrally buoyant block in contact, XPIC(4): %.4f m/s^2 (D/16)\n", a16);
  EXPECT_NEAR(a16, 0, band);
}

// The pool of scenes/rigid_rise_float_2d.json stirred by the 0.4 m block rising 1 m through it (D/8 here, 10 s):
// water's mass and volume are conserved, so after the block has come up the level far from it (the gauge 0.3 m
// from the left wall, mean over the last 2 s) is where it started, up to the seiche that remains (speeds under
// 0.05 m/s: under 2 mm of wave in 2 m of water) and the block's displaced volume (at most 0.4 m x 0.032 m of
// freeboard over the pool's 4 m: 3 mm). Bound: a quarter cell, 12.5 mm. With water's `continuity` "interpolated"
// (J advanced with the divergence of the velocity that moves the particles, transfer/g2p.h) the level falls 7 mm;
// with "apic" the particles pack while their J stays near 1 and it falls 25 mm (docs/water.md, "Packing").
TEST(RigidBody, StirredPoolKeepsItsLevelWithInterpolatedContinuity) {
  using namespace cdmpm::testing;
  const double dx = 0.05;
  TempDir dir;
  const auto r = run_cdmpm({"run", std::string(CDMPM_SOURCE_DIR) + "/scenes/rigid_rise_float_2d.json", "--out",
                            dir / "out", "--quiet", "--set", "parameters.dx=" + std::to_string(dx), "--set",
                            "output.frames=false", "--set", "materials.water.continuity=interpolated"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto p = read_probes(dir / "out/probes.csv");
  const auto& t = p.at("time");
  const auto& level = p.at("level");
  double start = 0, end = 0, n0 = 0, n1 = 0, speed = 0;
  for (size_t i = 0; i < t.size(); ++i) {
    if (t[i] <= 0.5) start += level[i], ++n0;
    if (t[i] >= t.back() - 2.0) {
      end += level[i], ++n1;
      speed = std::max(speed, std::hypot(p.at("speed_x")[i], p.at("speed_y")[i]));
    }
  }
  ASSERT_GT(n0, 0);
  ASSERT_GT(n1, 0);
  std::printf("level %.4f m at the start, %.4f m over the last 2 s; block's largest speed %.4f m/s\n", start / n0,
              end / n1, speed);
  EXPECT_NEAR(end / n1, start / n0, dx / 4);
  EXPECT_LT(speed, 0.05);
}

// The float criterion: a block of density 920 and height H_b released 0.05 m under the surface of still
// water rises, reaches the surface and floats at the draft of Archimedes' principle, (920 / 1000) H_b, within 5 %
// (the draft: the water level 0.2 m from the left wall less the block's bottom, over the last second). Not met
// yet: without j_bar and flip the block stalls below its floating position (+19 %); with both (as
// scenes/rigid_rise_2d.json) the run goes unstable when the block reaches the surface (at 0.9 s with flip = 1,
// 3.1 s with 0.95; docs/water.md, "Buoyancy: J-bar and FLIP"). Set here: both with XPIC(4), which runs the 6 s
// but leaves the block still creeping up, too deep (docs/water.md, "XPIC"). The block in contact (rigid key
// `contact`) floats deeper still, +14 to +17 % (docs/changelog.md, "Buoyancy coupling", 2026-12-05). The 0.4 m block
// (scenes/rigid_rise_float_2d.json, 1 m deep) stays at the surface with the water's `continuity` "interpolated", but
// 18-31 % too deep at D/16; with "apic" it comes to 4 cm under the level and sinks back while the water packs
// (docs/validation.md, "Buoyancy-driven motions"). Run with
// --gtest_also_run_disabled_tests.
TEST(RigidBody, DISABLED_SubmergedBlockRisesAndFloatsAtArchimedesDraft) {
  const double H_b = 0.2;
  json j = testing::float_tank(0.25, 0.25 + H_b);
  j["bodies"][0]["surface_level"] = 0.5;
  for (const char* m : {"water", "block"})
    j["materials"][m].update(json::parse(R"({"j_bar": true, "flip": 1, "xpic": 4})"));
  const Scene scene = scene_from_json(j, "rise_and_float.json");
  Simulation<2> sim(scene);
  const double t_end = 6;
  double draft = 0, speed = 0, n = 0;
  for (int k = 1; k <= 120; ++k) {
    run_until(sim, 0.05 * k);
    if (sim.time() < t_end - 1.0 - 1e-9) continue;
    // The water level far from the block: the highest water particle in the column 0.15-0.25 m from the left wall.
    double level = 0;
    for (size_t q = 0; q < sim.particles.size(); ++q)
      if (sim.particles.material[q] != sim.rigid.bodies[0].material && sim.particles.x[q][0] > 0.15 &&
          sim.particles.x[q][0] < 0.25)
        level = std::max(level, static_cast<double>(sim.particles.x[q][1]));
    level += 0.25 * 0.025;  // the top particle sits a quarter cell (half a particle spacing) below the surface
    const auto& B = sim.rigid.bodies[0];
    draft += level - (B.centre[1] - H_b / 2);
    speed = std::max(speed, static_cast<double>(B.velocity.norm()));
    ++n;
  }
  testing::expect_archimedes_draft(draft / n, speed, H_b);
}

}  // namespace
}  // namespace cdmpm
