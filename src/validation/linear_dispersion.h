// linear_dispersion.h - linear (Airy) water-wave theory for a wave-gauge record: the record at one gauge carried
// to another gauge of the same constant depth, so that a simulated wave can be compared with the wave that
// linear theory makes of it.
//
// Linear dispersion relation (Airy; e.g. Dean & Dalrymple, Water Wave Mechanics, eq. 4.32):
//   omega^2 = g k tanh(k h)
// phase speed c = omega / k, group speed c_g = c / 2 (1 + 2 k h / sinh(2 k h)); long waves (k h -> 0) travel at
// sqrt(g h) whatever their period, shorter waves slower, so the crests behind the front of an impulse wave fall
// behind it (the Airy front of the Cauchy-Poisson problem).
// A record eta(x_1, t) of waves travelling in +x is the sum of its Fourier components A(omega) e^(i omega t); at
// x_2 = x_1 + d each component has travelled d with its own wavenumber:
//   eta(x_2, t) = sum A(omega) e^(i (omega t - k(omega) d))
// A wall that reflects fully at x_w adds the image path d' = (x_w - x_1) + (x_w - x_2) with the same amplitude.
// Cauchy-Poisson problem (Lamb, Hydrodynamics, art. 238; Whitham, Linear and Nonlinear Waves, 13.2): water at
// rest whose surface is raised by a over |x| < w (a box of water on a layer of depth h, or the half of it against
// a wall at x = 0, which mirrors it), released at t = 0. By linear theory
//   eta(x, t) = (2 a / pi) * integral_0^inf sin(k w) / k * cos(k x) * cos(omega(k) t) dk,
// omega(k) = sqrt(g k tanh(k h)): two long waves of height a / 2 leave at sqrt(g h), with the shorter waves that
// the box's edges hold falling behind them.
// The record is taken as at rest before its first sample; its last 5 % are tapered to zero (cosine) and it is
// padded with zeros to 8 times its length before the discrete Fourier transform. A component whose group delay
// over a path exceeds the padding (slow short waves, or any wave on a long reflected path) would wrap around the
// transform's period onto the record; it arrives after the record's end and is left out of that path.
#pragma once

#include <optional>
#include <vector>

namespace cdmpm {

// k [1/m] with omega^2 = g k tanh(k h); omega >= 0 [rad/s], g > 0, h > 0. Newton's method from the deep- or
// shallow-water value, converged to round-off.
double dispersion_wavenumber(double omega, double g, double h);

// Group speed d omega / d k [m/s] at angular frequency omega > 0.
double group_speed(double omega, double g, double h);

// eta at a point the distance `distance` [m] further along x, sampled at the same times as eta (uniform spacing
// dt [s], eta[0] at the record's start), by linear theory in depth h; with reflected_distance, plus the wave that
// a fully reflecting wall returns after that path length [m]. Throws std::invalid_argument for non-finite samples,
// dt <= 0, h <= 0 or a negative distance.
std::vector<double> propagate_linear(const std::vector<double>& eta, double dt, double distance, double g, double h,
                                     std::optional<double> reflected_distance = std::nullopt);

// The Cauchy-Poisson elevation above for a box of height a [m] and half-width w [m] at distance x [m] and times t
// [s], integrated (Simpson) up to k = k_max_h / h with a step small against the integrand's oscillation.
std::vector<double> cauchy_poisson_box(double x, const std::vector<double>& t, double a, double w, double g, double h,
                                       double k_max_h = 100);

}  // namespace cdmpm
