// time_step.h - the explicit time-step rule, in one place for the simulation (on its current state,
// sim/simulation.cpp) and the run estimate (on the state at rest, run/run_estimate.cpp):
//   dt = min(cfl dx / max|v_p|, wave_cfl dx / c_max, wave_cfl * the materials' own limits, max_dt),
// c_max the largest wave speed of any material; a zero speed sets no limit, nor does a max_dt of 0.
#pragma once

#include <algorithm>
#include <vector>

#include "material/material.h"
#include "scene/scene.h"

namespace cdmpm {

inline Real stable_time_step(const TimeSpec& t, Real dx, Real max_speed, Real max_wave_speed, Real material_dt) {
  Real dt = material_dt * static_cast<Real>(t.wave_cfl);
  if (max_speed > 0) dt = std::min(dt, static_cast<Real>(t.cfl) * dx / max_speed);
  if (max_wave_speed > 0) dt = std::min(dt, static_cast<Real>(t.wave_cfl) * dx / max_wave_speed);
  if (t.max_dt > 0) dt = std::min(dt, static_cast<Real>(t.max_dt));
  return dt;
}

// The smallest of the materials' own time-step limits (material_model.h stable_dt: viscosity).
inline Real material_time_step_limit(const std::vector<Material>& materials, Real dx, int dim) {
  Real dt = no_time_step_limit;
  for (const Material& m : materials) dt = std::min(dt, m.visit([&](const auto& model) { return model.stable_dt(dx, dim); }));
  return dt;
}

}  // namespace cdmpm
