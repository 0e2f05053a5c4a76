// station_file.cpp - stations.nc, a CF 1.8 timeSeries discrete sampling geometry (station_file.h).
#include "io/station_file.h"

#include <algorithm>
#include <limits>

#include "io/cf.h"
#include "io/csv_table.h"

namespace cdmpm {
namespace {

// The quantities a station can have, in file order, with their CF description (standard names from the CF
// standard name table: d is the depth of the sea floor (the bed the water covers) below the surface; u, v the
// depth-averaged, barotropic, velocity).
const std::vector<CfVariable>& station_quantities() {
  static const std::vector<CfVariable> q = {
      {"eta", "free-surface elevation above the still water level", "m", "sea_surface_height_above_mean_sea_level"},
      {"d", "total water depth", "m", "sea_floor_depth_below_sea_surface"},
      {"u", "depth-averaged velocity along x", "m s-1", "barotropic_sea_water_x_velocity"},
      {"v", "depth-averaged velocity along y", "m s-1", "barotropic_sea_water_y_velocity"},
      {"q", "depth-integrated volume flux along x per unit width (d u)", "m2 s-1", ""},
      {"qx", "depth-integrated volume flux along x per unit width (d u)", "m2 s-1", ""},
      {"qy", "depth-integrated volume flux along y per unit width (d v)", "m2 s-1", ""}};
  return q;
}

}  // namespace

void write_station_file(const std::string& path, const std::string& probes_csv, const std::vector<Station>& stations,
                        const std::vector<double>& bed, const Scene& scene) {
  if (stations.empty()) return;
  const CsvTable table = read_csv_table(probes_csv);
  const std::vector<double> time = table.numbers("time");
  const int H = scene.dim - 1;
  size_t width = 1;
  for (const Station& s : stations) width = std::max(width, s.name.size());

  NetcdfFile f(path, NetcdfFile::Mode::Create);
  cf_global_attributes(f, scene, "Wave gauges and section stations", "timeSeries");
  const int station = f.dimension("station", stations.size());
  const int tdim = f.dimension("time", time.size());
  const int strlen = f.dimension("name_strlen", width);
  const int tvar = cf_time(f, tdim, scene);
  const int name = f.variable("station_name", NC_CHAR, {station, strlen});
  f.attribute(name, "long_name", "station name (the probes.csv column prefix)");
  f.attribute(name, "cf_role", "timeseries_id");
  const int xv = cf_coordinate(f, {"x", "station x in the domain", "m", ""}, {station});
  const int yv = H == 2 ? cf_coordinate(f, {"y", "station y in the domain", "m", ""}, {station}) : -1;
  const auto [ev, nv] = cf_map_coordinates(f, scene, {station});
  std::string coordinates = H == 2 ? "time x y station_name" : "time x station_name";
  if (ev >= 0) coordinates = "time easting northing x" + std::string(H == 2 ? " y" : "") + " station_name";
  const int bv = cf_data(f, {"bed", "bed height under the station above the domain's floor", "m", ""}, {station},
                         "station_name", scene);
  const int sv = cf_data(f, {"still_level", "still water level above the domain's floor", "m", ""}, {station},
                         "station_name", scene);
  // The quantities any station has, in the order of station_quantities().
  std::vector<CfVariable> present;
  for (const CfVariable& q : station_quantities())
    if (std::any_of(stations.begin(), stations.end(), [&](const Station& s) {
          return std::any_of(s.variables.begin(), s.variables.end(), [&](const auto& v) { return v.first == q.name; });
        }))
      present.push_back(q);
  std::vector<int> vars;
  for (const CfVariable& q : present) vars.push_back(cf_data(f, q, {station, tdim}, coordinates, scene));
  cf_crs(f, scene);
  f.end_definitions();

  f.put(tvar, time);
  std::vector<std::string> names;
  std::vector<double> x, y, e, n, still;
  for (const Station& s : stations) {
    names.push_back(s.name);
    x.push_back(s.position[0]);
    if (H == 2) y.push_back(s.position[1]);
    const std::array<double, 2> map = scene.georeference.map_point(s.position);
    e.push_back(map[0]), n.push_back(map[1]);
    still.push_back(s.still_level);
  }
  f.put_strings(name, names, width);
  f.put(xv, x);
  if (yv >= 0) f.put(yv, y);
  if (ev >= 0) f.put(ev, e), f.put(nv, n);
  f.put(bv, bed);
  f.put(sv, still);
  const double fill = std::numeric_limits<double>::quiet_NaN();
  for (size_t q = 0; q < present.size(); ++q) {
    std::vector<double> values(stations.size() * time.size(), fill);
    for (size_t k = 0; k < stations.size(); ++k)
      for (const auto& [quantity, column] : stations[k].variables)
        if (quantity == present[q].name) {
          const std::vector<double> c = table.numbers(column);
          std::copy(c.begin(), c.end(), values.begin() + static_cast<long>(k * time.size()));
        }
    f.put(vars[q], values);
  }
  f.close();
}

}  // namespace cdmpm
