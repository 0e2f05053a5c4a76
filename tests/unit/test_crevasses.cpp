// test_crevasses.cpp - surface crevasses from seeded simplex noise (shape/simplex_noise.h,
// shape/crevasse_field.h, the body key "crevasses"):
//   SimplexNoise  the noise lies in [-1, 1], is a pure function of its seed, differs between seeds, is
//                 Lipschitz-continuous with the bound of its formula, and has mean zero over independent samples;
//   Crevasses     the realised field has the scene's spacing and depth statistics, is reproducible from its seed,
//                 varies along y in 3D; seeding leaves every crevasse empty and the rest of the ice intact, and
//                 the missing ice is the crevasses' area; bad keys are refused naming the key;
// Through the program: tests/end_to_end/test_crevasses_cli.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "cli_helpers.h"
#include "hydrostatic_column.h"
#include "material/stress.h"
#include "scene/scene_loader.h"
#include "shape/crevasse_field.h"
#include "shape/simplex_noise.h"
#include "sim/simulation.h"
#include "scene_builders.h"

namespace cdmpm {
namespace {

// Points of a fixed, irregular sample of the plane (a Weyl sequence: not aligned with the simplex lattice).
std::array<double, 2> weyl_point(int k, double scale) {
  const double a = 0.7548776662466927, b = 0.5698402909980532;  // R2 sequence (plastic number)
  return {scale * std::fmod(0.5 + a * k, 1.0), scale * std::fmod(0.5 + b * k, 1.0)};
}

TEST(SimplexNoise, StaysWithinMinusOneAndOne) {
  const SimplexNoise n(1);
  double lo = 0, hi = 0;
  for (int k = 0; k < 200000; ++k) {
    const auto p = weyl_point(k, 256.0);
    const double v = n(p[0], p[1]);
    lo = std::min(lo, v), hi = std::max(hi, v);
  }
  EXPECT_GE(lo, -1.0);
  EXPECT_LE(hi, 1.0);
  // Not a degenerate (flat or tiny) field: both signs reach well away from zero.
  EXPECT_LT(lo, -0.5);
  EXPECT_GT(hi, 0.5);
}

TEST(SimplexNoise, SameSeedSameFieldOtherSeedOtherField) {
  const SimplexNoise a(42), b(42), c(43);
  int differ = 0, nonzero = 0;
  for (int k = 0; k < 2000; ++k) {
    const auto p = weyl_point(k, 100.0);
    EXPECT_EQ(a(p[0], p[1]), b(p[0], p[1])) << "at (" << p[0] << ", " << p[1] << ")";
    if (a(p[0], p[1]) == 0 && c(p[0], p[1]) == 0) continue;
    ++nonzero;
    differ += std::abs(a(p[0], p[1]) - c(p[0], p[1])) > 1e-3;
  }
  // Two seeds draw independent gradients at each corner: they agree only where the gradients happen to agree.
  EXPECT_GT(differ, 0.8 * nonzero);
}

// Each corner's term 70 t^4 (g . d), t = 1/2 - |d|^2, has gradient 70 (t^4 g - 8 t^3 (g . d) d), of norm at most
// 70 |g| (max t^4 + 8 max t^3 |d|^2) = 70 sqrt(2) (1/16 + 8 * 0.375^3 / 8) = 11.4 (t^3 |d|^2 is largest at
// |d|^2 = 1/8); three corners: a Lipschitz constant of 34.2 (the terms vanish smoothly where a corner leaves a
// point's simplex: in 2D the radius sqrt(1/2) is the triangles' height). Neighbouring samples delta apart
// differ by at most 34.2 delta.
TEST(SimplexNoise, NeighbouringSamplesAreClose) {
  const SimplexNoise n(7);
  const double lipschitz = 3 * 70 * std::sqrt(2.0) * (1.0 / 16 + 8 * std::pow(0.375, 3) * 0.125);
  const double delta = 1e-3;
  double steepest = 0;
  for (int k = 0; k < 20000; ++k) {
    const auto p = weyl_point(k, 64.0);
    const double v = n(p[0], p[1]);
    for (const auto& d : {std::array<double, 2>{delta, 0}, {0, delta}, {delta / std::sqrt(2.0), delta / std::sqrt(2.0)}}) {
      const double slope = std::abs(n(p[0] + d[0], p[1] + d[1]) - v) / delta;
      ASSERT_LE(slope, lipschitz) << "at (" << p[0] << ", " << p[1] << ")";
      steepest = std::max(steepest, slope);
    }
  }
  EXPECT_GT(steepest, 1.0);  // it does vary
}

// Samples on a square lattice 1.5 apart (more than sqrt(2): no two share a simplex corner), 90 x 90 of them so
// that their skewed lattice coordinates x + F (x + y) stay below 256, the period of the permutation (no corner's
// gradient is drawn twice), are independent draws of the noise; their mean is zero within its standard error.
TEST(SimplexNoise, MeanIsZeroWithinTheStandardError) {
  for (uint64_t seed : {1u, 2u, 3u}) {
    const SimplexNoise n(seed);
    double sum = 0, sum2 = 0;
    const int side = 90;
    for (int i = 0; i < side; ++i)
      for (int j = 0; j < side; ++j) {
        const double v = n(1.5 * i + 0.31, 1.5 * j + 0.17);
        sum += v, sum2 += v * v;
      }
    const double count = side * side, mean = sum / count;
    const double std = std::sqrt(sum2 / count - mean * mean);
    EXPECT_GT(std, 0.05);
    EXPECT_LT(std::abs(mean), 4 * std / std::sqrt(count)) << "seed " << seed;
  }
}

CrevasseField field_2d(uint64_t seed, double region, double depth, double depth_std, double spacing_std) {
  CrevasseField f;
  f.seed = seed;
  f.spacing = 40;
  f.spacing_std = spacing_std;
  f.depth = depth;
  f.depth_std = depth_std;
  f.width = 4;
  f.x_min = 0;
  f.x_max = region;
  f.max_depth = 180;
  f.realise();
  return f;
}

struct Moments {
  double mean = 0, std = 0;
};
Moments moments(const std::vector<double>& v) {
  Moments m;
  for (double x : v) m.mean += x;
  m.mean /= static_cast<double>(v.size());
  for (double x : v) m.std += (x - m.mean) * (x - m.mean);
  m.std = std::sqrt(m.std / static_cast<double>(v.size()));
  return m;
}

// 1000 crevasses over 40 km. Depths: the noise is standardised over the realised crevasses, so their mean and
// standard deviation are the parameters up to rounding (1e-9 relative) when none is clipped. Spacings
// x_{i+1} - x_i = s + e_{i+1} - e_i: their mean is s + (e_last - e_first) / (N - 1), within 2 (s - w) / 2 / (N - 1)
// of s as every offset is clipped to (s - w) / 2; their standard deviation estimates spacing_std with relative
// standard error sqrt(sum_k rho_k^2 / N) / 2 = sqrt(1.5 / N) / 2 = 1.9 % for independent offsets (the
// differences have lag-1 correlation -1/2); 4 standard errors allowed. Neighbouring depths are independent
// (noise samples 1.9 apart share no corner): lag-1 correlation within 4 / sqrt(N).
TEST(Crevasses, RealisedSpacingAndDepthHaveTheSceneStatistics) {
  for (uint64_t seed : {1u, 2u, 3u}) {
    const CrevasseField f = field_2d(seed, 40000, 60, 10, 8);
    ASSERT_EQ(f.count(), 1000);
    const auto st = f.stations();
    ASSERT_EQ(st.size(), 1000u);
    std::vector<double> depths, spacings;
    for (const auto& s : st) {
      EXPECT_FALSE(s.clipped) << "crevasse " << s.crevasse;
      depths.push_back(s.depth);
    }
    for (size_t i = 1; i < st.size(); ++i) spacings.push_back(st[i].x - st[i - 1].x);
    const Moments d = moments(depths), s = moments(spacings);
    EXPECT_NEAR(d.mean, 60, 60 * 1e-9) << "seed " << seed;
    EXPECT_NEAR(d.std, 10, 10 * 1e-9) << "seed " << seed;
    const double n = 1000;
    EXPECT_NEAR(s.mean, 40, (40 - 4) / (n - 1)) << "seed " << seed;
    EXPECT_NEAR(s.std, 8, 4 * 8 * std::sqrt(1.5 / n) / 2) << "seed " << seed;
    double lag1 = 0;
    for (size_t i = 1; i < depths.size(); ++i) lag1 += (depths[i] - 60) * (depths[i - 1] - 60);
    lag1 /= (n - 1) * 100;
    EXPECT_LT(std::abs(lag1), 4 / std::sqrt(n)) << "seed " << seed;
    for (const auto& c : st) {  // the slots never overlap or leave the region's nominal extent
      EXPECT_GE(c.x - 2, 0 - 18);
      EXPECT_LE(c.x + 2, 40000 + 18);
    }
  }
}

// Clipping at zero: a mean depth of one standard deviation leaves the shallowest crevasses at depth 0, flagged,
// and no depth below 0 or above max_depth.
TEST(Crevasses, DepthsAreClippedToTheBody) {
  const CrevasseField f = field_2d(5, 40000, 10, 10, 0);
  int clipped = 0;
  for (const auto& s : f.stations()) {
    EXPECT_GE(s.depth, 0.0);
    EXPECT_LE(s.depth, 180.0);
    clipped += s.clipped;
    if (s.clipped) {
      EXPECT_EQ(s.depth, 0.0);
    }
  }
  EXPECT_GT(clipped, 0);
}

TEST(Crevasses, TheFieldIsReproducibleFromItsSeed) {
  const auto a = field_2d(11, 4000, 30, 10, 8).stations(), b = field_2d(11, 4000, 30, 10, 8).stations();
  const auto c = field_2d(12, 4000, 30, 10, 8).stations();
  ASSERT_EQ(a.size(), 100u);
  ASSERT_EQ(c.size(), a.size());
  int differ = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].x, b[i].x);
    EXPECT_EQ(a[i].depth, b[i].depth);
    differ += std::abs(a[i].depth - c[i].depth) > 0.01 && std::abs(a[i].x - c[i].x) > 0.01;
  }
  EXPECT_GT(differ, 90);
}

// The 400 m x 100 m slab on a lattice of h = 1 m (dx 2, 4 particles per cell): 400 x 100 points. Every crevasse
// i of crevasses.csv is a slot |x - x_i| < w/2, y > 100 - d_i: no particle lies in one, every lattice point
// outside them holds one, and the missing particles are the slots' area w d_i / h^2 up to the rounding of each
// lattice column to whole points (at most one point in each of the w/h columns of a slot).
TEST(Crevasses, SeedingEmptiesTheCrevassesAndKeepsTheRestOfTheIce) {
  const nlohmann::json c = {{"seed", 3}, {"spacing", 40}, {"spacing_std", 8}, {"depth", 30}, {"depth_std", 10},
                            {"width", 4}};
  const Scene s = scene_from_json(testing::crevassed_ice_scene(2, c), "crevassed.json");
  ASSERT_TRUE(s.bodies[0].crevasses);
  const auto st = s.bodies[0].crevasses->stations();
  ASSERT_EQ(st.size(), 10u);
  auto in_crevasse = [&](double x, double y) {
    for (const auto& k : st)
      if (std::abs(x - k.x) < 2 && y > 100 - k.depth) return true;
    return false;
  };
  Simulation<2> sim(s);
  for (size_t q = 0; q < sim.particles.size(); ++q)
    ASSERT_FALSE(in_crevasse(sim.particles.x[q][0], sim.particles.x[q][1])) << "particle " << q << " in a crevasse";
  size_t lattice = 0, removed = 0;
  for (int i = 10; i < 410; ++i)
    for (int j = 0; j < 100; ++j) (in_crevasse(i + 0.5, j + 0.5) ? removed : lattice) += 1;
  EXPECT_EQ(sim.particles.size(), lattice);
  double area = 0;
  for (const auto& k : st) area += 4 * k.depth;
  EXPECT_NEAR(static_cast<double>(removed), area, 4.0 * static_cast<double>(st.size()));
  EXPECT_GT(area, 10 * 4 * 20);  // the crevasses are there (mean depth 30 m)
}

// Water in the crevasses (water_depth 20 m of "water", density 1000): every particle of the water material lies in
// a slot between its bottom 100 - d_i and its level 100 - d_i + min(20, d_i), every lattice point there holds one
// (the same lattice rounding as the ice), so the water's area is sum_i w min(20, d_i) up to one lattice row at the
// bottom and one at the level in each of the w/h columns of a slot; and the water starts at rest and hydrostatic
// below its level: the pressure of a column of compressed water at rest (hydrostatic_column.h; about
// rho_w g (level - y)) from the particle's own volume ratio, within the round-off of J
// (single-precision reals: 1e-6 relative of the bulk modulus's 1e6 Pa, 1 Pa). The ice is what it is dry.
TEST(Crevasses, WaterFillsEachCrevasseToItsLevelAtRestAndHydrostatic) {
  nlohmann::json c = {{"seed", 3}, {"spacing", 40}, {"spacing_std", 8}, {"depth", 30}, {"depth_std", 10}, {"width", 4}};
  const Scene dry = scene_from_json(testing::crevassed_ice_scene(2, c), "dry.json");
  c["water_depth"] = 20;
  c["water_material"] = "water";
  const Scene s = scene_from_json(testing::crevassed_ice_scene(2, c), "wet.json");
  const auto st = s.bodies[0].crevasses->stations();
  const int water = s.material_index("water");
  auto level_at = [&](double x, double y, double& level) {
    for (const auto& k : st)
      if (std::abs(x - k.x) < 2 && y > 100 - k.depth && y <= 100 - k.depth + std::min(20.0, k.depth)) {
        level = 100 - k.depth + std::min(20.0, k.depth);
        return true;
      }
    return false;
  };
  Simulation<2> sim(s, false);
  const Simulation<2> sim_dry(dry, false);
  size_t in_water = 0;
  double worst = 0;
  for (size_t q = 0; q < sim.particles.size(); ++q) {
    if (sim.particles.material[q] != water) continue;
    double level = 0;
    ASSERT_TRUE(level_at(sim.particles.x[q][0], sim.particles.x[q][1], level)) << "water particle " << q << " outside the water";
    EXPECT_EQ(sim.particles.v[q], Vec<2>::Zero());
    const double p = particle_pressure(sim.materials[water], sim.particles, q);
    worst = std::max(worst, std::abs(p - testing::tait_column_pressure(1000, 9.81, level - sim.particles.x[q][1], 1e6)));
    ++in_water;
  }
  EXPECT_LT(worst, 1.0);
  size_t lattice = 0;
  double level = 0;
  for (int i = 10; i < 410; ++i)
    for (int j = 0; j < 100; ++j) lattice += level_at(i + 0.5, j + 0.5, level);
  EXPECT_EQ(in_water, lattice);
  double area = 0;
  for (const auto& k : st) area += 4 * std::min(20.0, k.depth);
  EXPECT_NEAR(static_cast<double>(in_water), area, 8.0 * static_cast<double>(st.size()));
  EXPECT_GT(area, 10 * 4 * 15);
  EXPECT_EQ(sim.particles.solid_count(), sim_dry.particles.solid_count());
  EXPECT_EQ(sim.particles.size(), sim_dry.particles.size() + in_water);
}

// A sloping top (a polygon from 100 m high at x = 10 to 80 m at x = 410) with crevasses in a region behind the
// front, [210, 410]: each slot is cut from its own lattice column's top ice (the highest lattice point + h/2),
// so the lattice points missing are exactly those in a slot above that column's top minus the depth; with a
// given "surface" of 70 m the depths count from 70 m instead.
TEST(Crevasses, DepthsCountFromEachColumnsTopOrTheGivenSurface) {
  for (const bool given_surface : {false, true}) {
    nlohmann::json c = {{"seed", 4}, {"spacing", 40}, {"spacing_std", 8}, {"depth", 20}, {"depth_std", 5},
                        {"width", 4}, {"region", {210, 410}}};
    if (given_surface) c["surface"] = 70;
    nlohmann::json j = testing::crevassed_ice_scene(2, c);
    j["bodies"][0]["shape"] = {{"type", "polygon"}, {"vertices", {{10, 0}, {410, 0}, {410, 80}, {10, 100}}}};
    const Scene s = scene_from_json(j, "sloping.json");
    const auto st = s.bodies[0].crevasses->stations();
    ASSERT_EQ(st.size(), 5u);
    for (const auto& k : st) {
      EXPECT_GT(k.x, 210 - 18.0);
      EXPECT_LT(k.x, 410 + 18.0);
    }
    auto inside = [](double x, double y) { return y < 100 - 0.05 * (x - 10); };
    auto column_top = [&](double x) {
      double top = 0;
      for (int j = 0; j < 100; ++j)
        if (inside(x, j + 0.5)) top = j + 1.0;
      return given_surface ? 70.0 : top;
    };
    size_t lattice = 0;
    for (int i = 10; i < 410; ++i)
      for (int j = 0; j < 100; ++j) {
        const double x = i + 0.5, y = j + 0.5;
        if (!inside(x, y)) continue;
        bool cut = false;
        for (const auto& k : st) cut = cut || (std::abs(x - k.x) < 2 && y > column_top(x) - k.depth);
        lattice += !cut;
      }
    Simulation<2> sim(s);
    EXPECT_EQ(sim.particles.size(), lattice) << (given_surface ? "given surface" : "column tops");
  }
}

// 3D: a slab 80 m x 20 m x 20 m, h = 2 m; transverse crevasses every 20 m whose centre and depth vary along y
// over 10 m. No particle in a crevasse, the particles missing are exactly the lattice points in them, and the
// crevasses do vary along y.
TEST(Crevasses, ThreeDCrevassesVaryAlongYAndAreEmpty) {
  const nlohmann::json c = {{"seed", 9}, {"spacing", 20}, {"spacing_std", 3}, {"depth", 8}, {"depth_std", 3},
                            {"width", 4}, {"length", 10}};
  const Scene s = scene_from_json(testing::crevassed_ice_scene(3, c), "crevassed3d.json");
  const CrevasseField& f = *s.bodies[0].crevasses;
  ASSERT_EQ(f.count(), 4);
  auto in_crevasse = [&](double x, double y, double z) {
    for (int i = 0; i < f.count(); ++i)
      if (std::abs(x - f.centre(i, y)) < 2 && z > 20 - f.depth_at(i, y)) return true;
    return false;
  };
  Simulation<3> sim(s);
  for (size_t q = 0; q < sim.particles.size(); ++q) {
    const auto& x = sim.particles.x[q];
    ASSERT_FALSE(in_crevasse(x[0], x[1], x[2])) << "particle " << q << " in a crevasse";
  }
  size_t lattice = 0;
  for (int i = 1; i < 41; ++i)
    for (int j = 0; j < 10; ++j)
      for (int k = 0; k < 10; ++k) lattice += !in_crevasse(2 * i + 1, 2 * j + 1, 2 * k + 1);
  EXPECT_EQ(sim.particles.size(), lattice);
  double spread_depth = 0, spread_x = 0;
  for (int i = 0; i < f.count(); ++i) {
    double dlo = 1e9, dhi = -1e9, xlo = 1e9, xhi = -1e9;
    for (double y = 0; y <= 20; y += 0.5) {
      dlo = std::min(dlo, f.depth_at(i, y)), dhi = std::max(dhi, f.depth_at(i, y));
      xlo = std::min(xlo, f.centre(i, y)), xhi = std::max(xhi, f.centre(i, y));
    }
    spread_depth = std::max(spread_depth, dhi - dlo);
    spread_x = std::max(spread_x, xhi - xlo);
  }
  EXPECT_GT(spread_depth, 1.0);  // a standard deviation of 3 m
  EXPECT_GT(spread_x, 0.5);
  // Statistics over every crevasse and station, as in 2D (exact by the standardisation; none clipped).
  std::vector<double> depths;
  for (const auto& k : f.stations()) {
    depths.push_back(k.depth);
    EXPECT_FALSE(k.clipped);
  }
  EXPECT_EQ(depths.size(), 4u * 8u);  // stations every length / 4 = 2.5 m along 20 m
  EXPECT_NEAR(moments(depths).mean, 8, 8e-9);
  EXPECT_NEAR(moments(depths).std, 3, 3e-9);
}

// Each bad value is refused with its path in the message.
TEST(Crevasses, BadKeysAreRefusedNamingTheKey) {
  const nlohmann::json good = {{"seed", 1}, {"spacing", 40}, {"depth", 30}, {"depth_std", 10}, {"width", 4}};
  struct Case {
    std::string key;
    nlohmann::json value;
    std::string path;
  };
  const std::vector<Case> cases = {{"colour", "blue", "bodies[0].crevasses"},
                                   {"depth", -1, "bodies[0].crevasses.depth"},
                                   {"depth", 95, "bodies[0].crevasses.depth"},  // beyond max_depth (0.9 x 100 m)
                                   {"depth_std", -1, "bodies[0].crevasses.depth_std"},
                                   {"spacing", 0, "bodies[0].crevasses.spacing"},
                                   {"spacing", -40, "bodies[0].crevasses.spacing"},
                                   {"spacing_std", -1, "bodies[0].crevasses.spacing_std"},
                                   {"width", 40, "bodies[0].crevasses.width"},
                                   {"seed", 1.5, "bodies[0].crevasses.seed"},
                                   {"region", {300, 200}, "bodies[0].crevasses.region"},
                                   {"region", {0, 500}, "bodies[0].crevasses.region"},
                                   {"max_depth", 100, "bodies[0].crevasses.max_depth"},
                                   {"length", 10, "bodies[0].crevasses"},  // 3D only
                                   {"spacing", 1e-4, "bodies[0].crevasses"},  // 4 million crevasses
                                   {"water_depth", -1, "bodies[0].crevasses.water_depth"},
                                   {"water_depth", 20, "bodies[0].crevasses"},  // no water_material
                                   {"water_material", "ice", "bodies[0].crevasses.water_material"}};  // not a fluid
  for (const auto& c : cases) {
    nlohmann::json cr = good;
    cr[c.key] = c.value;
    if (c.key == "spacing" && c.value.get<double>() > 0) cr["width"] = 5e-5;
    try {
      scene_from_json(testing::crevassed_ice_scene(2, cr), "bad.json");
      ADD_FAILURE() << c.key << " = " << c.value.dump() << " accepted";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("bad.json: " + c.path), std::string::npos) << e.what();
    }
  }
  nlohmann::json missing = good;
  missing.erase("spacing");
  EXPECT_THROW(scene_from_json(testing::crevassed_ice_scene(2, missing), "bad.json"), SceneError);
  try {
    scene_from_json(testing::crevassed_ice_scene(2, good, "water"), "bad.json");
    ADD_FAILURE() << "crevasses accepted on a water body";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.json: bodies[0].crevasses"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace cdmpm
