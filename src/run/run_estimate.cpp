// run_estimate.cpp - a run's cost from its scene, and the check that it fits (run_estimate.h).
#include "run/run_estimate.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <sys/resource.h>

#include "grid/grid.h"
#include "run/progress.h"
#include "scene/scene_reader.h"
#include "sim/time_step.h"

namespace cdmpm {
namespace {

// Lattice points (k + 1/2) h of the body's bounding box: an upper bound of what it seeds.
double body_particles(const BodySpec& b, int dim, double dx) {
  const double n = std::round(std::pow(b.particles_per_cell, 1.0 / dim));
  const double h = dx / n;
  double count = 1;
  for (int a = 0; a < dim; ++a) count *= std::max(0.0, std::ceil(b.shape.upper(a) / h - 0.5) - std::floor(b.shape.lower(a) / h - 0.5) + 1);
  return count;
}

// The fastest wave of any material at rest [m/s] (stiffening state 1, material_model.h).
double rest_wave_speed(const Scene& s) {
  double wave = 0;
  for (const Material& m : s.materials)
    m.visit([&](const auto& model) {
      wave = std::max(wave, double(s.dim == 2 ? model.template wave_speed<2>(1) : model.template wave_speed<3>(1)));
    });
  return wave;
}

std::string gigabytes(double bytes) {
  std::ostringstream os;
  os.precision(3);
  os << bytes / 1e9 << " GB";
  return os.str();
}

}  // namespace

double machine_memory_bytes() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kb = 0;
  while (in >> key >> kb)
    if (key == "MemTotal:") return kb * 1024;
  return 0;
}

MemoryLimit usable_memory_bytes() {
  MemoryLimit m{machine_memory_bytes(), "the machine"};
  auto consider = [&](double bytes, const char* source) {
    if (bytes > 0 && (m.bytes <= 0 || bytes < m.bytes)) m = {bytes, source};
  };
  for (const char* path : {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"}) {
    std::ifstream in(path);
    double bytes = 0;
    if (in >> bytes && bytes < 1e18) consider(bytes, "its control group's limit");
  }
  rlimit r{};
  if (getrlimit(RLIMIT_AS, &r) == 0 && r.rlim_cur != RLIM_INFINITY)
    consider(std::max(0.0, double(r.rlim_cur) - 0.5e9) / 0.9, "ulimit -v");  // compared at 90 % below
  return m;
}

RunEstimate estimate_run(const Scene& s) {
  RunEstimate e;
  const double dx = s.domain.dx;
  for (const BodySpec& b : s.bodies) e.particles += body_particles(b, s.dim, dx);
  e.lattice_blocks = 1;
  for (int a = 0; a < s.dim; ++a)
    e.lattice_blocks *= std::ceil((std::ceil(s.domain.size[a] / dx) + 1 + 2 * Grid<2>::ghost) / Grid<2>::block_width);
  e.memory_bytes = e.particles * (bytes_per_particle(s.dim) + (s.output.frames ? frame_bytes_per_particle(s.dim) : 0)) +
                   process_bytes(e.lattice_blocks);
  // Every particle at rest: no speed limit, the materials' rest wave speeds.
  const Real rdx = static_cast<Real>(dx);
  e.first_dt = stable_time_step(s.time, rdx, Real(0), static_cast<Real>(rest_wave_speed(s)),
                                material_time_step_limit(s.materials, rdx, s.dim));
  e.steps = std::ceil((s.time.end + s.time.settle) / e.first_dt);  // the settling (time.settle) steps too
  e.frames = s.output.frames ? std::floor(s.time.end / s.time.frame_interval + 1e-9) + 1 : 0;
  e.frame_bytes = e.frames * e.particles * (s.dim == 3 ? 40 : 25);
  e.wall_seconds = e.particles * e.steps / (2 * core_rate(s.dim));
  return e;
}

std::string describe(const RunEstimate& e) {
  std::ostringstream os;
  os.precision(3);
  os << "particles <= " << e.particles << ", memory ~" << gigabytes(e.memory_bytes) << ", first dt " << e.first_dt
     << " s, ~" << e.steps << " steps, " << e.frames << " frames (~" << gigabytes(e.frame_bytes) << "), wall time ~"
     << format_duration(e.wall_seconds) << " on 2 cores";
  return os.str();
}

void check_run_fits(const Scene& s, const RunEstimate& whole, bool force, int ranks_here, int ranks) {
  RunEstimate e = whole;
  const double per_process = process_bytes(whole.lattice_blocks);
  e.memory_bytes = (whole.memory_bytes - per_process) * ranks_here / ranks + per_process * ranks_here;
  const std::string est = " (estimate: " + describe(e) + ")";
  for (int a = 0; a < s.dim; ++a)
    if (s.domain.size[a] / s.domain.dx >= double(1 << 30))
      throw SceneError(s.path + ": domain.dx: " + format_number(s.domain.size[a] / s.domain.dx) +
                       " cells along axis " + std::to_string(a) + ", more than the grid's 2^30: coarsen domain.dx" + est);
  if (e.lattice_blocks >= 4e9)
    throw SceneError(s.path + ": domain.dx: the grid lattice would have " + format_number(e.lattice_blocks) +
                     " blocks, more than its 32-bit block index holds: coarsen domain.dx" + est);
  if (force) return;
  const std::string override_text = est + "; cdmpm run --force runs it anyway";
  const MemoryLimit limit = usable_memory_bytes();
  const double machine = limit.bytes;
  if (machine > 0 && e.memory_bytes > 0.9 * machine)
    throw SceneError(s.path + ": the run needs about " + gigabytes(e.memory_bytes) + " of memory" +
                     (ranks > 1 ? " on this machine (" + std::to_string(ranks_here) + " of its " + std::to_string(ranks) + " ranks)" : "") +
                     ", " + (limit.source == "the machine" ? "the machine has " : "this process may use ") +
                     gigabytes(machine) + (limit.source == "the machine" ? "" : " (" + limit.source + ")") +
                     ": coarsen domain.dx or bodies' particles_per_cell" +
                     (ranks > 1 ? ", or run on more machines (cdmpm run --dry-run --ranks N plans it)" : "") + override_text);
  if (e.frames > max_frames)
    throw SceneError(s.path + ": time.frame_interval: the run would write " + format_number(e.frames) +
                     " frames, more than " + format_number(max_frames) + ": raise time.frame_interval" + override_text);
}

}  // namespace cdmpm
