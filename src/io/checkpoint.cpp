// checkpoint.cpp - writing and reading checkpoints (format in checkpoint.h, checks in checkpoint_format.h).
#include "io/checkpoint.h"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "io/checkpoint_format.h"

namespace cdmpm {
namespace {
constexpr char kMagic[8] = {'C', 'D', 'M', 'P', 'M', 'C', 'K', '9'};
constexpr uint64_t kMaxString = 4096;  // longest string field (frame file names, fingerprint section names)

// Writes and keeps the CRC-32 of everything written.
struct Writer {
  std::ofstream& os;
  uint32_t crc = 0;
  void raw(const void* data, size_t n) {
    os.write(static_cast<const char*>(data), static_cast<std::streamsize>(n));
    crc = crc32_update(crc, data, n);
  }
  template <class T> void pod(const T& v) { raw(&v, sizeof(T)); }
  void str(const std::string& s) { pod<uint64_t>(s.size()); raw(s.data(), s.size()); }
  template <class T> void vec(const std::vector<T>& a) { pod<uint64_t>(a.size()); raw(a.data(), a.size() * sizeof(T)); }
};

// Reads fields, checking each length against the bytes left before the trailing CRC before allocating.
struct Reader {
  std::ifstream& is;
  const std::string& path;
  uint64_t left;  // bytes between the read position and the CRC
  [[noreturn]] void corrupt(const std::string& what) const {
    throw CheckpointError(path + ": checkpoint is corrupt (" + what + ")");
  }
  void raw(void* data, uint64_t n, const char* what) {
    if (n > left) corrupt(std::string(what) + " runs past the end of the file");
    if (!is.read(static_cast<char*>(data), static_cast<std::streamsize>(n))) corrupt("read failed");
    left -= n;
  }
  template <class T> void pod(T& v) { raw(&v, sizeof(T), "a field"); }
  uint64_t length(uint64_t element_size, uint64_t max, const char* what) {
    uint64_t n = 0;
    pod(n);
    if (n > max || n > left / element_size) corrupt(std::string(what) + " length " + std::to_string(n));
    return n;
  }
  void str(std::string& s) {
    s.resize(length(1, kMaxString, "string"));
    raw(s.data(), s.size(), "a string");
  }
  template <class T> void vec(std::vector<T>& a, const char* what) {
    a.resize(length(sizeof(T), UINT64_MAX, what));
    raw(a.data(), a.size() * sizeof(T), what);
  }
};

// The file's size after checking that it is a checkpoint of this format with an intact CRC-32.
uint64_t check_file(std::ifstream& is, const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw CheckpointError(path + ": no checkpoint to resume from");
  const uint64_t size = std::filesystem::file_size(path, ec);
  char magic[8];
  if (ec || size < sizeof magic + 4 || !is.read(magic, 8) || std::memcmp(magic, kMagic, 7) != 0)
    throw CheckpointError(path + ": not a cdmpm checkpoint");
  if (magic[7] != kMagic[7])
    throw CheckpointError(path + ": checkpoint format CDMPMCK" + std::string(1, magic[7]) +
                          " was written by another cdmpm version (this one reads CDMPMCK" + std::string(1, kMagic[7]) +
                          ", which adds the hazard record); rerun the scene without --resume");
  uint32_t stored = 0;
  std::ifstream tail(path, std::ios::binary);
  tail.seekg(static_cast<std::streamoff>(size - 4));
  if (!tail.read(reinterpret_cast<char*>(&stored), 4) || stored != file_crc32(path, size - 4))
    throw CheckpointError(path + ": checkpoint is corrupt (checksum mismatch: the file was changed or cut short)");
  return size;
}

}  // namespace

template <int dim>
void write_checkpoint(const std::string& path, Particles<dim>& p, const CheckpointMeta& m) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream os(tmp, std::ios::binary | std::ios::trunc);
    if (!os) throw std::runtime_error(path + ": cannot write checkpoint");
    Writer w{os};
    w.raw(kMagic, 8);
    w.pod<int32_t>(dim);
    w.pod<int32_t>(sizeof(Real));
    w.pod<uint64_t>(p.size());
    w.pod<uint64_t>(p.solid_count());
    w.pod<uint64_t>(m.scene_fingerprint.size());
    for (const auto& [section, hash] : m.scene_fingerprint) { w.str(section); w.pod(hash); }
    w.pod(m.time); w.pod(m.steps); w.pod(m.frame_index); w.pod(m.probe_index); w.pod(m.wave_dt_at_start);
    w.vec(m.probe_state);
    w.pod<uint64_t>(m.frames.size());
    for (const auto& [t, f] : m.frames) { w.pod(t); w.str(f); }
    w.pod(m.probes_csv_bytes);
    w.pod(m.icebergs_csv_bytes);
    w.vec(m.first_iceberg);
    w.vec(m.crack_starts);
    w.vec(m.rigid_bodies);
    w.vec(m.hazard);
    p.for_each_array([&](auto& a) { w.vec(a); });
    p.for_each_solid_array([&](auto& a) { w.vec(a); });
    const uint32_t crc = w.crc;
    os.write(reinterpret_cast<const char*>(&crc), sizeof crc);
    if (!os.flush()) throw std::runtime_error(path + ": writing checkpoint failed");
  }
  std::filesystem::rename(tmp, path);
}

template <int dim>
CheckpointMeta read_checkpoint(const std::string& path, Particles<dim>& p) {
  std::ifstream is(path, std::ios::binary);
  const uint64_t size = check_file(is, path);
  Reader r{is, path, size - 8 - 4};
  int32_t d = 0, real = 0;
  uint64_t n = 0, ns = 0;
  r.pod(d); r.pod(real); r.pod(n); r.pod(ns);
  if (d != dim)
    throw CheckpointError(path + ": checkpoint is " + std::to_string(d) + "D, scene is " + std::to_string(dim) + "D");
  if (real != static_cast<int32_t>(sizeof(Real)))
    throw CheckpointError(path + ": checkpoint was written with another floating-point precision");
  if (ns > n) r.corrupt("more solid particles than particles");
  CheckpointMeta m;
  m.scene_fingerprint.resize(r.length(8 + 8, UINT64_MAX, "scene fingerprint"));
  for (auto& [section, hash] : m.scene_fingerprint) { r.str(section); r.pod(hash); }
  r.pod(m.time); r.pod(m.steps); r.pod(m.frame_index); r.pod(m.probe_index); r.pod(m.wave_dt_at_start);
  r.vec(m.probe_state, "probe states");
  m.frames.resize(r.length(8 + 8, UINT64_MAX, "frame list"));
  for (auto& [t, f] : m.frames) { r.pod(t); r.str(f); }
  r.pod(m.probes_csv_bytes);
  r.pod(m.icebergs_csv_bytes);
  r.vec(m.first_iceberg, "first iceberg");
  r.vec(m.crack_starts, "crack starts");
  r.vec(m.rigid_bodies, "rigid bodies");
  r.vec(m.hazard, "hazard record");
  auto read_arrays_of = [&](uint64_t count) {
    return [&, count](auto& a) {
      using T = typename std::decay_t<decltype(a)>::value_type;
      if (r.left / sizeof(T) < count) r.corrupt("particle arrays run past the end of the file");
      r.vec(a, "particle array");
      if (a.size() != count) r.corrupt("array sizes differ");
    };
  };
  p.for_each_array(read_arrays_of(n));
  p.for_each_solid_array(read_arrays_of(ns));
  if (r.left != 0) r.corrupt(std::to_string(r.left) + " bytes after the last array");
  return m;
}

template void write_checkpoint<2>(const std::string&, Particles<2>&, const CheckpointMeta&);
template void write_checkpoint<3>(const std::string&, Particles<3>&, const CheckpointMeta&);
template CheckpointMeta read_checkpoint<2>(const std::string&, Particles<2>&);
template CheckpointMeta read_checkpoint<3>(const std::string&, Particles<3>&);

}  // namespace cdmpm
