// wave_bounds.cpp - the physical bounds of a run's waves from its scene (wave_bounds.h).
#include "probe/wave_bounds.h"

#include <algorithm>
#include <cmath>

namespace cdmpm {
namespace {

// The horizontal box a body can occupy at t = 0: its shape's bounds, and for a rigid body that starts tilted or
// turns about a hinge (a prescribed motion) the box the shape sweeps about its pivot (the hinge, else the shape's
// centre) at any angle; for a replayed source (rigid key `track`) the shape's box grown by the track's reach.
std::pair<std::vector<double>, std::vector<double>> source_box(const BodySpec& b, int dim) {
  std::vector<double> lo(dim - 1), hi(dim - 1);
  const bool turns = b.tilt != 0 || !b.motion.empty() || !b.hinge.empty();
  double reach = 0;  // the largest distance from the pivot to a corner of the shape's box
  std::vector<double> pivot(dim);
  for (int a = 0; a < dim; ++a) pivot[a] = b.hinge.empty() ? 0.5 * (b.shape.lower(a) + b.shape.upper(a)) : b.hinge[a];
  for (int a = 0; a < dim; ++a) {
    const double far = std::max(std::abs(b.shape.lower(a) - pivot[a]), std::abs(b.shape.upper(a) - pivot[a]));
    reach += far * far;
  }
  reach = std::sqrt(reach);
  const double replayed = b.track ? b.track->reach() : 0;  // a replayed source moves at most this far
  for (int a = 0; a < dim - 1; ++a) {
    lo[a] = (turns ? std::min(b.shape.lower(a), pivot[a] - reach) : b.shape.lower(a)) - replayed;
    hi[a] = (turns ? std::max(b.shape.upper(a), pivot[a] + reach) : b.shape.upper(a)) + replayed;
  }
  return {lo, hi};
}

}  // namespace

WaveBounds wave_bounds(const Scene& scene) {
  WaveBounds w;
  const int dim = scene.dim, up = dim - 1;
  double g2 = 0;
  for (double c : scene.gravity) g2 += c * c;
  w.gravity = std::sqrt(g2);
  w.floor = scene.domain.dx / 1000;
  w.arrival_floor = scene.domain.dx / 100;
  bool moving_boundary = false;
  for (const BoundarySpec& b : scene.boundaries)
    if (b.json.contains("velocity"))
      for (const auto& v : b.json["velocity"]) moving_boundary = moving_boundary || (v.is_number() && v.get<double>() != 0);
  for (const BodySpec& b : scene.bodies) {
    const Material& m = scene.materials[b.material_index];
    if (m.traits().fluid)
      w.h_max = std::max(w.h_max, b.surface_level.value_or(b.shape.upper(up)));
    else
      w.sources.push_back(source_box(b, dim));
  }
  w.c_max = 2 * std::sqrt(w.gravity * w.h_max);
  w.bounded_source = !w.sources.empty() && !moving_boundary;
  return w;
}

double WaveBounds::earliest_arrival(const std::vector<double>& where) const {
  if (!bounded_source || !(c_max > 0)) return 0;
  double nearest = INFINITY;
  for (const auto& [lo, hi] : sources) {
    double d2 = 0;
    for (size_t a = 0; a < where.size(); ++a) {
      const double d = std::max({lo[a] - where[a], 0.0, where[a] - hi[a]});
      d2 += d * d;
    }
    nearest = std::min(nearest, std::sqrt(d2));
  }
  return nearest / c_max;
}

}  // namespace cdmpm
