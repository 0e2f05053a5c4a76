// test_waves.cpp - the wave analysis (probe/wave_analysis.h) on synthetic gauge records, and the Heller & Hager
// (2010) impulse-wave relations (validation/impulse_wave.h) on the worked example of the VAW manual
// (Evers et al. 2019; ../shared/data/impulse_waves.md): P = 0.64.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "probe/wave_analysis.h"
#include "validation/impulse_wave.h"

namespace cdmpm {
namespace {

// A solitary-like crest a sech^2((t - t0) / T) sampled every dt.
double crest(double t, double a, double t0, double T) {
  const double s = 1 / std::cosh((t - t0) / T);
  return a * s * s;
}

TEST(WaveAnalysis, FirstCrestIgnoresNoiseAndLaterHigherWaves) {
  // Record: +-eps noise, the leading crest (5 cm at t = 1.234 s), a trough, then a 12 cm reflection at 4 s.
  std::mt19937 rng(7);
  const double eps = 0.0005;
  std::uniform_real_distribution<double> noise(-eps, eps);
  const double dt = 0.01, a = 0.05, t0 = 1.234, T = 0.3;
  std::vector<double> t, eta;
  for (int i = 0; i <= 600; ++i) {
    t.push_back(i * dt);
    eta.push_back(noise(rng) + crest(t.back(), a, t0, T) - crest(t.back(), 0.02, 2.2, T) +
                  crest(t.back(), 0.12, 4.0, T));
  }
  const auto c = first_crest(t, eta);
  ASSERT_TRUE(c);
  // Noise lets any sample whose noiseless value is within 2 eps of the peak be the largest: a (1 - (s/T)^2) >=
  // a - 2 eps near the crest, so the time is within T sqrt(2 eps / a) (doubled for the parabola) plus a sample,
  // and the amplitude within the noise (twice, for the parabola through noisy samples).
  EXPECT_NEAR(c->time, t0, T * std::sqrt(4 * eps / a) + dt);
  EXPECT_NEAR(c->amplitude, a, 2 * eps);
}

TEST(WaveAnalysis, FirstCrestIsSeparatedFromAHigherWaveThatJoinsIt) {
  // A 1.6 cm crest at 5.1 s and a 2.1 cm wave at 7.2 s whose flanks overlap: the record stays above a quarter
  // of the largest elevation between them but dips by more than half of that quarter.
  std::vector<double> t, eta;
  for (int i = 0; i <= 1000; ++i) {
    t.push_back(0.01 * i);
    eta.push_back(crest(t.back(), 0.016, 5.1, 0.6) + crest(t.back(), 0.021, 7.2, 0.6));
  }
  const auto c = first_crest(t, eta);
  ASSERT_TRUE(c);
  // The second wave's flank adds sech^2(2.1 / 0.6) * 2.1 cm ~ 0.08 mm at the first crest and shifts it by a
  // fraction of a sample.
  EXPECT_NEAR(c->time, 5.1, 0.02);
  EXPECT_NEAR(c->amplitude, 0.016, 0.0002);
}

TEST(WaveAnalysis, ParabolicRefinementFindsTheCrestBetweenSamples) {
  // A parabola sampled off its vertex: the vertex is recovered exactly.
  std::vector<double> t, eta;
  for (int i = 0; i <= 20; ++i) {
    t.push_back(0.1 * i);
    eta.push_back(std::max(0.0, 0.3 - 2 * (t.back() - 1.03) * (t.back() - 1.03)));
  }
  const auto c = first_crest(t, eta);
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->time, 1.03, 1e-12);
  EXPECT_NEAR(c->amplitude, 0.3, 1e-12);
}

TEST(WaveAnalysis, FlatOrMissingRecordHasNoCrest) {
  const std::vector<double> t = {0, 1, 2}, flat = {0, 0, -0.1}, missing = {NAN, NAN, NAN};
  EXPECT_FALSE(first_crest(t, flat));
  EXPECT_FALSE(first_crest(t, missing));
}

TEST(WaveAnalysis, RecordThatEndsBeforeTheCrestHasPassedHasNoCrest) {
  // The run stops while the wave is still rising at the gauge (its crest at 2 s, the record to 1.5 s): the
  // record's last sample is its highest, not a crest. The same wave recorded past its crest has one.
  std::vector<double> t, eta;
  for (int i = 0; i <= 150; ++i) {
    t.push_back(0.01 * i);
    eta.push_back(crest(t.back(), 0.05, 2.0, 0.3));
  }
  EXPECT_FALSE(first_crest(t, eta));
  eta.push_back(NAN);  // a dry gauge after it does not make it a crest either
  t.push_back(1.51);
  EXPECT_FALSE(first_crest(t, eta));
  for (int i = 152; i <= 300; ++i) {
    t.push_back(0.01 * i);
    eta.push_back(crest(t.back(), 0.05, 2.0, 0.3));
  }
  const auto c = first_crest(t, eta);
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->time, 2.0, 1e-3);
  EXPECT_NEAR(c->amplitude, 0.05, 1e-5);
}

TEST(WaveAnalysis, CelerityIsTheLeastSquaresSlope) {
  // Crests at x = 2, 4, 6, 10 m passing at 3.2 m/s from t = 0.4 s, one time off by +0.01 s.
  const std::vector<double> x = {2, 4, 6, 10};
  std::vector<double> t;
  for (double xi : x) t.push_back(0.4 + xi / 3.2);
  EXPECT_NEAR(*celerity_fit(x, t), 3.2, 1e-12);
  t[1] += 0.01;
  EXPECT_NEAR(*celerity_fit(x, t), 3.2, 0.01 * 3.2);
  EXPECT_FALSE(celerity_fit({1}, {1}));
}

TEST(ImpulseWave, WorkedExampleGivesP064) {
  // V_s = 58 m/s, h = 80 m, s = 12 m, b = 100 m, volume 2.2e5 m^3 of density 1700 kg/m^3, alpha = 40 degrees.
  ImpulseWaveInput in;
  in.slide_velocity = 58;
  in.depth = 80;
  in.thickness = 12;
  in.width = 100;
  in.mass = 2.2e5 * 1700;
  in.water_density = 1000;
  in.angle_degrees = 40;
  const ImpulseWave w = heller_hager_2010(in);
  EXPECT_NEAR(w.P, 0.64, 0.005);
  EXPECT_NEAR(w.F, 58 / std::sqrt(9.81 * 80), 1e-12);
  EXPECT_NEAR(w.S, 0.15, 1e-12);
  EXPECT_NEAR(w.M, 3.74e8 / (1000 * 100 * 6400.0), 1e-12);
  EXPECT_TRUE(w.in_range);
  // a_M = 4/9 P^(4/5) h, H_M = 5/9 P^(4/5) h, x_M = 11/2 P^(1/2) h, and the decay law meets a_M's order beyond.
  EXPECT_NEAR(w.max_amplitude, 80 * 4.0 / 9 * std::pow(w.P, 0.8), 1e-9);
  EXPECT_NEAR(w.max_height / w.max_amplitude, 5.0 / 4, 1e-12);
  EXPECT_NEAR(w.max_location, 80 * 5.5 * std::sqrt(w.P), 1e-9);
  EXPECT_DOUBLE_EQ(w.amplitude_at(0.5 * w.max_location, 80), w.max_amplitude);
  const double X = 10;
  EXPECT_NEAR(w.amplitude_at(X * 80, 80), 80 * 0.6 * std::pow(w.P * std::pow(X, -1.0 / 3), 0.8), 1e-9);
  // Out of range: a slide Froude number below 0.86.
  in.slide_velocity = 10;
  EXPECT_FALSE(heller_hager_2010(in).in_range);
}

}  // namespace
}  // namespace cdmpm
