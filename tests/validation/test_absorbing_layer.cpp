// test_absorbing_layer.cpp - the "absorbing_layer" boundary (boundary/absorbing_layer.cpp): water waves leave the
// domain reflecting less than 5 % of their amplitude (the acceptance bound), for
//   - a long wave: the Boussinesq solitary wave of H/h = 0.1 (effective k h = sqrt(3 H / 4 h) = 0.27),
//     scenes/absorbing_solitary_2d.json;
//   - a short wave: a packet of k h ~ 1 released from rest, scenes/absorbing_packet_2d.json, whose carrier's
//     period at the gauge is checked against linear dispersion (k h within 0.7 to 1.5).
// The reflection is measured at a gauge between the source and the layer, as the largest difference between the
// gauge record and that of the same scene with the layer moved far away (a domain long enough that nothing
// comes back to the gauge during the run): the incident wave, its dispersive tail included, is the same in both
// runs, so the difference is what came back from the layer. Over its largest incident amplitude at the same gauge,
// it must be below 0.05. (With the layer removed, the same measure gives 0.996 for the solitary wave: the gauge
// sees a reflection; docs/water.md#absorbing-layer.)
// Also: still water against the layer is not drained (its spillway removes nothing, the surface stays flat). Bad
// keys: tests/unit/test_absorbing_layer_input.cpp, tests/end_to_end/test_absorbing_layer_cli.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cli_helpers.h"
#include "scene/scene_loader.h"
#include "validation/linear_dispersion.h"

namespace cdmpm::testing {
// Named, not anonymous: its constants (g, dx, h, ...) have the names of other test files' constants, and a unity
// batch shares the anonymous namespace of its files.
namespace absorbing_layer_test {

constexpr double g = 9.81;

struct Record {
  std::vector<double> time, gauge, mass;
};

Record run_scene(const TempDir& dir, const std::string& name, const std::string& scene, std::vector<std::string> sets) {
  std::vector<std::string> args = {"run", source_path(scene), "--out", dir / name, "--threads", "2", "--quiet"};
  for (const std::string& s : sets) args.insert(args.end(), {"--set", s});
  const CliResult r = run_cdmpm(args);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  auto p = read_probes(dir / (name + "/probes.csv"));
  return {p["time"], p["gauge"], p["mass"]};
}

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

// The largest |a - b| over the samples both records hold (the same sampling times), over max |b|.
double reflection(const Record& a, const Record& b) {
  const size_t n = std::min(a.time.size(), b.time.size());
  EXPECT_GT(n, 100u);
  double diff = 0;
  for (size_t i = 0; i < n; ++i) {
    EXPECT_DOUBLE_EQ(a.time[i], b.time[i]);
    diff = std::max(diff, std::abs(a.gauge[i] - b.gauge[i]));
  }
  return diff / max_abs(b.gauge);
}

TEST(AbsorbingBoundary, LongWaveReflectsLessThanFivePercent) {
  TempDir dir;
  const std::string scene = "scenes/absorbing_solitary_2d.json";
  const std::vector<std::string> coarse = {"parameters.cells_per_h=6", "time.end=14"};
  std::vector<std::string> far = coarse;
  far.push_back("parameters.layer_start=44");  // the layer's face 12 h further: its echo reaches the gauge after 16 s
  const Record absorbed = run_scene(dir, "absorbed", scene, coarse);
  const Record incident = run_scene(dir, "incident", scene, far);
  const double H = 0.1;  // H / h = 0.1, h = 1 m
  EXPECT_GT(max_abs(incident.gauge), 0.9 * H) << "the solitary wave passes the gauge";
  const double R = reflection(absorbed, incident);
  std::printf("solitary wave (k h = 0.27): reflection %.4f\n", R);
  EXPECT_LT(R, 0.05);
}

TEST(AbsorbingBoundary, ShortWaveReflectsLessThanFivePercent) {
  TempDir dir;
  const std::string scene = "scenes/absorbing_packet_2d.json";
  const std::vector<std::string> coarse = {"parameters.cells_per_h=6", "time.end=16"};
  std::vector<std::string> far = coarse;
  far.push_back("parameters.right_layer_start=66");
  const Record absorbed = run_scene(dir, "absorbed", scene, coarse);
  const Record incident = run_scene(dir, "incident", scene, far);
  // The carrier's period: the mean time between zero up-crossings while the packet is above a fifth of its
  // amplitude at the gauge; its k h from omega^2 = g k tanh(k h), h = 1 m.
  const double a = max_abs(incident.gauge);
  std::vector<double> ups;
  for (size_t i = 1; i < incident.time.size(); ++i)
    if (incident.gauge[i - 1] < 0 && incident.gauge[i] >= 0) ups.push_back(incident.time[i]);
  std::vector<double> strong;
  for (size_t i = 0; i < incident.time.size(); ++i)
    if (std::abs(incident.gauge[i]) > 0.2 * a) strong.push_back(incident.time[i]);
  ASSERT_FALSE(strong.empty());
  std::vector<double> inside;
  for (double t : ups)
    if (t >= strong.front() && t <= strong.back()) inside.push_back(t);
  ASSERT_GE(inside.size(), 2u) << "the packet passes the gauge";
  const double period = (inside.back() - inside.front()) / static_cast<double>(inside.size() - 1);
  const double kh = dispersion_wavenumber(2 * M_PI / period, g, 1.0);
  std::printf("packet: period %.3f s, k h %.3f, amplitude %.4f m\n", period, kh, a);
  EXPECT_GT(kh, 0.7);
  EXPECT_LT(kh, 1.5);
  const double R = reflection(absorbed, incident);
  std::printf("packet (k h ~ 1): reflection %.4f\n", R);
  EXPECT_LT(R, 0.05);
}

// Still water against the layer: the spillway removes nothing (the mass changes by less than 1e-12 of itself, far
// below one particle's share, 1 / 24,000; the sum's last bits may differ with the particle order) and the surface
// stays flat at the gauge, within a thousandth of the depth.
TEST(AbsorbingBoundary, StillWaterIsNotDrained) {
  TempDir dir;
  const Record r = run_scene(dir, "still", "scenes/absorbing_solitary_2d.json",
                             {"parameters.cells_per_h=6", "parameters.H_over_h=1e-9", "time.end=4"});
  ASSERT_FALSE(r.mass.empty());
  EXPECT_LT(std::abs(r.mass.back() - r.mass.front()), 1e-12 * r.mass.front());
  EXPECT_LT(max_abs(r.gauge), 1e-3);
}

}  // namespace absorbing_layer_test
}  // namespace cdmpm::testing
