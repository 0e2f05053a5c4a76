// test_lake_at_rest.cpp - the well-balanced bed (sim/bed_layer.h): water at rest over the sloping
// Eqip Sermia profile (scenes/lake_at_rest_2d.json) and over the same profile extruded into a channel with sloping
// sides (scenes/lake_at_rest_3d.json, scenes/data/eqip_sermia_channel.asc) stays at rest.
// What is asserted, at a coarse resolution, after the simulated time:
//   - the largest particle speed is below 0.1 m/s (the threshold for a lake at rest after 60 s);
//   - the bed pressure is within 5 % of rho g d along the whole profile (the tolerance). "Bed pressure":
//     the water particles at most one particle spacing (dx/2) above the bed (measured vertically; the bed height
//     found from the boundary's solid), in bins of 200 m along each horizontal axis; in each bin their mean
//     pressure against rho0 |g| times their mean depth below the still sea level. Bins where the water is less than
//     3 dx deep are left out (there the bed particles are the surface particles, a column of two or three cells;
//     in the 2D scene this is only the last 200 m before the shore line, of 4.8 km).
// Before this change (main at c0bc7f9, the plain slip condition) the same 2D lake ran at 21 m/s after 10 s, and
// its bed pressure was off by up to 150 % (docs/water.md#the-well-balanced-bed).
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include <omp.h>

#include "cli_helpers.h"
#include "material/stress.h"
#include "scene/scene_loader.h"
#include "sim/simulation.h"

namespace cdmpm::testing {
namespace {

constexpr double rho0 = 1000, g = 9.81, tolerance = 0.05, speed_limit = 0.1, bin_width = 200;

// Height of the bed below horizontal position x: bisection on the boundaries' solid along the vertical.
template <int dim>
double bed_height(const Simulation<dim>& sim, Vec<dim> x) {
  double lo = 0, hi = sim.domain_size[dim - 1];
  for (int it = 0; it < 50; ++it) {
    x[dim - 1] = static_cast<Real>(0.5 * (lo + hi));
    bool solid = false;
    for (const auto& b : sim.boundaries) solid = solid || b->is_solid(x);
    (solid ? lo : hi) = 0.5 * (lo + hi);
  }
  return 0.5 * (lo + hi);
}

struct LakeResult {
  double max_speed = 0, worst_error = 0;
  int bins = 0;
};

template <int dim>
LakeResult run_lake(const std::string& scene_file, const std::vector<std::string>& sets, double sea_level,
                    double across_lo = 0, double across_hi = 0) {
  // One thread: on the shared 2-core host, OpenMP threads spinning without the program's GOMP_SPINCOUNT (app/main.cpp)
  // made the 2D case 10 times slower; the result is the same bits for any thread count (docs/architecture.md).
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const Scene scene = load_scene(source_path(scene_file), sets);
  Simulation<dim> sim(scene);
  sim.run_until(scene.time.end);
  LakeResult r;
  const double dx = sim.grid.dx, spacing = dx / 2;
  std::map<std::vector<int>, std::array<double, 3>> bins;  // sum of p, sum of rho g d, count
  for (size_t q = 0; q < sim.particles.size(); ++q) {
    const Vec<dim>& x = sim.particles.x[q];
    r.max_speed = std::max(r.max_speed, static_cast<double>(sim.particles.v[q].norm()));
    const double h = bed_height(sim, x), depth_here = sea_level - h;
    if (x[dim - 1] - h > spacing || depth_here < 3 * dx) continue;
    if (dim == 3 && (x[1] < across_lo || x[1] > across_hi)) continue;  // 3D: the profile's strip of the channel
    std::vector<int> key;
    for (int a = 0; a < dim - 1; ++a) key.push_back(static_cast<int>(std::floor(x[a] / bin_width)));
    auto& b = bins[key];
    b[0] += particle_pressure(sim.materials[sim.particles.material[q]], sim.particles, q);
    b[1] += rho0 * g * (sea_level - x[dim - 1]);
    b[2] += 1;
  }
  omp_set_num_threads(threads);
  for (const auto& [key, b] : bins) {
    const double err = std::abs(b[0] - b[1]) / b[1];
    EXPECT_LT(err, tolerance) << "bin at x = " << key[0] * bin_width << " m: mean bed pressure " << b[0] / b[2]
                              << " Pa, rho g d " << b[1] / b[2] << " Pa (" << b[2] << " particles)";
    r.worst_error = std::max(r.worst_error, err);
    ++r.bins;
  }
  return r;
}

// 2D, dx = 20 m (5,126 particles, 60 s in about 9 s of CPU): the Eqip profile over 4.8 km of water.
TEST(LakeAtRest, Eqip2DStaysStillFor60sWithHydrostaticBedPressure) {
  const auto r = run_lake<2>("scenes/lake_at_rest_2d.json", {"parameters.dx=20"}, 200);
  EXPECT_LT(r.max_speed, speed_limit);
  EXPECT_GE(r.bins, 22);  // the whole profile: 200 m bins from x = 0 to 4.6 km with water at least 60 m deep
  RecordProperty("max_speed", std::to_string(r.max_speed));
  RecordProperty("worst_bed_pressure_error", std::to_string(r.worst_error));
}

// 3D, dx = 40 m (22,328 particles): 10 s simulated here (the full 60 s, measured by hand, is in docs/water.md).
// The bed pressure is asserted along the profile, i.e. on the channel's flat floor (y in [200, 400] m, where the
// profile is extruded); at the foot of the banks (sloping 0.75) it is 4-10 % high at this resolution (the water
// there is 3 cells deep; docs/water.md), which this test does not claim.
TEST(LakeAtRest, Eqip3DChannelStaysStillWithHydrostaticBedPressure) {
  const auto r = run_lake<3>("scenes/lake_at_rest_3d.json", {"time.end=10"}, 200, 200, 400);
  EXPECT_LT(r.max_speed, speed_limit);
  EXPECT_GE(r.bins, 8);  // 200 m bins from x = 1.2 km to 2.8 km, where the water is at least 3 dx = 120 m deep
  RecordProperty("max_speed", std::to_string(r.max_speed));
  RecordProperty("worst_bed_pressure_error", std::to_string(r.worst_error));
}

// The bed layer needs a slip bed: "well_balanced": true with another condition is an input error naming the key.
TEST(LakeAtRest, WellBalancedNeedsTheSlipCondition) {
  nlohmann::json j = {
      {"dim", 2},
      {"domain", {{"size", {100.0, 60.0}}, {"dx", 5.0}}},
      {"time", {{"end", 1.0}, {"frame_interval", 1.0}}},
      {"materials", {{"water", {{"type", "water"}, {"density", 1000}, {"bulk_modulus", 1e8}}}}},
      {"bodies", {{{"material", "water"}, {"particles_per_cell", 4},
                   {"shape", {{"type", "box"}, {"min", {0.0, 0.0}}, {"max", {100.0, 40.0}}}}}}},
      {"boundaries", {{{"type", "bathymetry"}, {"condition", "separate"}, {"well_balanced", true},
                       {"points", {{0.0, 10.0}, {100.0, 30.0}}}}}}};
  try {
    scene_from_json(j, "wb.json");
    FAIL() << "accepted well_balanced with the separate condition";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("boundaries[0].well_balanced"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("slip"), std::string::npos) << e.what();
  }
  j["boundaries"][0]["condition"] = "slip";  // the default with slip: a bed layer below the slope
  Simulation<2> with(scene_from_json(j, "wb.json"));
  j["boundaries"][0]["well_balanced"] = false;
  Simulation<2> without(scene_from_json(j, "wb.json"));
  EXPECT_EQ(with.particles.size(), without.particles.size());  // the layer is not among the particles
}

}  // namespace
}  // namespace cdmpm::testing
