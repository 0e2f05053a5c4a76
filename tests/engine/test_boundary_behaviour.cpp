// test_boundary_behaviour.cpp - what the boundaries do to material, through the whole engine step
// (boundary/boundary.h; Jiang et al. 2016 course notes, sec. 10), on short coarse 2D runs.
//
// An elastic ice block (E = 1e7 Pa, nu = 0.3, no plasticity, unstressed at t = 0) rests on a half-plane inclined
// at theta = 30 degrees (outward normal n = (sin theta, cos theta), downslope tangent s = (cos theta,
// -sin theta)), under gravity g. Newton for the block's centre of mass (velocities V_s, V_n, mass M), with the
// plane's normal force N(t) and tangential force T(t):
//   M dV_s/dt = M g sin theta - T,   M dV_n/dt = N - M g cos theta.
//   * Slip: the condition removes only the normal component of a node's velocity, so T = 0; the transfers
//     conserve momentum exactly (APIC p2g and g2p: sum_i w_ip = 1, sum_i w_ip (x_i - x_p) = 0), so
//     V_s(t) = g sin theta t to round-off (relative 1e-9 covers the ~1e-13 of one step's sums over the
//     steps taken).
//   * Coulomb friction mu < tan theta: every node the plane pushes slides, and its tangential impulse is mu times
//     its normal impulse, so T = mu N and V_s(t) = g (sin theta - mu cos theta) t - mu (V_n(t) - V_n(0)).
//     V_n stays within the block's elastic settling speed: the unstressed block settles onto the plane over a
//     quarter of its lowest period, h / c_s (h its height, c_s = sqrt(mu_s / rho) the shear wave speed, the
//     slowest of its waves, so the longest period), at most at the speed free fall reaches in that time,
//     g h / c_s. Hence |V_s - g (sin theta - mu cos theta) t| <= mu g h / c_s.
//   * Coulomb friction mu > tan theta: T <= mu N balances the pull g sin theta, and a sliding block decelerates at
//     g (mu cos theta - sin theta): on average dV_s/dt <= 0. The elastic block vibrates about its mean motion
//     (APIC hardly damps it; the node-wise separate and Coulomb conditions even rectify the vibration into a
//     slow creep of the order of its amplitude, so the block need not come exactly to rest), with a velocity
//     amplitude of at most g h / (2 c_s) (suddenly loaded fixed-free bar: v = g y / c behind the front, its
//     mean g h / (2 c) at t = h / c). So V_s(t) - V_s(t/2) <= g h / c_s, where the frictionless block gains
//     g sin theta t / 2 (here 16 times more) and mu = 0.4 < tan theta would gain 5 times more.
// A bathymetry (solid below a polyline): a water block dropped onto a straight sloping bed. Material may
// enter the solid only while some node of its stencil lies outside the solid: the separate condition gives
// every node inside v.n >= 0, and v_p.n = sum_i w_ip v_i.n, so a particle whose 3 x 3 stencil lies wholly in
// the solid cannot move deeper. The stencil reaches 1.5 dx along each axis, i.e. 1.5 (|n_x| + |n_y|) dx
// along n, plus one step's advection dt |v| <= cfl dx: no particle may lie deeper than that. Without the
// bathymetry the block would have fallen through it by metres.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scene/scene_loader.h"
#include "sim/simulation.h"

namespace cdmpm {
namespace {

constexpr double g = 9.81;
const double theta = std::numbers::pi / 6;
const Vec<2> n_plane(std::sin(theta), std::cos(theta)), s_plane(std::cos(theta), -std::sin(theta));

// Ice block L x h resting on the inclined half-plane through (3, 1.5) (solid below), under gravity.
constexpr double L = 1.0, h = 0.5, E = 1e7, nu = 0.3, rho = 900;

nlohmann::json incline_scene(const std::string& condition, double friction) {
  const Vec<2> p0(3, 1.5), b0 = p0 - 0.5 * L * s_plane, b1 = p0 + 0.5 * L * s_plane;
  const Vec<2> t1 = b1 + h * n_plane, t0 = b0 + h * n_plane;
  nlohmann::json plane = {{"type", "half_plane"}, {"condition", condition}, {"point", {p0[0], p0[1]}},
                          {"normal", {n_plane[0], n_plane[1]}}};
  if (friction > 0) plane["friction"] = friction;
  return {{"dim", 2},
          {"domain", {{"size", {6.0, 4.0}}, {"dx", 0.1}}},
          {"time", {{"end", 0.5}, {"frame_interval", 0.5}}},
          {"materials", {{"ice", {{"type", "ice"}, {"density", rho}, {"youngs_modulus", E}, {"poissons_ratio", nu},
                                  {"plastic", false}}}}},
          {"bodies", {{{"material", "ice"}, {"particles_per_cell", 4}, {"hydrostatic", false},
                       {"shape", {{"type", "polygon"},
                                  {"vertices", {{b0[0], b0[1]}, {b1[0], b1[1]}, {t1[0], t1[1]}, {t0[0], t0[1]}}}}}}}},
          {"boundaries", {plane}},
          {"output", {{"frames", false}}}};
}

struct Motion {
  double Vs, Vn, t, Vs_half;  // Vs_half: V_s at t/2
};

Motion run_incline(const std::string& condition, double friction) {
  const Scene scene = scene_from_json(incline_scene(condition, friction), "incline.json");
  Simulation<2> sim(scene);
  EXPECT_GT(sim.particles.size(), 150u);
  auto mean_velocity = [&] {
    double M = 0;
    Vec<2> P = Vec<2>::Zero();
    for (size_t q = 0; q < sim.particles.size(); ++q) {
      M += sim.particles.mass[q];
      P += sim.particles.mass[q] * sim.particles.v[q];
    }
    return Vec<2>(P / M);
  };
  const double half = 0.5 * scene.time.end;
  sim.run_until(half);
  const double Vs_half = mean_velocity().dot(s_plane);
  sim.run_until(scene.time.end);
  const Vec<2> V = mean_velocity();
  return {V.dot(s_plane), V.dot(n_plane), sim.time(), Vs_half};
}

// Settling speed bound g h / c_s (see the header; twice the vibration amplitude).
double settling_speed() {
  const double shear_modulus = E / (2 * (1 + nu));
  return g * h / std::sqrt(shear_modulus / rho);
}

TEST(BoundaryBehaviour, BlockOnASlipInclineAcceleratesAtGSinTheta) {
  const Motion m = run_incline("slip", 0);
  const double expected = g * std::sin(theta) * m.t;
  EXPECT_NEAR(m.Vs, expected, 1e-9 * expected);
}

TEST(BoundaryBehaviour, BlockOnAFrictionalInclineSlidesAtGSinMinusMuCos) {
  const double mu = 0.3;  // < tan 30 deg = 0.577
  const Motion m = run_incline("separate", mu);
  const double expected = g * (std::sin(theta) - mu * std::cos(theta)) * m.t;
  EXPECT_NEAR(m.Vs, expected, mu * settling_speed()) << "V_n = " << m.Vn;
}

TEST(BoundaryBehaviour, BlockOnARougherInclineDoesNotAccelerate) {
  const double mu = 0.8;  // > tan 30 deg
  const Motion m = run_incline("separate", mu);
  EXPECT_LE(m.Vs - m.Vs_half, settling_speed())
      << "V_s " << m.Vs_half << " -> " << m.Vs << "; frictionless it would gain " << g * std::sin(theta) * m.t / 2;
}

// Water block 1 m x 0.5 m, bottom 0.5 m above the bed y = 1.2 - 0.2 x (slope 0.2), in a 4 m x 3 m tank.
TEST(BoundaryBehaviour, WaterDoesNotPenetrateTheBathymetry) {
  const double dx = 0.05, cfl = 0.4;
  auto bed = [](double x) { return 1.2 - 0.2 * x; };
  nlohmann::json j = {
      {"dim", 2},
      {"domain", {{"size", {4.0, 3.0}}, {"dx", dx}}},
      {"time", {{"end", 0.6}, {"frame_interval", 0.6}, {"cfl", cfl}}},
      {"materials", {{"water", {{"type", "water"}, {"density", 1000}, {"bulk_modulus", 1e5}}}}},
      {"bodies", {{{"material", "water"}, {"particles_per_cell", 4}, {"hydrostatic", false},
                   {"shape", {{"type", "box"}, {"min", {1.5, 1.4}}, {"max", {2.5, 1.9}}}}}}},
      {"boundaries", {{{"type", "bathymetry"}, {"condition", "separate"}, {"points", {{0.0, bed(0)}, {4.0, bed(4)}}}},
                      {{"type", "walls"}, {"condition", "slip"}}}},
      {"output", {{"frames", false}}}};
  const Scene scene = scene_from_json(j, "bathymetry.json");
  Simulation<2> sim(scene);
  const Vec<2> n = Vec<2>(0.2, 1).normalized();
  const double allowed = (1.5 * (std::abs(n[0]) + std::abs(n[1])) + cfl) * dx;
  double deepest = 0, mean_height = 0;
  while (sim.time() < scene.time.end) {
    sim.step(sim.stable_dt());
    for (size_t q = 0; q < sim.particles.size(); ++q) {
      const auto& x = sim.particles.x[q];
      deepest = std::max(deepest, (bed(x[0]) - x[1]) * n[1]);  // depth below the bed along n
    }
  }
  for (size_t q = 0; q < sim.particles.size(); ++q)
    mean_height += (sim.particles.x[q][1] - bed(sim.particles.x[q][0])) / sim.particles.size();
  EXPECT_LE(deepest, allowed);
  // Free fall over 0.6 s would have carried the block's centre 1.77 m down, 1 m through the bed: it rests on it.
  EXPECT_GT(mean_height, 0);
}

}  // namespace
}  // namespace cdmpm
