// test_bspline.cpp - quadratic B-spline weights: partition of unity and linear reproduction.
#include <gtest/gtest.h>

#include <random>

#include "core/bspline.h"

namespace cdmpm {
namespace {

template <int dim>
void check_partition_and_linear() {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 50.0);
  const Real tol = std::numeric_limits<Real>::epsilon() * 200;
  for (int trial = 0; trial < 1000; ++trial) {
    Vec<dim> x;
    for (int a = 0; a < dim; ++a) x[a] = static_cast<Real>(u(rng));
    const BSplineStencil<dim> s(x);
    Real sum = 0;
    Vec<dim> first = Vec<dim>::Zero();
    Mat<dim> second = Mat<dim>::Zero();
    for_each_stencil_node<dim>([&](const IVec<dim>& o) {
      const Real w = s.weight(o);
      EXPECT_GE(w, 0);
      sum += w;
      first += w * (s.base + o).template cast<Real>();
      second += w * s.offset(o) * s.offset(o).transpose();
    });
    EXPECT_NEAR(sum, 1, tol);
    for (int a = 0; a < dim; ++a) EXPECT_NEAR(first[a], x[a], tol * 50);  // sum_i w_i x_i = x_p
    // Second moment sum_i w_i (x_i - x_p)(x_i - x_p)^T = I/4 (in units of dx^2): the APIC D matrix.
    EXPECT_TRUE(second.isApprox(Mat<dim>::Identity() / 4, tol * 10)) << second;
  }
}

TEST(BSpline, PartitionOfUnityAndLinearReproduction2D) { check_partition_and_linear<2>(); }
TEST(BSpline, PartitionOfUnityAndLinearReproduction3D) { check_partition_and_linear<3>(); }

TEST(BSpline, KernelValues) {
  EXPECT_DOUBLE_EQ(bspline_kernel(0), 0.75);
  EXPECT_DOUBLE_EQ(bspline_kernel(0.5), 0.5);
  EXPECT_DOUBLE_EQ(bspline_kernel(-1.0), 0.125);
  EXPECT_DOUBLE_EQ(bspline_kernel(1.5), 0.0);
}

}  // namespace
}  // namespace cdmpm
