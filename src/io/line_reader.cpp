// line_reader.cpp - strict line-oriented reading of the project's text input files (see line_reader.h).
#include "io/line_reader.h"

#include <cctype>
#include <charconv>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace cdmpm::text {

std::string fmt(double v) {
  std::ostringstream s;
  s << std::setprecision(12) << v;
  return s.str();
}

std::string shown(std::string_view t) {
  std::string s = "'";  // appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on "'" + string
  s.append(t.substr(0, 40)).append(t.size() > 40 ? "...'" : "'");
  return s;
}

void fail(const std::string& path, int line, const std::string& what, const std::string& got) {
  throw SceneError(path + (line > 0 ? ":" + std::to_string(line) : "") + ": expected " + what + ", got " + got);
}

LineReader::LineReader(const std::string& path, const std::string& kind) : path_(path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto st = fs::status(path, ec);
  if (!fs::exists(st)) throw SceneError(path + ": cannot open " + kind + " (no such file)");
  if (fs::is_directory(st)) fail(path, 0, "a " + kind, "a directory");
  in_.open(path, std::ios::binary);
  if (!in_) throw SceneError(path + ": cannot open " + kind);
}

bool LineReader::next(std::string& line) {
  line.clear();
  std::streambuf* buf = in_.rdbuf();
  int c = buf->sbumpc();
  if (c == std::char_traits<char>::eof()) return false;
  ++line_;
  for (; c != std::char_traits<char>::eof() && c != '\n'; c = buf->sbumpc()) {
    if (line.size() >= kMaxLineLength)
      fail(path_, line_, "a line of at most " + std::to_string(kMaxLineLength) + " characters", "a longer line");
    line.push_back(static_cast<char>(c));
  }
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return true;
}

std::string_view trim(std::string_view s) {
  const auto space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  while (!s.empty() && space(s.front())) s.remove_prefix(1);
  while (!s.empty() && space(s.back())) s.remove_suffix(1);
  return s;
}

Tokens split_whitespace(std::string_view s) {
  Tokens out;
  size_t i = 0;
  while (true) {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    if (i == s.size()) return out;
    size_t j = i;
    while (j < s.size() && !std::isspace(static_cast<unsigned char>(s[j]))) ++j;
    out.push_back(s.substr(i, j - i));
    i = j;
  }
}

Tokens split_commas(std::string_view s) {
  Tokens out;
  for (size_t start = 0;;) {
    const size_t comma = s.find(',', start);
    out.push_back(trim(s.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) return out;
    start = comma + 1;
  }
}

bool parse_number(std::string_view t, double& v) {
  if (t.size() > 1 && t[0] == '+' && t[1] != '-') t.remove_prefix(1);
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  return !t.empty() && ec == std::errc() && end == t.data() + t.size();
}

double finite_number(const LineReader& in, std::string_view t, const std::string& what) {
  double v = 0;
  if (!parse_number(t, v)) fail(in.path(), in.line(), what, shown(t));
  if (!std::isfinite(v)) fail(in.path(), in.line(), "a finite " + what.substr(what.find(' ') + 1), shown(t));
  return v;
}

}  // namespace cdmpm::text
