// checkpoint_format.h - integrity and validity checks of checkpoints (format in checkpoint.h).
//
// A checkpoint read for --resume is checked in three layers, each refusing with CheckpointError (an input
// error, exit 2) that names the file:
//   1. structure (checkpoint.cpp): magic and format version, the CRC-32 over the whole file, and every length
//      field against the bytes left in the file before anything is allocated;
//   2. values (validate_checkpoint): finite time >= 0, sane frame/probe indices and frame file names, finite
//      positions inside the domain (give or take two cells), material ids of the scene's materials with the
//      solids (ice) first, positive finite masses, finite J > 0, finite velocities, C, F and alpha;
//   3. the scene: the fingerprint of the resumed scene (scene_fingerprint.h) must equal the checkpoint's.
// restore_output_size refuses to grow probes.csv/icebergs.csv to a size the checkpoint claims but the file
// never had.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "core/particles.h"
#include "io/checkpoint.h"
#include "scene/scene.h"

namespace cdmpm {

struct CheckpointError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// CRC-32 (zlib's, polynomial 0xEDB88320) of `n` bytes continuing from `crc` (start with 0).
uint32_t crc32_update(uint32_t crc, const void* data, size_t n);

// CRC-32 of the first `bytes` bytes of the file `path`, read in 1 MiB blocks.
uint32_t file_crc32(const std::string& path, uint64_t bytes);

// Throws CheckpointError naming `path` for the first value of the checkpoint that the scene cannot have
// produced (layer 2 and 3 above).
template <int dim>
void validate_checkpoint(const std::string& path, const CheckpointMeta& meta, const Particles<dim>& p,
                         const Scene& scene);

// Truncates the output file `file` to `bytes` (the size recorded in the checkpoint); throws CheckpointError
// if the file is shorter than that (the checkpoint does not belong to this output). No file: nothing to do.
void restore_output_size(const std::filesystem::path& file, uint64_t bytes);

}  // namespace cdmpm
