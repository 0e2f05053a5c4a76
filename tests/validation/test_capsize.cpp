// test_capsize.cpp - floating ice slabs against hydrostatics and the inviscid capsize estimate
// (validation/capsize.h, docs/validation.md#capsizing-slabs; the estimate itself: tests/unit/test_capsize_estimate.cpp):
// in scenes/capsize_slab_2d.json a slab of
// w/h = 0.6 released at 5 degrees passes 45 degrees within twice the estimate's time (and not faster than with no
// water inertia at all, a lower bound); one of w/h = 0.9 should rock about upright (disabled: it capsizes).
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

constexpr double deg = std::numbers::pi / 180;

// The slab of scenes/capsize_slab_2d.json released at 5 degrees: its tilt [degrees] over time, sampled every 0.05 s.
struct Record {
  std::vector<double> t, angle;
};
Record run_slab(std::vector<std::string> sets, double t_end) {
  sets.push_back("time.end=" + std::to_string(t_end));
  const Scene scene = load_scene(std::string(CDMPM_SOURCE_DIR) + "/scenes/capsize_slab_2d.json", sets);
  Simulation<2> sim(scene);
  Record r;
  for (int k = 1; 0.05 * k <= t_end + 1e-9; ++k) {
    sim.run_until(0.05 * k);
    r.t.push_back(sim.time());
    r.angle.push_back(sim.rigid.bodies[0].angle / deg);
    if (std::abs(r.angle.back()) > 50) break;  // capsized, one way or the other
  }
  return r;
}
// The first time the angle reaches a [degrees] towards the side of its release tilt (+5 degrees: a slab capsizes
// the way it leans), linear between samples; infinity if never.
double time_to(const Record& r, double a) {
  double t0 = 0, a0 = 5;
  for (size_t i = 0; i < r.t.size(); ++i) {
    if (r.angle[i] >= a) return t0 + (r.t[i] - t0) * (a - a0) / (r.angle[i] - a0);
    t0 = r.t[i], a0 = r.angle[i];
  }
  return std::numeric_limits<double>::infinity();
}

void expect_narrow_slab_capsizes(const std::vector<std::string>& sets) {
  const capsize::Slab s{0.6, 1.0, 917, 1025};
  const double t_est = s.time_to(5 * deg, 45 * deg);
  const double t_dry = t_est * std::sqrt(s.body_inertia() / s.roll_inertia());  // no water inertia
  const Record r = run_slab(sets, 2 * t_est + 0.5);
  const double t45 = time_to(r, 45);
  std::printf("w/h 0.6 passes 45 deg at %.2f s; inviscid estimate %.2f s (no water inertia %.2f s)\n", t45, t_est,
              t_dry);
  EXPECT_LE(t45, 2 * t_est);
  EXPECT_GE(t45, t_dry);
}

void expect_wide_slab_stays_upright(const std::vector<std::string>& sets, double t_end) {
  std::vector<std::string> w = sets;
  w.push_back("parameters.aspect=0.9");
  const Record r = run_slab(w, t_end);
  double peak = 0, least = 90;
  for (double a : r.angle) peak = std::max(peak, std::abs(a)), least = std::min(least, std::abs(a));
  std::printf("w/h 0.9: tilt between %.2f and %.2f deg over %.1f s\n", least, peak, t_end);
  // Upright: its righting moment holds to 37 degrees, so released at 5 degrees it rocks about upright (an inviscid
  // rock stays within 5 degrees, passes upright a quarter period, about 2.1 s, after its release and returns after
  // 8.4 s): over 10 s it stays within twice its release angle and comes back to within half of it.
  EXPECT_LT(peak, 10);
  EXPECT_LT(least, 2.5);
}

TEST(Capsize, NarrowSlabCapsizesWithinTwiceTheInviscidEstimate) { expect_narrow_slab_capsizes({}); }
// Not met (docs/validation.md#capsizing-slabs): in contact the slab first turns back to upright (5 to -0.3 degrees
// by 3 s) and then capsizes the other way.
TEST(Capsize, DISABLED_NarrowSlabInContactCapsizesWithinTwiceTheInviscidEstimate) {
  expect_narrow_slab_capsizes({"materials.slab.contact=true"});
}
// Not met (docs/validation.md#capsizing-slabs): the slab of w/h = 0.9 rocks back to within a degree of upright
// and then capsizes, past 17 degrees at 8 s in the shared field and past 40 degrees at 5 s in contact (cells of h/16).
TEST(Capsize, DISABLED_WideSlabStaysUpright) { expect_wide_slab_stays_upright({}, 10); }
TEST(Capsize, DISABLED_WideSlabInContactStaysUpright) { expect_wide_slab_stays_upright({"materials.slab.contact=true"}, 10); }

}  // namespace
}  // namespace cdmpm
