// test_boundary.cpp - boundary conditions on grid nodes (boundary/boundary.h): moving boxes follow their
// prescribed kinematics (linear velocity ramp, then constant velocity) and impose the condition on the
// velocity relative to the box; nodes on a box edge or corner get the condition of every nearest face.
#include <gtest/gtest.h>

#include "boundary/boundary.h"

namespace cdmpm {
namespace {

BoundarySpec box(BoundaryCondition c, std::vector<double> velocity = {0, 0}, double ramp = 0) {
  BoundarySpec s;
  s.type = "box";
  s.condition = c;
  s.min = {0, 0};
  s.max = {1, 1};
  s.velocity = velocity;
  s.ramp_time = ramp;
  return s;
}

TEST(BoxObstacle, StickyMovingBoxDragsNodesWithItsRampedVelocity) {
  auto b = make_boundary<2>(box(BoundaryCondition::Sticky, {2, 0}, 4), Vec<2>(10, 10));
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
  auto b = make_boundary<2>(box(BoundaryCondition::Separate, {3, 0}), Vec<2>(10, 10));
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
  auto b = make_boundary<2>(box(BoundaryCondition::Separate), Vec<2>(10, 10));
  Vec<2> v(-1, -1);  // into the box through its top-right corner
  b->apply(Vec<2>(1.0, 1.0), v);
  EXPECT_EQ(v, Vec<2>(0, 0));
  v = Vec<2>(-1, -1);  // on the top face only: only the normal (y) component is removed
  b->apply(Vec<2>(0.5, 1.0), v);
  EXPECT_EQ(v, Vec<2>(-1, 0));
}

}  // namespace
}  // namespace cdmpm
