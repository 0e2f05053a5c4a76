// hazard_map.h - the tsunami-hazard record of a run (scene key "hazard"; scenes with a fluid): per surface column
// (the grid's cells in the horizontal, width dx; in 3D per (x, y) cell) the water top z_top (the highest fluid
// particle plus half its spacing, as the wave gauge measures, probe/wave_gauge.cpp), sampled every step or at
// most once per hazard.interval, and accumulated over the run:
//   still level      z_top at t = 0 (or hazard.still_level, for a scene that starts with a wave); a column
//                    without water at t = 0 is dry,
//   dry ground       a column that held neither water nor any other material (ice, a rigid block) at t = 0: the
//                    only place where inundation is measured (a flooded valley floor, a beach); land, dry ground
//                    whose bed lies above the still water level (the highest still level of the wet columns), the
//                    only place where run-up is (so it is never negative: a column that a calving block vacates
//                    was held by ice),
//   earliest arrival t_min = the column centre's distance from the wave sources / c_max (probe/wave_bounds.h):
//                    before it no wave can have reached the column, so what the column shows then is its noise,
//   noise            the largest |z_top - reference| before t_min (reference: the still level, or the bed of a
//                    dry column),
//   maximum          the largest z_top from t_min on and the first time it was reached: the maximum free-surface
//                    elevation eta_max = max z_top - still level (wet columns) or the maximum inundation depth
//                    d_max = max z_top - bed (dry ground),
//   arrival          the first time from t_min on that z_top exceeded the reference by the arrival threshold:
//                    hazard.arrival_threshold if given, else the column's noise floor, the larger of 3 x its noise
//                    and the gauges' resolution dx / 100 (a threshold tied to the run's own noise, not to dx alone:
//                    dx / 4 left coarse 3D grids without arrival times),
//   run-up (2D)      on every shore (a column dry at t = 0 and not held by another material, next to a wet one,
//                    whose bed lies at most dx below the wet column's still level), the waterline: the edge of the
//                    last particle of the water connected to the sea, in the furthest of the contiguous wet
//                    columns up the shore; the shoreline's elevation z_s = min(bed just beyond the waterline,
//                    water top of that column) (the bed on a slope; the water's top at a vertical wall); the
//                    run-up R = max z_s - still level, the maximum vertical elevation the shoreline reaches above
//                    still water (Synolakis 1987), where and when; and the inundation extent, the furthest
//                    horizontal position of the waterline, and when.
// The bed is hazard/bed_height.h under each column centre (0 without terrain). Everything accumulated is a
// maximum, a minimum or a first time, exact in any order, so the record has the same bits for any thread count;
// it is saved in checkpoints (save_state) so a resumed run continues it bit for bit. Written at the end of the
// run by hazard/hazard_report.h.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "sim/simulation.h"

namespace cdmpm {

template <int dim>
class HazardMap {
 public:
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  // One shore of a 2D run: its first dry column, the direction up the shore (+1: +x), the still level of the
  // wet column before it, and the maxima so far (NaN until the waterline was measured).
  struct Shore {
    size_t first_dry = 0;
    int direction = 1;
    double still_level = kNaN;
    double runup = kNaN, runup_x = kNaN, runup_time = kNaN;
    double extent_x = kNaN, extent_time = kNaN;
  };

  explicit HazardMap(const Simulation<dim>& sim);
  // Whether the scene records hazard (a fluid material, hazard.enabled).
  bool active() const { return active_; }
  // The initial state: still levels, shores, the first sample.
  void init(const Simulation<dim>& sim);
  // After a step: a sample, if the interval since the last one has passed.
  void sample(const Simulation<dim>& sim);
  std::vector<double> save_state() const;
  // Restores what save_state wrote; false if it does not fit this scene's columns.
  bool load_state(const std::vector<double>& state);

  size_t columns() const { return bed_.size(); }
  int count(int axis) const { return n_[axis]; }      // columns along horizontal axis `axis`
  double centre(size_t column, int axis) const;       // column centre [m]
  double dx() const { return dx_; }
  // The arrival threshold of a column [m] (see above); fixed_threshold(): whether the scene gave one.
  double threshold(size_t column) const;
  bool fixed_threshold() const { return !std::isnan(threshold_); }
  // Per column [m] and [s], NaN where not defined (still level of a dry column; never wet).
  const std::vector<double>& bed() const { return bed_; }
  const std::vector<double>& still_level() const { return still_; }
  const std::vector<double>& max_top() const { return max_top_; }
  const std::vector<double>& time_of_max() const { return t_max_; }
  const std::vector<double>& arrival() const { return arrival_; }
  const std::vector<double>& earliest_arrival() const { return earliest_; }
  bool land(size_t column) const { return land_[column] == 1; }
  bool dry_ground(size_t column) const { return land_[column] == 1 || land_[column] == 3; }
  double still_water_level() const { return level_; }
  const std::vector<Shore>& shores() const { return shores_; }

 private:
  void measure(const Simulation<dim>& sim);
  void accumulate(const Simulation<dim>& sim);
  void waterline(const Simulation<dim>& sim, Shore& s) const;
  void find_shores();
  size_t column_of(const Vec<dim>& x) const;  // the column holding point x (clamped to the domain's columns)
  void find_level();                          // level_ from the still levels
  void find_land(const std::vector<double>& held);

  bool active_ = false;
  double dx_ = 0, threshold_ = kNaN, floor_ = 0, interval_ = 0, last_sample_ = kNaN, level_ = kNaN;
  int n_[2] = {1, 1};
  std::vector<double> bed_, still_, max_top_, t_max_, arrival_, earliest_, noise_;
  std::vector<double> land_;  // 1: land, 3: other dry ground (see above), 2: held by another material at t = 0, 0: wet
  std::vector<double> top_, left_, right_;  // this sample: water top; 2D: leftmost and rightmost particle edge
  std::vector<Shore> shores_;
};

}  // namespace cdmpm
