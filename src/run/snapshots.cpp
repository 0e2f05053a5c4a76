// snapshots.cpp - gridded snapshots of the depth-averaged water, snapshots.nc (snapshots.h).
#include "run/snapshots.h"

#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include "hazard/bed_height.h"
#include "io/cf.h"
#include "io/netcdf_file.h"

namespace cdmpm {
namespace {

constexpr double kSnapshotFill = std::numeric_limits<double>::quiet_NaN();

bool snapshot_material(const Material& m, int) {
  return m.traits().fluid;
}

}  // namespace

template <int dim>
Snapshots<dim>::Snapshots(const Simulation<dim>& sim, const std::string& path) : path_(path) {
  const auto& spec = sim.scene.output.snapshots;
  if (!spec) return;
  spec_ = &*spec;
  typename ColumnSampler<dim>::Point start;
  for (int a = 0; a < dim - 1; ++a) start[a] = spec_->start[a];
  sampler_.emplace(ColumnSampler<dim>::grid(start, spec_->spacing, spec_->count));
}

template <int dim>
void Snapshots<dim>::start(Simulation<dim>& sim) {
  if (!active()) return;
  const auto& points = sampler_->stations();
  still_.assign(points.size(), spec_->still_level.value_or(kSnapshotFill));
  if (!spec_->still_level) {
    const auto columns = sampler_->measure(sim, snapshot_material);
    for (size_t k = 0; k < points.size(); ++k) still_[k] = columns[k].wet() ? columns[k].top : kSnapshotFill;
  }
  std::vector<double> bed(points.size());
  for (size_t k = 0; k < points.size(); ++k)
    bed[k] = bed_height<dim>(sim.boundaries, sim.domain_size, std::vector<double>(points[k].data(), points[k].data() + dim - 1));
  sim.on_root([&] { create(sim, bed); });
  sample(sim);
}

template <int dim>
void Snapshots<dim>::create(const Simulation<dim>& sim, const std::vector<double>& bed) const {
  const Scene& scene = sim.scene;
  const GeoreferenceSpec& g = scene.georeference;
  NetcdfFile f(path_, NetcdfFile::Mode::Create);
  cf_global_attributes(f, scene, "Snapshots of the depth-averaged water");
  const int tdim = f.dimension("time", spec_->times.size());
  const int ydim = dim == 3 ? f.dimension("y", static_cast<size_t>(spec_->count[1])) : -1;
  const int xdim = f.dimension("x", static_cast<size_t>(spec_->count[0]));
  const std::vector<int> plane = dim == 3 ? std::vector<int>{ydim, xdim} : std::vector<int>{xdim};
  std::vector<int> field = plane;
  field.insert(field.begin(), tdim);
  const int tv = cf_time(f, tdim, scene);
  const bool map3 = dim == 3 && g.given;
  const int xv = map3 ? cf_coordinate(f, {"x", "easting of the point", "m", "projection_x_coordinate"}, {xdim}, "X")
                      : cf_coordinate(f, {"x", dim == 2 ? "distance along the transect (x in the domain)" : "x in the domain", "m", ""},
                                      {xdim}, "X");
  const int yv = dim == 2 ? -1
                 : map3   ? cf_coordinate(f, {"y", "northing of the point", "m", "projection_y_coordinate"}, {ydim}, "Y")
                          : cf_coordinate(f, {"y", "y in the domain", "m", ""}, {ydim}, "Y");
  // 2D: the transect's points on the map (auxiliary coordinates).
  const auto [ev, nv] = dim == 2 ? cf_map_coordinates(f, scene, {xdim}) : std::pair<int, int>{-1, -1};
  const std::string coordinates = ev >= 0 ? "easting northing" : "";
  const int bv = cf_data(f, {"bed", "bed height above the domain's floor", "m", ""}, plane, coordinates, scene);
  const int sv = cf_data(f, {"still_level", "still water level above the domain's floor", "m", ""}, plane, coordinates, scene);
  cf_data(f, {"eta", "free-surface elevation above the still water level", "m", "sea_surface_height_above_mean_sea_level"},
          field, coordinates, scene);
  cf_data(f, {"d", "total water depth", "m", "sea_floor_depth_below_sea_surface"}, field, coordinates, scene);
  cf_data(f, {"hu", "depth-integrated discharge along x per unit width (d u)", "m2 s-1", ""}, field, coordinates, scene);
  if (dim == 3)
    cf_data(f, {"hv", "depth-integrated discharge along y per unit width (d v)", "m2 s-1", ""}, field, coordinates, scene);
  cf_crs(f, scene);
  f.end_definitions();
  f.put(tv, spec_->times);
  std::vector<double> x(static_cast<size_t>(spec_->count[0]));
  for (size_t i = 0; i < x.size(); ++i) x[i] = (map3 ? g.easting : 0.0) + spec_->start[0] + double(i) * spec_->spacing;
  f.put(xv, x);
  if (dim == 3) {
    std::vector<double> y(static_cast<size_t>(spec_->count[1]));
    for (size_t j = 0; j < y.size(); ++j) y[j] = (map3 ? g.northing : 0.0) + spec_->start[1] + double(j) * spec_->spacing;
    f.put(yv, y);
  }
  if (ev >= 0) {
    std::vector<double> e(x.size()), n(x.size());
    for (size_t i = 0; i < x.size(); ++i) {
      const std::array<double, 2> en = g.map_point({x[i]});
      e[i] = en[0], n[i] = en[1];
    }
    f.put(ev, e);
    f.put(nv, n);
  }
  f.put(bv, bed);
  f.put(sv, still_);
  f.close();
}

template <int dim>
void Snapshots<dim>::resume(Simulation<dim>& sim) {
  if (!active()) return;
  sim.on_root([&] {
    if (!std::filesystem::is_regular_file(path_))
      throw std::runtime_error(path_ + ": missing: the snapshots of the run being resumed (their still levels) are needed");
    NetcdfFile f(path_, NetcdfFile::Mode::Update);
    still_ = f.get(f.find_variable("still_level"), sampler_->stations().size());
    f.close();
  });
  // The other processes need no still levels: only rank 0 writes.
}

template <int dim>
void Snapshots<dim>::sample(Simulation<dim>& sim) {
  if (!active()) return;
  const double t = sim.time(), tolerance = 1e-9 * sim.scene.output.probe_interval;
  size_t k = 0;
  while (k < spec_->times.size() && std::abs(spec_->times[k] - t) > tolerance) ++k;
  if (k == spec_->times.size()) return;
  const auto columns = sampler_->measure(sim, snapshot_material);  // collective
  sim.on_root([&] {
    const size_t n = columns.size();
    std::vector<double> eta(n), d(n), hu(n), hv(n);
    for (size_t p = 0; p < n; ++p) {
      const auto& c = columns[p];
      d[p] = c.wet() ? c.top - c.bottom : 0.0;
      eta[p] = c.wet() ? c.top - still_[p] : kSnapshotFill;
      hu[p] = d[p] * c.u[0];
      if constexpr (dim == 3) hv[p] = d[p] * c.u[1];
    }
    NetcdfFile f(path_, NetcdfFile::Mode::Update);
    std::vector<size_t> start = {k, 0}, count = {1, static_cast<size_t>(spec_->count[0])};
    if (dim == 3) start.push_back(0), count.insert(count.begin() + 1, static_cast<size_t>(spec_->count[1]));
    f.put(f.find_variable("eta"), start, count, eta);
    f.put(f.find_variable("d"), start, count, d);
    f.put(f.find_variable("hu"), start, count, hu);
    if (dim == 3) f.put(f.find_variable("hv"), start, count, hv);
    f.close();
  });
}

template class Snapshots<2>;
template class Snapshots<3>;

}  // namespace cdmpm
