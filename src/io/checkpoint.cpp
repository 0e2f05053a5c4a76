// checkpoint.cpp - writing and reading checkpoints (format in checkpoint.h).
#include "io/checkpoint.h"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace cdmpm {
namespace {
constexpr char kMagic[8] = {'C', 'D', 'M', 'P', 'M', 'C', 'K', '6'};

struct Writer {
  std::ofstream& os;
  template <class T> void pod(const T& v) { os.write(reinterpret_cast<const char*>(&v), sizeof(T)); }
  void str(const std::string& s) { pod<uint64_t>(s.size()); os.write(s.data(), static_cast<std::streamsize>(s.size())); }
  template <class T> void vec(const std::vector<T>& a) {
    pod<uint64_t>(a.size());
    os.write(reinterpret_cast<const char*>(a.data()), static_cast<std::streamsize>(a.size() * sizeof(T)));
  }
};
struct Reader {
  std::ifstream& is;
  const std::string& path;
  template <class T> void pod(T& v) {
    if (!is.read(reinterpret_cast<char*>(&v), sizeof(T))) throw std::runtime_error(path + ": checkpoint is truncated");
  }
  void str(std::string& s) {
    uint64_t n = 0;
    pod(n);
    if (n > (1u << 20)) throw std::runtime_error(path + ": checkpoint is corrupt (string length)");
    s.resize(n);
    if (!is.read(s.data(), static_cast<std::streamsize>(n))) throw std::runtime_error(path + ": checkpoint is truncated");
  }
  template <class T> void vec(std::vector<T>& a) {
    uint64_t n = 0;
    pod(n);
    if (n > (uint64_t(1) << 36) / sizeof(T)) throw std::runtime_error(path + ": checkpoint is corrupt (array length)");
    a.resize(n);
    if (!is.read(reinterpret_cast<char*>(a.data()), static_cast<std::streamsize>(n * sizeof(T))))
      throw std::runtime_error(path + ": checkpoint is truncated");
  }
};
}  // namespace

template <int dim>
void write_checkpoint(const std::string& path, Particles<dim>& p, const CheckpointMeta& m) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream os(tmp, std::ios::binary | std::ios::trunc);
    if (!os) throw std::runtime_error(path + ": cannot write checkpoint");
    Writer w{os};
    os.write(kMagic, 8);
    w.pod<int32_t>(dim);
    w.pod<int32_t>(sizeof(Real));
    w.pod<uint64_t>(p.size());
    w.pod<uint64_t>(p.solid_count());
    w.pod(m.time); w.pod(m.steps); w.pod(m.frame_index); w.pod(m.probe_index); w.pod(m.wave_dt_at_start);
    w.vec(m.probe_state);
    w.pod<uint64_t>(m.frames.size());
    for (const auto& [t, f] : m.frames) { w.pod(t); w.str(f); }
    w.pod(m.probes_csv_bytes);
    w.pod(m.icebergs_csv_bytes);
    w.vec(m.first_iceberg);
    w.vec(m.rigid_bodies);
    p.for_each_array([&](auto& a) { w.vec(a); });
    p.for_each_solid_array([&](auto& a) { w.vec(a); });
    if (!os.flush()) throw std::runtime_error(path + ": writing checkpoint failed");
  }
  std::filesystem::rename(tmp, path);
}

template <int dim>
CheckpointMeta read_checkpoint(const std::string& path, Particles<dim>& p) {
  std::ifstream is(path, std::ios::binary);
  if (!is) throw std::runtime_error(path + ": no checkpoint to resume from");
  Reader r{is, path};
  char magic[8];
  if (!is.read(magic, 8) || std::memcmp(magic, kMagic, 7) != 0) throw std::runtime_error(path + ": not a cdmpm checkpoint");
  if (magic[7] != kMagic[7])
    throw std::runtime_error(path + ": checkpoint format CDMPMCK" + std::string(1, magic[7]) +
                             " was written by another cdmpm version (this one reads CDMPMCK" + std::string(1, kMagic[7]) +
                             ", which adds the particle ids); rerun the scene without --resume");
  int32_t d = 0, real = 0;
  uint64_t n = 0, ns = 0;
  r.pod(d); r.pod(real); r.pod(n); r.pod(ns);
  if (d != dim) throw std::runtime_error(path + ": checkpoint is " + std::to_string(d) + "D, scene is " + std::to_string(dim) + "D");
  if (real != static_cast<int32_t>(sizeof(Real)))
    throw std::runtime_error(path + ": checkpoint was written with another floating-point precision");
  if (ns > n) throw std::runtime_error(path + ": checkpoint is corrupt (more solid particles than particles)");
  CheckpointMeta m;
  r.pod(m.time); r.pod(m.steps); r.pod(m.frame_index); r.pod(m.probe_index); r.pod(m.wave_dt_at_start);
  r.vec(m.probe_state);
  uint64_t nf = 0;
  r.pod(nf);
  m.frames.resize(nf);
  for (auto& [t, f] : m.frames) { r.pod(t); r.str(f); }
  r.pod(m.probes_csv_bytes);
  r.pod(m.icebergs_csv_bytes);
  r.vec(m.first_iceberg);
  r.vec(m.rigid_bodies);
  auto read_arrays_of = [&](uint64_t count) {
    return [&, count](auto& a) {
      r.vec(a);
      if (a.size() != count) throw std::runtime_error(path + ": checkpoint is corrupt (array sizes differ)");
    };
  };
  p.for_each_array(read_arrays_of(n));
  p.for_each_solid_array(read_arrays_of(ns));
  return m;
}

template void write_checkpoint<2>(const std::string&, Particles<2>&, const CheckpointMeta&);
template void write_checkpoint<3>(const std::string&, Particles<3>&, const CheckpointMeta&);
template CheckpointMeta read_checkpoint<2>(const std::string&, Particles<2>&);
template CheckpointMeta read_checkpoint<3>(const std::string&, Particles<3>&);

}  // namespace cdmpm
