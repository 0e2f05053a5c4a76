// vtu_writer.cpp - VTK XML UnstructuredGrid (.vtu) writer with binary appended raw encoding, and the
// .pvd collection writer. Format reference: VTK file formats documentation ("XML File Formats").
//
// Layout of a .vtu: an XML header in which every DataArray has format="appended" and an `offset`
// (bytes from the first byte after the `_` marker), then <AppendedData encoding="raw">_ followed by
// the blocks in the same order, each a UInt64 byte count plus raw little-endian values.
#include "io/vtu_writer.h"

#include <algorithm>
#include <bit>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

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

// One appended block: its XML description plus where its bytes come from.
struct Block {
  std::string xml_attrs;  // type, Name, NumberOfComponents
  const void* data;       // nullptr: generated (cell arrays)
  uint64_t bytes;
};

// Writes a generated Int64 sequence first, first+1, ... (n values) in large chunks.
void write_iota64(AtomicFile& out, int64_t first, uint64_t n) {
  std::vector<int64_t> chunk(std::min<uint64_t>(n, 1u << 16));
  for (uint64_t done = 0; done < n;) {
    const uint64_t m = std::min<uint64_t>(n - done, chunk.size());
    for (uint64_t i = 0; i < m; ++i) chunk[i] = first + static_cast<int64_t>(done + i);
    out.write(chunk.data(), m * sizeof(int64_t));
    done += m;
  }
}

}  // namespace

void write_vtu(const std::string& path, const std::vector<double>& points, const std::vector<VtuField>& fields) {
  if (points.size() % 3 != 0) throw std::invalid_argument("write_vtu: points size is not a multiple of 3");
  const uint64_t n = points.size() / 3;

  std::vector<Block> point_data;
  for (const VtuField& f : fields) {
    if (f.components < 1) throw std::invalid_argument("write_vtu: field '" + f.name + "' has components < 1");
    const int nonempty = !f.f32.empty() + !f.f64.empty() + !f.i32.empty();
    if (nonempty > 1) throw std::invalid_argument("write_vtu: field '" + f.name + "' has more than one data vector");
    const char* type = "Float32";
    const void* data = f.f32.data();
    size_t count = f.f32.size(), elem = sizeof(float);
    if (!f.f64.empty()) type = "Float64", data = f.f64.data(), count = f.f64.size(), elem = sizeof(double);
    if (!f.i32.empty()) type = "Int32", data = f.i32.data(), count = f.i32.size(), elem = sizeof(int32_t);
    if (count != n * static_cast<uint64_t>(f.components))
      throw std::invalid_argument("write_vtu: field '" + f.name + "' has " + std::to_string(count) +
                                  " values, expected " + std::to_string(n * f.components));
    point_data.push_back({std::string("type=\"") + type + "\" Name=\"" + xml_escape(f.name) +
                              "\" NumberOfComponents=\"" + std::to_string(f.components) + "\"",
                          data, count * elem});
  }

  const Block pts{"type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"", points.data(), n * 3 * sizeof(double)};
  const Block conn{"type=\"Int64\" Name=\"connectivity\"", nullptr, n * sizeof(int64_t)};
  const Block offs{"type=\"Int64\" Name=\"offsets\"", nullptr, n * sizeof(int64_t)};
  const Block types{"type=\"UInt8\" Name=\"types\"", nullptr, n};

  // XML header, with offsets accumulated in the order blocks are appended.
  uint64_t offset = 0;
  auto array = [&offset](const Block& b) {
    std::string s = "        <DataArray " + b.xml_attrs + " format=\"appended\" offset=\"" + std::to_string(offset) + "\"/>\n";
    offset += sizeof(uint64_t) + b.bytes;
    return s;
  };
  const std::string ns = std::to_string(n);
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      "  <UnstructuredGrid>\n"
      "    <Piece NumberOfPoints=\"" + ns + "\" NumberOfCells=\"" + ns + "\">\n"
      "      <PointData>\n";
  for (const Block& b : point_data) xml += array(b);
  xml += "      </PointData>\n      <Points>\n";
  xml += array(pts);
  xml += "      </Points>\n      <Cells>\n";
  xml += array(conn);
  xml += array(offs);
  xml += array(types);
  xml += "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n  <AppendedData encoding=\"raw\">\n_";

  AtomicFile out(path);
  out.write(xml);
  auto header = [&out](uint64_t bytes) { out.write(&bytes, sizeof bytes); };
  for (const Block& b : point_data) header(b.bytes), out.write(b.data, b.bytes);
  header(pts.bytes), out.write(pts.data, pts.bytes);
  header(conn.bytes), write_iota64(out, 0, n);
  header(offs.bytes), write_iota64(out, 1, n);
  header(types.bytes), out.write(std::vector<uint8_t>(n, 1).data(), n);  // VTK_VERTEX = 1
  out.write("\n  </AppendedData>\n</VTKFile>\n");
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
