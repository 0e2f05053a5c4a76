// test_water.cpp - Tait equation of state: pressure is minus the derivative of the stored energy,
// the hydrostatic pre-compression inverts the pressure law, and the acoustic speed is sqrt(dp/drho).
// Tolerances scale with the unit roundoff eps of Real. The two finite-difference checks need double
// precision: in float the energy K/gamma [...] loses its significant digits to cancellation near J = 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <type_traits>

#include "material/weakly_compressible_water.h"

namespace cdmpm {
namespace {

constexpr double kEps = std::numeric_limits<Real>::epsilon();
#define SKIP_IF_FLOAT()                          \
  if constexpr (!std::is_same_v<Real, double>) \
  GTEST_SKIP() << "finite differences of the Tait energy need double precision"

TEST(WeaklyCompressibleWater, PressureIsMinusEnergyDerivative) {
  SKIP_IF_FLOAT();
  const WeaklyCompressibleWater w{1000, 2e5, 7, 0};
  for (double J : {0.97, 0.99, 1.0, 1.01, 1.05}) {
    const double h = 1e-6;
    const double fd = -(w.energy_density(Real(J + h)) - w.energy_density(Real(J - h))) / (2 * h);
    EXPECT_NEAR(fd, w.pressure(Real(J)), 1e-6 * w.K) << "J = " << J;
  }
  EXPECT_EQ(w.pressure(1), 0);
  EXPECT_EQ(w.energy_density(1), 0);
}

TEST(WeaklyCompressibleWater, PreCompressionInvertsPressure) {
  const WeaklyCompressibleWater w{1000, 1e6, 7, 0};
  // The round trip loses a few ulps of J, each worth K ulp(J) ~ K eps of pressure.
  for (double p : {0.0, 1e3, 1e4, 5e4})
    EXPECT_NEAR(w.pressure(w.volume_ratio_at_pressure(Real(p))), p, std::max(1e-9, 64 * kEps) * w.K);
}

TEST(WeaklyCompressibleWater, WaveSpeedIsSqrtDpDrho) {
  SKIP_IF_FLOAT();
  const WeaklyCompressibleWater w{1000, 1e6, 7, 0};
  for (double J : {0.98, 0.99, 0.999}) {  // compressed states; at J >= 1 the pressure is cut off at 0
    // rho = rho0 / J; dp/drho = dp/dJ * dJ/drho = p'(J) * (-J^2 / rho0)
    const double h = 1e-7;
    const double dpdJ = (w.pressure(Real(J + h)) - w.pressure(Real(J - h))) / (2 * h);
    const double c2 = -dpdJ * J * J / w.rho0;
    EXPECT_NEAR(w.wave_speed(Real(J)), std::sqrt(c2), 1e-5 * std::sqrt(c2));
  }
}

TEST(WeaklyCompressibleWater, NoTensionBeyondTheReferenceVolume) {
  const WeaklyCompressibleWater w{1000, 1e6, 7, 0};
  for (double J : {1.0, 1.001, 1.5}) {
    EXPECT_EQ(w.pressure(Real(J)), 0);
    EXPECT_EQ(w.energy_density(Real(J)), 0);
  }
  EXPECT_GT(w.pressure(Real(0.999)), 0);
  EXPECT_GT(w.energy_density(Real(0.999)), 0);
}

TEST(WeaklyCompressibleWater, ViscousStressIsDeviatoricAndSymmetric) {
  const WeaklyCompressibleWater w{1000, 1e6, 7, 1e-3};
  Mat<2> C;
  C << 0.3, 1.0, -0.2, 0.5;
  const Mat<2> tau = w.kirchhoff<2>(1, C);
  const double tol = 8 * kEps * 1e-3;  // a few roundings of numbers of size mu |C| = 1e-3
  EXPECT_NEAR(tau.trace(), 0, tol);  // J = 1: no pressure, viscous part traceless
  EXPECT_NEAR(tau(0, 1), tau(1, 0), tol);
  EXPECT_NEAR(tau(0, 1), 2 * 1e-3 * 0.5 * (1.0 - 0.2), tol);
}

}  // namespace
}  // namespace cdmpm
