// test_wave_bounds_arrival.cpp - a gauge's first crest (probe/wave_bounds.h, probe/wave_analysis.h) comes no
// earlier than the fastest wave can bring it (distance from the sources over 2 sqrt(g h_max)) and rises above the
// gauge's noise floor; otherwise no crest, with a reason.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "cli_helpers.h"
#include "probe/wave_analysis.h"
#include "probe/wave_bounds.h"
#include "scene/scene_loader.h"

namespace cdmpm::testing {
namespace {

constexpr double kG = 9.81;  // [m/s^2]

// A record sampled every 0.05 s to 20 s: millimetre noise from t = 0, and (if amplitude > 0) a Gaussian crest
// of that amplitude at t_crest.
void record(double amplitude, double t_crest, std::vector<double>& t, std::vector<double>& eta) {
  t.clear();
  eta.clear();
  for (int i = 0; i <= 400; ++i) {
    const double ti = 0.05 * i;
    t.push_back(ti);
    eta.push_back(1e-3 * std::sin(7.3 * ti) + amplitude * std::exp(-std::pow((ti - t_crest) / 0.8, 2)));
  }
}

// The calving front's sources and depth (scenes/calving_front_2d.json: ice up to x = 600 m, water 40 m deep):
// c_max = 2 sqrt(g 40) and the gauge 600 m from the ice front cannot see a wave before 600 / c_max = 15.1 s.
TEST(WaveBounds, EarliestArrivalIsTheSourceDistanceOverTwiceTheLongWaveSpeed) {
  const Scene s = load_scene(source_path("scenes/calving_front_2d.json"), {});
  const WaveBounds b = wave_bounds(s);
  EXPECT_DOUBLE_EQ(b.h_max, 40.0);
  EXPECT_NEAR(b.c_max, 2 * std::sqrt(kG * 40), 1e-12);
  EXPECT_TRUE(b.bounded_source);
  EXPECT_NEAR(b.earliest_arrival({1200}), 600 / (2 * std::sqrt(kG * 40)), 1e-12);
  EXPECT_EQ(b.earliest_arrival({300}), 0.0);  // over the ice
  EXPECT_DOUBLE_EQ(b.floor, 5.0 / 1000);
  EXPECT_DOUBLE_EQ(b.arrival_floor, 5.0 / 100);
  EXPECT_TRUE(b.possible_celerity(std::sqrt(kG * 40)));
  EXPECT_FALSE(b.possible_celerity(-5));
  EXPECT_FALSE(b.possible_celerity(2.01 * std::sqrt(kG * 40)));
  // Water that starts with its wave (a solitary wave, no other body) bounds no arrival.
  EXPECT_EQ(wave_bounds(load_scene(source_path("scenes/solitary_runup_2d.json"), {})).earliest_arrival({19}), 0.0);
}

// A crest that rises above the noise after the earliest arrival is the first crest; the noise before it is not.
TEST(WaveBounds, CrestAfterTheEarliestArrivalIsFoundAndTheNoiseBeforeItIsNot) {
  std::vector<double> t, eta;
  record(0.5, 12.0, t, eta);
  const GaugeReading r = read_gauge(t, eta, 8.0, 0.01);
  ASSERT_TRUE(r.crest) << r.reason;
  EXPECT_NEAR(r.crest->time, 12.0, 0.05);
  EXPECT_NEAR(r.crest->amplitude, 0.5, 0.01);
  EXPECT_NEAR(r.noise_floor, 0.01, 1e-12);  // 3 x 1 mm is below the resolution floor
}

// Millimetre jitter read before the wave can arrive is no crest (the old analysis took the record's own top as
// its scale and reported it); nor is a record that ends before the earliest arrival.
TEST(WaveBounds, NoiseBeforeTheEarliestArrivalIsNoCrest) {
  std::vector<double> t, eta;
  record(0, 0, t, eta);
  EXPECT_TRUE(first_crest(t, eta));  // what the unbounded analysis reads
  const GaugeReading quiet = read_gauge(t, eta, 5.0, 0.05);
  EXPECT_FALSE(quiet.crest);
  EXPECT_EQ(quiet.reason, "no rise above the noise floor");
  const GaugeReading early = read_gauge(t, eta, 25.0, 0.05);
  EXPECT_FALSE(early.crest);
  EXPECT_EQ(early.reason, "the record ends before the earliest possible arrival");
  // A rise before the earliest arrival sets the noise floor: a later crest must clear three times it.
  record(0.2, 3.0, t, eta);
  const GaugeReading masked = read_gauge(t, eta, 5.0, 0.01);
  EXPECT_GT(masked.noise_floor, 0.05);
  EXPECT_FALSE(masked.crest);
}

}  // namespace
}  // namespace cdmpm::testing
