// output_dir.h - the output folder of a fresh run is cleaned of a previous run's files.
//
// A fresh run (not --resume) into a folder that already holds a run's output first removes the files a run
// writes: particles_*.vtu and .pvtu, particles.pvd, probes.csv, icebergs.csv, waves.csv, linear_waves.csv,
// cauchy_poisson.csv, summary.json, checkpoint.bin, checkpoint.bin.tmp, checkpoint_*.bin (and .tmp), run.json, scene.resolved.json and the hazard
// products (hazard.csv, runup.csv, max_elevation.asc, max_elevation_time.asc, arrival_time.asc,
// inundation_depth.asc), crevasses.csv and crack_starts.csv. Other files are left alone,
// and so are sub-folders. Without this a shorter rerun would leave the old run's later frames beside its own.
#pragma once

#include <filesystem>
#include <string>

namespace cdmpm {

// Creates `out` if needed and removes a previous run's output files from it (list above); returns the number
// of files removed. Throws std::filesystem::filesystem_error if a file cannot be removed.
size_t prepare_output_dir(const std::filesystem::path& out);

// True for the names of the files a run writes (the list above).
bool is_run_output_file(const std::string& filename);

}  // namespace cdmpm
