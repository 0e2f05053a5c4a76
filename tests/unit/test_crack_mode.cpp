// test_crack_mode.cpp - the crack-start record (probe/crack_starts.h) and the shear strength of the ice model:
//   CrackMode      the mode rule on the reference stress states; the record's checkpoint form.
//   ShearStrength  the pure-shear strength of the yield surface (cohesive_cam_clay.h shear_strength) and its
//                  von Mises limits against the uniaxial tensile strength.
// The runs that record crack starts: tests/engine/test_crack_starts.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <string>

#include "cli_helpers.h"
#include "material/stress.h"
#include "probe/crack_starts.h"
#include "scene/scene_loader.h"
#include "sim/simulation.h"

namespace cdmpm {
namespace {

// ---- the mode rule --------------------------------------------------------------------------------------------

// p, q of a Cauchy stress in the record's convention.
template <int dim>
CrackMode mode_of(const Mat<dim>& s) {
  double p = 0, q = 0, s1 = 0;
  stress_state<dim>(s, p, q, s1);
  return crack_mode(p, q, dim);
}

TEST(CrackMode, ReferenceStatesOfTheRule) {
  const double t = 1e6;
  // Uniaxial tension, hydrostatic tension (the tensile tip): tension. Pure shear, uniaxial compression: shear.
  EXPECT_EQ(mode_of<2>((Mat<2>() << t, 0, 0, 0).finished()), CrackMode::tension);
  EXPECT_EQ(mode_of<2>((Mat<2>() << t, 0, 0, t).finished()), CrackMode::tension);
  EXPECT_EQ(mode_of<2>((Mat<2>() << 0, t, t, 0).finished()), CrackMode::shear);
  EXPECT_EQ(mode_of<2>((Mat<2>() << -t, 0, 0, 0).finished()), CrackMode::shear);
  EXPECT_EQ(mode_of<3>((Mat<3>() << t, 0, 0, 0, 0, 0, 0, 0, 0).finished()), CrackMode::tension);
  EXPECT_EQ(mode_of<3>((Mat<3>() << 0, t, 0, t, 0, 0, 0, 0, 0).finished()), CrackMode::shear);
  // The dividing line in 2D is sigma_2 = -sigma_1 / 3 (halfway in triaxiality between pure shear and uniaxial
  // tension): just above it tension, just below it shear.
  EXPECT_EQ(mode_of<2>((Mat<2>() << t, 0, 0, -0.33 * t).finished()), CrackMode::tension);
  EXPECT_EQ(mode_of<2>((Mat<2>() << t, 0, 0, -0.34 * t).finished()), CrackMode::shear);
  // sigma_1 is the largest principal stress: a pure shear t has sigma_1 = t; p is positive in compression.
  double p = 0, q = 0, s1 = 0;
  stress_state<2>((Mat<2>() << 0, t, t, 0).finished(), p, q, s1);
  EXPECT_NEAR(s1, t, 1e-9 * t);
  EXPECT_NEAR(q, std::sqrt(3.0) * t, 1e-9 * t);
  stress_state<3>((Mat<3>() << -t, 0, 0, 0, -t, 0, 0, 0, -t).finished(), p, q, s1);
  EXPECT_NEAR(p, t, 1e-9 * t);
  EXPECT_NEAR(s1, -t, 1e-9 * t);
}

TEST(CrackMode, RecordSavesAndLoadsAndRefusesBadRecords) {
  CrackStartRecord<2> a;
  std::vector<double> v = {12, 0.5, 7, 1.25, 2.5, -3e5, 4e5, 6e5, 1, 13, 0.625, 9, 0.5, 0.75, 1e5, 2e5, 3e5, 0};
  ASSERT_TRUE(a.load(v));
  ASSERT_EQ(a.events().size(), 2u);
  EXPECT_EQ(a.events()[0].mode, CrackMode::shear);
  EXPECT_EQ(a.events()[1].id, 9u);
  EXPECT_EQ(a.save(), v);
  std::vector<double> bad = v;
  bad[8] = 2;  // a mode other than 0 / 1
  EXPECT_FALSE(a.load(bad));
  bad = v;
  bad.pop_back();  // not whole events
  EXPECT_FALSE(a.load(bad));
  bad = v;
  bad[3] = std::nan("");
  EXPECT_FALSE(a.load(bad));
  EXPECT_EQ(a.save(), v);  // a refused record leaves the record unchanged
}

// ---- the shear strength of the yield surface -------------------------------------------------------------------

TEST(ShearStrength, LiesOnTheYieldSurfaceAndHasTheVonMisesLimits) {
  CohesiveCamClay c;
  for (double M : {0.3, 1.0, 1.85})
    for (double beta : {0.05, 0.3, 1.0}) {
      c.M = M;
      c.beta = beta;
      const double p0 = 1e7, ts = c.shear_strength(p0);
      // p = 0, q = sqrt(3) tau_s is on the surface: y = 0 to rounding (y scales as p0^2 M^2).
      EXPECT_NEAR(c.yield(0, std::sqrt(3.0) * ts, p0), 0, 1e-12 * M * M * p0 * p0) << M << ' ' << beta;
      // The same through the invariants of the stress tensor itself.
      Mat<2> tau = Mat<2>::Zero();
      tau(0, 1) = tau(1, 0) = ts;
      EXPECT_NEAR(CohesiveCamClay{}.mises<2>(tau), std::sqrt(3.0) * ts, 1e-12 * ts);
    }
  // von Mises limit (M -> 0): tau_s / sigma_t -> 1/2 in 2D (the in-plane convention), 1/sqrt(3) in 3D. The
  // correction is of order the strength over p0, i.e. M: M = 1e-4 leaves it below 1e-3.
  c.M = 1e-4;
  c.beta = 0.3;
  EXPECT_NEAR(c.shear_strength(1) / c.uniaxial_strength<2>(1, true), 0.5, 1e-3);
  EXPECT_NEAR(c.shear_strength(1) / c.uniaxial_strength<3>(1, true), 1 / std::sqrt(3.0), 1e-3);
  // Away from it the ratio rises: the scenes' ice (M = 1.85, beta = 0.1) is 1.68 in 2D (docs/ice.md).
  c.M = 1.85;
  c.beta = 0.1;
  EXPECT_GT(c.shear_strength(1) / c.uniaxial_strength<2>(1, true), 1.6);
}

}  // namespace
}  // namespace cdmpm
