// probes.h - point and integral measurements sampled into probes.csv at a fixed interval.
//
//   wave_gauge: free-surface elevation above still water at a horizontal position: the highest particle
//               (plus half the particle spacing) in the grid column of width dx around the position,
//               minus the still level (by default the level measured there at t = 0).
//   front:      furthest extent of a material along an axis (outermost particle plus half its spacing).
//   pressure:   B-spline weighted average of particle pressures around a point (kernel width 3 dx):
//               p(x) = sum_p N(x_p - x) p_p / sum_p N(x_p - x); zero where no particle is near.
//   kinetic_energy, gravitational_energy, elastic_energy, total_energy, mass: totals (probe/energy.h).
//   rigid_position, rigid_velocity: centre of mass and its velocity of the rigid body made of the probe's
//               material (sim/rigid_bodies.h), dim columns <name>_x, <name>_y(, <name>_z);
//   rigid_angle: its rotation from the untilted shape [rad] (2D: counter-clockwise, not wrapped; 3D: angle).
// Every probe may be restricted to one material; wave gauges default to the water materials.
#pragma once

#include <string>
#include <vector>

#include "sim/simulation.h"

namespace cdmpm {

template <int dim>
class Probes {
 public:
  // Measures the default still levels of wave gauges in the initial state.
  Probes(const Scene& scene, const Simulation<dim>& sim);
  std::vector<double> sample(const Simulation<dim>& sim) const;
  std::string csv_header() const;
  // Columns a probe writes: dim for rigid_position and rigid_velocity, else 1.
  static int columns(const ProbeSpec& p) {
    return p.type == "rigid_position" || p.type == "rigid_velocity" ? dim : 1;
  }

  std::vector<double> still_levels;  // per probe (NaN where not a gauge); saved in checkpoints

 private:
  const Scene& scene_;
  double surface_height(const Simulation<dim>& sim, const ProbeSpec& p) const;
};

}  // namespace cdmpm
