// test_rigid_body.cpp - rigid bodies (sim/rigid_bodies.h) against mechanics: free fall in air with g, exact
// conservation of linear and angular momentum of an isolated spinning block (2D and 3D), a hinged bar's
// initial angular acceleration m g d / I_o, a held block at rest until its release, and a block lighter than
// water floating at the draft of Archimedes' principle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "cli_helpers.h"
#include "scene/scene_loader.h"
#include "sim/simulation.h"

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
  while (sim.time() < t_end - 1e-12) {
    const Real dt = std::min<Real>(sim.stable_dt(), static_cast<Real>(t_end - sim.time()));
    sim.step(dt);  // advances sim.time()
  }
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

// A block of density 920 and height H_b, released with its bottom at the still water level in a 2 m wide
// tank, floats and comes to rest with draft d = (920 / 1000) H_b (Archimedes) within 5 %: draft = water level
// far from the block (gauge, absolute height) - bottom of the block (centre - H_b / 2), averaged over the
// last second; the block is then at rest (its speed is small against the heave speed sqrt(g d)).
TEST(RigidBody, LightBlockFloatsAtArchimedesDraft) {
  using namespace cdmpm::testing;
  const double H_b = 0.2, rho_b = 920, rho_w = 1000, level = 0.5;
  json j = json::parse(R"({
    "dim": 2,
    "domain": {"size": [2.0, 1.0], "dx": 0.025},
    "time": {"end": 6, "frame_interval": 0.5},
    "materials": {
      "water": {"type": "water", "density": 1000, "bulk_modulus": 4e5, "viscosity": 1e-3},
      "block": {"type": "rigid", "density": 920, "bulk_modulus": 4e5}
    },
    "bodies": [
      {"material": "block", "particles_per_cell": 4, "shape": {"type": "box", "min": [0.8, 0.45], "max": [1.2, 0.65]}},
      {"material": "water", "particles_per_cell": 4, "shape": {"type": "box", "min": [0, 0], "max": [2.0, 0.5]}}
    ],
    "boundaries": [{"type": "walls", "condition": "slip", "faces": ["x-", "x+", "y-"]}],
    "probes": {"interval": 0.05, "list": [
      {"name": "block", "type": "rigid_position", "material": "block"},
      {"name": "speed", "type": "rigid_velocity", "material": "block"},
      {"name": "angle", "type": "rigid_angle", "material": "block"},
      {"name": "level", "type": "wave_gauge", "position": [0.2], "still_level": 0}]},
    "output": {"frames": false}
  })");
  ASSERT_DOUBLE_EQ(j["bodies"][0]["shape"]["max"][1].get<double>() - j["bodies"][0]["shape"]["min"][1].get<double>(), H_b);
  ASSERT_DOUBLE_EQ(j["bodies"][1]["shape"]["max"][1].get<double>(), level);
  TempDir dir;
  std::ofstream(dir / "float.json") << j.dump();
  const auto r = run_cdmpm({"run", dir / "float.json", "--out", dir / "out", "--quiet"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto p = read_probes(dir / "out/probes.csv");
  const auto& t = p.at("time");
  double draft = 0, speed = 0, n = 0;
  for (size_t i = 0; i < t.size(); ++i)
    if (t[i] >= t.back() - 1.0) {
      draft += p.at("level")[i] - (p.at("block_y")[i] - H_b / 2);
      speed = std::max(speed, std::hypot(p.at("speed_x")[i], p.at("speed_y")[i]));
      EXPECT_NEAR(p.at("angle")[i], 0, std::max(1e-6, 1e3 * std::numeric_limits<Real>::epsilon()));  // symmetry
      ++n;
    }
  draft /= n;
  const double expected = rho_b / rho_w * H_b;
  std::printf("draft %.5f m (Archimedes %.5f m), largest speed over the last second %.5f m/s\n", draft, expected, speed);
  EXPECT_NEAR(draft, expected, 0.05 * expected);
  EXPECT_LT(speed, 0.05 * std::sqrt(g * expected));
}

}  // namespace
}  // namespace cdmpm
