// vtu_reader.h - a minimal reader for the .vtu files io/vtu_writer.cpp writes (XML header with appended
// offsets, then raw blocks, each a UInt64 byte count and the values), for tests that check frames.
#pragma once

#include <gtest/gtest.h>

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

  explicit ParsedVtu(const std::filesystem::path& p) : text(read_file(p)) {
    const std::string tag = "<AppendedData encoding=\"raw\">";
    const size_t a = text.find(tag);
    if (a == std::string::npos) throw std::runtime_error("no AppendedData");
    const size_t u = text.find('_', a + tag.size());
    if (u == std::string::npos) throw std::runtime_error("no _ marker");
    data_start = u + 1;
  }
  std::string header() const { return text.substr(0, data_start); }

  // NumberOfPoints of the (single) Piece.
  size_t points() const {
    const std::string key = "NumberOfPoints=\"";
    const size_t a = text.find(key);
    if (a == std::string::npos || a > data_start) throw std::runtime_error("no NumberOfPoints");
    return std::stoull(text.substr(a + key.size()));
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

  // Reads the appended block of array `name`, checking its byte count against the element count.
  template <class T>
  std::vector<T> array(const std::string& name, size_t expected_count) const {
    EXPECT_EQ(attr(name, "format"), "appended");
    const size_t pos = data_start + std::stoull(attr(name, "offset"));
    uint64_t bytes = 0;
    if (pos + sizeof bytes > text.size()) throw std::runtime_error("offset past end for " + name);
    std::memcpy(&bytes, text.data() + pos, sizeof bytes);
    EXPECT_EQ(bytes, expected_count * sizeof(T)) << name;
    if (pos + sizeof bytes + bytes > text.size()) throw std::runtime_error("block past end for " + name);
    std::vector<T> out(bytes / sizeof(T));
    if (bytes) std::memcpy(out.data(), text.data() + pos + sizeof bytes, bytes);
    return out;
  }
};

}  // namespace cdmpm::testing
