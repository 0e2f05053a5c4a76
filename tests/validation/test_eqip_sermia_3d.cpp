// test_eqip_sermia_3d.cpp - the paired 2D and 3D runs of the Eqip Sermia fjord
// (docs/eqip_sermia.md#2d-to-3d-from-paired-runs), coarse: the same driven block (a 60 m x 200 m block of ice
// toppling about its toe along a prescribed tilt, rigid key "motion") spans the fjord's width in 2D
// (scenes/eqip_sermia_block_2d.json) and is an 80 m wide section of the front in 3D (scenes/eqip_sermia_3d.json),
// here over the first 1.24 km of the fjord (x+ wall at 1400 m, its reflection back at the 500 m gauge after
// t = 60 s) and a 600 m half-width basin, at dx = 20 m to t = 32 s: the first crest has passed 500 m.
// What is asserted (from the geometry of spreading, not from the program's output):
//   - both runs raise a wave: a first crest at 250 m above 1 m, 7 times the largest elevation the gauges read
//     before it arrives (0.14 m in 2D, 0.08 m in 3D at this dx: the particle lattice's own ripple);
//   - the 3D crest is lower than the 2D one at 250 m (the section's water spreads sideways; the 2D wave does not);
//   - between 250 m and 500 m the 3D/2D ratio falls by at least cylindrical spreading's sqrt(250 / 500) = 0.71 with
//     20 % allowance for the near field: ratio(500) / ratio(250) < 0.85. A 3D run whose wave does not spread (the
//     section as wide as the basin) gives about 1 and fails.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "cli_helpers.h"

namespace cdmpm::testing {
namespace {

std::map<std::string, double> first_crests(const std::string& waves_csv) {
  const CsvTable t = read_csv_table(waves_csv);
  std::map<std::string, double> out;
  const auto amp = t.numbers("amplitude");
  for (size_t i = 0; i < amp.size(); ++i) out[t.rows[i][0]] = amp[i];
  return out;
}

// Runs one member of the pair over the shortened fjord with the given gauges (and extra --set values); its first crests.
std::map<std::string, double> run_pair_member(const TempDir& dir, const std::string& scene, const std::string& name,
                                              const std::string& probes, std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {"run", source_path(scene), "--out", dir / name, "--quiet",
                                   "--set", "parameters.dx=20", "--set", "time.end=32",
                                   "--set", "parameters.fjord_end=1400", "--set", "output.frames=false",
                                   "--set", "probes.list=" + probes};
  args.insert(args.end(), extra.begin(), extra.end());
  const auto r = run_cdmpm(args);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return first_crests(dir / (name + "/waves.csv"));
}

TEST(EqipSermia3D, FiniteSectionWaveSpreadsBeyondThe2DWave) {
  TempDir dir;
  const std::string g2 =
      R"([{"name": "gauge_250m", "type": "wave_gauge", "material": "water", "position": [410], "still_level": 160},)"
      R"( {"name": "gauge_500m", "type": "wave_gauge", "material": "water", "position": [660], "still_level": 160}])";
  const std::string g3 =
      R"([{"name": "gauge_250m", "type": "wave_gauge", "material": "water", "position": [410, 10], "still_level": 160},)"
      R"( {"name": "gauge_500m", "type": "wave_gauge", "material": "water", "position": [660, 10], "still_level": 160}])";
  const auto a2 = run_pair_member(dir, "scenes/eqip_sermia_block_2d.json", "2d", g2);
  const auto a3 = run_pair_member(dir, "scenes/eqip_sermia_3d.json", "3d", g3,
                                  {"--set", "parameters.fjord_width=600", "--set", "parameters.absorbing_width=200"});
  ASSERT_FALSE(a2.empty() || a3.empty());
  const double r250 = a3.at("gauge_250m") / a2.at("gauge_250m"), r500 = a3.at("gauge_500m") / a2.at("gauge_500m");
  std::printf("first crest 2D: %.3f m (250 m), %.3f m (500 m); 3D: %.3f m, %.3f m; 3D/2D %.4f, %.4f\n",
              a2.at("gauge_250m"), a2.at("gauge_500m"), a3.at("gauge_250m"), a3.at("gauge_500m"), r250, r500);
  EXPECT_GT(a2.at("gauge_250m"), 1.0);
  EXPECT_GT(a3.at("gauge_250m"), 1.0);
  EXPECT_LT(r250, 1.0);
  EXPECT_LT(r500 / r250, 0.85);
}


// The fjord at rest: the block held at its starting tilt (its motion a constant -30 deg), the absorbing layer, the
// bed layer and the cliff's two boxes as in the scene, at dx = 40 m for 60 s. Water at rest must stay at rest:
// every column's highest elevation (max_elevation.asc, from each column's earliest possible arrival on) and every
// gauge's record within dx/20 of the still level. (Before the boxes' shared face and the box face on the sloping bed
// were treated as such, the water at the cliff rose 3.85 m by 60 s, and in 6 s the corner of the cliff and the y+
// absorbing layer rose 1.09 m.)
TEST(EqipSermia3D, LakeAtRestWithTheBlockHeldStaysWithinATwentiethOfACellFor60s) {
  TempDir dir;
  constexpr double dx = 40;
  const auto r = run_cdmpm({"run", source_path("scenes/eqip_sermia_3d.json"), "--out", dir / "held", "--quiet",
                            "--set", "parameters.dx=40", "--set", "time.end=60", "--set", "output.frames=false",
                            "--set", "bodies.0.rigid.motion=[[0, -30], [1, -30]]"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream in(dir / "held/max_elevation.asc");
  std::string key;
  double value = 0, nodata = -9999;
  for (int k = 0; k < 6 && in >> key >> value; ++k)
    if (key == "NODATA_value") nodata = value;
  size_t cells = 0;
  while (in >> value) {
    if (value == nodata) continue;
    ++cells;
    EXPECT_LE(value, dx / 20) << "a column rose " << value << " m";
  }
  EXPECT_GT(cells, 1000u);
  for (const auto& [name, eta] : read_probes(dir / "held/probes.csv")) {
    if (name.rfind("gauge", 0) != 0 && name != "tide_gauge") continue;
    for (double e : eta) EXPECT_LE(std::abs(e), dx / 20) << name;
  }
}

}  // namespace
}  // namespace cdmpm::testing
