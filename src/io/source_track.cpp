// source_track.cpp - the reader of recorded calving sources and their interpolation (see source_track.h).
#include "io/source_track.h"

#include <algorithm>
#include <cmath>

#include "io/line_reader.h"

namespace cdmpm {
namespace {

using namespace text;

// The next line that is neither blank nor a comment, split at whitespace; empty at the end of the file.
Tokens next_record(LineReader& in, std::string& line) {
  while (in.next(line)) {
    const std::string_view t = trim(line);
    if (!t.empty() && t.front() != '#') return split_whitespace(line);
  }
  return {};
}

// A record that starts with `key` and has `count` values after it.
Tokens keyed(LineReader& in, std::string& line, const std::string& key, size_t count, const std::string& what) {
  const Tokens t = next_record(in, line);
  if (t.empty()) fail(in.path(), in.line(), "a line \"" + key + " " + what + "\"", "the end of the file");
  if (t[0] != key) fail(in.path(), in.line(), "a line \"" + key + " " + what + "\"", shown(t[0]));
  if (t.size() != count + 1)
    fail(in.path(), in.line(), std::to_string(count) + " values after \"" + key + "\" (" + what + ")",
         std::to_string(t.size() - 1));
  return t;
}

int count_in(const LineReader& in, std::string_view t, const std::string& what, double lo, double hi) {
  const double v = finite_number(in, t, "a number (" + what + ")");
  if (v != std::floor(v) || v < lo || v > hi)
    fail(in.path(), in.line(), "a whole number in [" + fmt(lo) + ", " + fmt(hi) + "] (" + what + ")", shown(t));
  return static_cast<int>(v);
}

}  // namespace

SourceTrack read_source_track(const std::string& path) {
  LineReader in(path, "source-track file");
  SourceTrack s;
  s.path = path;
  std::string line;
  const Tokens magic = keyed(in, line, "cdmpm_source_track", 1, "1 (the format's version)");
  if (magic[1] != "1") fail(path, in.line(), "format version 1", shown(magic[1]));
  const Tokens lat = keyed(in, line, "lattice", 5, "NX NZ X0 Z0 H");
  s.nx = count_in(in, lat[1], "NX", 2, double(kMaxTrackNodes));
  s.nz = count_in(in, lat[2], "NZ", 2, double(kMaxTrackNodes));
  const size_t nodes = size_t(s.nx) * size_t(s.nz);
  if (nodes > kMaxTrackNodes)
    fail(path, in.line(), "at most " + std::to_string(kMaxTrackNodes) + " lattice nodes", std::to_string(nodes));
  s.x0 = finite_number(in, lat[3], "a number (X0)");
  s.z0 = finite_number(in, lat[4], "a number (Z0)");
  s.h = finite_number(in, lat[5], "a number (H, the lattice spacing)");
  if (!(s.h > 0)) fail(path, in.line(), "a lattice spacing H > 0", shown(lat[5]));
  const Tokens fill = keyed(in, line, "fill", nodes, "one value in [0, 1] per node");
  s.fill.resize(nodes);
  for (size_t n = 0; n < nodes; ++n) {
    s.fill[n] = finite_number(in, fill[n + 1], "a number (fill)");
    if (s.fill[n] < 0 || s.fill[n] > 1) fail(path, in.line(), "a fill in [0, 1]", shown(fill[n + 1]));
  }
  const Tokens times = keyed(in, line, "times", 1, "T, the number of records");
  const int T = count_in(in, times[1], "T", 2, double(kMaxTrackValues));
  if (size_t(T) * nodes > kMaxTrackValues)
    fail(path, in.line(), "at most " + std::to_string(kMaxTrackValues) + " records times nodes",
         std::to_string(size_t(T) * nodes));
  for (int k = 0; k < T; ++k) {
    const Tokens r = next_record(in, line);
    if (r.empty())
      fail(path, in.line(), std::to_string(T) + " records (\"times\")", std::to_string(k) + " before the end of the file");
    if (r.size() != 1 + 2 * nodes)
      fail(path, in.line(), std::to_string(1 + 2 * nodes) + " values (t, then u_x u_z per node)",
           std::to_string(r.size()));
    const double t = finite_number(in, r[0], "a number (time)");
    if (k == 0 && t != 0) fail(path, in.line(), "a first time of 0 s", shown(r[0]));
    if (k > 0 && !(t > s.times.back())) fail(path, in.line(), "a time > " + fmt(s.times.back()) + " s", shown(r[0]));
    s.times.push_back(t);
    std::vector<double> u(2 * nodes);
    for (size_t c = 0; c < u.size(); ++c) u[c] = finite_number(in, r[c + 1], "a number (displacement)");
    s.u.push_back(std::move(u));
  }
  if (!next_record(in, line).empty()) fail(path, in.line(), "the end of the file after " + std::to_string(T) + " records", "more");
  return s;
}

bool SourceTrack::occupied(double x, double z) const {
  const double fi = (x - origin[0] - x0) / h, fj = (z - origin[1] - z0) / h;
  const double i = std::round(fi), j = std::round(fj);
  if (i < 0 || j < 0 || i > nx - 1 || j > nz - 1) return false;
  return fill[size_t(i) + size_t(nx) * size_t(j)] >= 0.5;
}

std::array<double, 2> SourceTrack::displacement(double x, double z, double t) const {
  // Bilinear weights of the four nodes around the point, clamped to the lattice.
  const double fi = std::clamp((x - origin[0] - x0) / h, 0.0, double(nx - 1));
  const double fj = std::clamp((z - origin[1] - z0) / h, 0.0, double(nz - 1));
  const int i = std::min(int(fi), nx - 2), j = std::min(int(fj), nz - 2);
  const double a = fi - i, b = fj - j;
  const size_t n00 = size_t(i) + size_t(nx) * size_t(j), n10 = n00 + 1, n01 = n00 + size_t(nx), n11 = n01 + 1;
  const auto at = [&](const std::vector<double>& u, int c) {
    return (1 - a) * (1 - b) * u[2 * n00 + c] + a * (1 - b) * u[2 * n10 + c] + (1 - a) * b * u[2 * n01 + c] +
           a * b * u[2 * n11 + c];
  };
  // The record interval holding t (held at the last record after it).
  if (t >= times.back()) return {at(u.back(), 0), at(u.back(), 1)};
  const size_t k = size_t(std::upper_bound(times.begin(), times.end(), std::max(t, 0.0)) - times.begin());
  const double f = (std::max(t, 0.0) - times[k - 1]) / (times[k] - times[k - 1]);
  return {(1 - f) * at(u[k - 1], 0) + f * at(u[k], 0), (1 - f) * at(u[k - 1], 1) + f * at(u[k], 1)};
}

double SourceTrack::reach() const {
  double r2 = 0;
  for (const auto& u : this->u)
    for (size_t n = 0; 2 * n < u.size(); ++n) r2 = std::max(r2, u[2 * n] * u[2 * n] + u[2 * n + 1] * u[2 * n + 1]);
  return std::sqrt(r2);
}

}  // namespace cdmpm
