// checkpoint.h - binary checkpoint of the full particle state and the run's bookkeeping, for resume: one file
// (one process, or a distributed run with --gather-output) or a manifest and one piece per rank (a distributed run).
//
// One file (format CDMPMCKA, native byte order; a "length" is a uint64 element count, a string is a length and
// its bytes):
//   magic "CDMPMCKA" | int32 dim | int32 sizeof(Real) | uint64 particle count n | uint64 solid count ns
//   | fingerprint: length, then per entry (string section, uint64 hash) (io/scene_fingerprint.h)
//   | double time | int64 steps | int64 frame_index | int64 probe_index | double wave_dt_at_start
//   | probe_state (length + doubles: each probe's own state, probe/probes.h) | frames: length, then per frame (double time, string file)
//   | uint64 probes_csv_bytes | uint64 icebergs_csv_bytes | first_iceberg (length + doubles)
//   | crack_starts (length + doubles, probe/crack_starts.h)
//   | rigid_bodies (length + doubles, sim/rigid_bodies.h) | hazard (length + doubles, hazard/hazard_map.h)
//   | every per-particle array as length + raw elements (Particles::for_each_array order: id x v C mass J material)
//   | the solid-only arrays F, alpha and (2D) Fz likewise (the solids are particles 0 .. ns - 1)
//   | uint32 CRC-32 of every byte before it.
// Per rank (format CDMPMCKD): the manifest checkpoint.bin has the same fields up to the hazard record (n and ns
// the totals over the pieces), then, instead of the arrays, the pieces: length, then per piece (string file name,
// uint64 n, uint64 ns, uint64 file size, uint32 the piece's CRC-32) | uint32 CRC-32. Each piece
// (checkpoint_S_rR.bin: S the slot a or b, R the rank) is
//   magic "CDMPMPC2" | int32 dim | int32 sizeof(Real) | uint64 n | uint64 ns | the particles' order keys (length +
//   uint64, ascending: their indices in the one-process array, parallel/migration.h) | the arrays as above | CRC-32.
// Reading merges the pieces by key into the one-process array, so a checkpoint resumes on any number of ranks
// (and in one process) with the bits of one file. A distributed run reads only its share (CheckpointShare): rank r
// of R reads the pieces k with k % R == r, merged by key, and the ranks then partition and migrate the particles
// (parallel/domain.h), so no rank holds the whole state. The two slots alternate: the new pieces are written while the
// manifest still names the previous slot's, then the manifest is replaced, then the previous slot is removed.
// Reading checks the magic, then the CRC over the whole file (and each piece's against the manifest and its own),
// then every length against the bytes left before allocating (checkpoint_format.h); older formats (CDMPMCK2..9;
// CK6 had no particle ids, CK7 no hazard record, CK8 no crack-start record, CK9 no out-of-plane stretch Fz of 2D
// solids) are refused with a message saying so.
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

// One rank's piece of a distributed checkpoint, as the manifest records it.
struct CheckpointPiece {
  std::string file;  // name in the checkpoint's folder (checkpoint_S_rR.bin)
  uint64_t n = 0, ns = 0, bytes = 0;
  uint32_t crc = 0;
};

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
  std::vector<CheckpointPiece> pieces;  // a distributed run's per-rank pieces (empty: the particles are in the file)
};

// The file name of rank `rank`'s piece in slot `slot` ('a' or 'b'): checkpoint_S_rR.bin.
std::string checkpoint_piece_name(char slot, int rank);
// The slot of a piece's file name ('a' or 'b'), or 0 if `file` is not a piece's name.
char checkpoint_piece_slot(const std::string& file);

// What a rank of a distributed run reads of a checkpoint: the pieces k with k % ranks == rank, merged by key (of a
// one-file checkpoint, read whole: the particles [rank n / ranks, (rank + 1) n / ranks)); `keys` receives their
// order keys, ascending.
struct CheckpointShare {
  int rank = 0, ranks = 1;
  std::vector<uint64_t> keys;
};

// One file (meta.pieces empty) with every particle.
template <int dim>
void write_checkpoint(const std::string& path, Particles<dim>& p, const CheckpointMeta& meta);
// A distributed run: this rank's piece (`keys` ascending, one per particle), written to `path` (a slot the manifest
// does not name), and the manifest naming every rank's piece (meta.pieces), written under a temporary name and
// renamed.
template <int dim>
CheckpointPiece write_checkpoint_piece(const std::string& path, Particles<dim>& p, const std::vector<uint64_t>& keys);
void write_checkpoint_manifest(const std::string& path, int dim, const CheckpointMeta& meta);
// Reads a file or a manifest and its pieces (merged by key: the one-process array; with `share`, only that share).
// Throws CheckpointError
// (io/checkpoint_format.h) naming the file if it (or a piece) is missing, corrupt (checksum, a length past the end
// of the file, a piece that is not the one the manifest names, keys not distinct), of another format version or
// of another dim/precision. The values are
// checked separately by validate_checkpoint.
template <int dim>
CheckpointMeta read_checkpoint(const std::string& path, Particles<dim>& p, CheckpointShare* share = nullptr);

}  // namespace cdmpm
