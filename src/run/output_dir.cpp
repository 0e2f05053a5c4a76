// output_dir.cpp - cleaning a reused output folder (see output_dir.h).
#include "run/output_dir.h"

#include <algorithm>
#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace cdmpm {
namespace fs = std::filesystem;

bool is_run_output_file(const std::string& name) {
  static constexpr std::array<std::string_view, 31> kFixed = {
      "particles.pvd", "probes.csv", "icebergs.csv",   "waves.csv",         "linear_waves.csv",
      "cauchy_poisson.csv", "summary.json", "checkpoint.bin", "checkpoint.bin.tmp", "run.json", "scene.resolved.json",
      "hazard.csv", "runup.csv", "max_elevation.asc", "max_elevation_time.asc", "arrival_time.asc",
      "inundation_depth.asc", "crevasses.csv", "crack_starts.csv", "max_elevation.prj", "max_elevation_time.prj",
      "arrival_time.prj", "inundation_depth.prj", "hazard.nc", "stations.nc", "snapshots.nc", "hazard.nc.part",
      "stations.nc.part", "snapshots.nc.part", "terrain.vtp", "terrain.vtp.tmp"};
  if (std::find(kFixed.begin(), kFixed.end(), name) != kFixed.end()) return true;
  // A distributed run's checkpoint pieces (checkpoint_S_rR.bin, io/checkpoint.h), and their temporary names.
  if (name.starts_with("checkpoint_") && (name.ends_with(".bin") || name.ends_with(".bin.tmp"))) return true;
  const std::string_view prefix = "particles_";
  for (const std::string_view suffix : {".vtu", ".pvtu"})  // frames, and a distributed run's pieces (_rR.vtu)
    if (name.size() > prefix.size() + suffix.size() && name.starts_with(prefix) && name.ends_with(suffix)) return true;
  return false;
}

size_t prepare_output_dir(const fs::path& out) {
  fs::create_directories(out);
  std::vector<fs::path> old;
  for (const auto& entry : fs::directory_iterator(out))
    if (!entry.is_directory() && is_run_output_file(entry.path().filename().string())) old.push_back(entry.path());
  for (const auto& p : old) fs::remove(p);
  return old.size();
}

}  // namespace cdmpm
