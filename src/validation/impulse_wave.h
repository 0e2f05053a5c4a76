// impulse_wave.h - the 2D impulse-wave relations of Heller & Hager (2010) for slide-generated waves.
//
// Heller, V. and Hager, W. H. (2010), "Impulse product parameter in landslide generated impulse waves",
// J. Waterway, Port, Coastal, Ocean Eng. 136(3) (relations as collected in ../shared/data/impulse_waves.md):
//   F = V_s / sqrt(g h),  S = s / h,  M = m_s / (rho_w b h^2)              (slide Froude number, thickness, mass)
//   P = F S^(1/2) M^(1/4) [cos(6/7 alpha)]^(1/2)                          (impulse product parameter)
//   a_M / h = 4/9 P^(4/5),  H_M / h = 5/9 P^(4/5),  x_M / h = 11/2 P^(1/2) (maximum amplitude, height, location)
//   a / h = 3/5 [P X^(-1/3)]^(4/5)  for X = x / h > x_M / h             (decay of the amplitude with distance)
// valid for F 0.86-6.83, S 0.09-1.64, M 0.11-10.02, P 0.17-8.13, alpha 30-90 degrees.
// The 2D-to-3D transformation of Heller & Spinneken (2015) is not implemented: its equation was not available
// from a primary source to this project (docs/validation.md).
#pragma once

#include <cmath>
#include <numbers>
#include <string>

namespace cdmpm {

struct ImpulseWaveInput {
  double slide_velocity = 0;   // V_s, impact velocity [m/s]
  double depth = 0;            // h, still-water depth [m]
  double thickness = 0;        // s, slide thickness [m]
  double mass = 0;             // m_s, slide mass [kg] (over the width b)
  double width = 0;            // b, slide width [m]
  double water_density = 1000; // rho_w [kg/m^3]
  double angle_degrees = 90;   // alpha, slide impact angle
  double gravity = 9.81;       // g [m/s^2]
};

struct ImpulseWave {
  double F = 0, S = 0, M = 0, P = 0;
  double max_amplitude = 0;  // a_M [m]
  double max_height = 0;     // H_M [m]
  double max_location = 0;   // x_M [m]
  bool in_range = false;     // every parameter inside the experiments' range

  // Amplitude a at distance x [m] from impact: the decay law beyond x_M, a_M up to it.
  double amplitude_at(double x, double h) const {
    const double X = x / h;
    if (X <= max_location / h) return max_amplitude;
    return h * 0.6 * std::pow(P * std::pow(X, -1.0 / 3.0), 0.8);
  }
};

inline ImpulseWave heller_hager_2010(const ImpulseWaveInput& in) {
  ImpulseWave w;
  const double h = in.depth;
  const double alpha = in.angle_degrees * std::numbers::pi / 180;
  w.F = in.slide_velocity / std::sqrt(in.gravity * h);
  w.S = in.thickness / h;
  w.M = in.mass / (in.water_density * in.width * h * h);
  w.P = w.F * std::sqrt(w.S) * std::pow(w.M, 0.25) * std::sqrt(std::cos(6.0 / 7.0 * alpha));
  const double p45 = std::pow(w.P, 0.8);
  w.max_amplitude = h * 4.0 / 9.0 * p45;
  w.max_height = h * 5.0 / 9.0 * p45;
  w.max_location = h * 5.5 * std::sqrt(w.P);
  auto within = [](double v, double lo, double hi) { return v >= lo && v <= hi; };
  w.in_range = within(w.F, 0.86, 6.83) && within(w.S, 0.09, 1.64) && within(w.M, 0.11, 10.02) &&
               within(w.P, 0.17, 8.13) && within(in.angle_degrees, 30, 90);
  return w;
}

}  // namespace cdmpm
