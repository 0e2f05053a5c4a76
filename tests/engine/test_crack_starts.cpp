// test_crack_starts.cpp - the crack-start record (probe/crack_starts.h) and the shear strength of the ice model.
//   SimpleShear       a block of ice in homogeneous simple shear (scenes/ice_shear_2d.json) reaches the
//                     yield surface's shear strength, softens, and its crack starts are recorded as "shear".
//   CrackStartsBar    the bar pulled in tension (scenes/ice_bar_2d.json) records "tension".
// The mode rule and the shear strength: tests/unit/test_crack_mode.cpp; the record through the program:
// tests/end_to_end/test_crack_starts_cli.cpp.
//
// The simple-shear test works like the uniaxial bar (test_ice_bar.cpp): the 2 m x 2 m block starts with the
// affine velocity field of homogeneous simple shear, v_x = gamma' (y - c), v_y = 0 (APIC C = [[0, gamma'], [0, 0]]).
// In the interior the stress is uniform, so div sigma = 0 and the field does not change: the shear strain grows as
// gamma' t with J = det(I + dt C) = 1 exactly (C is nilpotent), i.e. p = 0, until the disturbances from the free
// faces reach the measured middle square |x - c|, |y - c| < 0.25 m, at the earliest (1 - 0.25) m / c_p.
// The shear strain rate is chosen so that the yield strain tau_s / mu is reached in a quarter of that time.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <string>

#include "cli_helpers.h"
#include "material/stress.h"
#include "probe/crack_starts.h"
#include "scene/scene_loader.h"
#include "sim/simulation.h"

namespace cdmpm {
namespace {

using testing::set_value;

// ---- simple shear through the engine ---------------------------------------------------------------------------

Scene shear_scene(double rate, double end) {
  return load_scene(testing::source_path("scenes/ice_shear_2d.json"),
                    {set_value("parameters.shear_rate", rate), set_value("parameters.end", end), "output.frames=false"});
}

struct ShearRun {
  double peak = 0, p_at_peak = 0, time_at_peak = 0, final_stress = 0, max_dt = 0;
  std::vector<CrackStart<2>> events;
};

ShearRun run_shear(double rate, double end, double centre) {
  const Scene scene = shear_scene(rate, end);
  Simulation<2> sim(scene);
  const Material& m = sim.materials[0];
  ShearRun r;
  while (sim.time() < end) {
    const Real dt = std::min<Real>(sim.stable_dt(), static_cast<Real>(end - sim.time()));
    r.max_dt = std::max<double>(r.max_dt, dt);
    sim.step(dt);
    double txy = 0, p = 0, vol = 0;
    for (size_t q = 0; q < sim.particles.size(); ++q) {
      const Vec<2> d = sim.particles.x[q] - Vec<2>::Constant(static_cast<Real>(centre));
      if (std::abs(d[0]) > 0.25 || std::abs(d[1]) > 0.25) continue;
      const double V = reference_volume(m, sim.particles.mass[q]);
      const Mat<2> tau = kirchhoff_stress(m, sim.particles, q);
      txy += V * tau(0, 1);
      p += V * CohesiveCamClay::pressure<2>(tau);
      vol += V;
    }
    if (txy / vol > r.peak) r.peak = txy / vol, r.p_at_peak = p / vol, r.time_at_peak = sim.time();
    r.final_stress = txy / vol;
  }
  r.events = sim.crack_starts.events();
  return r;
}

TEST(SimpleShear, PeakIsTheYieldSurfacesShearStrengthAndTheCrackStartsInShear) {
  const Scene probe = shear_scene(1, 1);
  Simulation<2> sim(probe);
  const Ice& ice = std::get<Ice>(sim.materials[0].model);
  const double tau_s = ice.plastic.shear_strength(ice.p0_initial);
  const double centre = probe.parameters.at("centre");
  const double mu = ice.elastic.mu, cp = std::sqrt(ice.elastic.p_wave_modulus<2>() / ice.rho0);
  const double release = 0.75 / cp;             // the free faces' disturbance reaches the middle square
  const double rate = tau_s / mu / (0.25 * release);  // yield strain tau_s / mu at a quarter of it
  const ShearRun r = run_shear(rate, 0.9 * release, centre);
  // Below the surface by at most the stress change of one step (mu gamma' dt), on it once yielded: the return
  // mapping projects onto the surface of the step's initial p0, and the middle square is homogeneous. Above it
  // only by rounding; 1e-3 tau_s also covers the second-order normal stresses of finite shear (gamma^2 ~ 1e-5).
  const double one_step = mu * rate * r.max_dt;
  std::printf("simple shear: peak %.6g Pa at t = %.4g s (p = %.3g Pa), yield surface tau_s = %.6g Pa, one step %.3g Pa, "
              "final %.4g Pa; %zu crack starts\n",
              r.peak, r.time_at_peak, r.p_at_peak, tau_s, one_step, r.final_stress, r.events.size());
  EXPECT_GT(r.peak, tau_s - one_step - 1e-3 * tau_s);
  EXPECT_LT(r.peak, tau_s * (1 + 1e-3));
  EXPECT_LT(std::abs(r.p_at_peak), 1e-3 * tau_s) << "not pure shear: J drifted";
  EXPECT_LT(r.time_at_peak, 0.5 * release);
  EXPECT_LT(r.final_stress, 0.5 * r.peak) << "no softening after the peak";
  // The crack starts. The block breaks everywhere in a few steps, and the record (64 cells, in id order within a
  // step) fills in the first of them with the lowest ids, one column of particles 0.14 m inside the left face, which
  // the free face's release has not yet reached (c_s t = 0.135 m): every one of them must be shear, none before the peak.
  ASSERT_FALSE(r.events.empty());
  for (const CrackStart<2>& e : r.events) {
    EXPECT_EQ(e.mode, CrackMode::shear) << "event at (" << e.x[0] << ", " << e.x[1] << "): p " << e.p << " q " << e.q;
    EXPECT_GE(e.time, r.time_at_peak);
  }
  EXPECT_EQ(r.events.front().mode, CrackMode::shear);
}

// ---- the bar in tension ----------------------------------------------------------------------------------------

TEST(CrackStartsBar, BarPulledInTensionRecordsTension) {
  // The loading of IceBar.TensilePeakMatchesYieldSurfaceAndSoftens (test_ice_bar.cpp).
  const Scene probe = load_scene(testing::source_path("scenes/ice_bar_2d.json"), {"output.frames=false"});
  const nlohmann::json& mj = probe.json.at("materials").at("ice");
  const double E = mj.at("youngs_modulus").get<double>(), nu = probe.parameters.at("nu");
  const double rho = mj.at("density").get<double>(), sigma_t = mj.at("tensile_strength").get<double>();
  const NeoHookeanSplit el = NeoHookeanSplit::from_young_poisson(E, nu);
  const double release = 1.5 / std::sqrt(el.p_wave_modulus<2>() / rho);
  const double rate = sigma_t * (1 - nu * nu) / E / (0.25 * release), end = 0.9 * release;
  const Scene scene = load_scene(testing::source_path("scenes/ice_bar_2d.json"),
                                 {set_value("parameters.strain_rate", rate), set_value("parameters.end", end), "output.frames=false"});
  Simulation<2> sim(scene);
  sim.run_until(end);
  const auto& events = sim.crack_starts.events();
  ASSERT_FALSE(events.empty()) << "the bar did not break";
  // The record fills with the first crossings, 1.0-1.6 m from the middle (t = 1.2-1.5 ms, after the peak at
  // 1 ms); the whole bar is in uniaxial tension (or at the tensile tip), so every one must be tension.
  for (const CrackStart<2>& e : events) {
    EXPECT_EQ(e.mode, CrackMode::tension) << "event at x = " << e.x[0] << ": p " << e.p << " q " << e.q;
    EXPECT_GT(e.sigma_1, 0);
  }
  EXPECT_EQ(events.front().mode, CrackMode::tension);
  std::printf("bar: %zu crack starts, first at t = %.4g s x = %.4g m\n", events.size(), events.front().time,
              events.front().x[0]);
}

}  // namespace
}  // namespace cdmpm
