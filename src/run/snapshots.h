// snapshots.h - snapshots.nc: gridded snapshots of the depth-averaged water (scene key output.snapshots), the
// initial condition a depth-averaged (shallow-water or Boussinesq) model starts from (docs/handoff.md). At each
// snapshot time, on every point of the grid (start + i spacing per horizontal axis, x fastest), the columns of
// probe/column_sampler.h give
//   eta   free-surface elevation above the point's still level [m] (the fill value where the column holds no water),
//   d     total water depth [m] (0 where dry),
//   hu    depth-integrated discharge along x per unit width, d u_bar [m^2/s] (0 where dry), and in 3D hv along y,
// with the static bed (hazard/bed_height.h) and still level (output.snapshots.still_level, else the water top of
// each point at t = 0; NaN where dry then). A CF 1.8 grid (cf.h): dimensions time, [y,] x; 2D coordinates x (distance along the
// transect) with auxiliary easting and northing, 3D coordinates x, y in map coordinates when georeferenced.
//
// Snapshot times are probe sample times (the loader checks), so taking them adds no time step: the simulation has
// the same bits with and without snapshots. The file is created whole at the start (fill values) and each snapshot
// writes its record in place; a resumed run takes the still levels back from the file and rewrites the records
// from the checkpoint's time on with the same values. Measured on every process (collective), written by one.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "probe/column_sampler.h"
#include "sim/simulation.h"

namespace cdmpm {

template <int dim>
class Snapshots {
 public:
  Snapshots(const Simulation<dim>& sim, const std::string& path);
  bool active() const { return sampler_.has_value(); }
  // A fresh run: the still levels and the bed from the initial state, the file.
  void start(Simulation<dim>& sim);
  // A resumed run: the still levels from the file.
  void resume(Simulation<dim>& sim);
  // At a probe sample: the snapshot, if one falls at this time.
  void sample(Simulation<dim>& sim);

 private:
  void create(const Simulation<dim>& sim, const std::vector<double>& bed) const;
  const SnapshotSpec* spec_ = nullptr;
  std::string path_;
  std::optional<ColumnSampler<dim>> sampler_;
  std::vector<double> still_;
};

}  // namespace cdmpm
