// runner.cpp - the time loop and all run outputs (see runner.h). Output files under --out:
//   particles_NNNN.vtu + particles.pvd (frames), probes.csv, checkpoint.bin, summary.json, and waves.csv for
//   scenes with wave gauges (probe/wave_report.h).
#include "sim/runner.h"

#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "io/checkpoint.h"
#include "io/checkpoint_format.h"
#include "io/scene_fingerprint.h"
#include "io/process_memory.h"
#include "io/vtu_writer.h"
#include "material/stress.h"
#include "probe/energy.h"
#include "probe/iceberg_tracker.h"
#include "probe/probes.h"
#include "probe/wave_report.h"
#include "sim/interrupt.h"
#include "sim/output_dir.h"
#include "sim/simulation.h"

namespace cdmpm {
namespace fs = std::filesystem;
namespace {

using Clock = std::chrono::steady_clock;

template <int dim>
void write_frame(const std::string& path, const Simulation<dim>& sim) {
  const auto& P = sim.particles;
  const size_t n = P.size();
  std::vector<double> pts(3 * n, 0.0);
  VtuField vel{"velocity", 3, std::vector<float>(3 * n, 0.f), {}, {}};
  VtuField mat{"material", 1, {}, {}, std::vector<int32_t>(P.material.begin(), P.material.end())};
  VtuField pres{"pressure", 1, std::vector<float>(n), {}, {}};
  VtuField J{"J", 1, std::vector<float>(n), {}, {}};
  // Cauchy stress [Pa] (material/stress.h), a full 3x3 tensor (row-major, zero-padded in 2D) as ParaView expects.
  VtuField stress{"stress", 9, std::vector<float>(9 * n, 0.f), {}, {}};
  // Ice state: damage in [0, 1], the hardening variable alpha and the current strength p0(alpha).
  const bool ice = std::any_of(sim.materials.begin(), sim.materials.end(),
                               [](const Material& m) { return m.kind == MaterialKind::Ice; });
  const size_t ni = ice ? n : 0;
  VtuField damage{"damage", 1, std::vector<float>(ni), {}, {}};
  VtuField alpha{"alpha", 1, std::vector<float>(ni), {}, {}};
  VtuField p0{"p0", 1, std::vector<float>(ni), {}, {}};
#pragma omp parallel for schedule(static)
  for (size_t q = 0; q < n; ++q) {
    const Material& m = sim.materials[P.material[q]];
    for (int a = 0; a < dim; ++a) {
      pts[3 * q + a] = P.x[q][a];
      vel.f32[3 * q + a] = static_cast<float>(P.v[q][a]);
    }
    pres.f32[q] = static_cast<float>(particle_pressure(m, P, q));
    J.f32[q] = static_cast<float>(P.J[q]);
    const Mat<dim> sigma = cauchy_stress(m, P, q);
    for (int a = 0; a < dim; ++a)
      for (int b = 0; b < dim; ++b) stress.f32[9 * q + 3 * a + b] = static_cast<float>(sigma(a, b));
    if (ice && m.kind == MaterialKind::Ice) {
      damage.f32[q] = static_cast<float>(m.ice.damage(P.alpha[q]));
      alpha.f32[q] = static_cast<float>(P.alpha[q]);
      p0.f32[q] = static_cast<float>(m.ice.plasticity ? m.ice.p0(P.alpha[q]) : Real(0));
    }
  }
  std::vector<VtuField> fields = {vel, mat, pres, J, stress};
  if (ice) fields.insert(fields.end(), {damage, alpha, p0});
  write_vtu(path, pts, fields);
}

// Output times on a regular grid: the event after the one with index k is at origin + (k + 1 - origin_index) dt
// (origin 0, origin_index 0 for a fresh run, so the times are exactly (k + 1) dt). A resumed run keeps that
// grid when its interval is the one the checkpoint was written with; with another interval (a --set of
// time.frame_interval or probes.interval on --resume) the grid starts again at the resume time t, as the
// old grid would put the next event in the past (a negative step) or more than two intervals ahead.
struct OutputGrid {
  double dt, origin = 0;
  long long origin_index = 0;
  double after(long long k) const { return origin + double(k + 1 - origin_index) * dt; }
  // The time of the event after k, no later than `end` (a grid time within 1e-9 dt of end is end itself, so
  // rounding of the grid cannot put a separate event a hair before the last one).
  double next(long long k, double end) const {
    const double t = after(k);
    return t > end - 1e-9 * dt ? end : t;
  }
  void resume_at(double t, long long k) {
    const double n = after(k);
    if (!(n > t && n <= t + 2 * dt)) {
      origin = t;
      origin_index = k;
    }
  }
};

std::string format_duration(double s) {
  if (!std::isfinite(s) || s < 0) return "--:--:--";
  char buf[32];
  const long t = std::lround(s);
  std::snprintf(buf, sizeof buf, "%02ld:%02ld:%02ld", t / 3600, (t / 60) % 60, t % 60);
  return buf;
}

template <int dim>
RunResult run_dim(const Scene& scene, const RunOptions& opt) {
  const auto wall_start = Clock::now();
  Simulation<dim> sim(scene);
  Probes<dim> probes(scene, sim);
  const fs::path out(opt.out_dir);
  const std::string ckpt = (out / "checkpoint.bin").string();
  const double end = scene.time.end;
  OutputGrid frame_grid{scene.time.frame_interval}, probe_grid{scene.output.probe_interval};
  const EnergyTotals e0 = energy_totals(sim.particles, sim.materials, sim.gravity);

  IcebergTracker<dim> icebergs(sim);
  CheckpointMeta meta;
  std::ofstream csv, berg_csv;
  if (opt.resume) {
    const size_t seeded = sim.particles.size(), seeded_solids = sim.particles.solid_count();
    meta = read_checkpoint(ckpt, sim.particles);
    validate_checkpoint(ckpt, meta, sim.particles, scene);
    // Sinks remove particles, so a checkpoint of a scene with sinks may hold fewer than the scene seeds.
    const bool fewer_allowed = !scene.sinks.empty();
    const bool fits = fewer_allowed ? sim.particles.size() <= seeded && sim.particles.solid_count() <= seeded_solids
                                    : sim.particles.size() == seeded && sim.particles.solid_count() == seeded_solids;
    if (!fits)
      throw std::runtime_error(ckpt + ": checkpoint holds " + std::to_string(sim.particles.size()) + " particles (" +
                               std::to_string(sim.particles.solid_count()) + " ice), the scene seeds " +
                               (fewer_allowed ? "at most " : "") + std::to_string(seeded) + " (" +
                               std::to_string(seeded_solids) + " ice): resume with the scene and --set values of the run that wrote it");
    sim.time = meta.time;
    sim.steps = meta.steps;
    frame_grid.resume_at(sim.time, meta.frame_index);
    probe_grid.resume_at(sim.time, meta.probe_index);
    sim.wave_dt_at_start = static_cast<Real>(meta.wave_dt_at_start);
    sim.refresh();
    probes.still_levels = meta.still_levels;
    if (!sim.rigid.load(meta.rigid_bodies))
      throw std::runtime_error(ckpt + ": checkpoint holds the state of another set of rigid bodies than the scene's");
    const fs::path csv_path = out / "probes.csv";
    restore_output_size(csv_path, meta.probes_csv_bytes);
    csv.open(csv_path, std::ios::app);
    icebergs.first_ = meta.first_iceberg;
    if (icebergs.active()) {
      const fs::path berg_path = out / "icebergs.csv";
      restore_output_size(berg_path, meta.icebergs_csv_bytes);
      berg_csv.open(berg_path, std::ios::app);
    }
  } else {
    prepare_output_dir(out);
    csv.open(out / "probes.csv", std::ios::trunc);
    if (icebergs.active()) {
      berg_csv.open(out / "icebergs.csv", std::ios::trunc);
      berg_csv << IcebergTracker<dim>::csv_header() << '\n';
    }
    meta.wave_dt_at_start = sim.wave_dt_at_start;
    meta.still_levels = probes.still_levels;
    meta.scene_fingerprint = scene_fingerprint(scene);
  }
  if (!csv) throw std::runtime_error((out / "probes.csv").string() + ": cannot write");
  if (icebergs.active() && !berg_csv) throw std::runtime_error((out / "icebergs.csv").string() + ": cannot write");
  csv.precision(10);
  berg_csv.precision(10);
  auto write_probes = [&] {
    csv << sim.time;
    for (double v : probes.sample(sim)) csv << ',' << v;
    csv << '\n';
    csv.flush();
  };
  auto write_frame_now = [&] {
    if (!scene.output.frames) return;
    char name[64];
    std::snprintf(name, sizeof name, "particles_%04lld.vtu", meta.frame_index);
    write_frame((out / name).string(), sim);
    meta.frames.emplace_back(sim.time, name);
    write_pvd((out / "particles.pvd").string(), meta.frames);
  };
  auto write_icebergs = [&] { icebergs.write_frame(berg_csv, meta.frame_index); };
  auto checkpoint = [&] {
    meta.time = sim.time;
    meta.steps = sim.steps;
    meta.probes_csv_bytes = static_cast<uint64_t>(fs::file_size(out / "probes.csv"));
    meta.icebergs_csv_bytes = icebergs.active() ? static_cast<uint64_t>(fs::file_size(out / "icebergs.csv")) : 0;
    meta.first_iceberg = icebergs.first_;
    meta.rigid_bodies = sim.rigid.save();
    write_checkpoint(ckpt, sim.particles, meta);
  };
  if (!opt.resume) {
    csv << probes.csv_header() << '\n';
    write_probes();
    write_frame_now();
    write_icebergs();
  }

  RunResult result{"completed", "", 0};
  const double t_begin = sim.time;
  const long long first_step = sim.steps;
  const double setup_wall = std::chrono::duration<double>(Clock::now() - wall_start).count();
  double particle_steps = 0;  // sum over steps of the particle count (sinks may remove particles)
  auto last_progress = Clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - wall_start).count(); };
  const bool tty = isatty(fileno(stderr));
  auto progress_line = [&](bool final) {
    const double wall = elapsed(), rate = particle_steps / std::max(wall, 1e-9);
    const double left = (end - sim.time) / std::max(sim.time - t_begin, 1e-300) * wall;
    std::fprintf(stderr, "%sstep %lld  t = %.5g / %.5g s  dt = %.3e s  particles %zu  %.3g particle-steps/s  left %s%s",
                 tty ? "\r" : "", sim.steps, sim.time, end, static_cast<double>(sim.stable_dt()), sim.particles.size(), rate,
                 format_duration(left).c_str(), final || !tty ? "\n" : "   ");
  };

  while (sim.time < end) {
    Real dt = sim.stable_dt();
    if (dt < Real(1e-3) * sim.wave_dt_at_start || !(dt > 0)) {
      std::ostringstream os;
      os << "time step collapsed to " << dt << " s, below 1e-3 of the acoustic limit " << sim.wave_dt_at_start
         << " s: max particle speed " << sim.max_speed << " m/s at t = " << sim.time << " s, step " << sim.steps;
      result = {"unstable", os.str(), 3};
      break;
    }
    const double next_frame = frame_grid.next(meta.frame_index, end);
    const double next_probe = probe_grid.next(meta.probe_index, end);
    const double target = std::min(next_frame, next_probe);
    const bool hit = sim.time + dt >= target;
    if (hit) dt = static_cast<Real>(target - sim.time);
    particle_steps += double(sim.particles.size());
    sim.step(dt);
    if (hit) sim.time = target;
    if (auto bad = sim.check_state()) {
      result = {"unstable", *bad, 3};
      break;
    }
    if (hit && target == next_probe) {
      ++meta.probe_index;
      write_probes();
      if (icebergs.sample(berg_csv, meta.frame_index) && opt.progress)
        std::fprintf(stderr, "%sfirst iceberg at t = %.4g s: length %.4g m, height %.4g m\n", tty ? "\n" : "",
                     icebergs.first_[0], icebergs.first_[1], icebergs.first_[2]);
    }
    if (hit && target == next_frame) {
      ++meta.frame_index;
      write_frame_now();
      write_icebergs();
      if (scene.output.checkpoint_every > 0 && meta.frame_index % scene.output.checkpoint_every == 0) checkpoint();
    }
    if (scene.output.stop_after_first >= 0 && !icebergs.first_.empty() &&
        sim.time >= icebergs.first_[0] + scene.output.stop_after_first) {
      std::ostringstream os;
      os << "stopped " << scene.output.stop_after_first << " s after the first iceberg (output.icebergs.stop_after_first)";
      result.reason = os.str();
      break;
    }
    if (opt.max_steps > 0 && sim.steps - first_step >= opt.max_steps) {
      result.reason = "stopped after " + std::to_string(opt.max_steps) + " steps (--steps)";
      break;
    }
    if (const int sig = interrupt_signal()) {
      result = {"interrupted", std::string("stopped by ") + interrupt_signal_name(sig), 128 + sig};
      break;
    }
    if (opt.progress && Clock::now() - last_progress > std::chrono::seconds(2)) {
      progress_line(false);
      last_progress = Clock::now();
    }
  }
  const double loop_end_wall = elapsed();  // before the final checkpoint, which can take long on a big scene
  if (result.status != "unstable") checkpoint();
  if (opt.progress) progress_line(true);
  if (result.status != "completed") std::cerr << "cdmpm: run " << result.status << ": " << result.reason << "\n";

  const EnergyTotals e1 = energy_totals(sim.particles, sim.materials, sim.gravity);
  const double wall = elapsed();
  nlohmann::json s;
  s["scene"] = scene.name;
  s["scene_file"] = scene.path;
  s["parameters"] = scene.parameters;
  s["dim"] = dim;
  s["particles"] = sim.particles.size();
  s["steps"] = sim.steps;
  s["sim_time"] = sim.time;
  s["wall_time"] = wall;
  s["particle_steps_per_second"] = particle_steps / std::max(wall, 1e-9);
  // The same without the set-up (seeding or reading the checkpoint, first frame) and the final checkpoint:
  // the stepping rate (frames, probes and checkpoints written during the run are included).
  s["setup_wall_time"] = setup_wall;
  s["stepping_particle_steps_per_second"] = particle_steps / std::max(loop_end_wall - setup_wall, 1e-9);
  const double peak_memory = peak_rss_bytes();
  s["peak_memory_bytes"] = peak_memory;
  s["bytes_per_particle"] = peak_memory / std::max<double>(1, double(sim.particles.size()));
  s["mass_change"] = (e1.mass - e0.mass) / e0.mass;
  s["energy"] = {{"kinetic", e1.kinetic}, {"gravitational", e1.gravitational}, {"elastic", e1.elastic}, {"total", e1.total()}};
  s["energy_initial"] = {{"kinetic", e0.kinetic}, {"gravitational", e0.gravitational}, {"elastic", e0.elastic}, {"total", e0.total()}};
  if (icebergs.active()) s["first_iceberg"] = icebergs.summary();
  csv.close();
  s.update(wave_report(scene, (out / "probes.csv").string(), (out / "waves.csv").string()));
  s["status"] = result.status;
  s["reason"] = result.reason;
  s["resumed"] = opt.resume;
  s["threads"] = omp_get_max_threads();
  s["precision"] = sizeof(Real) == 8 ? "double" : "single";
  s["version"] = CDMPM_VERSION;
  std::ofstream((out / "summary.json").string()) << s.dump(2) << '\n';
  return result;
}

}  // namespace

RunResult run_scene(const Scene& scene, const RunOptions& opt) {
  if (opt.threads > 0) omp_set_num_threads(opt.threads);
  return scene.dim == 2 ? run_dim<2>(scene, opt) : run_dim<3>(scene, opt);
}

}  // namespace cdmpm
