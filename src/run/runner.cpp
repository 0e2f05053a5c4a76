// runner.cpp - the time loop (see runner.h). Output files under --out: particles_NNNN.vtu + particles.pvd
// (frames; a distributed run: per-rank pieces under particles_NNNN.pvtu), probes.csv, icebergs.csv, checkpoint.bin (run/run_files.h), summary.json (run/summary.h), and
// waves.csv for scenes with wave gauges (probe/wave_report.h), the hazard products for scenes with a fluid
// (hazard/hazard_report.h), stations.nc for scenes with wave gauges or sections (io/station_file.h), snapshots.nc
// for scenes with output.snapshots (run/snapshots.h), terrain.vtp for scenes with water over a bed
// (io/terrain_surface.h).
#include "run/runner.h"

#include <omp.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>

#include "hazard/bed_height.h"
#include "hazard/hazard_report.h"
#include "io/station_file.h"
#include "io/terrain_surface.h"
#include "parallel/reduction.h"
#include "run/fault_injection.h"
#include "run/interrupt.h"
#include "run/output_schedule.h"
#include "run/progress.h"
#include "run/run_files.h"
#include "run/snapshots.h"
#include "run/summary.h"

namespace cdmpm {
namespace {

using Clock = std::chrono::steady_clock;

// A time step that has collapsed below 1e-3 of the acoustic limit at the start means a blow-up.
template <int dim>
std::optional<std::string> collapsed(const Simulation<dim>& sim, Real dt) {
  if (dt >= Real(1e-3) * sim.wave_dt_at_start && dt > 0) return std::nullopt;
  std::ostringstream os;
  os << "time step collapsed to " << dt << " s, below 1e-3 of the acoustic limit " << sim.wave_dt_at_start
     << " s: max particle speed " << sim.max_speed << " m/s at t = " << sim.time() << " s, step " << sim.steps();
  return os.str();
}

template <int dim>
class TimeLoop {
 public:
  TimeLoop(const Scene& scene, const RunOptions& opt)
      : scene_(scene), opt_(opt), sim_(scene), probes_(scene, sim_), icebergs_(sim_), hazard_(sim_),
        files_(opt.out_dir, sim_, probes_, icebergs_, hazard_), snapshots_(sim_, files_.path("snapshots.nc").string()),
        frames_{scene.time.frame_interval}, samples_{scene.output.probe_interval},
        e0_(energy_totals(sim_.particles, sim_.materials, sim_.gravity)), progress_(opt.progress, 0, scene.time.end) {}

  RunResult run() {
#ifdef CDMPM_MPI
    files_.set_pieces(sim_.domain() != nullptr && !opt_.gather_output);
#endif
    if (opt_.resume) resume();
    else {
      sim_.on_root([&] { files_.start(opt_.command_line); });
      files_.write_probes();
      snapshots_.start(sim_);
      write_frame();
    }
    if (!opt_.resume) {
      hazard_.init(sim_);
      sim_.on_root([&] { write_terrain(); });
    }
    times_.setup = elapsed();
    progress_.start_at(sim_.time());
    RunResult result{"completed", "", 0};
    const long long first_step = sim_.steps();
    while (sim_.time() < scene_.time.end) {
      if (auto bad = step()) {
        result = {"unstable", *bad, 3};
        break;
      }
      if (auto why = stop_reason(first_step)) {
        result.reason = *why;
        break;
      }
      if (auto stop = interrupted()) {
        result = *stop;
        break;
      }
      progress_.update(sim_.steps(), sim_.time(), sim_.stable_dt(), sim_.particles.size(), times_.particle_steps, elapsed(), false,
                       balance());
    }
    times_.loop_end = elapsed();  // before the final checkpoint, which can take long on a big scene
    if (result.status != "unstable") files_.checkpoint();
    progress_.update(sim_.steps(), sim_.time(), sim_.stable_dt(), sim_.particles.size(), times_.particle_steps, elapsed(), true,
                     balance());
    if (result.status != "completed") std::cerr << "cdmpm: run " << result.status << ": " << result.reason << "\n";
    files_.close();
    times_.wall = elapsed();
    nlohmann::json hazard;
    sim_.on_root([&] {
      if (hazard_.active()) hazard = write_hazard_report(opt_.out_dir, hazard_, scene_);
      write_stations();
    });
    write_summary(opt_.out_dir, sim_, icebergs_, e0_, times_, result, opt_, hazard);
    return result;
  }

 private:
  void resume() {
    files_.resume();
    snapshots_.resume(sim_);
    frames_.resume_at(sim_.time(), files_.meta.frame_index);
    samples_.resume_at(sim_.time(), files_.meta.probe_index);
  }

  // One step, landing on the next output time if it is within reach, then the outputs due at its end.
  // Returns why the state went bad, if it did.
  std::optional<std::string> step() {
    const Real dt = sim_.stable_dt();
    if (auto bad = collapsed(sim_, dt)) return bad;
    const double next_frame = frames_.next(files_.meta.frame_index, scene_.time.end);
    const double next_sample = samples_.next(files_.meta.probe_index, scene_.time.end);
    const double target = std::min(next_frame, next_sample);
    times_.particle_steps += global::sum(double(sim_.particles.size()));
    const bool hit = sim_.time() + dt >= target;
    if (hit) sim_.step_until(target);
    else sim_.step(dt);
    if (auto bad = sim_.check_state()) return bad;
    fault_.after_step(sim_.steps());
    hazard_.sample(sim_);
    if (hit && target == next_sample) sample();
    if (hit && target == next_frame) frame();
    return std::nullopt;
  }

  void sample() {
    ++files_.meta.probe_index;
    files_.write_probes();
    snapshots_.sample(sim_);
    if (!icebergs_.active()) return;
    if (files_.sample_icebergs() && opt_.progress)  // collective; the same first iceberg on every rank
      sim_.on_root([&] {
        const auto& f = icebergs_.first_;
        std::fprintf(stderr, "%sfirst iceberg at t = %.4g s: length %.4g m, height %.4g m\n", progress_.tty() ? "\n" : "",
                     f[0], f[1], f[2]);
      });
  }

  void frame() {
    ++files_.meta.frame_index;
    const int every = scene_.output.checkpoint_every;
    write_frame();
    if (every > 0 && files_.meta.frame_index % every == 0) files_.checkpoint();
  }

  // The frame of index meta.frame_index: on the gathered state where it reads particles, its bodies of intact ice
  // (collective, parallel/rank_icebergs.h), then every rank's piece.
  void write_frame() {
    if (files_.frame_reads_particles()) sim_.with_whole_state([&] { files_.write_frame(); });
    else sim_.on_root([&] { files_.write_frame(); });
    files_.write_frame_icebergs();
    files_.write_frame_pieces();
  }

  // terrain.vtp: the bed under every surface column of the hazard record (io/terrain_surface.h), for scenes with
  // water and a bed above the floor somewhere.
  void write_terrain() const {
    if (!hazard_.active()) return;
    const auto& bed = hazard_.bed();
    if (std::none_of(bed.begin(), bed.end(), [](double b) { return b > 0; })) return;
    std::vector<std::array<double, 3>> points;
    for (size_t c = 0; c < hazard_.columns(); ++c)
      points.push_back(dim == 2 ? std::array<double, 3>{hazard_.centre(c, 0), bed[c], 0.0}
                                : std::array<double, 3>{hazard_.centre(c, 0), hazard_.centre(c, 1), bed[c]});
    write_terrain_surface(files_.path("terrain.vtp").string(), points, hazard_.count(0), dim == 2 ? 1 : hazard_.count(1), bed);
  }

  // stations.nc from probes.csv, with the bed under every station (io/station_file.h).
  void write_stations() const {
    const std::vector<Station> stations = probes_.stations();
    std::vector<double> bed;
    for (const Station& s : stations) bed.push_back(bed_height<dim>(sim_.boundaries, sim_.domain_size, s.position));
    write_station_file(files_.path("stations.nc").string(), files_.path("probes.csv").string(), stations, bed, scene_);
  }

  // A completed run that stops before the end time: after the first iceberg (output.icebergs.stop_after_first)
  // or after --steps.
  std::optional<std::string> stop_reason(long long first_step) const {
    const double after = scene_.output.stop_after_first;
    if (after >= 0 && !icebergs_.first_.empty() && sim_.time() >= icebergs_.first_[0] + after) {
      std::ostringstream os;
      os << "stopped " << after << " s after the first iceberg (output.icebergs.stop_after_first)";
      return os.str();
    }
    if (opt_.max_steps > 0 && sim_.steps() - first_step >= opt_.max_steps)
      return "stopped after " + std::to_string(opt_.max_steps) + " steps (--steps)";
    return std::nullopt;
  }

  // SIGINT or SIGTERM (run/interrupt.h): the run ends after this step, with a checkpoint.
  std::optional<RunResult> interrupted() const {
    // A distributed run stops on every rank after the same step when any rank was signalled.
    if (const int sig = static_cast<int>(global::max(double(interrupt_signal()))))
      return RunResult{"interrupted", std::string("stopped by ") + interrupt_signal_name(sig), 128 + sig};
    return std::nullopt;
  }

  // The progress line's part for a distributed run: the particle imbalance max / mean over the ranks at the last
  // sort (parallel/domain.h); empty in one process.
  std::string balance() const {
#ifdef CDMPM_MPI
    if (const Domain<dim>* d = sim_.domain()) {
      char buf[48];
      std::snprintf(buf, sizeof buf, "  imbalance %.3f", d->last_imbalance());
      return buf;
    }
#endif
    return {};
  }

  double elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

  const Clock::time_point start_ = Clock::now();
  const FaultInjection fault_ = FaultInjection::from_environment();
  const Scene& scene_;
  const RunOptions& opt_;
  Simulation<dim> sim_;
  Probes<dim> probes_;
  IcebergTracker<dim> icebergs_;
  HazardMap<dim> hazard_;
  RunFiles<dim> files_;
  Snapshots<dim> snapshots_;
  OutputSchedule frames_, samples_;
  EnergyTotals e0_;
  RunTimes times_;
  Progress progress_;
};

}  // namespace

RunResult run_scene(const Scene& scene, const RunOptions& opt) {
  if (opt.threads > 0) omp_set_num_threads(opt.threads);
  if (opt.progress && scene.time.settle > 0)
    std::cerr << "cdmpm: settling for " << scene.time.settle << " s before t = 0 (time.settle: solids elastic, "
              << "velocities damped at " << scene.time.settle_damping << " 1/s)\n";
  return scene.dim == 2 ? TimeLoop<2>(scene, opt).run() : TimeLoop<3>(scene, opt).run();
}

}  // namespace cdmpm
