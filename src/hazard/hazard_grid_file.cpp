// hazard_grid_file.cpp - hazard.nc, the 3D hazard maps as a CF 1.8 grid (hazard_grid_file.h).
#include "hazard/hazard_grid_file.h"

#include "io/netcdf_file.h"

namespace cdmpm {

void write_hazard_grid(const std::string& path, const HazardMap<3>& m, const std::vector<HazardLayer>& layers,
                       const Scene& scene) {
  const GeoreferenceSpec& g = scene.georeference;
  NetcdfFile f(path, NetcdfFile::Mode::Create);
  cf_global_attributes(f, scene, "Tsunami hazard maps");
  const int ydim = f.dimension("y", static_cast<size_t>(m.count(1)));
  const int xdim = f.dimension("x", static_cast<size_t>(m.count(0)));
  const int xv = g.given ? cf_coordinate(f, {"x", "easting of the cell centre", "m", "projection_x_coordinate"}, {xdim}, "X")
                         : cf_coordinate(f, {"x", "x of the cell centre in the domain", "m", ""}, {xdim}, "X");
  const int yv = g.given ? cf_coordinate(f, {"y", "northing of the cell centre", "m", "projection_y_coordinate"}, {ydim}, "Y")
                         : cf_coordinate(f, {"y", "y of the cell centre in the domain", "m", ""}, {ydim}, "Y");
  std::vector<int> vars;
  for (const HazardLayer& l : layers) vars.push_back(cf_data(f, l.variable, {ydim, xdim}, "", scene));
  cf_crs(f, scene);
  f.end_definitions();
  std::vector<double> x(static_cast<size_t>(m.count(0))), y(static_cast<size_t>(m.count(1)));
  for (size_t i = 0; i < x.size(); ++i) x[i] = (g.given ? g.easting : 0.0) + m.centre(i, 0);
  for (size_t j = 0; j < y.size(); ++j) y[j] = (g.given ? g.northing : 0.0) + m.centre(j * x.size(), 1);
  f.put(xv, x);
  f.put(yv, y);
  for (size_t l = 0; l < layers.size(); ++l) {
    std::vector<double> v(m.columns());
    for (size_t c = 0; c < v.size(); ++c) v[c] = layers[l].value(c);
    f.put(vars[l], v);
  }
  f.close();
}

}  // namespace cdmpm
