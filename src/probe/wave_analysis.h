// wave_analysis.h - leading-wave measures from wave-gauge records: first-crest amplitude and arrival time per
// gauge, and the celerity of the leading crest between gauges.
//
// First crest of a record eta(t) (elevation above the still level): let eta_max be the largest elevation in
// the record and eta_th = crest_fraction * eta_max (default 1/4). The leading wave starts at the first sample
// with eta >= eta_th and ends at the first later sample that falls below eta_th or more than eta_th / 2 below
// the largest sample since the start (so a crest that a later, higher wave joins before the record falls back
// below eta_th is still seen as the first). Its crest is its largest sample, refined by the vertex of the
// parabola through it and its two neighbours. The amplitude is the crest's elevation and the arrival time the
// crest's time. Noise ahead of the wave (surface-particle jitter of a fraction of the particle spacing) and
// wiggles smaller than eta_th / 2 do not move it, nor do later, higher waves (reflections); a record that never
// rises above zero has no crest, nor has one whose largest sample of the leading wave is its last (finite) sample:
// the record ends before the crest has passed (a run stopped while the wave is still rising at the gauge).
// A gauge's reading (read_gauge) asks more of the first crest: only what can be a wave counts. Samples before the
// earliest time a wave can reach the gauge (t_min, probe/wave_bounds.h) are the gauge's noise; its noise floor
// is the larger of three times their largest |eta| and the gauge's resolution (floor, dx / 1000). The first
// crest is sought in the record from t_min on, and must rise above the noise floor; otherwise the gauge reports
// no crest, with the reason.
// Celerity between two gauges: c = (x_2 - x_1) / (t_2 - t_1) of their crests; the run's celerity is the
// least-squares slope of x against arrival time over all gauges with a crest.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace cdmpm {

struct Crest {
  double amplitude = 0;  // [m]
  double time = 0;       // [s]
};

// t and eta have the same length; NaN samples (no water at the gauge) are skipped.
inline std::optional<Crest> first_crest(const std::vector<double>& t, const std::vector<double>& eta,
                                        double crest_fraction = 0.25) {
  double top = 0;
  for (double e : eta)
    if (std::isfinite(e) && e > top) top = e;
  if (!(top > 0)) return std::nullopt;
  const double threshold = crest_fraction * top;
  size_t i = 0;
  while (i < eta.size() && !(std::isfinite(eta[i]) && eta[i] >= threshold)) ++i;
  size_t best = i;
  for (; i < eta.size() && std::isfinite(eta[i]) && eta[i] >= threshold; ++i) {
    if (eta[i] > eta[best]) best = i;
    if (eta[i] < eta[best] - 0.5 * threshold) break;
  }
  size_t next = best + 1;  // the crest must be followed by a sample of the record
  while (next < eta.size() && !std::isfinite(eta[next])) ++next;
  if (next >= eta.size()) return std::nullopt;
  Crest c{eta[best], t[best]};
  if (best > 0 && best + 1 < eta.size() && std::isfinite(eta[best - 1]) && std::isfinite(eta[best + 1])) {
    // Vertex of the parabola through the crest sample and its two neighbours (Newton form).
    const double t0 = t[best - 1], t1 = t[best], t2 = t[best + 1];
    const double e0 = eta[best - 1], e1 = eta[best], e2 = eta[best + 1];
    const double d01 = (e1 - e0) / (t1 - t0), d12 = (e2 - e1) / (t2 - t1), curv = (d12 - d01) / (t2 - t0);
    if (curv < 0) {
      const double tv = 0.5 * (t0 + t1) - d01 / (2 * curv);
      if (tv > t0 && tv < t2) {
        c.time = tv;
        c.amplitude = e1 + d01 * (tv - t1) + curv * (tv - t0) * (tv - t1);
      }
    }
  }
  return c;
}

// What a gauge's record shows: its first crest (none if not arrived), its noise floor [m] and, without a crest, why.
struct GaugeReading {
  std::optional<Crest> crest;
  double noise_floor = 0;
  std::string reason;  // empty with a crest
};

// The first crest of a record that counts as a wave: from t >= earliest on, above the noise floor (see above).
inline GaugeReading read_gauge(const std::vector<double>& t, const std::vector<double>& eta, double earliest,
                               double floor) {
  GaugeReading r;
  double noise = 0;
  bool reaches = false;
  std::vector<double> tail_t, tail_eta;
  for (size_t i = 0; i < t.size(); ++i) {
    if (t[i] < earliest) {
      if (std::isfinite(eta[i])) noise = std::max(noise, std::abs(eta[i]));
      continue;
    }
    reaches = true;
    tail_t.push_back(t[i]);
    tail_eta.push_back(eta[i]);
  }
  r.noise_floor = std::max(3 * noise, floor);
  if (!reaches) {
    r.reason = "the record ends before the earliest possible arrival";
    return r;
  }
  double top = -INFINITY;
  for (double e : tail_eta)
    if (std::isfinite(e)) top = std::max(top, e);
  if (!(top > r.noise_floor)) {
    r.reason = "no rise above the noise floor";
    return r;
  }
  // The leading wave starts where the record first exceeds the noise floor: the crest fraction is taken of
  // the record's top with the noise floor as its least.
  const double fraction = std::max(0.25, r.noise_floor / top);
  r.crest = first_crest(tail_t, tail_eta, fraction);
  if (!r.crest) r.reason = "the record ends before the crest has passed";
  return r;
}

// Least-squares slope dx/dt of the points (t_i, x_i); nullopt for fewer than two distinct times.
inline std::optional<double> celerity_fit(const std::vector<double>& x, const std::vector<double>& t) {
  const size_t n = x.size();
  if (n < 2) return std::nullopt;
  double mt = 0, mx = 0;
  for (size_t i = 0; i < n; ++i) mt += t[i] / n, mx += x[i] / n;
  double stt = 0, stx = 0;
  for (size_t i = 0; i < n; ++i) stt += (t[i] - mt) * (t[i] - mt), stx += (t[i] - mt) * (x[i] - mx);
  if (!(stt > 0)) return std::nullopt;
  return stx / stt;
}

}  // namespace cdmpm
