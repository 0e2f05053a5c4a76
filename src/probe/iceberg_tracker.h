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
// broke off along, on the side facing the glacier) is measured at that same detection and goes into summary.json
// with it.
// icebergs.csv columns: frame, time, id, particles, volume, length, height, centroid_x, centroid_y
// (, centroid_z). Volumes are areas [m^2] in 2D.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <ostream>
#include <vector>

#include "material/stress.h"
#include "probe/failure_plane.h"
#include "probe/icebergs.h"
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
    return find_ice_bodies<dim>(P.x, volume, damage, is_ice, sim_.grid.dx, spacing_, o.flow_axis,
                                static_cast<Real>(o.damage_threshold), min_particles_, label);
  }

  // Detection at a probe sample: records the first iceberg and, when it is found, writes that detection's
  // bodies to csv (labelled with the index of the frame written last). Returns true if it was found just now.
  bool sample(std::ostream& csv, long long frame) {
    if (!active_ || !first_.empty()) return false;
    std::vector<int> label;
    const auto bodies = detect(&label);
    if (bodies.size() < 2) return false;
    const IceBody<dim>& b = bodies[1];
    first_ = {sim_.time(), b.length, b.height, b.volume, static_cast<double>(b.particles)};
    for (int a = 0; a < dim; ++a) first_.push_back(b.centroid[a]);
    std::vector<Vec<dim>> block;
    for (size_t q = 0; q < label.size(); ++q)
      if (label[q] == 1) block.push_back(sim_.particles.x[q]);
    const int axis = sim_.scene.output.flow_axis;
    const FailureGeometry f = failure_geometry<dim>(block, sim_.grid.dx, spacing_, axis,
                                                    bodies[0].centroid[axis] < b.centroid[axis] ? -1 : 1);
    first_.push_back(f.width);
    first_.push_back(f.angle);
    write_rows(csv, frame, bodies);
    return true;
  }

  static std::string csv_header() {
    std::string h = "frame,time,id,particles,volume,length,height,centroid_x,centroid_y";
    return dim == 3 ? h + ",centroid_z" : h;
  }

  void write_frame(std::ostream& csv, long long frame) const {
    if (active_) write_rows(csv, frame, detect());
  }

  void write_rows(std::ostream& csv, long long frame, const std::vector<IceBody<dim>>& bodies) const {
    for (const IceBody<dim>& b : bodies) {
      csv << frame << ',' << sim_.time() << ',' << b.id << ',' << b.particles << ',' << b.volume << ',' << b.length
          << ',' << b.height;
      for (int a = 0; a < dim; ++a) csv << ',' << b.centroid[a];
      csv << '\n';
    }
    csv.flush();
  }

  // (time, length, height, volume, particles, centroid..., failure width, failure angle) of the first iceberg;
  // empty if none yet. Saved in checkpoints so a resumed run reports it (a checkpoint written before the failure
  // geometry was measured ends after the centroid).
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
    return j;
  }

 private:
  const Simulation<dim>& sim_;
  bool active_ = false;
  size_t min_particles_ = 0;
  Real spacing_ = 0;
};

}  // namespace cdmpm
