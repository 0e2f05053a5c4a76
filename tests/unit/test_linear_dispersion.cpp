// test_linear_dispersion.cpp - linear water-wave theory (validation/linear_dispersion.h): the dispersion relation
// and its limits, a gauge record carried along x (long waves at sqrt(g h), a wave packet at the group speed, a
// wall's reflection) and the Cauchy-Poisson box, and the two against each other.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "probe/wave_analysis.h"
#include "validation/linear_dispersion.h"

namespace cdmpm {
namespace {

constexpr double g = 9.81;

std::vector<double> times(double dt, size_t n) {
  std::vector<double> t(n);
  for (size_t i = 0; i < n; ++i) t[i] = i * dt;
  return t;
}

size_t argmax(const std::vector<double>& v) { return std::max_element(v.begin(), v.end()) - v.begin(); }

TEST(LinearDispersion, WavenumberSolvesTheDispersionRelationWithItsLimits) {
  const double h = 3.0;
  for (double omega : {1e-4, 0.1, 1.0, 3.0, 10.0, 100.0}) {
    const double k = dispersion_wavenumber(omega, g, h);
    EXPECT_NEAR(g * k * std::tanh(k * h), omega * omega, 1e-12 * omega * omega) << omega;
  }
  EXPECT_EQ(dispersion_wavenumber(0, g, h), 0);
  // Shallow water: k = omega / sqrt(g h) (1 + (k h)^2 / 6 + ...); deep water: k = omega^2 / g.
  const double w_shallow = 1e-4;
  EXPECT_NEAR(dispersion_wavenumber(w_shallow, g, h), w_shallow / std::sqrt(g * h), 1e-9 * w_shallow / std::sqrt(g * h));
  EXPECT_NEAR(dispersion_wavenumber(30.0, g, h), 900 / g, 1e-12 * 900 / g);
  // Group speed: sqrt(g h) for long waves, half the phase speed in deep water.
  EXPECT_NEAR(group_speed(w_shallow, g, h), std::sqrt(g * h), 1e-8 * std::sqrt(g * h));
  EXPECT_NEAR(group_speed(30.0, g, h), 0.5 * g / 30.0, 1e-12);
}

TEST(LinearDispersion, LongHumpTravelsAtTheShallowWaterSpeedUnchanged) {
  // A Gaussian hump exp(-(t / sigma)^2) of sigma = 20 sqrt(h / g) holds k h up to about 2 sqrt(h / g) / sigma = 0.1;
  // its peak travels at about the group speed of those waves, sqrt(g h) (1 - (k h)^2 / 2): within 0.5 %.
  const double h = 1.0, c0 = std::sqrt(g * h), sigma = 20 * std::sqrt(h / g), t0 = 4 * sigma, d = 30 * h, dt = 0.02;
  const auto t = times(dt, size_t((t0 + d / c0 + 4 * sigma) / dt));
  std::vector<double> eta(t.size());
  for (size_t i = 0; i < t.size(); ++i) eta[i] = 0.01 * std::exp(-std::pow((t[i] - t0) / sigma, 2));
  const auto out = propagate_linear(eta, dt, d, g, h);
  const auto crest = first_crest(t, out);
  ASSERT_TRUE(crest);
  EXPECT_NEAR(crest->time - t0, d / c0, 0.005 * d / c0);
  EXPECT_NEAR(crest->amplitude, 0.01, 0.005 * 0.01);
  // Zero distance returns the record (the taper touches only its quiet end).
  const auto same = propagate_linear(eta, dt, 0, g, h);
  for (size_t i = 0; i < t.size(); ++i) ASSERT_NEAR(same[i], eta[i], 1e-12) << i;
}

TEST(LinearDispersion, WavePacketTravelsAtTheGroupSpeed) {
  // A packet of carrier k h = 1 and 4 carrier periods' envelope: its energy centre arrives after d / c_g. The
  // packet's spectrum is 1 / (sigma omega_0) = 4 % wide, over which 1 / c_g changes by well under 1 %.
  const double h = 1.0, omega0 = std::sqrt(g * std::tanh(1.0) / h), T = 2 * std::numbers::pi / omega0;
  const double sigma = 4 * T, t0 = 3.5 * sigma, d = 20 * h, dt = 0.02, cg = group_speed(omega0, g, h);
  const auto t = times(dt, size_t((t0 + d / cg + 3.5 * sigma) / dt));
  std::vector<double> eta(t.size());
  for (size_t i = 0; i < t.size(); ++i)
    eta[i] = 0.01 * std::exp(-std::pow((t[i] - t0) / sigma, 2)) * std::cos(omega0 * (t[i] - t0));
  const auto out = propagate_linear(eta, dt, d, g, h);
  auto centre = [&](const std::vector<double>& e) {
    double s = 0, st = 0;
    for (size_t i = 0; i < e.size(); ++i) s += e[i] * e[i], st += t[i] * e[i] * e[i];
    return st / s;
  };
  EXPECT_NEAR(centre(out) - centre(eta), d / cg, 0.01 * d / cg);
  // The phase speed is not the group speed here (c / c_g = 1.29): the check can tell them apart.
  EXPECT_GT(std::abs(centre(out) - centre(eta) - d * dispersion_wavenumber(omega0, g, h) / omega0), 0.1 * d / cg);
}

TEST(LinearDispersion, WallReturnsTheWaveAfterTheImagePath) {
  const double h = 1.0, c0 = std::sqrt(g * h), sigma = 10 * std::sqrt(h / g), t0 = 4 * sigma, dt = 0.02;
  const double x1 = 0, x2 = 10, wall = 25;  // image path 2 wall - x1 - x2 = 40 m
  const auto t = times(dt, size_t((t0 + 40 / c0 + 4 * sigma) / dt));
  std::vector<double> eta(t.size());
  for (size_t i = 0; i < t.size(); ++i) eta[i] = 0.01 * std::exp(-std::pow((t[i] - t0) / sigma, 2));
  const auto out = propagate_linear(eta, dt, x2 - x1, g, h, 2 * wall - x1 - x2);
  const size_t mid = size_t((t0 + 25 / c0) / dt);  // between the direct hump (at 10 m) and the reflected one (40 m)
  const std::vector<double> first(out.begin(), out.begin() + mid), second(out.begin() + mid, out.end());
  EXPECT_NEAR(t[argmax(first)] - t0, 10 / c0, 0.01 * 10 / c0 + dt);
  EXPECT_NEAR(t[mid + argmax(second)] - t0, 40 / c0, 0.01 * 40 / c0 + dt);
  EXPECT_NEAR(*std::max_element(second.begin(), second.end()), 0.01, 0.01 * 0.01);
}

TEST(LinearDispersion, CauchyPoissonBoxStartsAsTheBoxAndKeepsItsVolume) {
  const double h = 1.0, a = 0.01, w = 2 * h, c0 = std::sqrt(g * h);
  // t = 0: the box itself (inside, outside; away from its edges).
  for (double x : {0.0, 1.0, 3.0, 10.0})
    EXPECT_NEAR(cauchy_poisson_box(x, {0.0}, a, w, g, h)[0], x < w ? a : 0, 0.01 * a) << x;
  // Volume: linear theory keeps the integral of eta over x >= 0 (the wall at x = 0 mirrors the box) at a w.
  // At t = 20 h / sqrt(g h) the waves (and the slow short waves behind them) lie within 60 h of the wall.
  const double t = 20 * h / c0, dx = 0.05 * h;
  double volume = 0;
  for (double x = 0.5 * dx; x < 60 * h; x += dx) volume += cauchy_poisson_box(x, {t}, a, w, g, h)[0] * dx;
  EXPECT_NEAR(volume, a * w, 0.01 * a * w);
  // Still water ahead of the front.
  EXPECT_NEAR(cauchy_poisson_box(50 * h, {t}, a, w, g, h)[0], 0, 0.01 * a);
}

TEST(LinearDispersion, CarryingTheCauchyPoissonRecordAlongGivesTheCauchyPoissonRecordFurtherOn) {
  // Beyond the box every wave travels in +x, so the record at x1 carried to x2 must be the solution at x2.
  const double h = 1.0, a = 0.01, w = 1.0, x1 = 2, x2 = 8, dt = 0.01;
  const auto t = times(dt, 900);
  const auto at_x1 = cauchy_poisson_box(x1, t, a, w, g, h), at_x2 = cauchy_poisson_box(x2, t, a, w, g, h);
  const auto carried = propagate_linear(at_x1, dt, x2 - x1, g, h);
  double worst = 0;
  for (size_t i = 0; i < t.size() * 3 / 4; ++i) worst = std::max(worst, std::abs(carried[i] - at_x2[i]));
  EXPECT_LT(worst, 0.01 * a);
  const auto c1 = first_crest(t, carried), c2 = first_crest(t, at_x2);
  ASSERT_TRUE(c1 && c2);
  EXPECT_NEAR(c1->time, c2->time, dt);
}

}  // namespace
}  // namespace cdmpm
