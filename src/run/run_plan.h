// run_plan.h - `cdmpm run SCENE --dry-run --ranks N`: the decomposition of a distributed run of the scene on N
// ranks, set up without allocating its particles, so a user knows what cluster a run needs before asking for it.
//
// The scene is seeded once keeping no particle (its particles counted per block: 4 bytes per lattice block,
// parallel/decomposition.h), the blocks are partitioned as a distributed run partitions them at its start
// (parallel/partition.h; the same cuts), and for each rank the plan gives its particles, occupied blocks, halo
// blocks, the bytes it sends per step (patches and velocities, parallel/halo_exchange.h), an estimate of its memory
// and a projection of a step's time. The per-rank particles are those a run's ranks hold at t = 0
// (summary.json distributed.particles_per_rank after a first step, test Mpi.DryRunMatchesRun).
//
// Memory per rank (an estimate, as `cdmpm check`'s, run/run_estimate.h): its particles times 250 B (3D) or 160 B
// (2D), plus 8 B per lattice block, twice the halo bytes of a step (send and receive buffers), the bed layer of a
// well-balanced bed (seeded whole on every rank) and 64 MB for the program.
// Step time (a projection, not a measurement): the busiest rank's particles over `core_rate` particle-steps per
// second per core (default as run_estimate: 1 M in 3D, 2 M in 2D) times its threads, plus its halo bytes over
// `bandwidth` (default 12.5 GB/s, 100 Gb/s), plus the latency of the step's collectives: 4 all-to-all exchanges
// of (N - 1) messages and 6 reductions of 2 log2 N messages, `latency` each (default 2 us); docs/performance.md.
#pragma once

#include <nlohmann/json.hpp>

#include "scene/scene.h"

namespace cdmpm {

struct PlanOptions {
  int ranks = 1;
  int threads = 1;          // OpenMP threads per rank
  double core_rate = 0;     // particle-steps per second per core; 0: the default for the scene's dimension
  double bandwidth = 12.5e9;  // bytes per second per rank
  double latency = 2e-6;    // seconds per message
};

nlohmann::json plan_run(const Scene& scene, const PlanOptions& options);

}  // namespace cdmpm
