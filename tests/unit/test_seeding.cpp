// test_seeding.cpp - seeding asks the boundaries what is solid (sim/seeding.h): a box of water over a sloping
// bathymetry leaves the terrain empty (every lattice point below the profile, and only those, is left out), a
// half-plane does the same (bounded by `within`, only inside its box), and a moving box obstacle (a grip) keeps
// the material seeded inside it. A 3D prism (shape/prism.h) is seeded at exactly the lattice points inside its
// x-z section and its y range. Material seeded within a cell of a wall face that lies between two grid planes is
// refused, naming the face, the body and the sizes on the grid on either side. A rigid body seeded under water
// (its particles carry the water's column pressure) weighs its density times its volume.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "scene/scene_loader.h"
#include "sim/simulation.h"

namespace cdmpm {
namespace {

nlohmann::json pool(const nlohmann::json& boundary) {
  return {{"dim", 2},
          {"domain", {{"size", {10.0, 10.0}}, {"dx", 0.5}}},
          {"time", {{"end", 0.1}, {"frame_interval", 0.1}}},
          {"materials", {{"water", {{"type", "water"}, {"density", 1000}, {"bulk_modulus", 1e6}}}}},
          {"bodies", {{{"material", "water"}, {"particles_per_cell", 4},
                       {"shape", {{"type", "box"}, {"min", {0.0, 0.0}}, {"max", {10.0, 6.0}}}}}}},
          {"boundaries", {{{"type", "walls"}}, boundary}}};
}

// The message with which loading J fails (with `seed`, loading it and building its 2D simulation, which seeds it);
// empty if it does not fail.
std::string refusal(const nlohmann::json& j, bool seed = false) {
  try {
    const Scene s = scene_from_json(j, "refused.json");
    if (seed) {
      const Simulation<2> sim(s);
    }
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

// Lattice points (k + 1/2) h of the 10 x 6 box with h = 0.25 for which `solid` holds.
template <class F>
size_t lattice_count(F&& solid) {
  size_t n = 0;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 24; ++j) n += !solid((i + 0.5) * 0.25, (j + 0.5) * 0.25);
  return n;
}

TEST(Seeding, MaterialAgainstAWallFaceOffTheGridIsRefused) {
  // x+ at 10.25 m, 20.5 cells of 0.5 m: the wall acts on the nodes from 10.5 m, the particles stop at 10.25 m.
  nlohmann::json j = pool({{"type", "walls"}, {"faces", {"x-", "x+", "y-"}}});
  j["boundaries"].erase(0);  // pool()'s own walls (all faces)
  j["domain"]["size"] = {10.25, 10.0};
  j["bodies"][0]["shape"]["max"] = {10.25, 6.0};
  const std::string touching = refusal(j, true);
  EXPECT_NE(touching.find("refused.json: boundaries[0].faces[1]: the wall face \"x+\" lies at domain.size[0] = 10.25 m, "
                          "20.5 cells of dx = 0.5 m, and bodies[0] is seeded within a cell of it"),
            std::string::npos)
      << touching;
  EXPECT_NE(touching.find("(10 or 10.5 m)"), std::string::npos) << touching;
  // All faces by default: the walls object is named.
  j["boundaries"][0].erase("faces");
  EXPECT_NE(refusal(j, true).find("refused.json: boundaries[0]: the wall face \"x+\""), std::string::npos);
  // Material more than a cell from the face, or an off-grid face no material touches (y+ at 10.25 m, a lid over
  // water 6 m deep), is accepted; so is the face on a grid plane.
  j["bodies"][0]["shape"]["max"] = {9.5, 6.0};
  EXPECT_EQ(refusal(j, true), "");
  j["domain"]["size"] = {10.0, 10.25};
  j["bodies"][0]["shape"]["max"] = {10.0, 6.0};
  EXPECT_EQ(refusal(j, true), "");
}

TEST(Seeding, WaterOverSlopingBathymetryLeavesTheTerrainEmpty) {
  // Bed rising from 1 m at x = 0 to 4 m at x = 10: h(x) = 1 + 0.3 x.
  const Scene s = scene_from_json(pool({{"type", "bathymetry"}, {"points", {{0, 1}, {10, 4}}}}), "slope.json");
  Simulation<2> sim(s);
  for (size_t q = 0; q < sim.particles.size(); ++q) {
    const auto& x = sim.particles.x[q];
    ASSERT_GE(x[1], 1 + 0.3 * x[0]) << "particle " << q << " inside the terrain";
  }
  EXPECT_EQ(sim.particles.size(), lattice_count([](double x, double y) { return y < 1 + 0.3 * x; }));
}

TEST(Seeding, HalfPlaneLeavesItsSolidSideEmpty) {
  // Solid where (x - (5, 0)) . (-1, 1)/sqrt(2) < 0, i.e. y < x - 5.
  const Scene s = scene_from_json(pool({{"type", "half_plane"}, {"point", {5, 0}}, {"normal", {-1, 1}}}), "plane.json");
  Simulation<2> sim(s);
  EXPECT_EQ(sim.particles.size(), lattice_count([](double x, double y) { return y < x - 5; }));
}

TEST(Seeding, HalfPlaneWithinABoxIsSolidOnlyThere) {
  // The same plane, y < x - 5, bounded to x <= 8: beyond x = 8 the water is seeded down to the bed.
  const Scene s = scene_from_json(pool({{"type", "half_plane"}, {"point", {5, 0}}, {"normal", {-1, 1}},
                                        {"within", {{"min", {0, 0}}, {"max", {8, 10}}}}}), "bounded.json");
  Simulation<2> sim(s);
  EXPECT_EQ(sim.particles.size(), lattice_count([](double x, double y) { return x <= 8 && y < x - 5; }));
  // The grid condition acts inside the box only: a node below the plane beyond it keeps its velocity.
  Vec<2> v(1, -1);
  sim.boundaries.back()->apply(Vec<2>(9, 1), v);
  EXPECT_EQ(v, Vec<2>(1, -1));
  sim.boundaries.back()->apply(Vec<2>(7, 1), v);
  EXPECT_NE(v, Vec<2>(1, -1));
}

TEST(Seeding, MovingBoxKeepsTheMaterialItGrips) {
  nlohmann::json grip = {{"type", "box"}, {"condition", "sticky"}, {"min", {2, 2}}, {"max", {4, 4}}, {"velocity", {1, 0}}};
  Simulation<2> moving(scene_from_json(pool(grip), "grip.json"));
  EXPECT_EQ(moving.particles.size(), lattice_count([](double, double) { return false; }));
  grip.erase("velocity");
  Simulation<2> fixed(scene_from_json(pool(grip), "fixed.json"));
  EXPECT_EQ(fixed.particles.size(), lattice_count([](double x, double y) { return x > 2 && x < 4 && y > 2 && y < 4; }));
}

TEST(Seeding, PrismIsItsSectionExtrudedAlongY) {
  // Section: the triangle (2, 1), (8, 1), (2, 7) in (x, z), i.e. x > 2, z > 1, x + z < 9; y in [1, 3].
  nlohmann::json j = pool({{"type", "walls"}});
  j["dim"] = 3;
  j["domain"]["size"] = {10.0, 4.0, 10.0};
  j["bodies"][0]["particles_per_cell"] = 8;
  j["bodies"][0]["shape"] = {{"type", "prism"}, {"vertices", {{2, 1}, {8, 1}, {2, 7}}}, {"y", {1, 3}}};
  Simulation<3> sim(scene_from_json(j, "prism.json"));
  size_t expected = 0;  // lattice (k + 1/2) h, h = 0.25
  for (int i = 0; i < 40; ++i)
    for (int k = 0; k < 40; ++k) {
      const double x = (i + 0.5) * 0.25, z = (k + 0.5) * 0.25;
      expected += (x > 2 && z > 1 && x + z < 9) ? 8 : 0;  // y in [1, 3]: 8 lattice rows
    }
  EXPECT_EQ(sim.particles.size(), expected);
  // The seeded volume is the prism's, 18 m2 x 2 m, to the lattice's resolution of the slanted face.
  EXPECT_NEAR(sim.particles.size() * 0.25 * 0.25 * 0.25, 36.0, 0.5 * 6 * std::sqrt(2.0) * 2 * 0.25);
  for (size_t q = 0; q < sim.particles.size(); ++q) {
    const auto& x = sim.particles.x[q];
    ASSERT_TRUE(x[1] > 1 && x[1] < 3) << "particle " << q;
  }
  // A prism is a 3D shape: a 2D scene refuses it, naming the key.
  nlohmann::json flat = pool({{"type", "walls"}});
  flat["bodies"][0]["shape"] = j["bodies"][0]["shape"];
  EXPECT_NE(refusal(flat).find("bodies[0].shape.type"), std::string::npos);
  j["bodies"][0]["shape"]["y"] = {3, 1};
  EXPECT_NE(refusal(j).find("bodies[0].shape.y"), std::string::npos);
  // Its section is read as the polygon's: collinear vertices enclose no area.
  j["bodies"][0]["shape"]["y"] = {1, 3};
  j["bodies"][0]["shape"]["vertices"] = {{1, 1}, {2, 2}, {3, 3}};
  const std::string zero = refusal(j);
  EXPECT_NE(zero.find("bodies[0].shape.vertices"), std::string::npos) << zero;
  EXPECT_NE(zero.find("nonzero area"), std::string::npos) << zero;
}

// A rigid block of density rho_b under deep, soft water (K = 1e5 Pa, its top 3 m under the surface) is seeded with the water's pressure in its particles (their J < 1), and
// with its own mass rho_b V: its particles fill V = 1 m x 1 m on the lattice, so their masses sum to rho_b V to
// round-off, with and without a surface level above it (without one, the column is its own).
TEST(Seeding, RigidBodyUnderWaterWeighsItsDensityTimesItsVolume) {
  nlohmann::json j = pool({{"type", "walls"}});
  j["materials"]["water"]["bulk_modulus"] = 1e5;
  const double rho_b = 920, volume = 1.0;
  j["materials"]["block"] = {{"type", "rigid"}, {"density", rho_b}, {"bulk_modulus", 1e5}};
  j["bodies"].push_back({{"material", "block"}, {"particles_per_cell", 4}, {"surface_level", 6.0},
                         {"shape", {{"type", "box"}, {"min", {4.5, 2.0}}, {"max", {5.5, 3.0}}}}});
  for (const bool level : {true, false}) {
    if (!level) j["bodies"][1].erase("surface_level");
    const Scene scene = scene_from_json(j, "rigid.json");
    const auto block = static_cast<MaterialId>(scene.material_index("block"));
    const Simulation<2> sim(scene);
    double mass = 0, J_min = 1;
    size_t n = 0;
    for (size_t q = 0; q < sim.particles.size(); ++q)
      if (sim.particles.material[q] == block) {
        mass += sim.particles.mass[q];
        J_min = std::min(J_min, static_cast<double>(sim.particles.J[q]));
        ++n;
      }
    ASSERT_EQ(n, 16u);  // 4 x 4 particles of spacing 0.25 m
    EXPECT_LT(J_min, 0.97);  // compressed (Tait, gamma = 7): the body does carry a column pressure
    EXPECT_NEAR(mass, rho_b * volume, 64 * std::numeric_limits<Real>::epsilon() * rho_b * volume) << "surface level " << level;
  }
}

}  // namespace
}  // namespace cdmpm
