// crs.h - the map coordinate reference system of a scene's georeference (key "georeference.crs"): an EPSG code
// ("EPSG:32624") or a WKT string, resolved with the PROJ library (proj.org, ISO 19111) into what the outputs carry:
//   - the ESRI flavour of WKT 1 for the .prj file beside every ESRI ASCII raster (GDAL and QGIS read it),
//   - the WKT 1 (GDAL flavour) for the netCDF grid mapping's crs_wkt and spatial_ref attributes, and the CF
//     grid_mapping_name with its parameters for the projections CF names (CF conventions 1.8, section 5.6 and
//     appendix F: transverse_mercator, polar_stereographic, lambert_conformal_conic),
//   - its name and EPSG code for summary.json.
// Only projected systems in metres are accepted: the domain's coordinates are metres on the map.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace cdmpm {

struct Crs {
  std::string input;      // as the scene gave it
  std::string name;       // "WGS 84 / UTM zone 24N"
  int epsg = 0;           // 0: no EPSG identifier
  std::string wkt_esri;   // ESRI WKT 1 (.prj)
  std::string wkt;        // WKT 1, GDAL flavour (netCDF crs_wkt, spatial_ref)
  // CF grid mapping: grid_mapping_name (empty for a projection CF does not name) and its numeric parameters.
  std::string cf_grid_mapping_name;
  std::map<std::string, std::vector<double>> cf_parameters;
};

// Resolves an EPSG code or WKT; throws std::invalid_argument saying what was wrong (unknown code, not WKT, not a
// projected system in metres).
Crs resolve_crs(const std::string& text);

// Writes the .prj of a raster (the ESRI WKT on one line); throws std::runtime_error if it cannot be written.
void write_prj(const std::string& path, const Crs& crs);

}  // namespace cdmpm
