// terrain_file.h - terrain (bathymetry and shore) from files, for the "bathymetry" boundary (docs/scenes.md).
//
// Two formats:
//   2D  a CSV profile: two columns, distance and elevation [m]; one header line, '#' comments and blank
//       lines allowed; distance strictly increasing, at least 2 points.
//   3D  an ESRI ASCII grid (.asc, the "AAIGrid" of GDAL): header keys ncols, nrows, xllcorner|xllcenter,
//       yllcorner|yllcenter, cellsize and optional NODATA_value (case-insensitive, any order), then nrows rows
//       of ncols numbers, the first row the northernmost. It is returned as heights at the cell centres with
//       the rows flipped, so that row j lies at y = y0 + j cellsize (j increasing northwards).
// The readers are strict: every problem throws SceneError (so the program exits with code 2) with a message
//   <file>:<line>: expected <what>, got <found>
// Input is bounded before anything is stored: lines longer than kMaxLineLength, grids of more than
// kMaxGridNodes nodes and profiles of more than kMaxProfilePoints points are refused.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "io/line_reader.h"
#include "scene/scene_reader.h"

namespace cdmpm {

using text::kMaxLineLength;                                          // characters per line (io/line_reader.h)
inline constexpr std::size_t kMaxGridNodes = 100'000'000;            // ncols * nrows of an .asc grid
inline constexpr std::size_t kMaxProfilePoints = 10'000'000;         // data rows of a CSV profile

// A 2D profile: points[k] = {distance, elevation} [m], distance strictly increasing.
struct TerrainProfile {
  std::string path;
  std::vector<std::array<double, 2>> points;
  std::vector<int> lines;  // line of the file each point was read from (for messages)
};

// A regular height grid: heights[j][i] at (x0 + i cellsize, y0 + j cellsize), j increasing northwards (+y).
struct TerrainGrid {
  std::string path;
  double x0 = 0, y0 = 0;  // centre of the south-west cell [m]
  double cellsize = 0;    // [m]
  std::vector<std::vector<double>> heights;  // [m]; the NODATA value where nodata[j][i]
  std::vector<std::vector<bool>> nodata;
  std::vector<int> row_line;  // line of the file that row j was read from (for messages)
  int origin_line = 0;        // line of xllcorner / xllcenter (for messages about the extent)
  std::size_t ncols() const { return heights.empty() ? 0 : heights[0].size(); }
  std::size_t nrows() const { return heights.size(); }
};

TerrainProfile read_profile_csv(const std::string& path);
TerrainGrid read_esri_ascii(const std::string& path);

// The domain's horizontal extent [origin, origin + size] in file coordinates: throws SceneError naming the file
// unless the profile spans [x0, x0 + length], or the grid's cell centres span [x0, x0 + size_x] x
// [y0, y0 + size_y] with no NODATA node among those that bilinear interpolation inside that box uses.
void check_covers(const TerrainProfile& profile, double x0, double length);
void check_covers(const TerrainGrid& grid, double x0, double y0, double size_x, double size_y);

// The terrain of a bathymetry boundary (boundary/bathymetry.cpp) in domain coordinates: 2D, the profile's
// points (x, height); 3D, a height field heights[j][i] at origin + (i, j) * spacing.
struct TerrainSurface {
  std::vector<std::array<double, 2>> points;
  std::vector<double> origin, spacing;
  std::vector<std::vector<double>> heights;
};

// Fills a bathymetry's terrain from the terrain file `path`: a CSV profile when domain_size has 2 entries (sets
// spec.points), an .asc grid when it has 3 (sets spec.origin, spacing and heights, cropped to the nodes the
// domain uses). `file_origin` (domain_size.size() numbers: distance, elevation or easting, northing,
// elevation) is the point of the file that becomes the domain's origin: domain = file - file_origin. The
// terrain must cover the domain (check_covers). Messages are prefixed with `context` (e.g. the scene file and
// json path), if not empty.
void bathymetry_from_file(TerrainSurface& spec, const std::string& path, const std::vector<double>& file_origin,
                          const std::vector<double>& domain_size, const std::string& context = "");

// `file` relative to the directory of `scene_path` (unchanged if absolute).
std::string terrain_path(const std::string& scene_path, const std::string& file);

}  // namespace cdmpm
