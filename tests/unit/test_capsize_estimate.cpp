// test_capsize_estimate.cpp - the inviscid capsize estimate of a floating ice slab (validation/capsize.h,
// docs/validation.md#capsizing-slabs): its moment matches the metacentric height at small angles and changes sign at
// the stability limit w/h = 0.752. The capsizing runs: tests/validation/test_capsize.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "scene/scene_loader.h"
#include "sim/simulation.h"
#include "validation/capsize.h"

namespace cdmpm {
namespace {

// Hydrostatics of the estimate: the moment's slope at zero is -rho_w g A GM (the metacentric height of Archimedes'
// floating body), and GM changes sign at w/h = sqrt(6 (d/h)(1 - d/h)).
TEST(CapsizeEstimate, MomentMatchesTheMetacentricHeight) {
  for (double aspect : {0.5, 0.6, 0.75, 0.9, 1.2}) {
    const capsize::Slab s{aspect, 1.0, 917, 1025};
    const double th = 1e-4;
    const double slope = -s.rho_water * s.g * s.submerged_area() * s.metacentric_height();
    EXPECT_NEAR(s.moment(th) / th, slope, 1e-3 * std::abs(slope) + 1e-6) << "w/h = " << aspect;
    EXPECT_NEAR(s.moment(-th), -s.moment(th), 1e-9) << "mirror symmetry";
  }
  const double r = 917.0 / 1025.0, limit = std::sqrt(6 * r * (1 - r));
  EXPECT_LT(capsize::Slab({limit - 1e-3, 1.0, 917, 1025}).metacentric_height(), 0);
  EXPECT_GT(capsize::Slab({limit + 1e-3, 1.0, 917, 1025}).metacentric_height(), 0);
  // Turned by 180 degrees the slab is upright again: no moment.
  const capsize::Slab s{0.6, 1.0, 917, 1025};
  EXPECT_NEAR(s.moment(std::numbers::pi), 0, 1e-6 * s.rho_water * s.g * s.submerged_area());
}

}  // namespace
}  // namespace cdmpm
