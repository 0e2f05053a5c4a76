// bench_step.cpp - throughput of full MPM steps on a still block of water (Google Benchmark).
//
// Each iteration is one Simulation<dim>::step(sim.stable_dt()): particle reordering (every 8 steps), binning,
// p2g with stresses, wall folding, grid update with boundary conditions, g2p, constitutive update and the
// speed reduction. Scene setup (seeding the particles) is outside the timed loop.
//
//   water2d/T  2D block of water, 4 particles per cell, slip walls on all faces, T OpenMP threads
//   water3d/T  3D block of water, 8 particles per cell, slip walls on all faces, T OpenMP threads
//
// The block is a square (cube) of side 1 m resting in the corner of a domain about 1.25 times larger, so the
// domain holds a layer of empty cells above and beside the water. The water is pre-compressed
// hydrostatically and stays still, so every step costs the same.
//
// Counters:
//   particle_steps_per_second  particles x steps per second of wall-clock time (the headline number)
//   particles                  particle count
//   bytes_per_particle         peak resident memory (VmHWM) / particles
//
// Run (from a build with CDMPM_BUILD_BENCH=ON):
//   build/bench/cdmpm_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
//   build/bench/cdmpm_bench --benchmark_filter='water2d/2'          # one case
//   CDMPM_BENCH_PARTICLES=1000000 build/bench/cdmpm_bench           # bigger blocks
// The environment variable CDMPM_BENCH_PARTICLES sets the approximate particle count of each case
// (default 250000; at least 1000). The count is rounded so that the block is a whole number of cells.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "scene/scene_loader.h"
#include "sim/simulation.h"

namespace {

long target_particles() {
  long n = 250000;
  if (const char* s = std::getenv("CDMPM_BENCH_PARTICLES")) {
    char* end = nullptr;
    const long v = std::strtol(s, &end, 10);
    if (end != s && *end == '\0' && v >= 1000) n = v;
  }
  return n;
}

// The scene json of a still water block with about `particles` particles, validated like a user scene.
cdmpm::Scene water_block_scene(int dim, long particles) {
  const int ppc = dim == 2 ? 4 : 8;
  const double side = 1.0;  // block side [m]
  const int cells = std::max(4, static_cast<int>(std::lround(std::pow(double(particles) / ppc, 1.0 / dim))));
  const double dx = side / cells;
  // A whole number of cells, so the walls lie on grid planes and the mirror folding runs as in real scenes.
  const double domain_side = std::ceil(1.25 * cells) * dx;
  std::vector<double> size(dim, domain_side), zero(dim, 0.0), top(dim, side), gravity(dim, 0.0);
  gravity[dim - 1] = -9.81;
  nlohmann::json j = {
      {"name", dim == 2 ? "water2d" : "water3d"},
      {"dim", dim},
      {"domain", {{"size", size}, {"dx", dx}}},
      {"time", {{"end", 1.0}, {"frame_interval", 0.1}}},
      {"gravity", gravity},
      {"materials",
       {{"water", {{"type", "water"}, {"density", 1000}, {"bulk_modulus", 1.0e6}, {"gamma", 7}, {"viscosity", 1.0e-3}}}}},
      {"bodies",
       {{{"material", "water"},
         {"particles_per_cell", ppc},
         {"shape", {{"type", "box"}, {"min", zero}, {"max", top}}}}}},
      {"boundaries", {{{"type", "walls"}, {"condition", "slip"}}}},
      {"output", {{"frames", false}}}};
  return cdmpm::scene_from_json(j, dim == 2 ? "<water2d>" : "<water3d>");
}

// Resets the process's peak resident set size (VmHWM) to the current one; ignored where not supported.
void reset_peak_rss() {
  std::ofstream f("/proc/self/clear_refs");
  if (f) f << "5";
}

// Peak resident set size in bytes (VmHWM from /proc/self/status), 0 if unavailable.
double peak_rss_bytes() {
  std::ifstream f("/proc/self/status");
  std::string line;
  while (std::getline(f, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::atof(line.c_str() + 6) * 1024.0;  // reported in kB
  return 0;
}

template <int dim>
void bench_water_block(benchmark::State& state) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  reset_peak_rss();
  const cdmpm::Scene scene = water_block_scene(dim, target_particles());
  auto sim = std::make_unique<cdmpm::Simulation<dim>>(scene);
  const double n = static_cast<double>(sim->particles.size());

  for (auto _ : state) sim->step(sim->stable_dt());

  if (auto bad = sim->check_state()) state.SkipWithError(bad->c_str());
  state.counters["particle_steps_per_second"] =
      benchmark::Counter(n * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["particles"] = n;
  // Peak RSS since this case started, so it includes the process baseline (executable, libraries, OpenMP
  // runtime, benchmark bookkeeping; a few MB), not only the simulation's particle and grid data.
  state.counters["bytes_per_particle"] = peak_rss_bytes() / n;
}

}  // namespace

BENCHMARK(bench_water_block<2>)->Name("water2d")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(bench_water_block<3>)->Name("water3d")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
