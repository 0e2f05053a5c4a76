// test_failure_plane.cpp - failure width and failure-plane dip of a calved block (probe/failure_plane.h), on
// blocks of known geometry: the wedge of a cliff collapse as Luethi & Vieli (2016) describe Eqip Sermia's (a crack
// 75 m behind the front at the surface, dipping 54 degrees down to the front), a vertical slab, its mirror image,
// the same wedge extruded along the front in 3D, and a block too thin to fit a plane; and blocks behind a crevasse,
// cut along known planes (45, 60, 80 degrees) from the crevasse's tip down, beside a band of broken ice: the fit
// keeps the crack and leaves out the crevasse's wall above it (fitted with it, the dip reads steeper).
//
// Tolerances from the sampling: the block is a lattice of particles at spacing h, so each row's edge is the exact
// crack position to within h, and the top's extent to within h. Over the wedge's height Z (103 m) a least-squares
// slope through rows whose edges are off by at most h is off by at most 2 h / Z in slope, i.e.
// 2 h / Z * sin^2(54 deg) radians in dip: 0.5 degrees for h = 1.25 m; the test allows 1 degree.
#include <gtest/gtest.h>

#include <cmath>

#include "probe/failure_plane.h"

namespace cdmpm {
// Named, not anonymous: its constants (g, dx, h, ...) have the names of other test files' constants, and a unity
// batch shares the anonymous namespace of its files.
namespace failure_plane_test {

constexpr Real dx = 2.5, h = 1.25;  // two particles per cell per axis
constexpr double top = 200, width = 75, dip = 54;

// Back edge of the wedge at height z (the front is at x = 0, the glacier at x < 0), mirrored by `side`.
double crack_x(double z) { return -width + (top - z) / std::tan(dip * M_PI / 180); }

template <int dim>
std::vector<Vec<dim>> wedge(int side, double cross_width = 0) {
  std::vector<Vec<dim>> x;
  const double z0 = top - width * std::tan(dip * M_PI / 180);
  for (double z = z0 + h / 2; z < top; z += h)
    for (double s = -width + h / 2; s < 0; s += h) {
      if (s < crack_x(z)) continue;
      for (double y = h / 2; y < std::max(cross_width, h); y += h) {
        Vec<dim> p;
        p[0] = side < 0 ? s : -s;
        p[dim - 1] = z;
        if (dim == 3) p[1] = y;
        x.push_back(p);
      }
    }
  return x;
}

TEST(FailurePlane, WedgeOfACliffCollapseGivesItsDipAndTopWidth) {
  for (int side : {-1, 1}) {
    const FailureGeometry g = failure_geometry<2>(wedge<2>(side), dx, h, 0, side);
    EXPECT_NEAR(g.angle, dip, 1.0) << "glacier side " << side;
    EXPECT_NEAR(g.width, width, h) << "glacier side " << side;
  }
}

TEST(FailurePlane, WedgeExtrudedAlongTheFrontIn3D) {
  const FailureGeometry g = failure_geometry<3>(wedge<3>(-1, 20.0), dx, h, 0, -1);
  EXPECT_NEAR(g.angle, dip, 1.0);
  EXPECT_NEAR(g.width, width, h);
}

TEST(FailurePlane, VerticalSlabDipsNinetyDegrees) {
  std::vector<Vec<2>> x;
  for (double z = h / 2; z < 100; z += h)
    for (double s = h / 2; s < 30; s += h) x.push_back(Vec<2>(s, z));
  const FailureGeometry g = failure_geometry<2>(x, dx, h, 0, -1);
  EXPECT_NEAR(g.angle, 90.0, 1e-9);
  EXPECT_NEAR(g.width, 30.0, 1e-9);
}

// A block behind a crevasse: the crevasse (the glacier at x < 0, the front at x = 0) stands at x = -60 m from the top
// (200 m) down to its tip at 140 m; below, the block broke off along a plane dipping `angle` from the tip towards the
// front, to the bed (z = 0) or the front. The broken ice is a band two particles wide beyond that plane.
struct CutBlock {
  std::vector<Vec<2>> block, band;
};
CutBlock cut_block(double angle) {
  constexpr double W = 60, tip = 140;
  const double t = std::tan(angle * M_PI / 180);
  auto crack = [&](double z) { return z >= tip ? -W : -W + (tip - z) / t; };
  CutBlock c;
  const double bottom = std::max(0.0, tip - W * t);
  for (double z = bottom + h / 2; z < top; z += h) {
    for (double s = -W + h / 2; s < 0; s += h)
      if (s >= crack(z)) c.block.push_back(Vec<2>(s, z));
    if (z < tip)
      for (int k = 1; k <= 2; ++k) c.band.push_back(Vec<2>(crack(z) - k * h, z));
  }
  return c;
}

TEST(FailurePlane, CutBehindACrevasseFitsTheCrackNotTheWall) {
  for (const double angle : {45.0, 60.0, 80.0}) {
    const CutBlock c = cut_block(angle);
    const FailureGeometry g = failure_geometry<2>(c.block, dx, h, 0, -1, c.band);
    EXPECT_TRUE(g.band_only);
    EXPECT_NEAR(g.angle, angle, 1.0) << "cut at " << angle << " degrees";
    EXPECT_NEAR(g.width, 60.0, h);
    // The whole edge, wall included, reads steeper.
    const FailureGeometry whole = failure_geometry<2>(c.block, dx, h, 0, -1);
    EXPECT_FALSE(whole.band_only);
    if (angle < 80) EXPECT_GT(whole.angle, angle + 5) << "cut at " << angle << " degrees";
  }
}

TEST(FailurePlane, BlockOfOneRowHasNoPlane) {
  std::vector<Vec<2>> x;
  for (double s = h / 2; s < 30; s += h) x.push_back(Vec<2>(s, 0.5));
  const FailureGeometry g = failure_geometry<2>(x, dx, h, 0, -1);
  EXPECT_TRUE(std::isnan(g.angle));
  EXPECT_TRUE(std::isnan(g.width));
}

}  // namespace failure_plane_test
}  // namespace cdmpm
