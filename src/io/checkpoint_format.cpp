// checkpoint_format.cpp - checksum and value checks of checkpoints (see checkpoint_format.h).
#include "io/checkpoint_format.h"

#include <zlib.h>

#include <algorithm>
#include <cstddef>
#include <cmath>
#include <fstream>
#include <limits>
#include <vector>

#include "io/scene_fingerprint.h"

namespace cdmpm {
namespace {

bool finite_all(const std::vector<double>& a) {
  return std::all_of(a.begin(), a.end(), [](double v) { return std::isfinite(v); });
}

// Frame files are written as particles_NNNN.vtu into the output folder; a checkpoint must not point elsewhere.
bool plain_frame_name(const std::string& f) {
  return !f.empty() && f.find_first_of("/\\\"<>&") == std::string::npos && f.front() != '.';
}

// The first bad run bookkeeping value, "" if none.
std::string bad_meta(const CheckpointMeta& m, const Scene& scene) {
  if (!std::isfinite(m.time) || m.time < 0) return "time is not a finite number >= 0";
  if (m.steps < 0 || m.frame_index < 0 || m.probe_index < 0) return "negative step, frame or probe count";
  if (!(std::isfinite(m.wave_dt_at_start) && m.wave_dt_at_start > 0)) return "acoustic time step is not positive";
  if (m.frames.size() > uint64_t(m.frame_index) + 1) return "more frames listed than written";
  for (const auto& [t, f] : m.frames)
    if (!std::isfinite(t) || t < 0 || t > m.time || !plain_frame_name(f)) return "bad frame entry";
  // Probe states may hold NaN (a gauge over a dry column at t = 0), but never an infinity; Probes::load_state
  // checks that they fit the scene's probes. The first iceberg's record is empty or (time, length, height, volume,
  // particles, centroid[dim]) followed, since the failure geometry is measured, by its width and angle, which
  // are NaN when the block was too small to measure (probe/iceberg_tracker.h).
  const auto has_inf = [](const std::vector<double>& v) { return std::any_of(v.begin(), v.end(), [](double x) { return std::isinf(x); }); };
  const size_t base = 5 + static_cast<size_t>(scene.dim), nb = m.first_iceberg.size();
  const auto measured_end = m.first_iceberg.begin() + static_cast<std::ptrdiff_t>(std::min(nb, base));
  if (has_inf(m.probe_state) || !finite_all(m.rigid_bodies) || has_inf(m.first_iceberg) ||
      !std::all_of(m.first_iceberg.begin(), measured_end, [](double x) { return std::isfinite(x); }))
    return "non-finite probe, iceberg or rigid-body value";
  // Since the crack-start record, the first iceberg's record ends with its crack start (time, x[dim], mode,
  // p, q, sigma_1, particle id; NaN if none was found) and the band's event counts by mode, and the record itself holds at most 64 events of
  // 7 + dim finite numbers (probe/crack_starts.h).
  const size_t crack = 8 + static_cast<size_t>(scene.dim), event = 7 + static_cast<size_t>(scene.dim);
  if (m.probe_state.size() > 64 * (scene.probes.size() + 1) ||
      (nb != 0 && nb != base && nb != base + 2 && nb != base + 2 + crack) || m.crack_starts.size() % event != 0 ||
      m.crack_starts.size() > 64 * event)
    return "bad record length";
  if (!finite_all(m.crack_starts)) return "non-finite crack-start value";
  return "";
}

// The first bad particle value, "" if none.
template <int dim>
std::string bad_particle(const Particles<dim>& p, const Scene& scene) {
  const double margin = 2 * scene.domain.dx;
  const size_t nm = scene.materials.size(), ns = p.solid_count();
  for (size_t q = 0; q < p.size(); ++q) {
    const std::string at = " (particle " + std::to_string(q) + ")";
    if (!p.x[q].allFinite()) return "non-finite position" + at;
    for (int a = 0; a < dim; ++a)
      if (p.x[q][a] < -margin || p.x[q][a] > scene.domain.size[a] + margin) return "position outside the domain" + at;
    if (p.material[q] >= nm) return "material id " + std::to_string(p.material[q]) + " out of range" + at;
    if (scene.materials[p.material[q]].traits().solid_state != (q < ns)) return "solid/fluid material mismatch" + at;
    if (!(std::isfinite(p.mass[q]) && p.mass[q] > 0)) return "mass is not positive" + at;
    if (!(std::isfinite(p.J[q]) && p.J[q] > 0)) return "J is not a finite number > 0" + at;
    if (!p.v[q].allFinite() || !p.C[q].allFinite()) return "non-finite velocity or C" + at;
    if (q < ns && (!p.F[q].allFinite() || !std::isfinite(p.alpha[q]))) return "non-finite F or alpha" + at;
    if (q < ns && !(std::isfinite(p.out_of_plane(q)) && p.out_of_plane(q) > 0)) return "Fz is not a finite number > 0" + at;
  }
  return "";
}

}  // namespace

uint32_t crc32_update(uint32_t crc, const void* data, size_t n) {
  const auto* bytes = static_cast<const Bytef*>(data);
  while (n > 0) {  // zlib takes uInt lengths
    const uInt chunk = static_cast<uInt>(std::min<size_t>(n, std::numeric_limits<uInt>::max()));
    crc = static_cast<uint32_t>(::crc32(crc, bytes, chunk));
    bytes += chunk;
    n -= chunk;
  }
  return crc;
}

uint32_t file_crc32(const std::string& path, uint64_t bytes) {
  std::ifstream in(path, std::ios::binary);
  std::vector<char> block(1 << 20);
  uint32_t crc = 0;
  while (bytes > 0 && in) {
    const size_t n = static_cast<size_t>(std::min<uint64_t>(bytes, block.size()));
    if (!in.read(block.data(), static_cast<std::streamsize>(n))) break;
    crc = crc32_update(crc, block.data(), n);
    bytes -= n;
  }
  return bytes == 0 ? crc : ~crc;  // a short read can never match
}

template <int dim>
void validate_checkpoint(const std::string& path, const CheckpointMeta& meta, const Particles<dim>& p,
                         const Scene& scene) {
  const std::string diff = fingerprint_difference(meta.scene_fingerprint, scene_fingerprint(scene));
  if (!diff.empty())
    throw CheckpointError(path + ": checkpoint was written for another scene: " + diff +
                          ". Resume with the scene and --set values of the run that wrote it (only time.end, "
                          "time.frame_interval and probes.interval may change)");
  std::string bad = bad_meta(meta, scene);
  if (bad.empty()) bad = bad_particle(p, scene);
  if (!bad.empty()) throw CheckpointError(path + ": checkpoint is corrupt (" + bad + ")");
}

void restore_output_size(const std::filesystem::path& file, uint64_t bytes) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) return;
  const uint64_t size = std::filesystem::file_size(file, ec);
  if (ec || bytes > size)
    throw CheckpointError(file.string() + ": shorter (" + std::to_string(size) + " bytes) than the checkpoint says (" +
                          std::to_string(bytes) + "): the checkpoint does not belong to this output folder");
  std::filesystem::resize_file(file, bytes);
}

template void validate_checkpoint<2>(const std::string&, const CheckpointMeta&, const Particles<2>&, const Scene&);
template void validate_checkpoint<3>(const std::string&, const CheckpointMeta&, const Particles<3>&, const Scene&);

}  // namespace cdmpm
