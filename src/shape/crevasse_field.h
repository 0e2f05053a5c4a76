// crevasse_field.h - surface crevasses of an ice body from seeded simplex noise (body key "crevasses";
// docs/scenes.md#crevasses). The reference study mimicked surface crevasses with simplex Perlin noise to emulate
// their depth and opening statistics (Wolper et al. 2021, sec. on the Eqip Sermia case); here the noise drives
// the crevasses' positions and depths, and the scene fixes their statistics.
//
// N = floor((x_max - x_min) / s) crevasses cross the region [x_min, x_max] of the flow axis x, one every mean
// spacing s, centred in the region. Crevasse i (i = 0 .. N-1) at transverse position y (3D; y = 0 in 2D) has
//   centre  x_i(y) = x_c + (i - (N - 1) / 2) s + (sigma_s / sqrt(2)) z_p(i, y),
//   depth   d_i(y) = d + sigma_d z_d(i, y),
// x_c the region's centre, d and sigma_d the mean and standard deviation of the depth, sigma_s the standard
// deviation of the spacing x_{i+1} - x_i (the difference of two independent offsets of deviation
// sigma_s / sqrt(2)), and z = (n - mean n) / std n the noise n standardised over the realised sample: every
// crevasse, and in 3D every station y_j along the body (one every length / 4), so that the realised depths
// have exactly mean d and standard deviation sigma_d before clipping, whatever the seed. The noise of
// crevasse i is sampled at (1.9 i + 0.37, y / length + 0.61) of shape/simplex_noise.h, one noise for the
// depths and one (another seed) for the positions: samples 1.9 apart share no simplex corner (> sqrt(2)),
// so neighbouring crevasses are independent; along y the field varies smoothly over `length`.
// Depths are clipped to [0, max_depth], offsets to +-(s - w) / 2 (neighbouring crevasses never overlap).
// A crevasse is a vertical slot of width w (the opening) cut down from the body's top surface: a lattice
// point at (x, y, z) is left empty when |x - x_i(y)| < w / 2 and z > top - d_i(y), top the highest ice of its
// lattice column or the given `surface` elevation (sim/seeding.cpp).
// Water in crevasses (keys water_depth d_w and water_material): each crevasse holds water from its bottom up to
// min(d_w, d_i) above it, seeded as particles of the fluid material at rest and hydrostatic below that level. Water
// standing in a crevasse pushes its walls apart with rho_w g (level - z) and deepens a dry crevasse's Nye depth
// R_xx / (rho_i g) by (rho_w / rho_i) d_w (Benn et al. 2007, eq. 4), the load that drives crevasses through a
// glacier's front (docs/eqip_sermia.md).
#pragma once

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "scene/scene_reader.h"
#include "shape/shape.h"
#include "shape/simplex_noise.h"

namespace cdmpm {

class CrevasseField {
 public:
  uint64_t seed = 1;
  double spacing = 0;      // s, mean distance between neighbouring crevasses [m]
  double spacing_std = 0;  // sigma_s, standard deviation of that distance [m]
  double depth = 0;        // d, mean depth below the top surface [m]
  double depth_std = 0;    // sigma_d, standard deviation of the depth [m]
  double width = 0;        // w, opening of each crevasse along x [m]
  double x_min = 0, x_max = 0;    // region of the flow axis holding the crevasses [m]
  std::optional<double> surface;  // elevation the depths are measured from [m]; default: each column's top ice
  double max_depth = 0;    // depths are clipped to [0, max_depth] [m]
  double length = 0;       // 3D: length over which depth and position vary along y [m]
  double y_min = 0, y_max = 0;  // 3D: the body's extent along y [m]
  double water_depth = 0;        // d_w, water standing in each crevasse above its bottom [m] (0: dry)
  std::string water_material;    // the fluid that fills them (a material's name)
  int water_material_index = -1; // resolved by the scene loader
  int dim = 2;

  // "crevasses": {"seed", "spacing", "spacing_std", "depth", "depth_std", "width", "region", "surface",
  // "max_depth", "length", "water_depth", "water_material"} of a body with bounding box `shape` (docs/scenes.md#crevasses). Realises the field.
  static CrevasseField parse(const SceneReader& r, const Node& n, const Shape& shape);

  // Computes the number of crevasses and the standardisation of the noise (called by parse; again after a
  // change of the public parameters).
  void realise();

  int count() const { return count_; }
  double centre(int i, double y) const;
  double depth_at(int i, double y) const;
  // The depth of the crevasse whose slot holds the lattice column at (x, y), 0 if none.
  double cut_depth(double x, double y) const;

  // One realised crevasse at one station along y (2D: one station, y = 0).
  struct Station {
    int crevasse;
    double y, x, depth;
    bool clipped;  // its depth or its offset was clipped
  };
  // Every crevasse at every station y_j, in crevasse order then y order (the sample the noise is standardised over).
  std::vector<Station> stations() const;
  std::vector<double> station_ys() const;
  // crevasses.csv rows of body `body` (header from csv_header()).
  static std::string csv_header(int dim);
  void write_csv(std::ostream& out, size_t body) const;

 private:
  double sample(const SimplexNoise& noise, int i, double y) const;
  double raw_offset(int i, double y) const;
  double raw_depth(int i, double y) const;
  SimplexNoise depth_noise_{0}, position_noise_{0};
  int count_ = 0;
  double mean_d_ = 0, std_d_ = 1, mean_p_ = 0, std_p_ = 1;  // the noise's sample statistics
};

}  // namespace cdmpm
