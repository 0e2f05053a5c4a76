// hazard_grid_file.h - hazard.nc: the 3D hazard maps (hazard/hazard_report.h) as one CF grid file (CF conventions
// 1.8): dimensions y, x, one cell per surface column; coordinate variables x, y the cell centres, in map
// coordinates (projection_x_coordinate, projection_y_coordinate: the georeference's easting and northing plus the
// domain coordinates) when the scene is georeferenced, else in the domain; the grid mapping "crs" when it has a
// CRS (section 5.6); one variable per layer, the fill value where a layer is not defined (the rasters' NODATA).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "hazard/hazard_map.h"
#include "io/cf.h"

namespace cdmpm {

struct HazardLayer {
  CfVariable variable;
  std::function<double(size_t)> value;  // per column (x fastest); NaN where not defined
  std::string raster;                   // the ESRI ASCII raster of the layer ("" if none)
};

// Throws std::runtime_error if the file cannot be written.
void write_hazard_grid(const std::string& path, const HazardMap<3>& map, const std::vector<HazardLayer>& layers,
                       const Scene& scene);

}  // namespace cdmpm
