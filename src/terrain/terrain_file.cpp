// terrain_file.cpp - strict readers of CSV terrain profiles and ESRI ASCII grids, their coverage check against
// the scene domain, and the filling of a bathymetry boundary from them (see terrain_file.h).
//
// The ESRI ASCII grid layout follows the format as GDAL's AAIGrid driver reads and writes it: a header of
// "key value" lines (ncols, nrows, xllcorner or xllcenter, yllcorner or yllcenter, cellsize, NODATA_value),
// then nrows lines of ncols values from the northernmost row to the southernmost.
#include "terrain/terrain_file.h"

#include "io/line_reader.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>
#include <string_view>

namespace cdmpm {
namespace {

using namespace text;

}  // namespace

// ---- CSV profile -----------------------------------------------------------------------------------------

TerrainProfile read_profile_csv(const std::string& path) {
  LineReader in(path, "terrain file");
  TerrainProfile p;
  p.path = path;
  bool header_allowed = true;
  for (std::string line; in.next(line);) {
    const std::string_view t = trim(line);
    if (t.empty() || t.front() == '#') continue;
    const Tokens f = split_commas(t);
    double ignored = 0;
    if (header_allowed && !parse_number(f[0], ignored)) {  // the header line, e.g. "distance_m,elevation_m"
      header_allowed = false;
      if (f.size() != 2) fail(path, in.line(), "a header of 2 comma-separated columns", std::to_string(f.size()));
      continue;
    }
    header_allowed = false;
    if (f.size() != 2)
      fail(path, in.line(), "2 comma-separated columns (distance, elevation)", std::to_string(f.size()) + " columns");
    const double x = finite_number(in, f[0], "a number (distance)");
    const double z = finite_number(in, f[1], "a number (elevation)");
    if (!p.points.empty() && !(x > p.points.back()[0]))
      fail(path, in.line(), "a distance > " + fmt(p.points.back()[0]) + " (strictly increasing)", shown(f[0]));
    if (p.points.size() >= kMaxProfilePoints)
      fail(path, in.line(), "at most " + std::to_string(kMaxProfilePoints) + " points", "more");
    p.points.push_back({x, z});
    p.lines.push_back(in.line());
  }
  if (p.points.size() < 2)
    fail(path, in.line(), "at least 2 data rows (distance, elevation)", std::to_string(p.points.size()));
  return p;
}

// ---- ESRI ASCII grid -------------------------------------------------------------------------------------

namespace {

struct HeaderValue {
  std::string key;    // as written in the file
  std::string value;
  int line = 0;
};

// The header keys, lower case, and the slot each fills (xllcorner and xllcenter are two ways to give one).
const std::map<std::string, std::string>& header_slots() {
  static const std::map<std::string, std::string> slots = {
      {"ncols", "ncols"}, {"nrows", "nrows"}, {"xllcorner", "x"}, {"xllcenter", "x"},
      {"yllcorner", "y"}, {"yllcenter", "y"},  {"cellsize", "cellsize"}, {"nodata_value", "nodata"}};
  return slots;
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// Reads "key value" lines up to the first line that starts with a number, which is left in `first_row`.
std::map<std::string, HeaderValue> read_header(LineReader& in, std::string& first_row) {
  std::map<std::string, HeaderValue> h;
  const std::string keys = "a header key (ncols, nrows, xllcorner|xllcenter, yllcorner|yllcenter, cellsize, "
                           "NODATA_value) or a row of numbers";
  first_row.clear();
  for (std::string line; in.next(line);) {
    const Tokens t = split_whitespace(line);
    double ignored = 0;
    if (t.empty()) continue;
    if (parse_number(t[0], ignored)) return first_row = line, h;
    const auto slot = header_slots().find(lower(t[0]));
    if (slot == header_slots().end()) fail(in.path(), in.line(), keys, shown(t[0]));
    if (t.size() != 2) fail(in.path(), in.line(), "one value after " + std::string(t[0]), std::to_string(t.size() - 1));
    if (h.count(slot->second))
      fail(in.path(), in.line(), "each header key once", shown(t[0]) + " after " + shown(h[slot->second].key) +
                                                           " on line " + std::to_string(h[slot->second].line));
    h[slot->second] = {std::string(t[0]), std::string(t[1]), in.line()};
  }
  return h;
}

// ncols / nrows: an integer in [2, kMaxGridNodes].
std::size_t grid_count(const std::string& path, const HeaderValue& v) {
  const std::string what = "an integer " + v.key + " in [2, " + std::to_string(kMaxGridNodes) + "]";
  std::size_t n = 0;
  const auto [end, ec] = std::from_chars(v.value.data(), v.value.data() + v.value.size(), n);
  if (ec != std::errc() || end != v.value.data() + v.value.size() || n < 2 || n > kMaxGridNodes)
    fail(path, v.line, what, shown(v.value));
  return n;
}

double header_number(const std::string& path, const HeaderValue& v, bool positive) {
  double x = 0;
  if (!parse_number(v.value, x) || !std::isfinite(x) || (positive && !(x > 0)))
    fail(path, v.line, std::string(positive ? "a positive" : "a finite") + " number for " + v.key, shown(v.value));
  return x;
}

// Checks the header and fills the grid's geometry; returns {ncols, nrows} and the NODATA value, if any.
std::array<std::size_t, 2> grid_header(LineReader& in, const std::map<std::string, HeaderValue>& h,
                                       TerrainGrid& g, bool& has_nodata, double& nodata) {
  for (const char* slot : {"ncols", "nrows", "x", "y", "cellsize"})
    if (!h.count(slot)) {
      const std::string name = slot == std::string("x") ? "xllcorner or xllcenter"
                               : slot == std::string("y") ? "yllcorner or yllcenter" : slot;
      fail(in.path(), in.line(), "the header key " + name, "none before the data");
    }
  const std::size_t nc = grid_count(in.path(), h.at("ncols")), nr = grid_count(in.path(), h.at("nrows"));
  if (nc > kMaxGridNodes / nr)
    fail(in.path(), h.at("nrows").line, "ncols * nrows <= " + std::to_string(kMaxGridNodes),
         std::to_string(nc) + " * " + std::to_string(nr));
  g.cellsize = header_number(in.path(), h.at("cellsize"), true);
  const bool x_corner = lower(h.at("x").key) == "xllcorner", y_corner = lower(h.at("y").key) == "yllcorner";
  g.x0 = header_number(in.path(), h.at("x"), false) + (x_corner ? g.cellsize / 2 : 0);
  g.y0 = header_number(in.path(), h.at("y"), false) + (y_corner ? g.cellsize / 2 : 0);
  g.origin_line = h.at("x").line;
  has_nodata = h.count("nodata") > 0;
  if (has_nodata) nodata = header_number(in.path(), h.at("nodata"), false);
  return {nc, nr};
}

}  // namespace

TerrainGrid read_esri_ascii(const std::string& path) {
  LineReader in(path, "terrain file");
  TerrainGrid g;
  g.path = path;
  std::string line;
  const auto header = read_header(in, line);
  bool has_nodata = false;
  double nodata = 0;
  const auto [nc, nr] = grid_header(in, header, g, has_nodata, nodata);
  for (bool have = !line.empty(); have; have = in.next(line)) {
    const Tokens t = split_whitespace(line);
    if (t.empty()) continue;
    if (g.heights.size() == nr)
      fail(path, in.line(), std::to_string(nr) + " rows (nrows) and nothing after them", "more: " + shown(line));
    if (t.size() != nc)
      fail(path, in.line(), std::to_string(nc) + " values in the row (ncols)", std::to_string(t.size()));
    auto& row = g.heights.emplace_back();
    auto& mask = g.nodata.emplace_back();
    row.reserve(nc);
    for (std::string_view v : t) {
      row.push_back(finite_number(in, v, "a number (height)"));
      mask.push_back(has_nodata && row.back() == nodata);
    }
    g.row_line.push_back(in.line());
  }
  if (g.heights.size() < nr)
    fail(path, in.line(), std::to_string(nr) + " rows of values (nrows)", std::to_string(g.heights.size()));
  std::reverse(g.heights.begin(), g.heights.end());  // first row read = northernmost -> j = nrows - 1
  std::reverse(g.nodata.begin(), g.nodata.end());
  std::reverse(g.row_line.begin(), g.row_line.end());
  return g;
}

// ---- coverage and placement ------------------------------------------------------------------------------

namespace {

// The node index range [lo, hi] (at least 2 nodes) that bilinear interpolation over [a, a + size] uses on an
// axis with nodes at start + k cellsize, k < count.
std::array<std::size_t, 2> node_range(double start, double cellsize, std::size_t count, double a, double size) {
  const double eps = 1e-9;
  const double lo = std::floor((a - start) / cellsize + eps), hi = std::ceil((a + size - start) / cellsize - eps);
  std::size_t i0 = static_cast<std::size_t>(std::clamp(lo, 0.0, double(count - 1)));
  std::size_t i1 = static_cast<std::size_t>(std::clamp(hi, 0.0, double(count - 1)));
  if (i1 == i0) {
    if (i0 == 0) ++i1;
    else --i0;
  }
  return {i0, i1};
}

std::string span(double a, double b) {
  std::string s = "[";
  s.append(fmt(a)).append(", ").append(fmt(b)).append("]");
  return s;
}

}  // namespace

void check_covers(const TerrainProfile& p, double x0, double length) {
  const double tol = 1e-9 * length, first = p.points.front()[0], last = p.points.back()[0];
  const std::string what = "a profile spanning the domain, distance " + span(x0, x0 + length) + " in the file";
  if (first > x0 + tol) fail(p.path, p.lines.front(), what, "a first point at distance " + fmt(first));
  if (last < x0 + length - tol) fail(p.path, p.lines.back(), what, "a last point at distance " + fmt(last));
}

void check_covers(const TerrainGrid& g, double x0, double y0, double size_x, double size_y) {
  const double cs = g.cellsize, tol = 1e-9 * std::max({size_x, size_y, cs});
  const double x1 = g.x0 + cs * double(g.ncols() - 1), y1 = g.y0 + cs * double(g.nrows() - 1);
  if (g.x0 > x0 + tol || x1 < x0 + size_x - tol || g.y0 > y0 + tol || y1 < y0 + size_y - tol)
    fail(g.path, g.origin_line,
         "cell centres spanning the domain, x " + span(x0, x0 + size_x) + " and y " + span(y0, y0 + size_y) +
             " in the file",
         "cell centres over x " + span(g.x0, x1) + " and y " + span(g.y0, y1));
  const auto is = node_range(g.x0, cs, g.ncols(), x0, size_x), js = node_range(g.y0, cs, g.nrows(), y0, size_y);
  for (std::size_t j = js[0]; j <= js[1]; ++j)
    for (std::size_t i = is[0]; i <= is[1]; ++i)
      if (g.nodata[j][i])
        fail(g.path, g.row_line[j], "no NODATA value at the nodes the domain uses",
             "NODATA in column " + std::to_string(i + 1) + " (x = " + fmt(g.x0 + cs * double(i)) +
                 ", y = " + fmt(g.y0 + cs * double(j)) + ")");
}

namespace {

void fill_from_grid(TerrainSurface& spec, const TerrainGrid& g, const std::vector<double>& o,
                    const std::vector<double>& size) {
  const auto is = node_range(g.x0, g.cellsize, g.ncols(), o[0], size[0]);
  const auto js = node_range(g.y0, g.cellsize, g.nrows(), o[1], size[1]);
  spec.origin = {g.x0 + g.cellsize * double(is[0]) - o[0], g.y0 + g.cellsize * double(js[0]) - o[1]};
  spec.spacing = {g.cellsize, g.cellsize};
  spec.heights.clear();
  for (std::size_t j = js[0]; j <= js[1]; ++j) {
    auto& row = spec.heights.emplace_back();
    for (std::size_t i = is[0]; i <= is[1]; ++i) row.push_back(g.heights[j][i] - o[2]);
  }
}

}  // namespace

void bathymetry_from_file(TerrainSurface& spec, const std::string& path, const std::vector<double>& file_origin,
                          const std::vector<double>& domain_size, const std::string& context) {
  const auto& o = file_origin;
  const std::string ext = lower(std::filesystem::path(path).extension().string());
  try {
    if (domain_size.size() == 2 && ext == ".asc") fail(path, 0, "a CSV profile in a 2D scene", "an .asc grid (3D)");
    if (domain_size.size() == 3 && ext == ".csv") fail(path, 0, "an .asc grid in a 3D scene", "a .csv profile (2D)");
    if (domain_size.size() == 2) {
      const TerrainProfile p = read_profile_csv(path);
      check_covers(p, o[0], domain_size[0]);
      spec.points.clear();
      for (const auto& q : p.points) spec.points.push_back({q[0] - o[0], q[1] - o[1]});
    } else {
      const TerrainGrid g = read_esri_ascii(path);
      check_covers(g, o[0], o[1], domain_size[0], domain_size[1]);
      fill_from_grid(spec, g, o, domain_size);
    }
  } catch (const SceneError& e) {
    if (context.empty()) throw;
    throw SceneError(context + ": " + e.what());
  }
}

std::string terrain_path(const std::string& scene_path, const std::string& file) {
  return (std::filesystem::path(scene_path).parent_path() / file).lexically_normal().string();
}

}  // namespace cdmpm
