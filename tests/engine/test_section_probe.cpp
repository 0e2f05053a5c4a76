// test_section_probe.cpp - the "section" probe (probe/section.cpp), the far-field hand-off to a shallow-water
// model: a long wave released in a tank (a box of water a high and w long against the wall at x = 0, the
// Cauchy-Poisson release of scenes/wave_celerity_2d.json made long) passes the section;
//   - mass balance: the volume that passes, the integral of q dt, equals the change of the water volume beyond
//     the section measured from the particles' own volumes (V = J m / rho0), within 2 % (the bound);
//   - linear long-wave theory: u_bar = c eta / h, c = sqrt(g h), within 10 % (the bound), at the crest
//     and as the regression of u_bar on eta over the wave's passage;
//   - 3D: the stations of a line, a uniform current's exact answer and the same mass balance across a channel;
//   - a dry station (eta NaN, d = u = q = 0);
// Input errors: tests/unit/test_section_probe_input.cpp; through the program (exit code 2, probes.csv the same bytes
// on 1 and 2 threads and after a resume): tests/end_to_end/test_section_probe_cli.cpp.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <bit>
#include <cstdio>
#include <cmath>
#include <fstream>

#include "cli_helpers.h"
#include "probe/probes.h"
#include "scene/scene_loader.h"
#include "sim/simulation.h"
#include "scene_builders.h"

namespace cdmpm::testing {
namespace {

constexpr double g = 9.81, rho = 1000;

// Volume of the water beyond x = X [m^2 in 2D, m^3 in 3D] from the particles' volumes V = J m / rho0, each
// counted with the fraction of its cell-wide slab [x - dx/2, x + dx/2] beyond X: a linear ramp, so a lattice of
// particles (2 per dx) crossing the section changes it continuously and not in steps of a particle column.
// Independent of the probe: it uses no velocity and no surface.
template <int dim>
double volume_beyond(const Simulation<dim>& sim, double X) {
  const auto& P = sim.particles;
  double v = 0;
  for (size_t q = 0; q < P.size(); ++q) {
    const double f = std::clamp((P.x[q][0] - X) / sim.grid.dx + 0.5, 0.0, 1.0);
    v += f * P.J[q] * P.mass[q] / rho;
  }
  return v;
}

// The engine on one thread while it lives: with libgomp's default spinning (the test binary does not set the
// wait policy as cdmpm does), 2 threads on the shared 2-core host ran the 2D case in 79 s instead of 10 s. The
// probe's independence of the thread count is checked apart (sample_on_1_and_2_threads, the Cli test).
struct OneThread {
  const int saved = omp_get_max_threads();
  OneThread() { omp_set_num_threads(1); }
  ~OneThread() { omp_set_num_threads(saved); }
};

// Steps `sim` to `t_end`, landing on every multiple of `interval`, and calls sample() there (and at t = 0).
template <int dim, class F>
void run_sampled(Simulation<dim>& sim, double t_end, double interval, F&& sample) {
  sample();
  for (long k = 1; k * interval <= t_end + 1e-9; ++k) {
    const double t_next = k * interval;
    while (sim.time() < t_next - 1e-12) {
      const double dt = sim.stable_dt();
      if (sim.time() + dt >= t_next - 1e-12) sim.step_until(t_next);
      else sim.step(static_cast<Real>(dt));
    }
    sample();
  }
}

// Samples the probes on 1 and on 2 threads, expects the same bits, and returns the sample.
template <int dim>
std::vector<double> sample_on_1_and_2_threads(const Probes<dim>& probes, const Simulation<dim>& sim) {
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const std::vector<double> one = probes.sample(sim);
  omp_set_num_threads(2);
  const std::vector<double> two = probes.sample(sim);
  omp_set_num_threads(threads);
  EXPECT_EQ(one.size(), two.size());
  for (size_t i = 0; i < one.size() && i < two.size(); ++i)
    EXPECT_EQ(std::bit_cast<uint64_t>(one[i]), std::bit_cast<uint64_t>(two[i])) << "value " << i;
  return one;
}

// 2D: h = 0.5 m (not 1, so that a lost depth factor shows), a = h / 8 over w = 6 h, a 20 h tank, dx = h / 8 (the
// raised box is two particle layers), section at X = 10 h, for 22 h / c = 5.0 s (c = sqrt(g h) = 2.2 m/s).
// Linear theory splits the box into two halves of a/2 that run apart at c; the one running left reflects at the
// wall, so a hump of a/2 = h / 16 and 2 w = 12 h long passes X between (X - w) / c = 4 h / c and
// (X + w) / c = 16 h / c: a long wave, its wavelength 2 * 12 h gives k h = 0.26, where
// c(k) = sqrt(g tanh(kh) / k) is 1.1 % below sqrt(g h); its amplitude h / 16 makes u_bar of the simple wave,
// 2 (sqrt(g (h + eta)) - c), 1.5 % below c eta / h. Its leading crest is higher than a/2 and shorter (the
// dispersive front of a released box), so c(k) is lower there. The reflection from the far wall returns to X at
// (2 L - w - X) / c = 24 h / c, after the run.
TEST(SectionProbe, LongWaveFluxBalancesTheVolumeAndFollowsLinearTheory) {
  const double h = 0.5, a = h / 8, w = 6 * h, L = 20 * h, X = 10 * h, T = 22 * h / std::sqrt(g * h);
  const double interval = 0.01;
  nlohmann::json j = section_tank(2, h, a, w, L, 0, h / 8, {{"position", {X}}});
  j["probes"]["list"].push_back({{"name", "gauge"}, {"type", "wave_gauge"}, {"position", {X}}});
  const Scene scene = scene_from_json(j, "<section_2d>");
  Simulation<2> sim(scene);
  Probes<2> probes(scene, sim);
  EXPECT_EQ(probes.csv_header(), "time,s_eta,s_d,s_u,s_q,gauge");
  std::vector<double> t, eta, d, u, q, beyond;
  const OneThread one_thread;
  run_sampled(sim, T, interval, [&] {
    const std::vector<double> row = probes.sample(sim);
    t.push_back(sim.time());
    eta.push_back(row[0]), d.push_back(row[1]), u.push_back(row[2]), q.push_back(row[3]);
    EXPECT_EQ(row[0], row[4]) << "eta is the wave gauge's, t = " << sim.time();
    beyond.push_back(volume_beyond(sim, X));
  });
  // The still water: eta = 0 and d = h at t = 0 (the first particle layer sits half a spacing above the bed).
  EXPECT_NEAR(eta[0], 0, 1e-12);
  EXPECT_NEAR(d[0], h, 1e-9);
  EXPECT_EQ(q[0], 0);

  // (a) Mass balance: the integral of q dt (trapezoidal rule) against the volume change beyond X, at every
  // sample (the bound: 2 % of what has passed at the end, the volume a w of the raised box).
  double passed = 0, worst = 0;
  for (size_t i = 1; i < t.size(); ++i) {
    passed += 0.5 * (q[i] + q[i - 1]) * (t[i] - t[i - 1]);
    worst = std::max(worst, std::abs(passed - (beyond[i] - beyond[0])));
  }
  const double moved = beyond.back() - beyond[0];
  // Most of the raised box has gone past: a w less what is still within the trailing waves.
  EXPECT_GT(moved, 0.8 * a * w);
  std::printf("2D section: %zu particles, %lld steps; integral of q dt %.6g m^2, volume change %.6g m^2 (%+.2f %%), "
              "largest imbalance %.3g m^2\n", sim.particles.size(), sim.steps(), passed, moved,
              100 * (passed / moved - 1), worst);
  EXPECT_NEAR(passed, moved, 0.02 * moved) << "integral of q dt " << passed << ", volume change " << moved;
  EXPECT_LT(worst, 0.02 * moved) << "largest imbalance during the run";

  // (b) Long wave: u_bar = c eta / h, c = sqrt(g h). At the crest (the largest eta), and as the least-squares
  // slope of u_bar against eta through the origin over the whole record.
  const double c = std::sqrt(g * h);
  size_t crest = 0;
  for (size_t i = 0; i < t.size(); ++i)
    if (eta[i] > eta[crest]) crest = i;
  EXPECT_GT(eta[crest], 0.3 * a);  // a/2 in linear theory; the crest is a real wave, not noise
  EXPECT_NEAR(u[crest], c * eta[crest] / h, 0.10 * c * eta[crest] / h) << "crest at t = " << t[crest];
  double su = 0, se = 0;
  for (size_t i = 0; i < t.size(); ++i) su += u[i] * eta[i], se += eta[i] * eta[i];
  EXPECT_NEAR(su / se, c / h, 0.10 * c / h) << "regression slope of u_bar on eta";
  std::printf("2D section: crest eta %.4g m at t = %.3g s, u_bar / (c eta / h) = %.4f; regression slope / (c / h) = "
              "%.4f\n", eta[crest], t[crest], u[crest] / (c * eta[crest] / h), su / se / (c / h));
  // The same bits on 1 and 2 threads (the probe's sums run serially in particle order).
  sample_on_1_and_2_threads(probes, sim);
  // d = h + eta throughout (the bed is the lowest water, half a spacing below the first layer).
  for (size_t i = 0; i < t.size(); ++i) EXPECT_NEAR(d[i], h + eta[i], 0.01 * h) << "t = " << t[i];
}

// 3D: a water layer of depth h moving as one at (U, V): every station of the line reads eta = 0, d = h,
// u = U, v = V, q = h (U, V) exactly (to rounding); the same bits on 1 and 2 threads.
TEST(SectionProbe, Line3DStationsReadAUniformCurrent) {
  const double h = 0.5, U = 0.3, V = -0.2;
  nlohmann::json j = section_tank(3, h, 0, 0.5, 2, 1, 0.1, {{"start", {0.3, 0.2}}, {"end", {1.7, 0.8}}, {"points", 5}});
  j["bodies"].erase(0);
  j["bodies"][0]["shape"]["min"] = {0, 0, 0};
  j["bodies"][0]["velocity"] = {U, V, 0};
  const Scene scene = scene_from_json(j, "<section_3d>");
  Simulation<3> sim(scene);
  Probes<3> probes(scene, sim);
  std::string header = "time";
  for (int k = 0; k < 5; ++k)
    for (const char* f : {"eta", "d", "u", "v", "qx", "qy"}) header += ",s_" + std::to_string(k) + "_" + f;
  EXPECT_EQ(probes.csv_header(), header);
  const std::vector<double> one = sample_on_1_and_2_threads(probes, sim);
  ASSERT_EQ(one.size(), 30u);
  for (int k = 0; k < 5; ++k) {
    const double* s = &one[6 * k];
    EXPECT_NEAR(s[0], 0, 1e-12) << k;
    EXPECT_NEAR(s[1], h, 1e-12) << k;
    EXPECT_NEAR(s[2], U, 1e-12) << k;
    EXPECT_NEAR(s[3], V, 1e-12) << k;
    EXPECT_NEAR(s[4], h * U, 1e-12) << k;
    EXPECT_NEAR(s[5], h * V, 1e-12) << k;
  }
  // The still levels are the probe's state: five levels, and eta is measured from the levels loaded.
  const std::vector<double> state = probes.save_state();
  ASSERT_EQ(state.size(), 6u);
  EXPECT_EQ(state[0], 5);
  EXPECT_FALSE(probes.load_state({1, h}));
  ASSERT_TRUE(probes.load_state({5, h + 0.1, h + 0.1, h + 0.1, h + 0.1, h + 0.1}));
  const std::vector<double> raised = probes.sample(sim);
  for (int k = 0; k < 5; ++k) EXPECT_NEAR(raised[6 * k], -0.1, 1e-12) << k;
}

// A station over a dry bed: eta NaN (no still level at t = 0), d = u = q = 0; with still_level given, eta is
// still NaN while dry.
TEST(SectionProbe, DryStationReadsNaNAndZeros) {
  for (const bool given : {false, true}) {
    nlohmann::json section = {{"position", {3.5}}};
    if (given) section["still_level"] = 1.0;
    nlohmann::json j = section_tank(2, 1, 0.1, 1, 4, 0, 0.1, section);
    j["bodies"][1]["shape"]["max"] = {3.0, 1.0};  // the water ends at x = 3, the section stands at 3.5
    const Scene scene = scene_from_json(j, "<section_dry>");
    Simulation<2> sim(scene);
    Probes<2> probes(scene, sim);
    const std::vector<double> row = probes.sample(sim);
    ASSERT_EQ(row.size(), 4u);
    EXPECT_TRUE(std::isnan(row[0])) << given;
    EXPECT_EQ(row[1], 0) << given;
    EXPECT_EQ(row[2], 0) << given;
    EXPECT_EQ(row[3], 0) << given;
    EXPECT_EQ(std::isnan(probes.save_state()[1]), !given);
  }
}

// 3D mass balance across a channel of width W = h: a box a = h / 4 high (two particle layers), w = 2 h long
// released at x = 0 in an 8 h tank of depth h = 0.5 m, dx = h / 4; the line crosses the channel at X = 4 h
// (5 stations). The discharge through the line, the trapezoidal rule of qx over its stations, integrated over
// 8 h / c, against the volume change beyond X (the hump, 2 w long, passes X between (X - w) / c = 2 h / c and
// (X + w) / c = 6 h / c; the far wall's reflection returns at (2 L - w - X) / c = 10 h / c).
TEST(SectionProbe, Line3DDischargeBalancesTheVolume) {
  const double h = 0.5, a = h / 4, w = 2 * h, L = 8 * h, W = h, X = 4 * h, T = 8 * h / std::sqrt(g * h);
  const Scene scene = scene_from_json(
      section_tank(3, h, a, w, L, W, h / 4, {{"start", {X, 0}}, {"end", {X, W}}, {"points", 5}}), "<section_3d_balance>");
  Simulation<3> sim(scene);
  Probes<3> probes(scene, sim);
  std::vector<double> t, Q, beyond;
  const OneThread one_thread;
  run_sampled(sim, T, 0.01, [&] {
    const std::vector<double> row = probes.sample(sim);
    t.push_back(sim.time());
    double sum = 0;  // trapezoidal rule over the 5 stations, W / 4 apart
    for (int k = 0; k < 5; ++k) sum += (k == 0 || k == 4 ? 0.5 : 1.0) * row[6 * k + 4];
    Q.push_back(W / 4 * sum);
    beyond.push_back(volume_beyond(sim, X));
  });
  double passed = 0;
  for (size_t i = 1; i < t.size(); ++i) passed += 0.5 * (Q[i] + Q[i - 1]) * (t[i] - t[i - 1]);
  const double moved = beyond.back() - beyond[0];
  EXPECT_GT(moved, 0.8 * a * w * W);
  std::printf("3D section: %zu particles, %lld steps; integral of Q dt %.6g m^3, volume change %.6g m^3 (%+.2f %%)\n",
              sim.particles.size(), sim.steps(), passed, moved, 100 * (passed / moved - 1));
  EXPECT_NEAR(passed, moved, 0.02 * moved) << "integral of Q dt " << passed << ", volume change " << moved;
}

}  // namespace
}  // namespace cdmpm::testing
