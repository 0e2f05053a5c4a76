// linear_dispersion.cpp - linear water-wave propagation of a gauge record (see linear_dispersion.h).
#include "validation/linear_dispersion.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

namespace cdmpm {

double dispersion_wavenumber(double omega, double g, double h) {
  if (!(omega >= 0) || !(g > 0) || !(h > 0)) throw std::invalid_argument("dispersion_wavenumber: omega >= 0, g > 0, h > 0");
  if (omega == 0) return 0;
  // f(k) = g k tanh(k h) - omega^2 is increasing and convex in k > 0, so Newton from above converges monotonically;
  // the larger of the shallow- and deep-water values lies above the root.
  double k = std::max(omega / std::sqrt(g * h), omega * omega / g);
  for (int it = 0; it < 100; ++it) {
    const double th = std::tanh(k * h);
    const double f = g * k * th - omega * omega;
    const double df = g * th + g * k * h * (1 - th * th);
    const double step = f / df;
    k -= step;
    if (std::abs(step) <= 1e-15 * k) break;
  }
  return k;
}

namespace {

// c_g = (omega / k) / 2 (1 + 2 k h / sinh(2 k h)) for a wavenumber k > 0 that solves the dispersion relation.
double group_speed_of(double omega, double k, double h) {
  const double kh = k * h;
  // 2 k h / sinh(2 k h) tends to 1 as k h -> 0 and underflows harmlessly to 0 for deep water.
  const double ratio = kh < 1e-8 ? 1.0 : (kh > 350 ? 0.0 : 2 * kh / std::sinh(2 * kh));
  return 0.5 * (omega / k) * (1 + ratio);
}

}  // namespace

double group_speed(double omega, double g, double h) {
  return group_speed_of(omega, dispersion_wavenumber(omega, g, h), h);
}

std::vector<double> propagate_linear(const std::vector<double>& eta, double dt, double distance, double g, double h,
                                     std::optional<double> reflected_distance) {
  if (!(dt > 0) || !(h > 0) || !(g > 0)) throw std::invalid_argument("propagate_linear: dt, g and h must be positive");
  if (!(distance >= 0) || (reflected_distance && !(*reflected_distance >= 0)))
    throw std::invalid_argument("propagate_linear: distances must be >= 0");
  const size_t n = eta.size();
  if (n == 0) return {};
  std::vector<double> x(eta);
  for (double v : x)
    if (!std::isfinite(v)) throw std::invalid_argument("propagate_linear: the record has a non-finite sample");
  // Cosine taper over the last 5 % of the record.
  const size_t taper = n / 20;
  for (size_t i = 0; i < taper; ++i) x[n - 1 - i] *= 0.5 * (1 - std::cos(std::numbers::pi * i / taper));

  const size_t N = 8 * n, half = N / 2;
  std::vector<double> cs(N), sn(N);
  for (size_t q = 0; q < N; ++q) {
    const double a = 2 * std::numbers::pi * double(q) / double(N);
    cs[q] = std::cos(a), sn[q] = std::sin(a);
  }
  std::vector<std::complex<double>> spectrum(half + 1);
  for (size_t m = 0; m <= half; ++m) {
    std::complex<double> s = 0;
    for (size_t j = 0; j < n; ++j) {
      const size_t q = (j * m) % N;
      s += x[j] * std::complex<double>(cs[q], -sn[q]);
    }
    const double omega = 2 * std::numbers::pi * double(m) / (double(N) * dt);
    const double k = dispersion_wavenumber(omega, g, h);
    // A component that a path delays by more than the padding, d / c_g > (N - n) dt, would wrap around the
    // transform's period onto the record: it arrives after the record's end, so it is left out.
    const double cg = m == 0 ? std::sqrt(g * h) : group_speed_of(omega, k, h), max_delay = double(N - n) * dt;
    std::complex<double> path = 0;
    if (distance <= max_delay * cg) path += std::polar(1.0, -k * distance);
    if (reflected_distance && *reflected_distance <= max_delay * cg) path += std::polar(1.0, -k * *reflected_distance);
    spectrum[m] = s * path;
  }
  std::vector<double> out(n);
  for (size_t j = 0; j < n; ++j) {
    double s = spectrum[0].real();
    for (size_t m = 1; m < half; ++m) {
      const size_t q = (j * m) % N;
      s += 2 * (spectrum[m].real() * cs[q] - spectrum[m].imag() * sn[q]);
    }
    s += spectrum[half].real() * ((j % 2) ? -1.0 : 1.0);
    out[j] = s / double(N);
  }
  return out;
}

std::vector<double> cauchy_poisson_box(double x, const std::vector<double>& t, double a, double w, double g, double h,
                                       double k_max_h) {
  if (!(w > 0) || !(g > 0) || !(h > 0) || !(k_max_h > 0))
    throw std::invalid_argument("cauchy_poisson_box: w, g, h and k_max_h must be positive");
  double t_max = 0;
  for (double ti : t) t_max = std::max(t_max, std::abs(ti));
  const double k_max = k_max_h / h;
  // The phase k (x +- w) +- omega t changes by at most (|x| + w + sqrt(g h) t_max) per unit k (group and phase
  // speeds are at most sqrt(g h)): 40 intervals per 2 pi of it.
  const double rate = std::abs(x) + w + std::sqrt(g * h) * t_max;
  size_t n = size_t(std::ceil(k_max * rate / (2 * std::numbers::pi) * 40));
  n += n % 2;  // Simpson: an even number of intervals
  const double dk = k_max / double(n);
  std::vector<double> k(n + 1), weight(n + 1), omega(n + 1);
  for (size_t i = 0; i <= n; ++i) {
    k[i] = i * dk;
    omega[i] = std::sqrt(g * k[i] * std::tanh(k[i] * h));
    const double simpson = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
    const double sinc = i == 0 ? w : std::sin(k[i] * w) / k[i];  // sin(k w) / k -> w as k -> 0
    weight[i] = simpson * dk / 3 * sinc * std::cos(k[i] * x);
  }
  std::vector<double> eta(t.size());
  for (size_t j = 0; j < t.size(); ++j) {
    double s = 0;
    for (size_t i = 0; i <= n; ++i) s += weight[i] * std::cos(omega[i] * t[j]);
    eta[j] = 2 * a / std::numbers::pi * s;
  }
  return eta;
}

}  // namespace cdmpm
