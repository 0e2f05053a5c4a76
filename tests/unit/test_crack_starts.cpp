// test_crack_starts.cpp - the crack-start record (probe/crack_starts.h) and the shear strength of the ice model.
//   CrackMode         (unit) the mode rule on the reference stress states; the record's checkpoint form.
//   ShearStrength     (unit) the pure-shear strength of the yield surface (cohesive_cam_clay.h shear_strength)
//                     and its von Mises limits against the uniaxial tensile strength.
//   SimpleShear       (engine) a block of ice in homogeneous simple shear (scenes/ice_shear_2d.json) reaches the
//                     yield surface's shear strength, softens, and its crack starts are recorded as "shear".
//   CrackStartsBar    (engine) the bar pulled in tension (scenes/ice_bar_2d.json) records "tension".
//   CrackStartsCli    (end-to-end) the record (crack_starts.csv, summary.json) is the same on 1 and 2 threads
//                     and after a resume.
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

// ---- the mode rule --------------------------------------------------------------------------------------------

// p, q of a Cauchy stress in the record's convention.
template <int dim>
CrackMode mode_of(const Mat<dim>& s) {
  double p = 0, q = 0, s1 = 0;
  stress_state<dim>(s, p, q, s1);
  return crack_mode(p, q, dim);
}

TEST(CrackMode, ReferenceStatesOfTheRule) {
  const double t = 1e6;
  // Uniaxial tension, hydrostatic tension (the tensile tip): tension. Pure shear, uniaxial compression: shear.
  EXPECT_EQ(mode_of<2>((Mat<2>() << t, 0, 0, 0).finished()), CrackMode::tension);
  EXPECT_EQ(mode_of<2>((Mat<2>() << t, 0, 0, t).finished()), CrackMode::tension);
  EXPECT_EQ(mode_of<2>((Mat<2>() << 0, t, t, 0).finished()), CrackMode::shear);
  EXPECT_EQ(mode_of<2>((Mat<2>() << -t, 0, 0, 0).finished()), CrackMode::shear);
  EXPECT_EQ(mode_of<3>((Mat<3>() << t, 0, 0, 0, 0, 0, 0, 0, 0).finished()), CrackMode::tension);
  EXPECT_EQ(mode_of<3>((Mat<3>() << 0, t, 0, t, 0, 0, 0, 0, 0).finished()), CrackMode::shear);
  // The dividing line in 2D is sigma_2 = -sigma_1 / 3 (halfway in triaxiality between pure shear and uniaxial
  // tension): just above it tension, just below it shear.
  EXPECT_EQ(mode_of<2>((Mat<2>() << t, 0, 0, -0.33 * t).finished()), CrackMode::tension);
  EXPECT_EQ(mode_of<2>((Mat<2>() << t, 0, 0, -0.34 * t).finished()), CrackMode::shear);
  // sigma_1 is the largest principal stress: a pure shear t has sigma_1 = t; p is positive in compression.
  double p = 0, q = 0, s1 = 0;
  stress_state<2>((Mat<2>() << 0, t, t, 0).finished(), p, q, s1);
  EXPECT_NEAR(s1, t, 1e-9 * t);
  EXPECT_NEAR(q, std::sqrt(3.0) * t, 1e-9 * t);
  stress_state<3>((Mat<3>() << -t, 0, 0, 0, -t, 0, 0, 0, -t).finished(), p, q, s1);
  EXPECT_NEAR(p, t, 1e-9 * t);
  EXPECT_NEAR(s1, -t, 1e-9 * t);
}

TEST(CrackMode, RecordSavesAndLoadsAndRefusesBadRecords) {
  CrackStartRecord<2> a;
  std::vector<double> v = {12, 0.5, 7, 1.25, 2.5, -3e5, 4e5, 6e5, 1, 13, 0.625, 9, 0.5, 0.75, 1e5, 2e5, 3e5, 0};
  ASSERT_TRUE(a.load(v));
  ASSERT_EQ(a.events().size(), 2u);
  EXPECT_EQ(a.events()[0].mode, CrackMode::shear);
  EXPECT_EQ(a.events()[1].id, 9u);
  EXPECT_EQ(a.save(), v);
  std::vector<double> bad = v;
  bad[8] = 2;  // a mode other than 0 / 1
  EXPECT_FALSE(a.load(bad));
  bad = v;
  bad.pop_back();  // not whole events
  EXPECT_FALSE(a.load(bad));
  bad = v;
  bad[3] = std::nan("");
  EXPECT_FALSE(a.load(bad));
  EXPECT_EQ(a.save(), v);  // a refused record leaves the record unchanged
}

// ---- the shear strength of the yield surface -------------------------------------------------------------------

TEST(ShearStrength, LiesOnTheYieldSurfaceAndHasTheVonMisesLimits) {
  CohesiveCamClay c;
  for (double M : {0.3, 1.0, 1.85})
    for (double beta : {0.05, 0.3, 1.0}) {
      c.M = M;
      c.beta = beta;
      const double p0 = 1e7, ts = c.shear_strength(p0);
      // p = 0, q = sqrt(3) tau_s is on the surface: y = 0 to rounding (y scales as p0^2 M^2).
      EXPECT_NEAR(c.yield(0, std::sqrt(3.0) * ts, p0), 0, 1e-12 * M * M * p0 * p0) << M << ' ' << beta;
      // The same through the invariants of the stress tensor itself.
      Mat<2> tau = Mat<2>::Zero();
      tau(0, 1) = tau(1, 0) = ts;
      EXPECT_NEAR(CohesiveCamClay{}.mises<2>(tau), std::sqrt(3.0) * ts, 1e-12 * ts);
    }
  // von Mises limit (M -> 0): tau_s / sigma_t -> 1/2 in 2D (the in-plane convention), 1/sqrt(3) in 3D. The
  // correction is of order the strength over p0, i.e. M: M = 1e-4 leaves it below 1e-3.
  c.M = 1e-4;
  c.beta = 0.3;
  EXPECT_NEAR(c.shear_strength(1) / c.uniaxial_strength<2>(1, true), 0.5, 1e-3);
  EXPECT_NEAR(c.shear_strength(1) / c.uniaxial_strength<3>(1, true), 1 / std::sqrt(3.0), 1e-3);
  // Away from it the ratio rises: the scenes' ice (M = 1.85, beta = 0.1) is 1.68 in 2D (docs/ice.md).
  c.M = 1.85;
  c.beta = 0.1;
  EXPECT_GT(c.shear_strength(1) / c.uniaxial_strength<2>(1, true), 1.6);
}

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

// ---- the program: threads and resume ---------------------------------------------------------------------------

TEST(CrackStartsCli, SameRecordOnOneAndTwoThreadsAndAfterAResume) {
  testing::TempDir dir;
  // Pulled at 0.3 /s the bar breaks from t = 3.33 ms on, and the record of 64 events is full at 4.3 ms. The half
  // run stops at the frame time 4 ms (an output time of the straight run too, so both take the same steps) with
  // 40 events: the resumed run must continue the record it loaded from the checkpoint.
  const std::string err = testing::run_straight_other_threads_and_resumed(
      dir, testing::source_path("scenes/ice_bar_2d.json"),
      {"--quiet", "--set", "output.frames=false", "--set", "parameters.strain_rate=0.3"}, "1", "2", "0.004", "0.006");
  ASSERT_EQ(err, "");
  const std::string full = testing::read_bytes(dir / "full/crack_starts.csv");
  ASSERT_NE(full.find('\n'), std::string::npos);
  ASSERT_GT(std::count(full.begin(), full.end(), '\n'), 1) << "no crack start recorded";
  EXPECT_EQ(full, testing::read_bytes(dir / "other/crack_starts.csv")) << "differs between 1 and 2 threads";
  EXPECT_EQ(full, testing::read_bytes(dir / "half/crack_starts.csv")) << "differs after a resume";
  const auto a = testing::read_json(dir / "full/summary.json"), b = testing::read_json(dir / "other/summary.json"),
             c = testing::read_json(dir / "half/summary.json");
  ASSERT_TRUE(a["first_iceberg"].is_object());
  ASSERT_TRUE(a["first_iceberg"]["crack_start"].is_object());
  EXPECT_EQ(a["first_iceberg"]["crack_start"]["mode"], "tension");
  EXPECT_EQ(a["first_iceberg"], b["first_iceberg"]);
  EXPECT_EQ(a["first_iceberg"], c["first_iceberg"]);
}

}  // namespace
}  // namespace cdmpm
