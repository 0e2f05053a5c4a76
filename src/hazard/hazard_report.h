// hazard_report.h - the hazard products of a run, written at its end from its hazard record (hazard_map.h):
//   2D  hazard.csv: per column x, bed, still_level, max_elevation, time_of_max, arrival_time, max_depth (dry
//       ground only), earliest_arrival, arrival_threshold (docs/outputs in docs/scenes.md#hazard), and runup.csv: per
//       shore its direction, still level, run-up, where and when, inundation extent and when (not written
//       without a shore: the summary's "shores_reason" says so);
//   3D  ESRI ASCII rasters (the format of the terrain input, terrain/terrain_file.h) max_elevation.asc,
//       max_elevation_time.asc, arrival_time.asc, inundation_depth.asc, one cell per column, the lower-left
//       corner at the scene's georeference (easting, northing) plus the domain's origin, NODATA_value -9999
//       where a value is not defined, each with its .prj when the georeference has a CRS (geo/crs.h); and the
//       same maps with the bed and still level as one CF grid, hazard.nc (hazard/hazard_grid_file.h);
//   2D  hazard.csv's easting and northing of each column when georeferenced;
// and the summary.json entry "hazard": arrival threshold, interval, the largest elevation and where, the shores'
// run-up and inundation extent (2D), the run-up, inundated area and largest inundation depth (3D).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "hazard/hazard_map.h"

namespace cdmpm {

// Writes the files into out_dir and returns the summary entry. Throws std::runtime_error if a file cannot be
// written.
template <int dim>
nlohmann::json write_hazard_report(const std::string& out_dir, const HazardMap<dim>& map, const Scene& scene);

}  // namespace cdmpm
