// cf.h - the parts of the CF metadata conventions (version 1.8, cfconventions.org) that every netCDF output of a
// run shares (io/station_file.h, hazard/hazard_grid_file.h, run/snapshots.h):
//   - the global attributes (section 2.6.2: Conventions, title, institution, source, references, comment; and
//     featureType for discrete sampling geometries, section 9.4),
//   - data and coordinate variables with units (UDUNITS), long_name and, where the CF standard name table has
//     one, standard_name (sections 3.1 - 3.3); data variables with _FillValue NaN (section 2.5.1),
//   - the time coordinate "seconds since" the georeference's time origin (section 4.4),
//   - the map coordinates projection_x_coordinate / projection_y_coordinate and the grid mapping variable "crs"
//     (section 5.6, appendix F: grid_mapping_name and its parameters where CF names the projection, crs_wkt; and
//     GDAL's spatial_ref, the same WKT, which GDAL reads first).
#pragma once

#include <string>
#include <vector>

#include "io/netcdf_file.h"
#include "scene/scene.h"

namespace cdmpm {

struct CfVariable {
  std::string name, long_name, units, standard_name;  // standard_name empty: CF has none
  std::string cell_methods = "";                      // section 7.3 ("time: maximum"); empty: none
};

// The global attributes; feature_type empty for gridded data.
void cf_global_attributes(NetcdfFile& f, const Scene& scene, const std::string& title, const std::string& feature_type = "");
// A coordinate or auxiliary coordinate variable (no fill value); axis "X", "Y", "T" or empty.
int cf_coordinate(NetcdfFile& f, const CfVariable& v, const std::vector<int>& dims, const std::string& axis = "");
// A data variable of doubles with _FillValue NaN, its coordinates attribute (empty: none) and, with a CRS, its
// grid_mapping "crs".
int cf_data(NetcdfFile& f, const CfVariable& v, const std::vector<int>& dims, const std::string& coordinates,
            const Scene& scene);
// The time coordinate variable "time" on dimension `dim`.
int cf_time(NetcdfFile& f, int dim, const Scene& scene);
// The grid mapping variable "crs" if the scene's georeference has a CRS (else nothing); returns whether it wrote it.
bool cf_crs(NetcdfFile& f, const Scene& scene);
// Map coordinates easting / northing (projection_x/y_coordinate) on `dims`, if the scene is georeferenced; returns
// their variables (or -1, -1).
std::pair<int, int> cf_map_coordinates(NetcdfFile& f, const Scene& scene, const std::vector<int>& dims);

}  // namespace cdmpm
