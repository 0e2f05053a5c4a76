// hazard_map.cpp - the hazard record of a run (hazard_map.h).
#include "hazard/hazard_map.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "hazard/bed_height.h"
#include "probe/wave_bounds.h"
#include "parallel/reduction.h"

namespace cdmpm {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kStateTag = 2108.0;  // first number of a saved state (its layout), against foreign states

}  // namespace

template <int dim>
HazardMap<dim>::HazardMap(const Simulation<dim>& sim) {
  const Scene& scene = sim.scene;
  active_ = scene.hazard.enabled &&
            std::any_of(sim.materials.begin(), sim.materials.end(), [](const Material& m) { return m.traits().fluid; });
  if (!active_) return;
  dx_ = scene.domain.dx;
  const WaveBounds bounds = wave_bounds(scene);
  threshold_ = scene.hazard.arrival_threshold.value_or(kNaN);
  floor_ = bounds.arrival_floor;
  interval_ = scene.hazard.interval;
  size_t nc = 1;
  for (int a = 0; a < dim - 1; ++a) {
    n_[a] = std::max(1, static_cast<int>(std::ceil(scene.domain.size[a] / dx_ - 1e-9)));
    nc *= static_cast<size_t>(n_[a]);
  }
  bed_.resize(nc);
  earliest_.resize(nc);
  for (size_t c = 0; c < nc; ++c) {
    std::vector<double> h(dim - 1);
    for (int a = 0; a < dim - 1; ++a) h[a] = centre(c, a);
    bed_[c] = bed_height<dim>(sim.boundaries, sim.domain_size, h);
    earliest_[c] = bounds.earliest_arrival(h);
  }
  noise_.assign(nc, 0.0);
  land_.assign(nc, 0.0);
  still_.assign(nc, kNaN);
  max_top_.assign(nc, kNaN);
  t_max_.assign(nc, kNaN);
  arrival_.assign(nc, kNaN);
}

template <int dim>
double HazardMap<dim>::threshold(size_t c) const {
  return fixed_threshold() ? threshold_ : std::max(3 * noise_[c], floor_);
}

template <int dim>
double HazardMap<dim>::centre(size_t c, int axis) const {
  const size_t i = axis == 0 ? c % static_cast<size_t>(n_[0]) : c / static_cast<size_t>(n_[0]);
  return (static_cast<double>(i) + 0.5) * dx_;
}

// The water top of every column (and in 2D the outer particle edges): per-thread maxima and minima, merged by
// max and min, which are exact in any order.
template <int dim>
void HazardMap<dim>::measure(const Simulation<dim>& sim) {
  constexpr int up = vertical_axis<dim>;
  const size_t nc = columns();
  const bool edges = dim == 2;
  top_.assign(nc, -kInf);
  left_.assign(edges ? nc : 0, kInf);
  right_.assign(edges ? nc : 0, -kInf);
  const auto& P = sim.particles;
  const size_t n = P.size();
#pragma omp parallel
  {
    std::vector<double> top(nc, -kInf), left(edges ? nc : 0, kInf), right(edges ? nc : 0, -kInf);
#pragma omp for schedule(static) nowait
    for (size_t q = 0; q < n; ++q) {
      const Material& m = sim.materials[P.material[q]];
      if (!m.traits().fluid) continue;
      const size_t c = column_of(P.x[q]);
      top[c] = std::max(top[c], static_cast<double>(P.x[q][up] + m.half_spacing));
      if (edges) {
        left[c] = std::min(left[c], static_cast<double>(P.x[q][0] - m.half_spacing));
        right[c] = std::max(right[c], static_cast<double>(P.x[q][0] + m.half_spacing));
      }
    }
#pragma omp critical(hazard_merge)
    for (size_t c = 0; c < nc; ++c) {
      top_[c] = std::max(top_[c], top[c]);
      if (edges) left_[c] = std::min(left_[c], left[c]), right_[c] = std::max(right_[c], right[c]);
    }
  }
  global::max(top_);
  global::max(right_);
  global::min(left_);
}

template <int dim>
size_t HazardMap<dim>::column_of(const Vec<dim>& x) const {
  size_t c = 0, stride = 1;
  for (int a = 0; a < dim - 1; ++a) {
    c += stride * static_cast<size_t>(std::clamp(static_cast<int>(std::floor(x[a] / dx_)), 0, n_[a] - 1));
    stride *= static_cast<size_t>(n_[a]);
  }
  return c;
}

template <int dim>
void HazardMap<dim>::init(const Simulation<dim>& sim) {
  if (!active_) return;
  measure(sim);
  const std::optional<double>& given = sim.scene.hazard.still_level;
  for (size_t c = 0; c < columns(); ++c) still_[c] = std::isinf(top_[c]) ? kNaN : given ? *given : top_[c];
  // The columns that any material other than the fluids holds at t = 0 (ice, rigid blocks).
  std::vector<double> held(columns(), 0.0);
  const auto& P = sim.particles;
  for (size_t q = 0; q < P.size(); ++q)
    if (!sim.materials[P.material[q]].traits().fluid) held[column_of(P.x[q])] = 1;
  global::max(held);
  find_land(held);
  find_shores();
  accumulate(sim);
}

// The still water level: the highest still level of the wet columns (NaN without any).
template <int dim>
void HazardMap<dim>::find_level() {
  level_ = kNaN;
  for (size_t c = 0; c < columns(); ++c)
    if (!std::isnan(still_[c]) && !(still_[c] <= level_)) level_ = still_[c];
}

// Dry ground: dry at t = 0 and held by no other material; land (1) if its bed lies above the still water level,
// else 3; 2: held by another material; 0: wet.
template <int dim>
void HazardMap<dim>::find_land(const std::vector<double>& held) {
  find_level();
  for (size_t c = 0; c < columns(); ++c)
    land_[c] = held[c] != 0 ? 2.0 : !std::isnan(still_[c]) ? 0.0 : !std::isnan(level_) && bed_[c] > level_ ? 1.0 : 3.0;
}

template <int dim>
void HazardMap<dim>::sample(const Simulation<dim>& sim) {
  if (!active_ || (interval_ > 0 && sim.time() < last_sample_ + interval_)) return;
  measure(sim);
  accumulate(sim);
}

template <int dim>
void HazardMap<dim>::accumulate(const Simulation<dim>& sim) {
  const double t = sim.time();
  last_sample_ = t;
  for (size_t c = 0; c < columns(); ++c) {
    const double top = top_[c];
    if (std::isinf(top)) continue;
    const double ref = std::isnan(still_[c]) ? bed_[c] : still_[c];
    if (t < earliest_[c]) {  // no wave can be here yet: the column's noise
      noise_[c] = std::max(noise_[c], std::abs(top - ref));
      continue;
    }
    if (!(top <= max_top_[c])) max_top_[c] = top, t_max_[c] = t;  // NaN at first: taken
    if (std::isnan(arrival_[c]) && top - ref > threshold(c)) arrival_[c] = t;
  }
  for (Shore& s : shores_) waterline(sim, s);
}

// The waterline of a 2D shore at this sample: from the last wet column before the shore, up the shore through
// the contiguous columns holding water, to the outer particle edge in the last of them; its elevation is the
// bed there, or the water's top in that column where it is lower (a vertical wall).
template <int dim>
void HazardMap<dim>::waterline(const Simulation<dim>& sim, Shore& s) const {
  const long d = s.direction;
  long j = static_cast<long>(s.first_dry) - d;
  if (std::isinf(top_[j])) return;  // drawn down below the shore's first column
  while (j + d >= 0 && j + d < n_[0] && !std::isinf(top_[j + d])) j += d;
  const double x = std::clamp(d > 0 ? right_[j] : left_[j], 0.0, n_[0] * dx_);
  // The shoreline's elevation: the bed just beyond the waterline, or the water's top if that is lower (a
  // steep or vertical shore, where the bed beyond the waterline is the top of the wall).
  const double beyond = std::clamp(x + d * 1e-3 * dx_, 0.0, n_[0] * dx_);
  const double runup = std::min(bed_height<dim>(sim.boundaries, sim.domain_size, {beyond}), top_[j]) - s.still_level;
  const double t = sim.time();
  if (!(runup <= s.runup)) s.runup = runup, s.runup_x = x, s.runup_time = t;
  if (!(d * x <= d * s.extent_x)) s.extent_x = x, s.extent_time = t;
}

template <int dim>
void HazardMap<dim>::find_shores() {
  shores_.clear();
  if (dim != 2) return;
  auto wet = [&](size_t c) { return !std::isnan(still_[c]); };
  // A dry column that another material holds (an ice cliff) is no shore.
  auto dry = [&](size_t c) { return std::isnan(still_[c]) && land_[c] != 2; };
  for (size_t i = 0; i + 1 < columns(); ++i) {
    if (wet(i) && dry(i + 1) && bed_[i + 1] > still_[i] - dx_) shores_.push_back({i + 1, 1, still_[i]});
    if (dry(i) && wet(i + 1) && bed_[i] > still_[i + 1] - dx_) shores_.push_back({i, -1, still_[i + 1]});
  }
}

// Layout: tag, columns, shores, last sample time, then per column still level, max top, time of max, arrival,
// noise, land, then per shore run-up, its x and time, extent and its time.
template <int dim>
std::vector<double> HazardMap<dim>::save_state() const {
  if (!active_) return {};
  std::vector<double> s = {kStateTag, double(columns()), double(shores_.size()), last_sample_};
  for (size_t c = 0; c < columns(); ++c)
    s.insert(s.end(), {still_[c], max_top_[c], t_max_[c], arrival_[c], noise_[c], land_[c]});
  for (const Shore& h : shores_) s.insert(s.end(), {h.runup, h.runup_x, h.runup_time, h.extent_x, h.extent_time});
  return s;
}

template <int dim>
bool HazardMap<dim>::load_state(const std::vector<double>& s) {
  if (!active_) return s.empty();
  const size_t nc = columns();
  if (s.size() < 4 || s[0] != kStateTag || s[1] != double(nc)) return false;
  const size_t shores = static_cast<size_t>(s[2]);
  if (!(s[2] >= 0) || s.size() != 4 + 6 * nc + 5 * shores) return false;
  last_sample_ = s[3];
  size_t k = 4;
  for (size_t c = 0; c < nc; ++c) {
    still_[c] = s[k++], max_top_[c] = s[k++], t_max_[c] = s[k++], arrival_[c] = s[k++], noise_[c] = s[k++];
    land_[c] = s[k++];
  }
  find_level();
  find_shores();  // from the still levels, the land and the bed, as at the start
  if (shores_.size() != shores) return false;
  for (Shore& h : shores_) {
    h.runup = s[k++], h.runup_x = s[k++], h.runup_time = s[k++], h.extent_x = s[k++], h.extent_time = s[k++];
  }
  return true;
}

template class HazardMap<2>;
template class HazardMap<3>;

}  // namespace cdmpm
