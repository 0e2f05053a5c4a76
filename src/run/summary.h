// summary.h - summary.json, written at the end of every run (completed, unstable or stopped): the scene and
// its resolved parameters, particles, steps, simulated and wall time, particle-steps per second (overall and
// while stepping), the wall time of each phase of the step (phase_seconds, sim/phases.h), peak memory and
// bytes per particle, mass change, energies at the start and the end, the first iceberg (with its crack start, probe/iceberg_tracker.h), the wave report of
// the gauges (probe/wave_report.h), the hazard entry (hazard/hazard_report.h), the georeference, status and reason, threads, precision, version, git commit, the --set values
// and the command line.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "probe/energy.h"
#include "probe/iceberg_tracker.h"
#include "run/runner.h"
#include "sim/simulation.h"

namespace cdmpm {

// Wall-clock figures of a run [s]: its total, the set-up (seeding or reading the checkpoint, first frame) and
// the end of the time loop (before the final checkpoint), and the particle-steps it made.
struct RunTimes {
  double wall = 0, setup = 0, loop_end = 0, particle_steps = 0;
};

// Collective in a distributed run (every rank calls it; rank 0 writes): the final energies and counts are reduced
// over the ranks' particles in place, and `hazard` need only be given on rank 0.
template <int dim>
void write_summary(const std::string& out_dir, const Simulation<dim>& sim, const IcebergTracker<dim>& icebergs,
                   const EnergyTotals& e0, const RunTimes& times, const RunResult& result, const RunOptions& options,
                   const nlohmann::json& hazard);

}  // namespace cdmpm
