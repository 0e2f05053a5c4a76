// vtu_reader.h - a minimal reader for the .vtu files io/vtu_writer.cpp writes (XML header with appended
// offsets, then the arrays' blocks), for tests that check frames and for tools/vtu_reencode.cpp.
// Reads both appended layouts with header_type UInt64 (VTK file formats documentation, "XML File
// Formats"): uncompressed (a UInt64 byte count and the values) and compressor="vtkZLibDataCompressor"
// (UInt64 header [blocks, block size, partial last block size or 0, compressed sizes...], then zlib
// streams). Throws std::runtime_error on anything unexpected, which fails the calling test.
#pragma once

#include <zlib.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace cdmpm::testing {

inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

struct ParsedVtu {
  std::string text;
  size_t data_start = 0;  // first byte after the '_' marker
  bool compressed = false;

  explicit ParsedVtu(const std::filesystem::path& p) : text(read_file(p)) {
    const std::string tag = "<AppendedData encoding=\"raw\">";
    const size_t a = text.find(tag);
    if (a == std::string::npos) throw std::runtime_error("no AppendedData");
    const size_t u = text.find('_', a + tag.size());
    if (u == std::string::npos) throw std::runtime_error("no _ marker");
    data_start = u + 1;
    const std::string root = text.substr(0, text.find('>', text.find("<VTKFile")));
    if (root.find("header_type=\"UInt64\"") == std::string::npos) throw std::runtime_error("header_type is not UInt64");
    compressed = root.find("compressor=\"vtkZLibDataCompressor\"") != std::string::npos;
    if (!compressed && root.find("compressor=") != std::string::npos) throw std::runtime_error("unknown compressor");
  }
  std::string header() const { return text.substr(0, data_start); }

  // NumberOfPoints of the (single) Piece.
  size_t points() const {
    const std::string key = "NumberOfPoints=\"";
    const size_t a = text.find(key);
    if (a == std::string::npos || a > data_start) throw std::runtime_error("no NumberOfPoints");
    return std::stoull(text.substr(a + key.size()));
  }

  // Names of the PointData arrays, in file order.
  std::vector<std::string> point_data_names() const {
    std::vector<std::string> names;
    const size_t end = text.find("</PointData>");
    for (size_t a = text.find("<PointData>"); (a = text.find("<DataArray", a + 1)) < end;) {
      const size_t v = text.find("Name=\"", a) + 6;
      names.push_back(text.substr(v, text.find('"', v) - v));
    }
    return names;
  }

  // Value of attribute `attr` in the DataArray element named `name`.
  std::string attr(const std::string& name, const std::string& attr) const {
    const size_t n = text.find("Name=\"" + name + "\"");
    if (n == std::string::npos || n > data_start) throw std::runtime_error("no array " + name);
    const size_t start = text.rfind("<DataArray", n), end = text.find("/>", n);
    const std::string elem = text.substr(start, end - start);
    const size_t a = elem.find(" " + attr + "=\"");
    if (a == std::string::npos) throw std::runtime_error("no attribute " + attr + " on " + name);
    const size_t v = a + attr.size() + 3;
    return elem.substr(v, elem.find('"', v) - v);
  }

  // The decoded (uncompressed) bytes of array `name`.
  std::string bytes(const std::string& name) const {
    if (attr(name, "format") != "appended") throw std::runtime_error(name + " is not appended");
    size_t pos = data_start + std::stoull(attr(name, "offset"));
    auto u64 = [&](size_t at) {
      uint64_t v = 0;
      if (at + sizeof v > text.size()) throw std::runtime_error("header past end for " + name);
      std::memcpy(&v, text.data() + at, sizeof v);
      return v;
    };
    if (!compressed) {
      const uint64_t n = u64(pos);
      if (pos + 8 + n > text.size()) throw std::runtime_error("block past end for " + name);
      return text.substr(pos + 8, n);
    }
    const uint64_t blocks = u64(pos), block = u64(pos + 8), last = u64(pos + 16);
    std::string out;
    size_t at = pos + 8 * (3 + blocks);
    for (uint64_t b = 0; b < blocks; ++b) {
      const uint64_t csize = u64(pos + 8 * (3 + b));
      if (at + csize > text.size()) throw std::runtime_error("block past end for " + name);
      uLongf usize = (b + 1 == blocks && last) ? last : block;
      const size_t base = out.size();
      out.resize(base + usize);
      const auto* src = reinterpret_cast<const Bytef*>(text.data() + at);
      if (uncompress(reinterpret_cast<Bytef*>(out.data() + base), &usize, src, csize) != Z_OK ||
          usize != ((b + 1 == blocks && last) ? last : block))
        throw std::runtime_error("bad zlib block in " + name);
      at += csize;
    }
    return out;
  }

  // Reads array `name` as values of T, checking its byte count against the element count.
  template <class T>
  std::vector<T> array(const std::string& name, size_t expected_count) const {
    const std::string b = bytes(name);
    if (b.size() != expected_count * sizeof(T))
      throw std::runtime_error(name + ": " + std::to_string(b.size()) + " bytes, expected " +
                               std::to_string(expected_count * sizeof(T)));
    std::vector<T> out(expected_count);
    if (!b.empty()) std::memcpy(out.data(), b.data(), b.size());
    return out;
  }

  // Reads a String array (each string followed by a NUL byte).
  std::vector<std::string> strings(const std::string& name) const {
    if (attr(name, "type") != "String") throw std::runtime_error(name + " is not a String array");
    const std::string b = bytes(name);
    std::vector<std::string> out;
    for (size_t a = 0, z; a < b.size(); a = z + 1) {
      z = b.find('\0', a);
      if (z == std::string::npos) throw std::runtime_error(name + ": string without NUL");
      out.push_back(b.substr(a, z - a));
    }
    return out;
  }
};

}  // namespace cdmpm::testing
