// run_estimate.h - what a run will cost, estimated from the scene alone before anything is allocated: particles
// (at most: every lattice point of each body's bounding box), memory, the first time step, steps to the end (and of the settling, time.settle),
// frames, output size and wall time on this machine; and the check that refuses, before it starts, a run that
// would not fit the machine's memory, whose grid lattice would overflow its indices, or that would write more
// frames than a set limit (`cdmpm run --force` runs it anyway; docs/scenes.md, "Limits").
//
// Memory: bytes_per_particle (3D 250 B, 2D 160 B: a particle's arrays, solids first, docs/performance.md,
// plus bins and grid) times the particles, plus, when frames are written, frame_bytes_per_particle (3D 200 B, 2D
// 220 B: the frame being encoded; measured peaks 362 and 300 B per particle in all on 2.5 M and 4.1 M particles),
// plus 8 B per block of the grid's lattice (the dense block slot and bin tables), plus 64 MB for the program. It
// must fit the memory this process may use: the machine's, its control group's limit and its address-space limit
// (ulimit -v), whichever is least (usable_memory_bytes). First time step: the scene's time step rule
// (sim/time_step.h) with every particle at rest (the materials' rest wave speeds and own limits, max_dt).
// Wall time: particles x steps over the particle-steps per second measured on this machine's 2 cores
// (2D 4 M/s, 3D 2 M/s, docs/performance.md), i.e. a rough guide, not a promise.
#pragma once

#include <cstdint>
#include <string>

#include "scene/scene.h"

namespace cdmpm {

struct RunEstimate {
  double particles = 0;        // at most
  double lattice_blocks = 0;   // blocks of 4^dim nodes over the whole domain
  double memory_bytes = 0;
  double first_dt = 0;         // [s]
  double steps = 0;            // to time.end at the first time step
  double frames = 0;
  double frame_bytes = 0;      // all frames, compressed (about 25 B per particle in 2D, 40 in 3D)
  double wall_seconds = 0;
};

// The cost model of the estimate (above), also the dry run's (run/run_plan.h): a particle's bytes with its share of
// bins, grid and buffers; what every process holds besides its particles (the lattice tables, the program); and one
// core's particle-steps per second on this machine.
inline double bytes_per_particle(int dim) { return dim == 3 ? 250 : 160; }
inline double frame_bytes_per_particle(int dim) { return dim == 3 ? 200 : 220; }
inline double process_bytes(double lattice_blocks) { return 8 * lattice_blocks + 64e6; }
inline double core_rate(int dim) { return dim == 3 ? 1e6 : 2e6; }

RunEstimate estimate_run(const Scene& scene);

// The machine's physical memory [bytes] (/proc/meminfo MemTotal; 0 if unknown).
double machine_memory_bytes();

// The memory this process may use [bytes] and what sets it: the least of the machine's memory, its control
// group's limit (cgroup v2 memory.max, v1 memory.limit_in_bytes) and its address-space limit (RLIMIT_AS, less
// 0.5 GB for the threads' stacks and allocator arenas); 0 if none is known.
struct MemoryLimit {
  double bytes = 0;
  std::string source;  // "the machine", "its control group's limit", "ulimit -v"
};
MemoryLimit usable_memory_bytes();

// Throws SceneError, with the estimate in the message, if the grid's lattice overflows its indices (always), or,
// unless `force`, if the run would need more memory than the machine has or write more than max_frames frames.
// A distributed run of `ranks` ranks, `ranks_here` of them on this machine: each rank holds its share of the
// particles and, whole, the lattice tables and the program (parallel/domain.h), so this machine needs
// ranks_here / ranks of the particles' memory and ranks_here times the rest.
inline constexpr double max_frames = 10000;
void check_run_fits(const Scene& scene, const RunEstimate& estimate, bool force = false, int ranks_here = 1, int ranks = 1);

// One line a person reads: "particles <= N, memory ~X GB, first dt Y s, ~S steps, F frames (~B GB), ~T".
std::string describe(const RunEstimate& estimate);

}  // namespace cdmpm
