// vtu_writer.cpp - VTK XML UnstructuredGrid (.vtu) writer with binary appended raw encoding, and the
// .pvd collection writer. Format reference: VTK file formats documentation ("XML File Formats").
//
// Layout of a .vtu: an XML header (optional <FieldData>, then the Piece's PointData, Points and Cells) in
// which every DataArray has format="appended" and an `offset` (bytes from the first byte after the `_`
// marker), then <AppendedData encoding="raw">_ followed by the arrays in the same order. Uncompressed, an
// array is a UInt64 byte count plus the raw little-endian values. With compressor="vtkZLibDataCompressor"
// the values are cut into blocks of block_bytes (the last may be shorter), each compressed on its own as a
// zlib stream, and the array is the UInt64 header [number of blocks, block_bytes, size of the last block if
// partial else 0, compressed size of block 1, ..., of block N] followed by the compressed blocks.
#include "io/vtu_writer.h"

#include <algorithm>
#include <bit>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <deque>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include <zlib.h>

namespace cdmpm {

static_assert(std::endian::native == std::endian::little, "vtu_writer writes native bytes as LittleEndian");

namespace {

// A file written under `path.tmp` and renamed onto `path` by commit(); removed if never committed.
class AtomicFile {
 public:
  explicit AtomicFile(const std::string& path) : path_(path), tmp_(path + ".tmp") {
    f_ = std::fopen(tmp_.c_str(), "wb");
    if (!f_) fail("cannot open");
  }
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile() {
    if (f_) std::fclose(f_);
    if (!committed_) std::remove(tmp_.c_str());
  }

  void write(const void* data, size_t bytes) {
    if (bytes && std::fwrite(data, 1, bytes, f_) != bytes) fail("cannot write");
  }
  void write(const std::string& s) { write(s.data(), s.size()); }

  void commit() {
    const int rc = std::fclose(f_);
    f_ = nullptr;
    if (rc != 0) fail("cannot write");
    std::error_code ec;
    std::filesystem::rename(tmp_, path_, ec);
    if (ec) throw std::runtime_error("vtu_writer: cannot rename " + tmp_ + " to " + path_ + ": " + ec.message());
    committed_ = true;
  }

 private:
  [[noreturn]] void fail(const char* what) const {
    throw std::runtime_error(std::string("vtu_writer: ") + what + " " + tmp_ + " (for " + path_ +
                             "): " + std::strerror(errno));
  }

  std::string path_, tmp_;
  std::FILE* f_ = nullptr;
  bool committed_ = false;
};

std::string xml_escape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// Shortest representation that round-trips exactly.
std::string fmt_double(double v) {
  char buf[64];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, end);
}

// Where an appended array's bytes come from: borrowed memory, or generated for the cell arrays.
struct Source {
  enum class Kind { Bytes, Iota64, Vertex8 } kind = Kind::Bytes;
  const unsigned char* data = nullptr;  // Kind::Bytes
  int64_t first = 0;                    // Kind::Iota64: the values first, first+1, ...
  uint64_t bytes = 0;

  // Copies bytes [begin, begin + count) of the array into dst.
  void copy(uint64_t begin, uint64_t count, unsigned char* dst) const {
    if (kind == Kind::Bytes) {
      if (count) std::memcpy(dst, data + begin, count);
    } else if (kind == Kind::Vertex8) {
      std::memset(dst, 1, count);  // VTK_VERTEX = 1
    } else {
      const uint64_t i0 = begin / 8, i1 = (begin + count + 7) / 8;
      std::vector<int64_t> v(i1 - i0);
      for (uint64_t i = i0; i < i1; ++i) v[i - i0] = first + static_cast<int64_t>(i);
      if (count) std::memcpy(dst, reinterpret_cast<const unsigned char*>(v.data()) + begin % 8, count);
    }
  }
};

// One appended array: its XML description plus its bytes.
struct Array {
  std::string xml_attrs;  // type, Name, NumberOfComponents or NumberOfTuples
  Source src;
};

template <class T>
Source bytes_of(const std::vector<T>& v) {
  return {Source::Kind::Bytes, reinterpret_cast<const unsigned char*>(v.data()), 0, v.size() * sizeof(T)};
}

std::string attrs(const char* type, const std::string& name, const std::string& count_attr, uint64_t count) {
  return std::string("type=\"") + type + "\" Name=\"" + xml_escape(name) + "\" " + count_attr + "=\"" +
         std::to_string(count) + "\"";
}

Array point_field(const VtuField& f, uint64_t n) {
  if (f.components < 1) throw std::invalid_argument("write_vtu: field '" + f.name + "' has components < 1");
  const int nonempty = !f.f32.empty() + !f.f64.empty() + !f.i32.empty() + !f.i64.empty();
  if (nonempty > 1) throw std::invalid_argument("write_vtu: field '" + f.name + "' has more than one data vector");
  const char* type = "Float32";
  Source src = bytes_of(f.f32);
  size_t elem = sizeof(float);
  if (!f.f64.empty()) type = "Float64", src = bytes_of(f.f64), elem = sizeof(double);
  if (!f.i32.empty()) type = "Int32", src = bytes_of(f.i32), elem = sizeof(int32_t);
  if (!f.i64.empty()) type = "Int64", src = bytes_of(f.i64), elem = sizeof(int64_t);
  const uint64_t count = src.bytes / elem;
  if (count != n * static_cast<uint64_t>(f.components))
    throw std::invalid_argument("write_vtu: field '" + f.name + "' has " + std::to_string(count) +
                                " values, expected " + std::to_string(n * f.components));
  return {attrs(type, f.name, "NumberOfComponents", f.components), src};
}

// Owned buffers that arrays point into; std::deque keeps the elements in place as it grows.
using Pool = std::deque<std::vector<unsigned char>>;

template <class T>
Source pooled(Pool& pool, const T* values, size_t count) {
  const auto* p = reinterpret_cast<const unsigned char*>(values);
  pool.emplace_back(p, p + count * sizeof(T));
  return {Source::Kind::Bytes, pool.back().data(), 0, pool.back().size()};
}

Array strings_array(const VtuStrings& s, Pool& pool) {
  std::string joined;
  for (const std::string& v : s.values) {
    if (v.find('\0') != std::string::npos)
      throw std::invalid_argument("write_vtu: field data '" + s.name + "' has a string with a NUL byte");
    joined += v;
    joined += '\0';
  }
  return {attrs("String", s.name, "NumberOfTuples", s.values.size()), pooled(pool, joined.data(), joined.size())};
}

std::vector<Array> field_data(const VtuOptions& o, Pool& pool) {
  std::vector<Array> out;
  if (o.time) out.push_back({attrs("Float64", kVtuTimeValue, "NumberOfTuples", 1), pooled(pool, &*o.time, 1)});
  for (const VtuStrings& s : o.metadata) out.push_back(strings_array(s, pool));
  return out;
}

Array points_array(const std::vector<double>& points, VtuReal precision, Pool& pool) {
  if (precision == VtuReal::Float64) return {"type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"", bytes_of(points)};
  const std::vector<float> f(points.begin(), points.end());
  return {"type=\"Float32\" Name=\"Points\" NumberOfComponents=\"3\"", pooled(pool, f.data(), f.size())};
}

std::vector<Array> cell_arrays(uint64_t n) {
  return {{"type=\"Int64\" Name=\"connectivity\"", {Source::Kind::Iota64, nullptr, 0, n * sizeof(int64_t)}},
          {"type=\"Int64\" Name=\"offsets\"", {Source::Kind::Iota64, nullptr, 1, n * sizeof(int64_t)}},
          {"type=\"UInt8\" Name=\"types\"", {Source::Kind::Vertex8, nullptr, 0, n}}};
}

// An array as it is appended: a UInt64 header, then either the source's raw bytes (uncompressed) or the
// zlib streams of its blocks.
struct Encoded {
  std::vector<uint64_t> header;
  std::vector<std::vector<unsigned char>> blocks;  // empty when uncompressed
  uint64_t bytes(const Source& src) const {
    uint64_t b = header.size() * sizeof(uint64_t);
    if (blocks.empty()) return b + src.bytes;
    for (const auto& blk : blocks) b += blk.size();
    return b;
  }
};

std::vector<unsigned char> compress_block(const Source& src, uint64_t begin, uint64_t count, int level) {
  std::vector<unsigned char> raw;
  const unsigned char* in = src.data + begin;
  if (src.kind != Source::Kind::Bytes) raw.resize(count), src.copy(begin, count, raw.data()), in = raw.data();
  uLongf out_size = compressBound(static_cast<uLong>(count));
  std::vector<unsigned char> out(out_size);
  if (compress2(out.data(), &out_size, in, static_cast<uLong>(count), level) != Z_OK)
    throw std::runtime_error("write_vtu: zlib compression failed");
  out.resize(out_size);
  return out;
}

// Compresses every block of every array, in parallel over all blocks; each block is compressed on its own,
// so the result does not depend on the number of threads or on the schedule.
std::vector<Encoded> compress_arrays(const std::vector<Array>& arrays, const VtuOptions& o) {
  if (o.block_bytes == 0 || o.block_bytes > (uint64_t{1} << 30))
    throw std::invalid_argument("write_vtu: block_bytes must be in [1, 2^30]");
  if (o.zlib_level < 1 || o.zlib_level > 9) throw std::invalid_argument("write_vtu: zlib_level must be in [1, 9]");
  std::vector<Encoded> enc(arrays.size());
  std::vector<std::pair<size_t, uint64_t>> tasks;  // (array, block)
  for (size_t a = 0; a < arrays.size(); ++a) {
    const uint64_t total = arrays[a].src.bytes, nblocks = (total + o.block_bytes - 1) / o.block_bytes;
    enc[a].header = {nblocks, o.block_bytes, total % o.block_bytes};
    enc[a].blocks.resize(nblocks);
    for (uint64_t b = 0; b < nblocks; ++b) tasks.emplace_back(a, b);
  }
  const long long ntasks = static_cast<long long>(tasks.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (long long t = 0; t < ntasks; ++t) {
    const auto [a, b] = tasks[t];
    const Source& src = arrays[a].src;
    const uint64_t begin = b * o.block_bytes, count = std::min(o.block_bytes, src.bytes - begin);
    enc[a].blocks[b] = compress_block(src, begin, count, o.zlib_level);
  }
  for (Encoded& e : enc)
    for (const auto& blk : e.blocks) e.header.push_back(blk.size());
  return enc;
}

std::vector<Encoded> encode(const std::vector<Array>& arrays, const VtuOptions& o) {
  if (o.compression == VtuCompression::ZLib) return compress_arrays(arrays, o);
  std::vector<Encoded> enc(arrays.size());
  for (size_t a = 0; a < arrays.size(); ++a) enc[a].header = {arrays[a].src.bytes};
  return enc;
}

// Streams an uncompressed source, generated ones in large chunks.
void write_source(AtomicFile& out, const Source& src) {
  if (src.kind == Source::Kind::Bytes) return out.write(src.data, src.bytes);
  std::vector<unsigned char> chunk(std::min<uint64_t>(src.bytes, 1u << 19));
  for (uint64_t done = 0; done < src.bytes;) {
    const uint64_t m = std::min<uint64_t>(src.bytes - done, chunk.size());
    src.copy(done, m, chunk.data());
    out.write(chunk.data(), m);
    done += m;
  }
}

// The arrays of a .vtu in file order, in the XML sections they belong to.
struct Layout {
  std::vector<Array> field, point, points, cells;
  std::vector<Array> all() const {
    std::vector<Array> v;
    for (const auto* sec : {&field, &point, &points, &cells}) v.insert(v.end(), sec->begin(), sec->end());
    return v;
  }
};

std::string xml_header(const Layout& L, const std::vector<Encoded>& enc, uint64_t n, bool zlib) {
  size_t i = 0;
  uint64_t offset = 0;
  auto section = [&](const std::vector<Array>& arrays, const char* indent) {
    std::string s;
    for (const Array& a : arrays) {
      s += std::string(indent) + "<DataArray " + a.xml_attrs + " format=\"appended\" offset=\"" + std::to_string(offset) + "\"/>\n";
      offset += enc[i++].bytes(a.src);
    }
    return s;
  };
  const std::string ns = std::to_string(n);
  std::string xml = "<?xml version=\"1.0\"?>\n"
                    "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\"";
  xml += zlib ? " compressor=\"vtkZLibDataCompressor\">\n" : ">\n";
  xml += "  <UnstructuredGrid>\n";
  if (!L.field.empty()) xml += "    <FieldData>\n" + section(L.field, "      ") + "    </FieldData>\n";
  xml += "    <Piece NumberOfPoints=\"" + ns + "\" NumberOfCells=\"" + ns + "\">\n      <PointData>\n";
  xml += section(L.point, "        ");
  xml += "      </PointData>\n      <Points>\n" + section(L.points, "        ");
  xml += "      </Points>\n      <Cells>\n" + section(L.cells, "        ");
  xml += "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n  <AppendedData encoding=\"raw\">\n_";
  return xml;
}

}  // namespace

void write_vtu(const std::string& path, const std::vector<double>& points, const std::vector<VtuField>& fields,
               const VtuOptions& options) {
  if (points.size() % 3 != 0) throw std::invalid_argument("write_vtu: points size is not a multiple of 3");
  const uint64_t n = points.size() / 3;

  Pool pool;
  Layout L;
  for (const VtuField& f : fields) L.point.push_back(point_field(f, n));
  L.field = field_data(options, pool);
  L.points = {points_array(points, options.positions, pool)};
  L.cells = cell_arrays(n);
  const std::vector<Array> arrays = L.all();
  const std::vector<Encoded> enc = encode(arrays, options);

  AtomicFile out(path);
  out.write(xml_header(L, enc, n, options.compression == VtuCompression::ZLib));
  for (size_t i = 0; i < arrays.size(); ++i) {
    out.write(enc[i].header.data(), enc[i].header.size() * sizeof(uint64_t));
    if (enc[i].blocks.empty()) write_source(out, arrays[i].src);
    for (const auto& blk : enc[i].blocks) out.write(blk.data(), blk.size());
  }
  out.write("\n  </AppendedData>\n</VTKFile>\n");
  out.commit();
}

void write_pvtu(const std::string& path, const std::vector<std::string>& pieces, const std::vector<VtuField>& fields,
                const VtuOptions& options) {
  std::string xml = "<?xml version=\"1.0\"?>\n"
                    "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\"";
  xml += options.compression == VtuCompression::ZLib ? " compressor=\"vtkZLibDataCompressor\">\n" : ">\n";
  xml += "  <PUnstructuredGrid GhostLevel=\"0\">\n    <PPointData>\n";
  for (const VtuField& f : fields) {
    const char* type = !f.f64.empty() ? "Float64" : !f.i32.empty() ? "Int32" : !f.i64.empty() ? "Int64" : "Float32";
    xml += "      <PDataArray " + attrs(type, f.name, "NumberOfComponents", f.components) + "/>\n";
  }
  xml += "    </PPointData>\n    <PPoints>\n      <PDataArray type=\"";
  xml += options.positions == VtuReal::Float64 ? "Float64" : "Float32";
  xml += "\" Name=\"Points\" NumberOfComponents=\"3\"/>\n    </PPoints>\n";
  for (const std::string& piece : pieces) xml += "    <Piece Source=\"" + xml_escape(piece) + "\"/>\n";
  xml += "  </PUnstructuredGrid>\n</VTKFile>\n";
  AtomicFile out(path);
  out.write(xml);
  out.commit();
}

void write_pvd(const std::string& path, const std::vector<std::pair<double, std::string>>& frames) {
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      "  <Collection>\n";
  for (const auto& [time, file] : frames)
    xml += "    <DataSet timestep=\"" + fmt_double(time) + "\" group=\"\" part=\"0\" file=\"" + xml_escape(file) + "\"/>\n";
  xml += "  </Collection>\n</VTKFile>\n";
  AtomicFile out(path);
  out.write(xml);
  out.commit();
}

}  // namespace cdmpm
