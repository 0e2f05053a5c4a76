// runner.cpp - the time loop and all run outputs (see runner.h). Output files under --out:
//   particles_NNNN.vtu + particles.pvd (frames), probes.csv, checkpoint.bin, summary.json.
#include "sim/runner.h"

#include <omp.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "io/checkpoint.h"
#include "io/vtu_writer.h"
#include "material/stress.h"
#include "probe/energy.h"
#include "probe/probes.h"
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
#pragma omp parallel for schedule(static)
  for (size_t q = 0; q < n; ++q) {
    for (int a = 0; a < dim; ++a) {
      pts[3 * q + a] = P.x[q][a];
      vel.f32[3 * q + a] = static_cast<float>(P.v[q][a]);
    }
    pres.f32[q] = static_cast<float>(particle_pressure(sim.materials[P.material[q]], P, q));
    J.f32[q] = static_cast<float>(P.J[q]);
  }
  write_vtu(path, pts, {vel, mat, pres, J});
}

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
  const double frame_dt = scene.time.frame_interval, probe_dt = scene.output.probe_interval, end = scene.time.end;
  const EnergyTotals e0 = energy_totals(sim.particles, sim.materials, sim.gravity);

  CheckpointMeta meta;
  std::ofstream csv;
  if (opt.resume) {
    meta = read_checkpoint(ckpt, sim.particles);
    sim.time = meta.time;
    sim.steps = meta.steps;
    sim.wave_dt_at_start = static_cast<Real>(meta.wave_dt_at_start);
    sim.refresh();
    probes.still_levels = meta.still_levels;
    const fs::path csv_path = out / "probes.csv";
    if (fs::exists(csv_path)) fs::resize_file(csv_path, meta.probes_csv_bytes);
    csv.open(csv_path, std::ios::app);
  } else {
    fs::create_directories(out);
    csv.open(out / "probes.csv", std::ios::trunc);
    meta.wave_dt_at_start = sim.wave_dt_at_start;
    meta.still_levels = probes.still_levels;
  }
  if (!csv) throw std::runtime_error((out / "probes.csv").string() + ": cannot write");
  csv.precision(10);
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
  auto checkpoint = [&] {
    meta.time = sim.time;
    meta.steps = sim.steps;
    meta.probes_csv_bytes = static_cast<uint64_t>(fs::file_size(out / "probes.csv"));
    write_checkpoint(ckpt, sim.particles, meta);
  };
  if (!opt.resume) {
    csv << probes.csv_header() << '\n';
    write_probes();
    write_frame_now();
  }

  RunResult result{"completed", "", 0};
  const double t_begin = sim.time;
  const long long steps_begin = sim.steps;
  const size_t n = sim.particles.size();
  auto last_progress = Clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - wall_start).count(); };
  const bool tty = isatty(fileno(stderr));
  auto progress_line = [&](bool final) {
    const double wall = elapsed(), rate = (sim.steps - steps_begin) * double(n) / std::max(wall, 1e-9);
    const double left = (end - sim.time) / std::max(sim.time - t_begin, 1e-300) * wall;
    std::fprintf(stderr, "%sstep %lld  t = %.5g / %.5g s  dt = %.3e s  particles %zu  %.3g particle-steps/s  left %s%s",
                 tty ? "\r" : "", sim.steps, sim.time, end, static_cast<double>(sim.stable_dt()), n, rate,
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
    const double next_frame = std::min(end, (meta.frame_index + 1) * frame_dt);
    const double next_probe = std::min(end, (meta.probe_index + 1) * probe_dt);
    const double target = std::min(next_frame, next_probe);
    const bool hit = sim.time + dt >= target;
    if (hit) dt = static_cast<Real>(target - sim.time);
    sim.step(dt);
    if (hit) sim.time = target;
    if (auto bad = sim.check_state()) {
      result = {"unstable", *bad, 3};
      break;
    }
    if (hit && target == next_probe) {
      ++meta.probe_index;
      write_probes();
    }
    if (hit && target == next_frame) {
      ++meta.frame_index;
      write_frame_now();
      if (scene.output.checkpoint_every > 0 && meta.frame_index % scene.output.checkpoint_every == 0) checkpoint();
    }
    if (opt.progress && Clock::now() - last_progress > std::chrono::seconds(2)) {
      progress_line(false);
      last_progress = Clock::now();
    }
  }
  if (result.status == "completed") checkpoint();
  if (opt.progress) progress_line(true);
  if (result.status != "completed") std::cerr << "cdmpm: run unstable: " << result.reason << "\n";

  const EnergyTotals e1 = energy_totals(sim.particles, sim.materials, sim.gravity);
  const double wall = elapsed();
  nlohmann::json s;
  s["scene"] = scene.name;
  s["scene_file"] = scene.path;
  s["dim"] = dim;
  s["particles"] = n;
  s["steps"] = sim.steps;
  s["sim_time"] = sim.time;
  s["wall_time"] = wall;
  s["particle_steps_per_second"] = (sim.steps - steps_begin) * double(n) / std::max(wall, 1e-9);
  s["mass_change"] = (e1.mass - e0.mass) / e0.mass;
  s["energy"] = {{"kinetic", e1.kinetic}, {"gravitational", e1.gravitational}, {"elastic", e1.elastic}, {"total", e1.total()}};
  s["energy_initial"] = {{"kinetic", e0.kinetic}, {"gravitational", e0.gravitational}, {"elastic", e0.elastic}, {"total", e0.total()}};
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
