// hazard_report.cpp - the hazard products (hazard_report.h).
#include "hazard/hazard_report.h"

#include "geo/crs.h"
#include "hazard/hazard_grid_file.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>

namespace cdmpm {
namespace {

constexpr double kNoData = -9999;

std::string field(double v) {
  if (std::isnan(v)) return "";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

std::ofstream open(const std::filesystem::path& p) {
  std::ofstream os(p);
  if (!os) throw std::runtime_error(p.string() + ": cannot write");
  return os;
}

// Whether v is a number larger than best (or best is NaN: none yet).
bool larger(double v, double best) { return !std::isnan(v) && !(v <= best); }

// A JSON number, or null for NaN.
nlohmann::json number(double v) { return std::isnan(v) ? nlohmann::json(nullptr) : nlohmann::json(v); }

template <int dim>
double elevation(const HazardMap<dim>& m, size_t c) {  // NaN for a dry or never wet column
  return m.max_top()[c] - m.still_level()[c];
}
template <int dim>
double depth(const HazardMap<dim>& m, size_t c) {  // maximum inundation depth of dry ground (NaN elsewhere)
  // A particle beside the column centre may lie below the bed there: counted as 0.
  return !m.dry_ground(c) ? std::nan("") : std::isnan(m.max_top()[c]) ? 0.0 : std::max(0.0, m.max_top()[c] - m.bed()[c]);
}

// The largest elevation over the columns and where.
template <int dim>
nlohmann::json largest_elevation(const HazardMap<dim>& m) {
  double best = std::nan("");
  size_t at = 0;
  for (size_t c = 0; c < m.columns(); ++c)
    if (larger(elevation(m, c), best)) best = elevation(m, c), at = c;
  if (std::isnan(best)) return nullptr;
  nlohmann::json j = {{"elevation", best}, {"time", m.time_of_max()[at]}};
  std::vector<double> where;
  for (int a = 0; a < dim - 1; ++a) where.push_back(m.centre(at, a));
  j["position"] = where;
  return j;
}

// Georeferenced: each column centre's map coordinates too, along the transect (GeoreferenceSpec::map_point).
void write_csv_2d(const std::filesystem::path& out, const HazardMap<2>& m, const GeoreferenceSpec& geo) {
  std::ofstream os = open(out / "hazard.csv");
  os << "x,bed,still_level,max_elevation,time_of_max,arrival_time,max_depth,earliest_arrival,arrival_threshold"
     << (geo.given ? ",easting,northing\n" : "\n");
  for (size_t c = 0; c < m.columns(); ++c) {
    os << field(m.centre(c, 0)) << ',' << field(m.bed()[c]) << ',' << field(m.still_level()[c]) << ','
       << field(elevation(m, c)) << ',' << field(m.time_of_max()[c]) << ',' << field(m.arrival()[c]) << ','
       << field(depth(m, c)) << ',' << field(m.earliest_arrival()[c]) << ',' << field(m.threshold(c));
    if (geo.given) {
      const std::array<double, 2> en = geo.map_point({m.centre(c, 0)});
      os << ',' << field(en[0]) << ',' << field(en[1]);
    }
    os << '\n';
  }
  if (m.shores().empty()) return;  // no run-up to tabulate: the summary says why
  std::ofstream rs = open(out / "runup.csv");
  rs << "shore,direction,shore_x,still_level,runup,runup_x,runup_time,extent_x,extent_time\n";
  for (size_t k = 0; k < m.shores().size(); ++k) {
    const auto& s = m.shores()[k];
    const double edge = (static_cast<double>(s.first_dry) + (s.direction > 0 ? 0.0 : 1.0)) * m.dx();
    rs << k << ',' << s.direction << ',' << field(edge) << ',' << field(s.still_level) << ',' << field(s.runup) << ','
       << field(s.runup_x) << ',' << field(s.runup_time) << ',' << field(s.extent_x) << ',' << field(s.extent_time)
       << '\n';
  }
}

// One ESRI ASCII raster: the first row the northernmost (largest y); with the scene's CRS, its .prj beside it.
void write_asc(const std::filesystem::path& p, const HazardMap<3>& m, const GeoreferenceSpec& geo,
               const std::function<double(size_t)>& value) {
  if (geo.crs) write_prj(std::filesystem::path(p).replace_extension(".prj").string(), *geo.crs);
  std::ofstream os = open(p);
  os << "ncols " << m.count(0) << "\nnrows " << m.count(1) << "\nxllcorner " << field(geo.easting) << "\nyllcorner "
     << field(geo.northing) << "\ncellsize " << field(m.dx()) << "\nNODATA_value " << field(kNoData) << '\n';
  for (int j = m.count(1) - 1; j >= 0; --j) {
    for (int i = 0; i < m.count(0); ++i) {
      const double v = value(static_cast<size_t>(j) * static_cast<size_t>(m.count(0)) + static_cast<size_t>(i));
      os << (i ? " " : "") << field(std::isnan(v) ? kNoData : v);
    }
    os << '\n';
  }
}

nlohmann::json shores_json(const HazardMap<2>& m) {
  nlohmann::json shores = nlohmann::json::array();
  for (const auto& s : m.shores())
    shores.push_back({{"direction", s.direction}, {"still_level", s.still_level}, {"runup", number(s.runup)},
                      {"runup_x", number(s.runup_x)}, {"runup_time", number(s.runup_time)},
                      {"extent_x", number(s.extent_x)}, {"extent_time", number(s.extent_time)}});
  return shores;
}

// 3D: an inundated column is dry ground (hazard_map.h: dry at t = 0, held by no other material) with a maximum
// depth above its arrival threshold; the inundated area is their number times dx^2. The run-up is the highest bed
// of an inundated column of land (its bed above the still water level, the highest still level of the wet
// columns) above that level, so it is never negative.
nlohmann::json inundation_3d(const HazardMap<3>& m) {
  const double level = m.still_water_level();
  double runup = std::nan(""), deepest = 0;
  size_t inundated = 0, at = 0, land = 0;
  for (size_t c = 0; c < m.columns(); ++c) {
    land += m.land(c);
    const double d = depth(m, c);
    if (!(d > m.threshold(c))) continue;
    ++inundated;
    deepest = std::max(deepest, d);
    if (m.land(c) && larger(m.bed()[c] - level, runup)) runup = m.bed()[c] - level, at = c;
  }
  nlohmann::json j = {{"still_level", number(level)}, {"inundated_area", double(inundated) * m.dx() * m.dx()},
                      {"max_inundation_depth", deepest}, {"runup", number(runup)}};
  if (!std::isnan(runup))
    j.update({{"runup_position", {m.centre(at, 0), m.centre(at, 1)}}, {"runup_time", number(m.arrival()[at])}});
  else
    j["runup_reason"] = land == 0 ? "no land: no column is dry ground above the still water level at t = 0"
                                  : "no land was inundated above the arrival threshold";
  return j;
}

// The arrival threshold: the scene's, or the per-column rule with its range over the columns.
template <int dim>
nlohmann::json threshold_json(const HazardMap<dim>& m) {
  if (m.fixed_threshold()) return {{"arrival_threshold", m.threshold(0)}};
  double lo = INFINITY, hi = 0;
  for (size_t c = 0; c < m.columns(); ++c) lo = std::min(lo, m.threshold(c)), hi = std::max(hi, m.threshold(c));
  return {{"arrival_threshold", nullptr},
          {"arrival_threshold_rule", "per column: max(3 x its noise before the earliest arrival, dx / 100)"},
          {"arrival_threshold_range", {lo, hi}}};
}

// The 3D maps: the four rasters and hazard.nc's layers (CF standard names where CF has one; the maxima over time
// with cell_methods "time: maximum", CF section 7.3).
std::vector<HazardLayer> layers_3d(const HazardMap<3>& m) {
  const std::string eta = "sea_surface_height_above_mean_sea_level";
  return {{{"max_elevation", "maximum free-surface elevation above the still water level", "m", eta, "time: maximum"},
           [&m](size_t c) { return elevation(m, c); }, "max_elevation.asc"},
          {{"max_elevation_time", "time of the maximum free-surface elevation since the start of the run", "s", ""},
           [&m](size_t c) { return m.time_of_max()[c]; }, "max_elevation_time.asc"},
          {{"arrival_time", "first arrival time of the wave since the start of the run", "s", ""},
           [&m](size_t c) { return m.arrival()[c]; }, "arrival_time.asc"},
          {{"inundation_depth", "maximum inundation depth of dry ground", "m", "", "time: maximum"},
           [&m](size_t c) { return depth(m, c); }, "inundation_depth.asc"},
          {{"bed", "bed height under the cell centre above the domain's floor", "m", ""},
           [&m](size_t c) { return m.bed()[c]; }, ""},
          {{"still_level", "still water level above the domain's floor (wet at the start)", "m", ""},
           [&m](size_t c) { return m.still_level()[c]; }, ""}};
}

}  // namespace

template <int dim>
nlohmann::json write_hazard_report(const std::string& out_dir, const HazardMap<dim>& m, const Scene& scene) {
  const std::filesystem::path out(out_dir);
  nlohmann::json j = threshold_json(m);
  j.update({{"interval", scene.hazard.interval}, {"columns", m.columns()}, {"max_elevation", largest_elevation(m)}});
  if constexpr (dim == 2) {
    write_csv_2d(out, m, scene.georeference);
    j["shores"] = shores_json(m);
    if (m.shores().empty())
      j["shores_reason"] = "no shore: no column dry at t = 0 (and held by no other material) beside a wet one "
                           "with its bed within dx of the still level; runup.csv not written";
  } else {
    for (const HazardLayer& l : layers_3d(m))
      if (!l.raster.empty()) write_asc(out / l.raster, m, scene.georeference, l.value);
    write_hazard_grid((out / "hazard.nc").string(), m, layers_3d(m), scene);
    j.update(inundation_3d(m));
  }
  return j;
}

template nlohmann::json write_hazard_report<2>(const std::string&, const HazardMap<2>&, const Scene&);
template nlohmann::json write_hazard_report<3>(const std::string&, const HazardMap<3>&, const Scene&);

}  // namespace cdmpm
