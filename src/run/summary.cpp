// summary.cpp - summary.json (summary.h).
#include "run/summary.h"

#include <omp.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>

#include "io/process_memory.h"
#include "parallel/reduction.h"
#include "probe/wave_report.h"
#include "sim/phases.h"

namespace cdmpm {
namespace {

nlohmann::json energy_json(const EnergyTotals& e) {
  return {{"kinetic", e.kinetic}, {"gravitational", e.gravitational}, {"elastic", e.elastic}, {"total", e.total()}};
}

}  // namespace

template <int dim>
void write_summary(const std::string& out_dir, const Simulation<dim>& sim, const IcebergTracker<dim>& icebergs,
                   const EnergyTotals& e0, const RunTimes& t, const RunResult& result, const RunOptions& options,
                   const nlohmann::json& hazard) {
  const Scene& scene = sim.scene;
  const std::filesystem::path out(out_dir);
  // Collective: the sums over every rank's particles, and each rank's particles and peak memory.
  const EnergyTotals e1 = energy_totals(sim.particles, sim.materials, sim.gravity);
  const double particles = global::sum(double(sim.particles.size()));
  std::vector<std::array<double, 2>> per_rank{{double(sim.particles.size()), peak_rss_bytes()}};
  global::concatenate(per_rank);
#ifdef CDMPM_MPI
  if (mpi::rank() != 0) return;
#endif
  nlohmann::json s;
  s["scene"] = scene.name;
  s["scene_file"] = scene.path;
  s["parameters"] = scene.parameters;
  s["dim"] = dim;
  s["particles"] = static_cast<uint64_t>(particles);
  s["steps"] = sim.steps();
  s["sim_time"] = sim.time();
  s["wall_time"] = t.wall;
  s["particle_steps_per_second"] = t.particle_steps / std::max(t.wall, 1e-9);
  // The same without the set-up and the final checkpoint: the stepping rate (frames, probes and checkpoints
  // written during the run are included).
  s["setup_wall_time"] = t.setup;
  s["stepping_particle_steps_per_second"] = t.particle_steps / std::max(t.loop_end - t.setup, 1e-9);
  nlohmann::json phases;
  for (size_t k = 0; k < phase_names.size(); ++k) phases[phase_names[k]] = sim.phase_timer().seconds(static_cast<Phase>(k));
  s["phase_seconds"] = phases;
  // A distributed run: rank 0's (every rank's below).
  s["peak_memory_bytes"] = per_rank[0][1];
  s["bytes_per_particle"] = per_rank[0][1] / std::max(1.0, per_rank[0][0]);
  s["mass_change"] = (e1.mass - e0.mass) / e0.mass;
  s["energy"] = energy_json(e1);
  s["energy_initial"] = energy_json(e0);
  if (icebergs.active()) s["first_iceberg"] = icebergs.summary();
  s.update(wave_report(scene, (out / "probes.csv").string(), (out / "waves.csv").string()));
  if (!hazard.is_null()) s["hazard"] = hazard;
  if (scene.georeference.given) {
    const GeoreferenceSpec& g = scene.georeference;
    s["georeference"] = {{"easting", g.easting}, {"northing", g.northing}};
    if (dim == 2) s["georeference"]["azimuth"] = g.azimuth;
    s["georeference"]["time_origin"] = g.time_origin;
    if (g.crs)
      s["georeference"]["crs"] = {{"input", g.crs->input}, {"name", g.crs->name},
                                  {"epsg", g.crs->epsg ? nlohmann::json(g.crs->epsg) : nlohmann::json(nullptr)},
                                  {"wkt", g.crs->wkt}};
  }
  s["status"] = result.status;
  s["reason"] = result.reason;
  s["resumed"] = options.resume;
  s["overrides"] = scene.overrides;
  s["command_line"] = options.command_line;
  s["git_commit"] = CDMPM_GIT_COMMIT;
  s["threads"] = omp_get_max_threads();
#ifdef CDMPM_MPI
  // A distributed run (docs/architecture.md): its ranks, the repartitions, the particle imbalance max / mean over the
  // ranks at the particle sorts (the last, the largest, the largest after the first repartition), and rank 0's
  // share of the traffic: the halo bytes of the last step, the particles it migrated, and of iceberg detection the
  // records it sent to other ranks' cells and the largest merge it gathered (bytes; parallel/rank_icebergs.h).
  if (const Domain<dim>* d = sim.domain())
    s["distributed"] = {{"ranks", mpi::size()}, {"repartitions", d->repartitions()},
                        {"last_imbalance", d->last_imbalance()}, {"max_imbalance", d->max_imbalance()},
                        {"max_imbalance_after_first_repartition", d->max_imbalance_repartitioned()},
                        {"rank0_halo_bytes", d->halo.halo_bytes()},
                        {"rank0_migrated_particles", d->migrated()},
                        {"rank0_iceberg_records_sent", rank_iceberg_traffic.records_sent},
                        {"rank0_iceberg_merge_bytes_max", rank_iceberg_traffic.merge_bytes_max}};
  if (sim.domain()) {
    nlohmann::json& d = s["distributed"];
    for (const auto& [n, bytes] : per_rank) d["particles_per_rank"].push_back(n), d["peak_memory_bytes_per_rank"].push_back(bytes);
  }
#endif
  s["precision"] = sizeof(Real) == 8 ? "double" : "single";
  s["version"] = CDMPM_VERSION;
  std::ofstream((out / "summary.json").string()) << s.dump(2) << '\n';
}

template void write_summary<2>(const std::string&, const Simulation<2>&, const IcebergTracker<2>&, const EnergyTotals&,
                               const RunTimes&, const RunResult&, const RunOptions&,
                               const nlohmann::json&);
template void write_summary<3>(const std::string&, const Simulation<3>&, const IcebergTracker<3>&, const EnergyTotals&,
                               const RunTimes&, const RunResult&, const RunOptions&,
                               const nlohmann::json&);

}  // namespace cdmpm
