// iceberg_tracker.h - runs iceberg detection (probe/icebergs.h) on a simulation's ice, writes one row per
// body per output frame to icebergs.csv, and remembers the first iceberg that separates from the glacier.
//
// Body 0 of each detection is the glacier (the largest connected intact body); the first time a second
// body appears, the largest non-glacier body is "the first iceberg": its time, length (extent along
// output.icebergs.flow_axis), height, volume and centroid go into summary.json. Detection runs at every
// probe sample, so the separation time is known to the probe interval; the detection that finds it is also
// written to icebergs.csv (with the index of the last frame written), since a berg may break up before the
// next frame.
// The first iceberg's failure geometry (probe/failure_plane.h: the width of its top and the dip of the surface it
// broke off along, on the side facing the glacier, fitted where that side faces the broken ice, so a crevasse's wall
// above it is left out) is measured at that same detection and goes into summary.json with it.
// In a distributed run detection is collective and no rank gathers the ice (parallel/rank_icebergs.h): every rank
// gets the same bodies and labels its own particles; the first iceberg's particle positions are gathered (in order-key
// order) for the failure geometry, and the crack-start band below is reduced over the ranks (exact maxima and minima),
// so every rank records the same first iceberg.
// The first iceberg's crack start (probe/crack_starts.h) is the earliest event of the simulation's crack-start
// record that lies on the band separating the new iceberg from the glacier. Where its particle is at the
// detection, take its row: the intact particles of the glacier (body 0) and of the iceberg (body 1) within
// w = band_cells dx = 2 dx of it across the flow (vertically; and laterally in 3D). Along the flow, oriented from
// the glacier to the iceberg, the event lies on the band if it is between the glacier's front and the iceberg's
// rear in that row, to w: front_0 - w <= u <= rear_1 + w. A row without glacier or iceberg particles has no band.
// The band may have opened wide by the detection (the berg tilts away), which a distance to both bodies would
// miss; damage under the iceberg (beyond its rear by more than w) or in the glacier behind its front is not on it.
// None found: the crack start is null.
// With it, the number of the band's events in each mode (band_events): the earliest event may be damage that
// predates the crack and that the crack ran into (e.g. ice crushed at a support), so the counts say how the
// band as a whole broke.
// icebergs.csv columns: frame, time, id, particles, volume, length, height, centroid_x, centroid_y
// (, centroid_z). Volumes are areas [m^2] in 2D.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <vector>

#include "material/stress.h"
#include "probe/crack_starts.h"
#include "probe/failure_plane.h"
#include "parallel/reduction.h"
#include "probe/icebergs.h"
#ifdef CDMPM_MPI
#include "parallel/rank_icebergs.h"
#endif
#include "sim/simulation.h"

namespace cdmpm {

template <int dim>
class IcebergTracker {
 public:
  explicit IcebergTracker(const Simulation<dim>& sim) : sim_(sim) {
    const Scene& s = sim.scene;
    int ppc = 0;
    for (const BodySpec& b : s.bodies)
      if (sim.materials[b.material_index].traits().breakable) ppc = std::max(ppc, b.particles_per_cell);
    active_ = ppc > 0;
    min_particles_ = static_cast<size_t>(s.output.min_iceberg_cells) * static_cast<size_t>(ppc);
    for (const Material& m : sim.materials)
      if (m.traits().breakable) spacing_ = std::max(spacing_, Real(2) * m.half_spacing);
  }

  bool active() const { return active_; }

  // The bodies of intact ice now (probe/icebergs.h) and, if label is non-null, the body of each of this process's
  // particles. Collective in a distributed run (parallel/rank_icebergs.h: no rank gathers the ice); the same
  // bodies on every rank.
  std::vector<IceBody<dim>> detect(std::vector<int>* label = nullptr) const {
    const auto& P = sim_.particles;
    const size_t n = P.size();
    std::vector<Real> volume(n), damage(n);
    std::vector<uint8_t> is_ice(n);
#pragma omp parallel for schedule(static)
    for (size_t q = 0; q < n; ++q) {
      const Material& m = sim_.materials[P.material[q]];
      is_ice[q] = m.traits().breakable;
      volume[q] = reference_volume(sim_.materials[P.material[q]], P.mass[q]) * P.J[q];
      damage[q] = particle_damage(m, P, q);
    }
    const OutputSpec& o = sim_.scene.output;
#ifdef CDMPM_MPI
    if (const Domain<dim>* d = sim_.domain())
      return find_ice_bodies_on_ranks<dim>(P.x, volume, damage, is_ice, d->keys(), *d, sim_.grid, spacing_, o.flow_axis,
                                           static_cast<Real>(o.damage_threshold), min_particles_, label);
#endif
    return find_ice_bodies<dim>(P.x, volume, damage, is_ice, sim_.grid.dx, spacing_, o.flow_axis,
                                static_cast<Real>(o.damage_threshold), min_particles_, label);
  }

  // Detection at a probe sample (collective): records the first iceberg; returns that detection's bodies when it is
  // found just now (the caller writes them to icebergs.csv with the index of the frame written last), else nothing.
  std::optional<std::vector<IceBody<dim>>> sample() {
    if (!active_ || !first_.empty()) return std::nullopt;
    std::vector<int> label;
    auto bodies = detect(&label);
    if (bodies.size() < 2) return std::nullopt;
    const IceBody<dim>& b = bodies[1];
    first_ = {sim_.time(), b.length, b.height, b.volume, static_cast<double>(b.particles)};
    for (int a = 0; a < dim; ++a) first_.push_back(b.centroid[a]);
    const int axis = sim_.scene.output.flow_axis;
    const std::vector<Vec<dim>> block = block_positions(label);
    const FailureGeometry f = failure_geometry<dim>(block, sim_.grid.dx, spacing_, axis,
                                                    bodies[0].centroid[axis] < b.centroid[axis] ? -1 : 1,
                                                    broken_positions(block));
    first_.push_back(f.width);
    first_.push_back(f.angle);
    bodies_sign_ = bodies[0].centroid[axis] < b.centroid[axis] ? Real(1) : Real(-1);
    append_crack_start(label);
    return bodies;
  }

  static std::string csv_header() {
    std::string h = "frame,time,id,particles,volume,length,height,centroid_x,centroid_y";
    return dim == 3 ? h + ",centroid_z" : h;
  }

  // One row per body to icebergs.csv (on rank 0 of a distributed run).
  void write_rows(std::ostream& csv, long long frame, const std::vector<IceBody<dim>>& bodies) const {
    for (const IceBody<dim>& b : bodies) {
      csv << frame << ',' << sim_.time() << ',' << b.id << ',' << b.particles << ',' << b.volume << ',' << b.length
          << ',' << b.height;
      for (int a = 0; a < dim; ++a) csv << ',' << b.centroid[a];
      csv << '\n';
    }
    csv.flush();
  }

  // (time, length, height, volume, particles, centroid..., failure width, failure angle, crack start: time,
  // x..., mode, p, q, sigma_1, particle id, band events in tension, in shear) of the first iceberg; empty if none yet. Saved in checkpoints so a
  // resumed run reports it (a checkpoint written before the failure geometry was measured ends after the
  // centroid, one written before the crack start was recorded after the failure angle).
  std::vector<double> first_;

  nlohmann::json summary() const {
    if (first_.empty()) return nullptr;
    nlohmann::json j = {{"time", first_[0]}, {"length", first_[1]}, {"height", first_[2]}, {"volume", first_[3]},
                        {"particles", static_cast<long long>(first_[4])}};
    j["centroid"] = std::vector<double>(first_.begin() + 5, first_.begin() + 5 + dim);
    const auto number_or_null = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
    if (first_.size() >= size_t(7 + dim)) {
      j["failure_width"] = number_or_null(first_[5 + dim]);
      j["failure_angle"] = number_or_null(first_[6 + dim]);
    }
    if (first_.size() >= size_t(7 + dim + crack_start_size)) {
      const double* c = first_.data() + 7 + dim;  // time, x[dim], mode, p, q, sigma_1, particle id, counts
      j["band_events"] = {{"tension", static_cast<long long>(c[6 + dim])}, {"shear", static_cast<long long>(c[7 + dim])}};
      if (!std::isfinite(c[0])) {
        j["crack_start"] = nullptr;
      } else {
        nlohmann::json cs = {{"time", c[0]}};
        for (int a = 0; a < dim; ++a) cs[std::string(1, "xyz"[a])] = c[1 + a];
        cs["mode"] = crack_mode_name(static_cast<CrackMode>(static_cast<int>(c[1 + dim])));
        cs["p"] = c[2 + dim];
        cs["q"] = c[3 + dim];
        cs["sigma_1"] = c[4 + dim];
        cs["particle"] = static_cast<unsigned long long>(c[5 + dim]);
        j["crack_start"] = cs;
      }
    }
    return j;
  }

  static constexpr int band_cells = 2;
  static constexpr size_t crack_start_size = 8 + dim;

  // Index in sim.crack_starts.events() of the first iceberg's crack start (see the header), -1 if none, and
  // the number of band events in each mode (tension, shear); `label` is the detection's body of each particle.
  long find_crack_start(const std::vector<int>& label, std::array<long, 2>& counts) const {
    counts = {0, 0};
    const auto& events = sim_.crack_starts.events();
    const auto& P = sim_.particles;
    const size_t ne = events.size(), n = P.size();
    if (ne == 0) return -1;
    constexpr Real inf = std::numeric_limits<Real>::infinity();
    std::vector<Vec<dim>> at(ne, Vec<dim>::Constant(-inf));
    std::vector<Real> present(ne, 0);
    for (size_t q = 0; q < n; ++q)  // where the event particles are now (a sink may have removed one)
      for (size_t k = 0; k < ne; ++k)
        if (P.id[q] == events[k].id) at[k] = P.x[q], present[k] = 1;
    global::max(at);  // one rank holds each (parallel/reduction.h)
    global::max(present);
    // Per event particle, over the particles of its row (within w of it across the flow: vertically, and
    // laterally in 3D): the glacier's front and the iceberg's rear along the flow, u = the flow coordinate
    // oriented from the glacier to the iceberg. Exact maxima / minima, any order.
    const int axis = sim_.scene.output.flow_axis;
    const Real sgn = bodies_sign_;
    const Real w = band_cells * sim_.grid.dx;
    std::vector<Real> front(ne, -inf), rear(ne, inf);
#pragma omp parallel
    {
      std::vector<Real> f(ne, -inf), r(ne, inf);
#pragma omp for schedule(static) nowait
      for (size_t q = 0; q < n; ++q) {
        if (label[q] != 0 && label[q] != 1) continue;
        const Real u = sgn * P.x[q][axis];
        for (size_t k = 0; k < ne; ++k) {
          bool row = present[k];
          for (int a = 0; a < dim && row; ++a)
            if (a != axis && std::abs(P.x[q][a] - at[k][a]) > w) row = false;
          if (!row) continue;
          if (label[q] == 0) f[k] = std::max(f[k], u);
          else r[k] = std::min(r[k], u);
        }
      }
#pragma omp critical(cdmpm_crack_band)
      for (size_t k = 0; k < ne; ++k) front[k] = std::max(front[k], f[k]), rear[k] = std::min(rear[k], r[k]);
    }
    global::max(front);
    global::min(rear);
    long first = -1;
    for (size_t k = 0; k < ne; ++k) {  // events are in time order
      const Real u = sgn * at[k][axis];
      if (present[k] > 0 && front[k] > -inf && rear[k] < inf && front[k] - w <= u && u <= rear[k] + w) {
        if (first < 0) first = static_cast<long>(k);
        ++counts[static_cast<int>(events[k].mode)];
      }
    }
    return first;
  }

 private:
  // The positions of the broken ice (damage at or above output.icebergs.damage_threshold) within 3 dx of the block's
  // bounding box, over every rank, in order-key order: the band the block broke off along, for failure_geometry.
  std::vector<Vec<dim>> broken_positions(const std::vector<Vec<dim>>& block) const {
    Vec<dim> lo = Vec<dim>::Constant(std::numeric_limits<Real>::max()), hi = -lo;
    for (const Vec<dim>& x : block) {
      lo = lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
    }
    const Real margin = 3 * sim_.grid.dx, threshold = static_cast<Real>(sim_.scene.output.damage_threshold);
    const auto& P = sim_.particles;
    return gathered_positions([&](size_t q) {
      const Material& m = sim_.materials[P.material[q]];
      return m.traits().breakable && particle_damage(m, P, q) >= threshold &&
             ((P.x[q] - lo).array() >= -margin).all() && ((hi - P.x[q]).array() >= -margin).all();
    });
  }

  // The positions of the first iceberg's particles (label 1) over every rank, in order-key order (one process:
  // particle order), for failure_geometry.
  std::vector<Vec<dim>> block_positions(const std::vector<int>& label) const {
    return gathered_positions([&](size_t q) { return label[q] == 1; });
  }

  // The positions of this process's particles that `keep` selects, gathered over every rank in order-key order.
  template <class Keep>
  std::vector<Vec<dim>> gathered_positions(Keep&& keep) const {
    struct Point {
      uint64_t key;
      Vec<dim> x;
    };
    std::vector<Point> points;
    for (size_t q = 0; q < sim_.particles.size(); ++q)
      if (keep(q)) points.push_back({q, sim_.particles.x[q]});
#ifdef CDMPM_MPI
    if (const Domain<dim>* d = sim_.domain())
      for (Point& pt : points) pt.key = d->keys()[pt.key];
#endif
    global::concatenate(points);
    std::sort(points.begin(), points.end(), [](const Point& a, const Point& b) { return a.key < b.key; });
    std::vector<Vec<dim>> x;
    for (const Point& pt : points) x.push_back(pt.x);
    return x;
  }

  void append_crack_start(const std::vector<int>& label) {
    std::array<long, 2> counts{};
    const long k = find_crack_start(label, counts);
    if (k < 0) {
      first_.insert(first_.end(), crack_start_size - 2, std::nan(""));
    } else {
      const CrackStart<dim>& e = sim_.crack_starts.events()[static_cast<size_t>(k)];
      first_.push_back(e.time);
      for (int a = 0; a < dim; ++a) first_.push_back(e.x[a]);
      first_.insert(first_.end(), {double(static_cast<int>(e.mode)), e.p, e.q, e.sigma_1, double(e.id)});
    }
    first_.insert(first_.end(), {double(counts[0]), double(counts[1])});
  }

  const Simulation<dim>& sim_;
  Real bodies_sign_ = 1;  // +1 if the first iceberg lies downstream of the glacier along flow_axis
  bool active_ = false;
  size_t min_particles_ = 0;
  Real spacing_ = 0;
};

}  // namespace cdmpm
