// checkpoint.h - binary checkpoint of the full particle state and the run's bookkeeping, for resume.
//
// Layout (format CDMPMCK9, native byte order; a "length" is a uint64 element count, a string is a length and
// its bytes):
//   magic "CDMPMCK9" | int32 dim | int32 sizeof(Real) | uint64 particle count n | uint64 solid count ns
//   | fingerprint: length, then per entry (string section, uint64 hash) (io/scene_fingerprint.h)
//   | double time | int64 steps | int64 frame_index | int64 probe_index | double wave_dt_at_start
//   | probe_state (length + doubles: each probe's own state, probe/probes.h) | frames: length, then per frame (double time, string file)
//   | uint64 probes_csv_bytes | uint64 icebergs_csv_bytes | first_iceberg (length + doubles)
//   | crack_starts (length + doubles, probe/crack_starts.h)
//   | rigid_bodies (length + doubles, sim/rigid_bodies.h) | hazard (length + doubles, hazard/hazard_map.h)
//   | every per-particle array as length + raw elements (Particles::for_each_array order: id x v C mass J material)
//   | the solid-only arrays F and alpha likewise (the solids are particles 0 .. ns - 1)
//   | uint32 CRC-32 of every byte before it.
// Reading checks the magic, then the CRC over the whole file, then every length against the bytes left
// before allocating (checkpoint_format.h); older formats (CDMPMCK2..8; CK6 had no particle ids, CK7 no hazard record, CK8 no crack-start record) are refused with a message saying so.
// Written to a temporary file and renamed, so the previous checkpoint stays valid until the new one is
// complete. A resumed run continues bit for bit: the grid, particle bins and speeds are all recomputed from
// the particle state.
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
  std::vector<double> crack_starts;                     // CrackStartRecord::save() (empty: none yet)
  std::vector<double> rigid_bodies;                     // RigidBodies::save() (empty: no rigid body)
  std::vector<double> hazard;                           // HazardMap::save_state() (empty: no hazard record)
  std::vector<std::pair<std::string, uint64_t>> scene_fingerprint;  // io/scene_fingerprint.h
};

template <int dim>
void write_checkpoint(const std::string& path, Particles<dim>& p, const CheckpointMeta& meta);
// Throws CheckpointError (io/checkpoint_format.h) naming the file if it is missing, corrupt (checksum, a
// length past the end of the file), of another format version or of another dim/precision. The values are
// checked separately by validate_checkpoint.
template <int dim>
CheckpointMeta read_checkpoint(const std::string& path, Particles<dim>& p);

}  // namespace cdmpm
