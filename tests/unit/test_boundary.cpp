// test_boundary.cpp - boundary conditions on grid nodes (boundary/boundary.h): moving boxes follow their
// prescribed kinematics (linear velocity ramp, then constant velocity) and impose the condition on the
// velocity relative to the box; nodes on a box edge or corner get the condition of every nearest face;
// a node on a face that lies on a grid plane gets the condition despite the rounding of its coordinate. Still
// water beside a box: tests/engine/test_boundary_still_water.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "boundary/boundary.h"
#include "material/stress.h"
#include "scene/scene_loader.h"
#include "sim/simulation.h"

namespace cdmpm {
namespace {

// A 2D boundary built from its scene object, as the loader and the simulation build it.
std::unique_ptr<Boundary<2>> make(const nlohmann::json& j, const Vec<2>& size, Real dx) {
  SceneReader r("test.json", 2);
  r.set_domain({size[0], size[1]});
  return make_boundary<2>(r, Node{j, "boundaries[0]"}, BoundaryContext<2>{size, dx});
}

nlohmann::json box(const std::string& condition, std::vector<double> velocity = {0, 0}, double ramp = 0) {
  return {{"type", "box"}, {"condition", condition}, {"min", {0, 0}}, {"max", {1, 1}}, {"velocity", velocity},
          {"ramp_time", ramp}};
}

TEST(BoxObstacle, StickyMovingBoxDragsNodesWithItsRampedVelocity) {
  auto b = make(box("sticky", {2, 0}, 4), Vec<2>(10, 10), Real(0.1));
  // Ramp: u(t) = U t / T, displacement U t^2 / (2 T); after the ramp U (t - T / 2).
  b->move_to(1.0);  // u = 0.5, box spans x in [0.25, 1.25]
  Vec<2> v(7, 7);
  b->apply(Vec<2>(1.2, 0.5), v);
  EXPECT_DOUBLE_EQ(v[0], 0.5);
  EXPECT_DOUBLE_EQ(v[1], 0);
  v = Vec<2>(7, 7);
  b->apply(Vec<2>(0.2, 0.5), v);  // left behind by the box: untouched
  EXPECT_EQ(v, Vec<2>(7, 7));
  b->move_to(6.0);  // u = 2, displacement 2 (6 - 2) = 8: box spans [8, 9]
  v = Vec<2>(7, 7);
  b->apply(Vec<2>(8.5, 0.5), v);
  EXPECT_DOUBLE_EQ(v[0], 2);
  EXPECT_DOUBLE_EQ(v[1], 0);
}

TEST(BoxObstacle, SeparateConditionActsOnTheRelativeVelocity) {
  auto b = make(box("separate", {3, 0}), Vec<2>(10, 10), Real(0.1));
  b->move_to(0.0);
  // Node on the right face (normal +x), moving into the box relative to it (1 < 3): pushed to the box speed.
  Vec<2> v(1, 0.25);
  b->apply(Vec<2>(1.0, 0.5), v);
  EXPECT_DOUBLE_EQ(v[0], 3);
  EXPECT_DOUBLE_EQ(v[1], 0.25);
  // Moving away faster than the box: free to separate.
  v = Vec<2>(5, 0.25);
  b->apply(Vec<2>(1.0, 0.5), v);
  EXPECT_EQ(v, Vec<2>(5, 0.25));
}

TEST(BoxObstacle, CornerNodeIsSupportedByBothFaces) {
  auto b = make(box("separate"), Vec<2>(10, 10), Real(0.1));
  Vec<2> v(-1, -1);  // into the box through its top-right corner
  b->apply(Vec<2>(1.0, 1.0), v);
  EXPECT_EQ(v, Vec<2>(0, 0));
  v = Vec<2>(-1, -1);  // on the top face only: only the normal (y) component is removed
  b->apply(Vec<2>(0.5, 1.0), v);
  EXPECT_EQ(v, Vec<2>(-1, 0));
}

// Still water beside a static slip box: with the mirror at the box face the water next to the face must
// be in the same hydrostatic state as the water next to the (mirrored) domain wall on the other side of the
// pool; the geometry is mirror-symmetric, so the two sides agree to round-off growth, far below 1 % of
// rho g h. Without the mirror (or with the corner of box and floor left out of it) the first particle
// column next to the box settles at about half the hydrostatic pressure.
// A face placed on a grid plane holds the nodes on that plane, whichever way the rounding of i dx goes: with
// dx = H / 12 (H = 100 m) the face x = 9 H = 900 m is node 108, computed as 108 dx = 900.0000000000001 in double,
// and the wall x = 17 H = 1700 m is node 204, 1699.9999 in single precision.
TEST(BoundaryNodes, NodeOnAFaceOnAGridPlaneGetsTheConditionDespiteRounding) {
  const Real dx = Real(100.0 / 12.0);
  nlohmann::json s = box("sticky");
  s["max"] = {900, 100};
  auto bed = make(s, Vec<2>(1700, 275), dx);
  Vec<2> v(-1, -1);
  bed->apply(Vec<2>(Real(108) * dx, Real(6) * dx), v);
  EXPECT_EQ(v, Vec<2>(0, 0));
  v = Vec<2>(-1, -1);  // one node beyond the face: free
  bed->apply(Vec<2>(Real(109) * dx, Real(6) * dx), v);
  EXPECT_EQ(v, Vec<2>(-1, -1));
  auto walls = make({{"type", "walls"}, {"condition", "slip"}}, Vec<2>(1700, 275), dx);
  v = Vec<2>(1, 0.5);
  walls->apply(Vec<2>(Real(204) * dx, Real(6) * dx), v);
  EXPECT_EQ(v, Vec<2>(0, 0.5));
  v = Vec<2>(1, 0.5);  // one node inside: free
  walls->apply(Vec<2>(Real(203) * dx, Real(6) * dx), v);
  EXPECT_EQ(v, Vec<2>(1, 0.5));
}

}  // namespace
}  // namespace cdmpm
