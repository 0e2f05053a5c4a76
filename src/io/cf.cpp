// cf.cpp - CF 1.8 metadata shared by the netCDF outputs (cf.h).
#include "io/cf.h"

#include <limits>

namespace cdmpm {

void cf_global_attributes(NetcdfFile& f, const Scene& scene, const std::string& title, const std::string& feature_type) {
  f.attribute(NC_GLOBAL, "Conventions", "CF-1.8");
  f.attribute(NC_GLOBAL, "title", title + " of scene " + scene.name);
  f.attribute(NC_GLOBAL, "institution", "cdmpm");
  // No commit or date here (run.json and summary.json beside the file record them), so that the same results give
  // the same bytes from any build of the same version.
  f.attribute(NC_GLOBAL, "source", std::string("cdmpm ") + CDMPM_VERSION +
                                       ", Material Point Method simulation of scene " + scene.path);
  f.attribute(NC_GLOBAL, "references", "docs/running.md and docs/handoff.md of cdmpm");
  f.attribute(NC_GLOBAL, "comment",
              "Heights (bed, still_level, d) are metres above the domain's floor z = 0; horizontal coordinates x, y "
              "are metres in the domain, easting and northing (or x, y of a georeferenced grid) metres on the map.");
  if (!feature_type.empty()) f.attribute(NC_GLOBAL, "featureType", feature_type);
}

namespace {
void cf_describe(NetcdfFile& f, int v, const CfVariable& c) {
  f.attribute(v, "long_name", c.long_name);
  f.attribute(v, "units", c.units);
  if (!c.standard_name.empty()) f.attribute(v, "standard_name", c.standard_name);
  if (!c.cell_methods.empty()) f.attribute(v, "cell_methods", c.cell_methods);
}
}  // namespace

int cf_coordinate(NetcdfFile& f, const CfVariable& c, const std::vector<int>& dims, const std::string& axis) {
  const int v = f.variable(c.name, NC_DOUBLE, dims);
  cf_describe(f, v, c);
  if (!axis.empty()) f.attribute(v, "axis", axis);
  return v;
}

int cf_data(NetcdfFile& f, const CfVariable& c, const std::vector<int>& dims, const std::string& coordinates,
            const Scene& scene) {
  const int v = f.variable(c.name, NC_DOUBLE, dims);
  f.attribute(v, "_FillValue", std::numeric_limits<double>::quiet_NaN());
  cf_describe(f, v, c);
  if (!coordinates.empty()) f.attribute(v, "coordinates", coordinates);
  if (scene.georeference.crs) f.attribute(v, "grid_mapping", "crs");
  return v;
}

int cf_time(NetcdfFile& f, int dim, const Scene& scene) {
  const int v = cf_coordinate(f, {"time", "time since the start of the run", "seconds since " + scene.georeference.time_origin, "time"},
                              {dim}, "T");
  f.attribute(v, "calendar", "standard");
  return v;
}

bool cf_crs(NetcdfFile& f, const Scene& scene) {
  if (!scene.georeference.crs) return false;
  const Crs& crs = *scene.georeference.crs;
  const int v = f.variable("crs", NC_INT, {});
  f.attribute(v, "long_name", "coordinate reference system: " + crs.name);
  if (!crs.cf_grid_mapping_name.empty()) f.attribute(v, "grid_mapping_name", crs.cf_grid_mapping_name);
  for (const auto& [name, values] : crs.cf_parameters) f.attribute(v, name, values);
  f.attribute(v, "crs_wkt", crs.wkt);
  f.attribute(v, "spatial_ref", crs.wkt);
  if (crs.epsg) f.attribute(v, "epsg_code", "EPSG:" + std::to_string(crs.epsg));
  return true;
}

std::pair<int, int> cf_map_coordinates(NetcdfFile& f, const Scene& scene, const std::vector<int>& dims) {
  if (!scene.georeference.given) return {-1, -1};
  return {cf_coordinate(f, {"easting", "easting", "m", "projection_x_coordinate"}, dims),
          cf_coordinate(f, {"northing", "northing", "m", "projection_y_coordinate"}, dims)};
}

}  // namespace cdmpm
