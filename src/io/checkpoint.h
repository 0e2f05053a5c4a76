// checkpoint.h - binary checkpoint of the full particle state and the run's bookkeeping, for resume.
//
// Layout (format CDMPMCK6): magic "CDMPMCK6", dim, sizeof(Real), particle count, solid particle count,
// the run metadata (with the probes' own states and the rigid bodies' state), then every per-particle array raw
// (Particles::for_each_array order, the 64-bit particle ids first), then the solid-only arrays F and alpha
// (Particles::for_each_solid_array order; the solids are particles 0 .. solid count - 1). A checkpoint of
// another format (an older cdmpm: CDMPMCK5 had no particle ids) is refused with a message saying so. Written to a temporary file
// and renamed, so the previous checkpoint stays valid until the new one is complete. A resumed run
// continues bit for bit: the grid, particle bins and speeds are all recomputed from the particle state.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/particles.h"

namespace cdmpm {

struct CheckpointMeta {
  double time = 0;
  long long steps = 0;
  long long frame_index = 0;   // index of the last frame written
  long long probe_index = 0;   // index of the last probe sample written
  double wave_dt_at_start = 0;
  std::vector<double> probe_state;                      // Probes::save_state() (each probe saves its own)
  std::vector<std::pair<double, std::string>> frames;  // (time, file) written so far, for particles.pvd
  uint64_t probes_csv_bytes = 0;                        // size of probes.csv at the checkpoint
  uint64_t icebergs_csv_bytes = 0;                      // size of icebergs.csv at the checkpoint
  std::vector<double> first_iceberg;                    // IcebergTracker::first_ (empty: none yet)
  std::vector<double> rigid_bodies;                     // RigidBodies::save() (empty: no rigid body)
};

template <int dim>
void write_checkpoint(const std::string& path, Particles<dim>& p, const CheckpointMeta& meta);
// Throws std::runtime_error naming the file if it is missing, truncated, of another format version or of
// another dim/precision.
template <int dim>
CheckpointMeta read_checkpoint(const std::string& path, Particles<dim>& p);

}  // namespace cdmpm
