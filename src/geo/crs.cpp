// crs.cpp - resolving a coordinate reference system with PROJ (crs.h). The CF grid mapping parameters follow CF
// conventions 1.8 appendix F, from the EPSG method and parameter codes of the projection (EPSG guidance note 7-2).
#include "geo/crs.h"

#include <proj.h>

#include <fstream>
#include <memory>
#include <stdexcept>
#include <vector>

namespace cdmpm {
namespace {

struct ProjContext {
  PJ_CONTEXT* ctx = proj_context_create();
  ~ProjContext() { proj_context_destroy(ctx); }
};
struct ProjObject {
  PJ* pj;
  ~ProjObject() {
    if (pj) proj_destroy(pj);
  }
};

// The value of the projection parameter of EPSG code `code` (in degrees for angles, metres for lengths), if any.
bool projection_parameter(PJ_CONTEXT* ctx, PJ* op, int code, double& value) {
  const int n = proj_coordoperation_get_param_count(ctx, op);
  for (int i = 0; i < n; ++i) {
    const char *name = nullptr, *auth = nullptr, *id = nullptr, *unit_name = nullptr, *unit_auth = nullptr,
               *unit_code = nullptr, *category = nullptr, *value_string = nullptr;
    double v = 0, conversion = 1;
    proj_coordoperation_get_param(ctx, op, i, &name, &auth, &id, &v, &value_string, &conversion, &unit_name,
                                  &unit_auth, &unit_code, &category);
    if (!id || std::stoi(id) != code) continue;
    // Angles to degrees (conversion: to radians), lengths to metres, scales as they are.
    const std::string cat = category ? category : "";
    value = cat == "angular" ? v * conversion * 180 / 3.14159265358979323846 : cat == "linear" ? v * conversion : v;
    return true;
  }
  return false;
}

// CF appendix F: the grid mapping of the projection methods with EPSG codes 9807 (Transverse Mercator), 9810 and
// 9829 (Polar Stereographic A and B) and 9802 (Lambert Conic Conformal 2SP); none for other methods.
void cf_grid_mapping(PJ_CONTEXT* ctx, PJ* crs, Crs& out) {
  ProjObject op{proj_crs_get_coordoperation(ctx, crs)};
  if (!op.pj) return;
  const char *method = nullptr, *auth = nullptr, *code = nullptr;
  if (!proj_coordoperation_get_method_info(ctx, op.pj, &method, &auth, &code) || !code) return;
  const int m = std::stoi(code);
  auto& p = out.cf_parameters;
  auto take = [&](int epsg_code, const char* cf_name) {
    double v;
    if (projection_parameter(ctx, op.pj, epsg_code, v)) p[cf_name].push_back(v);
  };
  take(8806, "false_easting");
  take(8807, "false_northing");
  if (m == 9807) {
    out.cf_grid_mapping_name = "transverse_mercator";
    take(8805, "scale_factor_at_central_meridian");
    take(8802, "longitude_of_central_meridian");
    take(8801, "latitude_of_projection_origin");
  } else if (m == 9810) {
    out.cf_grid_mapping_name = "polar_stereographic";
    take(8801, "latitude_of_projection_origin");
    take(8802, "straight_vertical_longitude_from_pole");
    take(8805, "scale_factor_at_projection_origin");
  } else if (m == 9829) {
    out.cf_grid_mapping_name = "polar_stereographic";
    take(8833, "straight_vertical_longitude_from_pole");
    take(8832, "standard_parallel");
    if (p.count("standard_parallel")) p["latitude_of_projection_origin"] = {p["standard_parallel"][0] < 0 ? -90.0 : 90.0};
  } else if (m == 9802) {
    out.cf_grid_mapping_name = "lambert_conformal_conic";
    take(8823, "standard_parallel");
    take(8824, "standard_parallel");
    take(8821, "latitude_of_projection_origin");
    take(8822, "longitude_of_central_meridian");
    take(8826, "false_easting");
    take(8827, "false_northing");
  } else {
    p.clear();
    return;
  }
  ProjObject ellipsoid{proj_get_ellipsoid(ctx, crs)};
  double a = 0, b = 0, inverse_flattening = 0;
  int computed = 0;
  if (ellipsoid.pj && proj_ellipsoid_get_parameters(ctx, ellipsoid.pj, &a, &b, &computed, &inverse_flattening)) {
    p["semi_major_axis"] = {a};
    p["inverse_flattening"] = {inverse_flattening};
  }
}

}  // namespace

Crs resolve_crs(const std::string& text) {
  if (text.empty() || text.size() > 65536) throw std::invalid_argument("expected an EPSG code (\"EPSG:32624\") or WKT");
  ProjContext c;
  proj_log_level(c.ctx, PJ_LOG_NONE);
  ProjObject crs{proj_create(c.ctx, text.c_str())};
  if (!crs.pj)
    throw std::invalid_argument("expected an EPSG code (\"EPSG:32624\") or WKT that PROJ knows (" +
                                std::string(proj_context_errno_string(c.ctx, proj_context_errno(c.ctx))) + ")");
  if (proj_get_type(crs.pj) != PJ_TYPE_PROJECTED_CRS)
    throw std::invalid_argument("expected a projected coordinate reference system (easting, northing in metres), got " +
                                std::string(proj_get_name(crs.pj) ? proj_get_name(crs.pj) : "another kind"));
  ProjObject cs{proj_crs_get_coordinate_system(c.ctx, crs.pj)};
  for (int axis = 0; axis < 2; ++axis) {
    double to_metres = 0;
    const char* unit = nullptr;
    if (!cs.pj || !proj_cs_get_axis_info(c.ctx, cs.pj, axis, nullptr, nullptr, nullptr, &to_metres, &unit, nullptr,
                                         nullptr) || to_metres != 1.0)
      throw std::invalid_argument("expected a projected coordinate reference system in metres, got one in " +
                                  std::string(unit ? unit : "unknown units"));
  }
  Crs out;
  out.input = text;
  out.name = proj_get_name(crs.pj) ? proj_get_name(crs.pj) : "";
  const char* auth = proj_get_id_auth_name(crs.pj, 0);
  const char* code = proj_get_id_code(crs.pj, 0);
  if (auth && code && std::string(auth) == "EPSG") out.epsg = std::stoi(code);
  const char* options[] = {"MULTILINE=NO", nullptr};
  // Each string is copied at once: the next proj_as_wkt call on the object invalidates the previous one's.
  for (const auto& [type, target] : {std::pair{PJ_WKT1_ESRI, &out.wkt_esri}, std::pair{PJ_WKT1_GDAL, &out.wkt}}) {
    const char* text = proj_as_wkt(c.ctx, crs.pj, type, options);
    if (!text) throw std::invalid_argument("expected a coordinate reference system that WKT 1 can express");
    *target = text;
  }
  cf_grid_mapping(c.ctx, crs.pj, out);
  return out;
}

void write_prj(const std::string& path, const Crs& crs) {
  std::ofstream os(path);
  os << crs.wkt_esri << '\n';
  if (!os) throw std::runtime_error(path + ": cannot write");
}

}  // namespace cdmpm
