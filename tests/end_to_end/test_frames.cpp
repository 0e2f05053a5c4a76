// test_frames.cpp - the particle frames' stress tensor (field "stress", Cauchy sigma = tau / J, 3x3 row-major,
// zero-padded in 2D). Frame 0 of scenes/calving_front_2d.json holds the initial equilibrium state that the
// seeding prescribes (src/sim/seeding.cpp), which the stress must reproduce:
//   ice   (lithostatic, laterally free): sigma_yy = -rho_i g (H - y), sigma_xx = sigma_xy = 0;
//   water (hydrostatic):                 sigma = -p I with p the pressure of a column of compressed water at
//                                        rest (hydrostatic_column.h; about rho_w g (h - y));
// and for every particle the frame's "pressure" is -tr(sigma)/2; ice is intact (damage 0) and water has no
// damage (NaN: the field belongs to ice).
// Tolerance: the seeding's Newton solve stops at a residual of 64 eps kappa (ice), the equation of state is
// inverted to the same relative precision (water), and the frame stores float32 (relative 2^-24).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "cli_helpers.h"
#include "core/types.h"
#include "hydrostatic_column.h"
#include "vtu_reader.h"

namespace cdmpm::testing {
namespace {

TEST(Frames, StressTensorIsTheSeededEquilibriumState) {
  TempDir dir;
  const auto scene = read_json(source_path("scenes/calving_front_2d.json"));
  const auto r = run_cdmpm({"run", source_path("scenes/calving_front_2d.json"), "--out", dir / "out", "--quiet",
                            "--set", "parameters.dx=10", "--set", "time.end=0.01", "--set", "time.frame_interval=0.01"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  SKIP_IN_MPI_BUILD_LAYOUT();
  const ParsedVtu vtu(dir / "out/particles_0000.vtu");
  const size_t n = vtu.points();
  ASSERT_GT(n, 0u);
  const auto pts = vtu.array<double>("Points", 3 * n);
  const auto mat = vtu.array<int32_t>("material", n);
  const auto pres = vtu.array<float>("pressure", n);
  const auto S = vtu.array<float>("stress", 9 * n);
  const auto damage = vtu.array<float>("damage", n);

  const double g = 9.81, H = scene["parameters"]["H"], h = scene["parameters"]["water_depth"];
  const auto& ice = scene["materials"]["ice"];
  const double rho_i = ice["density"], rho_w = scene["materials"]["water"]["density"];
  const double E = ice["youngs_modulus"], nu = ice["poissons_ratio"];
  const double K_w = scene["materials"]["water"]["bulk_modulus"];
  // Largest modulus in play (the ice's bulk modulus E / (3 (1 - 2 nu)) is below E / (1 - 2 nu)).
  const double modulus = std::max(E / (1 - 2 * nu), K_w);
  const double eps = std::numeric_limits<Real>::epsilon();
  const double tol = 64 * eps * modulus + std::ldexp(rho_i * g * H, -20);

  size_t n_ice = 0, n_water = 0;
  for (size_t q = 0; q < n; ++q) {
    const double y = pts[3 * q + 1];
    const float* s = &S[9 * q];
    // 2D: the z row and column are zero.
    for (int k : {2, 5, 6, 7, 8}) ASSERT_EQ(s[k], 0.f) << "particle " << q;
    ASSERT_EQ(s[1], s[3]) << "particle " << q << ": sigma not symmetric";
    if (mat[q] == 0) {  // ice: plane strain, its pressure the mean of the 3x3 stress, sigma_zz = sigma_xx (the lateral
                        // stress ratio acts on both horizontal axes)
      EXPECT_NEAR(pres[q], -(2 * double(s[0]) + s[4]) / 3, tol) << "particle " << q;
      ++n_ice;
      EXPECT_NEAR(s[4], -rho_i * g * (H - y), tol) << "ice particle " << q << " at y = " << y;
      EXPECT_NEAR(s[0], 0.0, tol) << "ice particle " << q;
      EXPECT_NEAR(s[1], 0.0, tol) << "ice particle " << q;
      EXPECT_EQ(damage[q], 0.f) << "ice particle " << q << ": intact at seeding";
    } else {  // water
      EXPECT_NEAR(pres[q], -(double(s[0]) + s[4]) / 2, tol) << "particle " << q;
      ++n_water;
      EXPECT_NEAR(s[0], -tait_column_pressure(rho_w, g, h - y, K_w), tol) << "water particle " << q << " at y = " << y;
      EXPECT_EQ(s[0], s[4]) << "water particle " << q;
      EXPECT_EQ(s[1], 0.f) << "water particle " << q;
      EXPECT_TRUE(std::isnan(damage[q])) << "water particle " << q << ": damage is an ice field, absent (NaN) on water";
    }
  }
  EXPECT_GT(n_ice, 100u);
  EXPECT_GT(n_water, 100u);
}

// Frames carry what a user needs to trace and weigh particles: ids 0 .. n-1 at seeding (each once), the mass and
// the current volume (at seeding every particle occupies (dx/2)^2, 4 particles per cell) and the frame's time.
// Tolerance: float32 storage, relative 2^-23.
TEST(Frames, CarryIdsMassVolumeAndTime) {
  TempDir dir;
  const auto r = run_cdmpm({"run", source_path("scenes/calving_front_2d.json"), "--out", dir / "out", "--quiet",
                            "--set", "parameters.dx=10", "--set", "time.end=0.01", "--set", "time.frame_interval=0.01"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  SKIP_IN_MPI_BUILD_LAYOUT();
  const ParsedVtu first(dir / "out/particles_0000.vtu");
  EXPECT_TRUE(first.compressed);
  const size_t n = first.points();
  std::vector<int64_t> ids = first.array<int64_t>("id", n);
  std::sort(ids.begin(), ids.end());
  for (size_t q = 0; q < n; ++q) ASSERT_EQ(ids[q], int64_t(q));
  const auto volume = first.array<float>("volume", n);
  for (size_t q = 0; q < n; ++q) ASSERT_NEAR(volume[q], 25.0, 25.0 * std::ldexp(1.0, -23)) << "particle " << q;
  EXPECT_EQ(first.array<double>("TimeValue", 1)[0], 0.0);
  // A particle keeps its mass, found by its id whatever the particles' order in the later frame.
  const ParsedVtu last(dir / "out/particles_0001.vtu");
  EXPECT_EQ(last.array<double>("TimeValue", 1)[0], 0.01);
  std::vector<float> mass_by_id(n), later_by_id(n);
  const auto id0 = first.array<int64_t>("id", n), id1 = last.array<int64_t>("id", n);
  const auto m0 = first.array<float>("mass", n), m1 = last.array<float>("mass", n);
  for (size_t q = 0; q < n; ++q) mass_by_id[id0[q]] = m0[q], later_by_id[id1[q]] = m1[q];
  EXPECT_EQ(mass_by_id, later_by_id);
}

}  // namespace
}  // namespace cdmpm::testing
