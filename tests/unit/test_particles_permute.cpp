// test_particles_permute.cpp - the particle storage (core/particles.h): solids first, and a permutation carries the
// solid state (F, alpha) with its particles.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <stdexcept>

#include "cli_helpers.h"
#include "io/checkpoint.h"
#include "scene/scene_loader.h"
#include "sim/simulation.h"

namespace cdmpm {
namespace {

Mat<2> diag(Real a) { return Vec<2>(a, a).asDiagonal(); }

TEST(Particles, SolidsFirstAndPermuteCarriesTheSolidState) {
  // Particles are told apart by their mass k; solid k has F = k I and alpha = -k.
  Particles<2> p;
  auto fluid = [&](Real k) { p.add_fluid(Vec<2>::Constant(k), Vec<2>::Zero(), k, 1, 0); };
  auto solid = [&](Real k) { p.add_solid(Vec<2>::Constant(k), Vec<2>::Zero(), k, 1, 1, Mat<2>::Zero(), diag(k), -k); };
  solid(1);
  fluid(2);
  solid(3);  // added after a fluid: goes in front of it
  fluid(4);
  ASSERT_EQ(p.size(), 4u);
  ASSERT_EQ(p.solid_count(), 2u);
  EXPECT_EQ(p.mass, (std::vector<Real>{1, 3, 2, 4}));
  EXPECT_EQ(p.material, (std::vector<MaterialId>{1, 1, 0, 0}));

  // Reversed order: the solids stay in front, in reversed order, and bring their F and alpha.
  p.permute({3, 2, 1, 0});
  EXPECT_EQ(p.mass, (std::vector<Real>{3, 1, 4, 2}));
  EXPECT_EQ(p.material, (std::vector<MaterialId>{1, 1, 0, 0}));
  ASSERT_EQ(p.solid_count(), 2u);
  for (size_t q = 0; q < p.size(); ++q) EXPECT_EQ(p.x[q], Vec<2>::Constant(p.mass[q]));
  for (size_t q = 0; q < p.solid_count(); ++q) {
    EXPECT_EQ(p.F[q], diag(p.mass[q]));
    EXPECT_EQ(p.alpha[q], -p.mass[q]);
  }
}

}  // namespace
}  // namespace cdmpm
