// checkpoint.cpp - writing and reading checkpoints (format in checkpoint.h, checks in checkpoint_format.h).
#include "io/checkpoint.h"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <tuple>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numeric>

#include "io/checkpoint_format.h"

namespace cdmpm {
namespace {
constexpr char kMagic[8] = {'C', 'D', 'M', 'P', 'M', 'C', 'K', 'A'};          // one file
constexpr char kManifestMagic[8] = {'C', 'D', 'M', 'P', 'M', 'C', 'K', 'D'};  // a distributed run's manifest
constexpr char kPieceMagic[8] = {'C', 'D', 'M', 'P', 'M', 'P', 'C', '2'};     // one rank's piece
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

// The file's size after checking that it starts with `magic` (the format named by its first 7 characters, the
// version by the 8th) and has an intact CRC-32.
uint64_t check_file(std::ifstream& is, const std::string& path, const char (&magic)[8], const char* what,
                    uint32_t* crc = nullptr) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw CheckpointError(path + ": no " + what + " to resume from");
  const uint64_t size = std::filesystem::file_size(path, ec);
  char read[8];
  if (ec || size < sizeof read + 4 || !is.read(read, 8) || std::memcmp(read, magic, 7) != 0)
    throw CheckpointError(path + ": not a cdmpm " + what);
  if (read[7] != magic[7])
    throw CheckpointError(path + ": " + what + " format " + std::string(magic, 7) + std::string(1, read[7]) +
                          " was written by another cdmpm version (this one reads " + std::string(magic, 8) +
                          "); rerun the scene without --resume");
  uint32_t stored = 0;
  std::ifstream tail(path, std::ios::binary);
  tail.seekg(static_cast<std::streamoff>(size - 4));
  if (!tail.read(reinterpret_cast<char*>(&stored), 4) || stored != file_crc32(path, size - 4))
    throw CheckpointError(path + ": " + what + " is corrupt (checksum mismatch: the file was changed or cut short)");
  if (crc) *crc = stored;
  return size;
}

// The header after the magic: dim, precision, particle and solid counts.
void write_counts(Writer& w, int dim, uint64_t n, uint64_t ns) {
  w.pod<int32_t>(dim);
  w.pod<int32_t>(sizeof(Real));
  w.pod(n);
  w.pod(ns);
}
void read_counts(Reader& r, int dim, uint64_t& n, uint64_t& ns) {
  int32_t d = 0, real = 0;
  r.pod(d); r.pod(real); r.pod(n); r.pod(ns);
  if (d != dim)
    throw CheckpointError(r.path + ": checkpoint is " + std::to_string(d) + "D, scene is " + std::to_string(dim) + "D");
  if (real != static_cast<int32_t>(sizeof(Real)))
    throw CheckpointError(r.path + ": checkpoint was written with another floating-point precision");
  if (ns > n) r.corrupt("more solid particles than particles");
}

// The bookkeeping, from the fingerprint to the hazard record.
void write_meta(Writer& w, const CheckpointMeta& m) {
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
}
CheckpointMeta read_meta(Reader& r) {
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
  return m;
}

template <int dim>
void write_arrays(Writer& w, Particles<dim>& p) {
  p.for_each_array([&](auto& a) { w.vec(a); });
  p.for_each_solid_array([&](auto& a) { w.vec(a); });
}
template <int dim>
void read_arrays(Reader& r, Particles<dim>& p, uint64_t n, uint64_t ns) {
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
}

// Writes `body` between the magic and the CRC to path.tmp, renames it to path, and returns the file's size and CRC.
template <class Body>
std::pair<uint64_t, uint32_t> write_file(const std::string& path, const char (&magic)[8], Body&& body) {
  const std::string tmp = path + ".tmp";
  uint64_t bytes = 0;
  uint32_t crc = 0;
  {
    std::ofstream os(tmp, std::ios::binary | std::ios::trunc);
    if (!os) throw std::runtime_error(path + ": cannot write checkpoint");
    Writer w{os};
    w.raw(magic, 8);
    body(w);
    crc = w.crc;
    os.write(reinterpret_cast<const char*>(&crc), sizeof crc);
    if (!os.flush()) throw std::runtime_error(path + ": writing checkpoint failed");
    bytes = static_cast<uint64_t>(os.tellp());
  }
  std::filesystem::rename(tmp, path);
  return {bytes, crc};
}

// A piece the manifest names: its file in the manifest's folder, checked against the manifest's record, its
// particles appended to `pieces` and their keys to `keys`.
template <int dim>
void read_piece(const std::string& manifest, const CheckpointPiece& rec, Particles<dim>& piece, std::vector<uint64_t>& keys) {
  if (!checkpoint_piece_slot(rec.file))
    throw CheckpointError(manifest + ": checkpoint is corrupt (piece file name '" + rec.file +
                          "', expected checkpoint_S_rR.bin with S a or b)");
  const std::string path = (std::filesystem::path(manifest).parent_path() / rec.file).string();
  std::ifstream is(path, std::ios::binary);
  uint32_t crc = 0;
  const uint64_t size = check_file(is, path, kPieceMagic, "checkpoint piece", &crc);
  if (size != rec.bytes || crc != rec.crc)
    throw CheckpointError(path + ": checkpoint piece is not the one " + manifest +
                          " names (another checkpoint's piece: its size or checksum differs)");
  Reader r{is, path, size - 8 - 4};
  uint64_t n = 0, ns = 0;
  read_counts(r, dim, n, ns);
  if (n != rec.n || ns != rec.ns) r.corrupt("particle counts differ from the manifest's");
  r.vec(keys, "order keys");
  if (keys.size() != n) r.corrupt("a key per particle expected");
  if (!std::is_sorted(keys.begin(), keys.end(), std::less_equal<>())) r.corrupt("order keys not strictly ascending");
  read_arrays(r, piece, n, ns);
  if (r.left != 0) r.corrupt(std::to_string(r.left) + " bytes after the last array");
}

// The pieces `which` merged into one array in key order (of every piece: the one-process array; every solid key is
// below every fluid key), and their keys.
template <int dim>
void merge_pieces(const std::string& manifest, const std::vector<CheckpointPiece>& recs, const std::vector<size_t>& which,
                  Particles<dim>& p, std::vector<uint64_t>& merged_keys) {
  std::vector<Particles<dim>> pieces(which.size());
  std::vector<std::vector<uint64_t>> keys(which.size());
  struct Entry { uint64_t key; uint32_t piece, q; };
  std::vector<Entry> order;
  for (size_t k = 0; k < which.size(); ++k) {
    read_piece(manifest, recs[which[k]], pieces[k], keys[k]);
    for (size_t q = 0; q < keys[k].size(); ++q) order.push_back({keys[k][q], uint32_t(k), uint32_t(q)});
  }
  std::sort(order.begin(), order.end(), [](const Entry& a, const Entry& b) { return a.key < b.key; });
  Particles<dim> out;
  out.next_id = p.next_id;
  merged_keys.resize(order.size());
  for (size_t i = 0; i < order.size(); ++i) {
    const Entry& e = order[i];
    if (i > 0 && order[i - 1].key == e.key)
      throw CheckpointError(manifest + ": checkpoint is corrupt (two pieces hold a particle of key " + std::to_string(e.key) + ")");
    const Particles<dim>& s = pieces[e.piece];
    if (e.q < s.solid_count() && out.size() > out.solid_count())
      throw CheckpointError(manifest + ": checkpoint is corrupt (a solid's key after a fluid's)");
    out.add_copy(s, e.q);
    merged_keys[i] = e.key;
  }
  p = std::move(out);
}

}  // namespace

std::string checkpoint_piece_name(char slot, int rank) {
  return "checkpoint_" + std::string(1, slot) + "_r" + std::to_string(rank) + ".bin";
}

// checkpoint_S_rR.bin, S a or b, R a rank: a name in the manifest's folder (no path).
char checkpoint_piece_slot(const std::string& f) {
  const std::string prefix = "checkpoint_", suffix = ".bin";
  if (f.size() <= prefix.size() + 3 + suffix.size() || !f.starts_with(prefix) || !f.ends_with(suffix)) return 0;
  if ((f[11] != 'a' && f[11] != 'b') || f[12] != '_' || f[13] != 'r') return 0;
  const std::string rank = f.substr(14, f.size() - 14 - suffix.size());
  const bool digits = !rank.empty() && rank.size() < 10 && std::all_of(rank.begin(), rank.end(), [](char c) { return c >= '0' && c <= '9'; });
  return digits ? f[11] : 0;
}

template <int dim>
void write_checkpoint(const std::string& path, Particles<dim>& p, const CheckpointMeta& m) {
  write_file(path, kMagic, [&](Writer& w) {
    write_counts(w, dim, p.size(), p.solid_count());
    write_meta(w, m);
    write_arrays(w, p);
  });
}

template <int dim>
CheckpointPiece write_checkpoint_piece(const std::string& path, Particles<dim>& p, const std::vector<uint64_t>& keys) {
  CheckpointPiece rec{std::filesystem::path(path).filename().string(), p.size(), p.solid_count(), 0, 0};
  std::tie(rec.bytes, rec.crc) = write_file(path, kPieceMagic, [&](Writer& w) {
    write_counts(w, dim, p.size(), p.solid_count());
    w.vec(keys);
    write_arrays(w, p);
  });
  return rec;
}

void write_checkpoint_manifest(const std::string& path, int dim, const CheckpointMeta& m) {
  uint64_t n = 0, ns = 0;
  for (const CheckpointPiece& piece : m.pieces) n += piece.n, ns += piece.ns;
  write_file(path, kManifestMagic, [&](Writer& w) {
    write_counts(w, dim, n, ns);
    write_meta(w, m);
    w.pod<uint64_t>(m.pieces.size());
    for (const CheckpointPiece& piece : m.pieces) {
      w.str(piece.file);
      w.pod(piece.n); w.pod(piece.ns); w.pod(piece.bytes); w.pod(piece.crc);
    }
  });
}

template <int dim>
CheckpointMeta read_checkpoint(const std::string& path, Particles<dim>& p, CheckpointShare* share) {
  std::ifstream is(path, std::ios::binary);
  char magic[8] = {};
  is.read(magic, 8);
  const bool manifest = is && std::memcmp(magic, kManifestMagic, 8) == 0;
  is.seekg(0);
  is.clear();
  const uint64_t size = check_file(is, path, manifest ? kManifestMagic : kMagic, "checkpoint");
  Reader r{is, path, size - 8 - 4};
  uint64_t n = 0, ns = 0;
  read_counts(r, dim, n, ns);
  CheckpointMeta m = read_meta(r);
  if (!manifest) {
    read_arrays(r, p, n, ns);
  } else {
    m.pieces.resize(r.length(8 + 8 * 4 + 4, 1u << 24, "piece list"));
    uint64_t total = 0, solids = 0;
    for (CheckpointPiece& piece : m.pieces) {
      r.str(piece.file);
      r.pod(piece.n); r.pod(piece.ns); r.pod(piece.bytes); r.pod(piece.crc);
      if (piece.ns > piece.n) r.corrupt("a piece with more solid particles than particles");
      total += piece.n, solids += piece.ns;
    }
    if (total != n || solids != ns) r.corrupt("the pieces' particle counts do not add up to the manifest's");
  }
  if (r.left != 0) r.corrupt(std::to_string(r.left) + " bytes after the last field");
  std::vector<uint64_t> keys;
  if (manifest) {
    std::vector<size_t> which;
    for (size_t k = 0; k < m.pieces.size(); ++k)
      if (!share || int(k % size_t(share->ranks)) == share->rank) which.push_back(k);
    merge_pieces(path, m.pieces, which, p, keys);
  } else if (share) {  // the whole file was read: this rank keeps its range of the one-process array
    const size_t R = size_t(share->ranks), r = size_t(share->rank), first = r * n / R, last = (r + 1) * n / R;
    std::vector<uint32_t> kept(last - first);
    std::iota(kept.begin(), kept.end(), uint32_t(first));
    p.permute(std::move(kept));
    keys.resize(last - first);
    std::iota(keys.begin(), keys.end(), uint64_t(first));
  }
  if (share) share->keys = std::move(keys);
  return m;
}

template void write_checkpoint<2>(const std::string&, Particles<2>&, const CheckpointMeta&);
template void write_checkpoint<3>(const std::string&, Particles<3>&, const CheckpointMeta&);
template CheckpointPiece write_checkpoint_piece<2>(const std::string&, Particles<2>&, const std::vector<uint64_t>&);
template CheckpointPiece write_checkpoint_piece<3>(const std::string&, Particles<3>&, const std::vector<uint64_t>&);
template CheckpointMeta read_checkpoint<2>(const std::string&, Particles<2>&, CheckpointShare*);
template CheckpointMeta read_checkpoint<3>(const std::string&, Particles<3>&, CheckpointShare*);

}  // namespace cdmpm
