// bench_step.cpp - throughput of full MPM steps (Google Benchmark), on the scenes of bench_scenes.h.
//
// Each iteration is one reordering cycle of 8 steps, Simulation<dim>::step(sim.stable_dt()) each: particle
// reordering (once per cycle), binning, p2g with stresses, wall folding, grid update with boundary
// conditions, g2p fused with the constitutive update (with the Cam Clay return mapping for ice) and the
// speed reduction. Scene setup (seeding the particles) and one warm-up cycle are outside the timed loop.
//
//   water2d/T    2D still block of water, 4 particles per cell             (benchmark size: 1M particles)
//   ice2d/T      2D Cam Clay ice block yielding in extension every step    (1M)
//   water3d/T    3D still block of water, 8 particles per cell             (2M)
//   ice3d/T      3D Cam Clay ice block yielding in extension every step    (2M)
//   calving2d/T  2D glacier front (elastic ice) next to a water basin      (1M; the issue names no size)
//   machine_fma/T, machine_triad/T   the machine's own two-thread ceilings: core throughput and memory
//                bandwidth (bench_machine.h), to read the cases' two-thread speed-ups against
// T is the number of OpenMP threads (1 and 2). The scenes are described in bench_scenes.h.
//
// Counters:
//   particle_steps_per_second  particles x steps per second of wall-clock time (the headline number)
//   particles                  particle count
//   bytes_per_particle         peak resident memory (VmHWM) / particles, grid and buffers included
//   yielding_fraction          (cases with ice) fraction of the ice particles that yielded (changed alpha)
//                              in one more step after the timed ones
//
// Run (from a build with CDMPM_BUILD_BENCH=ON):
//   build/bench/cdmpm_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
//   build/bench/cdmpm_bench --benchmark_filter='ice2d/2'                    # one case
//   CDMPM_BENCH_PARTICLES=issue build/bench/cdmpm_bench --benchmark_repetitions=5
//       --benchmark_report_aggregates_only=true                             # the issue's sizes (one line)
//   CDMPM_BENCH_PARTICLES=1000000 build/bench/cdmpm_bench                   # every case at about 1M
// The environment variable CDMPM_BENCH_PARTICLES sets the approximate particle count of every case (at least
// 1000), or "issue" for each case's full size; default 250000. The count is rounded so that the bodies
// are whole numbers of cells.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>

#include "bench_machine.h"
#include "bench_scenes.h"
#include "io/process_memory.h"
#include "sim/simulation.h"

namespace {

// Particle count of a case: CDMPM_BENCH_PARTICLES (a number, or "issue" for `issue_size`), default 250000.
long target_particles(long issue_size) {
  long n = 250000;
  if (const char* s = std::getenv("CDMPM_BENCH_PARTICLES")) {
    char* end = nullptr;
    const long v = std::strtol(s, &end, 10);
    if (std::strcmp(s, "issue") == 0) n = issue_size;
    else if (end != s && *end == '\0' && v >= 1000) n = v;
  }
  return n;
}

// Fraction of the solid particles whose hardening variable alpha changes in one step, i.e. that yield.
template <int dim>
double yielding_fraction(cdmpm::Simulation<dim>& sim) {
  const std::vector<cdmpm::Real> before = sim.particles.alpha;
  sim.step(sim.stable_dt());
  size_t yielded = 0;
  for (size_t q = 0; q < before.size(); ++q) yielded += sim.particles.alpha[q] != before[q];
  return double(yielded) / double(before.size());
}

// One benchmark case: the scene make_scene(particles) stepped at state.range(0) threads.
template <int dim>
void bench_case(benchmark::State& state, cdmpm::Scene (*make_scene)(long), long issue_size) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  cdmpm::reset_peak_rss();
  const cdmpm::Scene scene = make_scene(target_particles(issue_size));
  auto sim = std::make_unique<cdmpm::Simulation<dim>>(scene);
  const double n = static_cast<double>(sim->particles.size());
  // Steady state: one reordering cycle first, so the particles start in block order (the first reordering
  // of the seeding order is a one-off) and the grid and buffers are allocated. Then each iteration is one
  // full reordering cycle, so every figure carries its share of reorderings.
  constexpr int cycle = cdmpm::Simulation<dim>::reorder_interval;
  for (int s = 0; s < cycle; ++s) sim->step(sim->stable_dt());

  for (auto _ : state)
    for (int s = 0; s < cycle; ++s) sim->step(sim->stable_dt());

  if (auto bad = sim->check_state()) state.SkipWithError(bad->c_str());
  state.counters["particle_steps_per_second"] =
      benchmark::Counter(n * cycle * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["particles"] = n;
  // Peak RSS since this case started, so it includes the process baseline (executable, libraries, OpenMP
  // runtime, benchmark bookkeeping; a few MB), not only the simulation's particle and grid data.
  state.counters["bytes_per_particle"] = cdmpm::peak_rss_bytes() / n;
  if (sim->particles.solid_count() > 0) state.counters["yielding_fraction"] = yielding_fraction(*sim);
}

cdmpm::Scene water2d(long n) { return cdmpm::bench::water_block(2, n); }
cdmpm::Scene water3d(long n) { return cdmpm::bench::water_block(3, n); }
cdmpm::Scene ice2d(long n) { return cdmpm::bench::ice_block(2, n); }
cdmpm::Scene ice3d(long n) { return cdmpm::bench::ice_block(3, n); }

// Registers case `name` at 1 and 2 threads (named name/1, name/2).
template <int dim>
void register_case(const char* name, cdmpm::Scene (*make_scene)(long), long issue_size) {
  benchmark::RegisterBenchmark(name, bench_case<dim>, make_scene, issue_size)
      ->Arg(1)
      ->Arg(2)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
}

}  // namespace

int main(int argc, char** argv) {
  register_case<2>("water2d", water2d, 1000000);
  register_case<2>("ice2d", ice2d, 1000000);
  register_case<3>("water3d", water3d, 2000000);
  register_case<3>("ice3d", ice3d, 2000000);
  register_case<2>("calving2d", cdmpm::bench::calving_2d, 1000000);
  cdmpm::bench::register_machine_cases();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
