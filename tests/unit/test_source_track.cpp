// test_source_track.cpp - recorded calving sources replayed (io/source_track.h, rigid key `track`,
// sim/rigid_bodies.h).
// What is asserted:
//   - the reader refuses malformed files naming the file and the line, and bounds the lattice before storing it;
//   - the interpolation is exact for a field it can represent: u = t (a + b X + c Z) is bilinear in X, Z and linear
//     in t, so between records and nodes it is reproduced to round-off, and it is held after the last record;
//   - a replayed body's particles are where the track puts them, x = X + u(X, t), to round-off, after any number of
//     steps, its particles are seeded only where the recorded ice was (fill >= 1/2), and water is seeded in the rest
//     of its shape;
//   - extruded across the whole width of a 3D channel, the recorded Eqip Sermia calving raises the wave it raises in
//     2D (the same plane problem: first crests at 250 m within 3 %), and that crest lies in the observed 35-65 m.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_helpers.h"
#include "io/source_track.h"
#include "scene/scene_loader.h"
#include "sim/simulation.h"

namespace cdmpm {
namespace {

using json = nlohmann::json;

// A track of u = t (a + b X + c Z) per component on an nx x nz lattice at (x0 + i h, z0 + j h), records at `times`;
// fill 1 where X <= fill_below, else 0.
std::string linear_track(int nx, int nz, double x0, double z0, double h, const std::vector<double>& times,
                         const double (&a)[2], const double (&b)[2], const double (&c)[2], double fill_below = 1e300) {
  std::ostringstream s;
  s.precision(17);
  s << "# a test track\ncdmpm_source_track 1\nlattice " << nx << " " << nz << " " << x0 << " " << z0 << " " << h << "\n";
  s << "fill";
  for (int j = 0; j < nz; ++j)
    for (int i = 0; i < nx; ++i) s << " " << (x0 + i * h <= fill_below ? 1 : 0);
  s << "\ntimes " << times.size() << "\n";
  for (double t : times) {
    s << t;
    for (int j = 0; j < nz; ++j)
      for (int i = 0; i < nx; ++i)
        for (int k = 0; k < 2; ++k) s << " " << t * (a[k] + b[k] * (x0 + i * h) + c[k] * (z0 + j * h));
    s << "\n";
  }
  return s.str();
}

std::string write(const testing::TempDir& dir, const std::string& name, const std::string& text) {
  const std::string path = dir / name;
  std::ofstream(path) << text;
  return path;
}

TEST(SourceTrack, InterpolationIsExactForABilinearFieldAndHeldAfterTheLastRecord) {
  testing::TempDir dir;
  const double a[2] = {0.5, -0.25}, b[2] = {0.01, 0.02}, c[2] = {-0.03, 0.005};
  SourceTrack s = read_source_track(write(dir, "t.txt", linear_track(5, 4, -20, -10, 5, {0, 0.5, 2}, a, b, c, -5)));
  s.origin = {100, 50};
  for (double t : {0.0, 0.2, 0.5, 1.3, 2.0}) {
    for (double X : {-20.0, -13.7, -4.1, 0.0}) {
      for (double Z : {-10.0, -6.2, 1.3, 5.0}) {
        const auto u = s.displacement(X + 100, Z + 50, t);
        for (int k = 0; k < 2; ++k) EXPECT_NEAR(u[k], t * (a[k] + b[k] * X + c[k] * Z), 1e-12) << t << " " << X << " " << Z;
      }
    }
  }
  const auto held = s.displacement(90, 50, 7.5), last = s.displacement(90, 50, 2.0);
  EXPECT_EQ(held[0], last[0]);
  EXPECT_EQ(held[1], last[1]);
  EXPECT_TRUE(s.occupied(100 - 20, 50));    // node X = -20: filled
  EXPECT_TRUE(s.occupied(100 - 7.6, 50));   // nearest node X = -10
  EXPECT_FALSE(s.occupied(100 - 2.4, 50));  // nearest node X = 0: empty
  EXPECT_FALSE(s.occupied(100 - 23, 50));   // beyond the lattice
  double reach = 0;  // the largest |u| over the nodes, at the last record (t = 2 s)
  for (double X = -20; X <= 0; X += 5)
    for (double Z = -10; Z <= 5; Z += 5)
      reach = std::max(reach, std::hypot(2 * (a[0] + b[0] * X + c[0] * Z), 2 * (a[1] + b[1] * X + c[1] * Z)));
  EXPECT_NEAR(s.reach(), reach, 1e-12);
}

TEST(SourceTrack, MalformedFilesAreRefusedNamingTheFileAndLine) {
  testing::TempDir dir;
  const double a[2] = {1, 0}, b[2] = {0, 0}, c[2] = {0, 0};
  const std::string good = linear_track(2, 2, 0, 0, 1, {0, 1}, a, b, c);
  ASSERT_NO_THROW(read_source_track(write(dir, "good.txt", good)));
  const auto replace = [&](const std::string& from, const std::string& to) {
    std::string s = good;
    s.replace(s.find(from), from.size(), to);
    return s;
  };
  struct Case {
    std::string name, text, expected;
  };
  const std::vector<Case> cases = {
      {"magic", replace("cdmpm_source_track 1", "track 1"), ":2: expected a line \"cdmpm_source_track"},
      {"version", replace("cdmpm_source_track 1", "cdmpm_source_track 2"), ":2: expected format version 1"},
      {"nx", replace("lattice 2 2", "lattice 1 2"), ":3: expected a whole number in [2, "},
      {"huge", replace("lattice 2 2", "lattice 5000 5000"), ":3: expected at most 10000000 lattice nodes"},
      {"spacing", replace("0 0 1\n", "0 0 -1\n"), ":3: expected a lattice spacing H > 0"},
      {"fill", replace("fill 1 1", "fill 1 1.5"), ":4: expected a fill in [0, 1]"},
      {"fill count", replace("fill 1 1 1 1", "fill 1 1 1"), ":4: expected 4 values after \"fill\""},
      {"first time", replace("\n0 ", "\n0.5 "), ":6: expected a first time of 0 s"},
      {"record", replace("\n1 1 0 1 0 1 0 1 0", "\n1 1 0 1 0 1 0 1"), ":7: expected 9 values"},
      {"times", replace("times 2", "times 3"), "expected 3 records (\"times\"), got 2 before the end of the file"},
      {"nan", replace("\n1 1 0", "\n1 nan 0"), ":7: expected a finite number (displacement)"},
      {"extra", good + "2 1 0 1 0 1 0 1 0\n", ":8: expected the end of the file after 2 records"},
  };
  for (const Case& k : cases) {
    const std::string path = write(dir, k.name + ".txt", k.text);
    try {
      read_source_track(path);
      ADD_FAILURE() << k.name << ": accepted";
    } catch (const SceneError& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.rfind(path, 0), 0u) << k.name << ": " << msg;
      EXPECT_NE(msg.find(k.expected), std::string::npos) << k.name << ": " << msg;
    }
  }
  EXPECT_THROW(read_source_track((dir / "none.txt")), SceneError);
}

// A 2D box of 10 m x 6 m in a 20 m x 12 m domain with water beside it in a pool, replayed along u = t (a + b X + c Z):
// it translates, stretches and shears. Its particles are where the track puts them.
TEST(Replay, ParticlesAreWhereTheTrackPutsThem) {
  testing::TempDir dir;
  const double a[2] = {0.8, 0.3}, b[2] = {0.02, 0.0}, c[2] = {0.0, -0.01};
  // Lattice over X in [-10, 0], Z in [0, 6] relative to the origin (12, 2); the ice filled X <= -2.5 only.
  const std::string track = write(dir, "track.txt", linear_track(11, 7, -10, 0, 1, {0, 0.3, 1.0, 2.0}, a, b, c, -2.5));
  json s;
  s["dim"] = 2;
  s["domain"] = {{"size", {20.0, 12.0}}, {"dx", 0.5}};
  s["time"] = {{"end", 1.0}, {"frame_interval", 1.0}};
  s["gravity"] = {0, -9.81};
  s["materials"] = {{"source", {{"type", "rigid"}, {"density", 917}, {"bulk_modulus", 1e6}}},
                    {"water", {{"type", "water"}, {"density", 1000}, {"bulk_modulus", 1e6}}}};
  s["bodies"] = json::array(
      {{{"material", "source"}, {"particles_per_cell", 4}, {"hydrostatic", false},
        {"shape", {{"type", "box"}, {"min", {2.0, 2.0}}, {"max", {12.0, 8.0}}}},
        {"rigid", {{"track", {{"file", track}, {"origin", {12.0, 2.0}}}}}}},
       {{"material", "water"}, {"particles_per_cell", 4},
        {"shape", {{"type", "box"}, {"min", {2.0, 0.0}}, {"max", {20.0, 4.0}}}}}});
  s["boundaries"] = json::array({{{"type", "walls"}, {"condition", "slip"}, {"faces", {"x-", "x+", "y-"}}}});
  Simulation<2> sim(scene_from_json(s, (dir / "replay.json")));
  const auto& p = sim.particles;
  // Seeded where the ice was: nearest node X <= -2.5, i.e. X < -2.5 + ... (nodes at -3 and below: X < -2.5).
  size_t source = 0, water_in_shape = 0;
  std::vector<Vec<2>> start;
  std::vector<uint64_t> ids;
  for (size_t q = 0; q < p.size(); ++q) {
    if (p.material[q] == 0) {
      ++source;
      EXPECT_LT(p.x[q][0], 12 - 2.5) << "a source particle where the ice was not";
      start.push_back(p.x[q]), ids.push_back(p.id[q]);
    } else if (p.x[q][0] > 2 && p.x[q][0] < 12 && p.x[q][1] > 2) {
      ++water_in_shape;
    }
  }
  EXPECT_EQ(source, size_t(4 * 15 * 12));  // 4 per cell; X in [-10, -2.5]: 15 cells of 0.5 m; Z in [0, 6]: 12
  EXPECT_GT(water_in_shape, 0u);               // the water fills the part of the shape the ice did not
  sim.run_until(1.7);
  const double t = sim.time();
  ASSERT_NEAR(t, 1.7, 1e-9);
  for (size_t q = 0; q < p.size(); ++q) {
    if (p.material[q] != 0) continue;
    const size_t k = size_t(std::find(ids.begin(), ids.end(), p.id[q]) - ids.begin());
    ASSERT_LT(k, ids.size());
    const double X = start[k][0] - 12, Z = start[k][1] - 2;
    for (int c2 = 0; c2 < 2; ++c2)
      EXPECT_NEAR(p.x[q][c2], start[k][c2] + t * (a[c2] + b[c2] * X + c[c2] * Z), 1e-4) << "particle " << p.id[q];
  }
}

// The recorded calving (scenes/data/eqip_sermia_calving_track.txt) across the whole width of a 3D channel 160 m wide
// (slip walls at y = 0 and 80 m, no absorbing layer) against the 2D replay, both at dx = 40 m over the first 1.16 km
// of the fjord to t = 20 s.
TEST(EqipSermia3D, ReplayedCalvingAcrossTheWholeWidthRaisesThe2DWave) {
  testing::TempDir dir;
  const auto crest = [&](const std::string& scene, const std::string& name, std::vector<std::string> extra) {
    std::vector<std::string> args = {"run", testing::source_path(scene), "--out", dir / name, "--quiet",
                                     "--set", "parameters.dx=40", "--set", "time.end=20",
                                     "--set", "parameters.fjord_end=1400", "--set", "output.frames=false",
                                     "--set", "output.checkpoint_every=0"};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto r = testing::run_cdmpm(args);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    const auto t = read_csv_table(dir / (name + "/waves.csv"));
    return t.numbers("amplitude")[0];
  };
  const std::string g2 = R"([{"name": "gauge_250m", "type": "wave_gauge", "material": "water", "position": [490], "still_level": 160}])";
  const std::string g3 = R"([{"name": "gauge_250m", "type": "wave_gauge", "material": "water", "position": [490, 20], "still_level": 160}])";
  const double a2 = crest("scenes/eqip_sermia_replay_2d.json", "2d", {"--set", "probes.list=" + g2});
  // The 3D scene's boundaries without the box beside the section and the absorbing layer; the channel 160 m wide, the
  // section as wide.
  const json all = testing::read_json(testing::source_path("scenes/eqip_sermia_replay_3d.json"))["boundaries"];
  ASSERT_EQ(all.size(), 6u);
  const json b = json::array({all[0], all[1], all[2], all[4]});
  const double a3 = crest("scenes/eqip_sermia_replay_3d.json", "3d",
                          {"--set", "probes.list=" + g3, "--set", "parameters.fjord_width=160", "--set",
                           "parameters.section_width=320", "--set", "boundaries=" + b.dump()});
  std::printf("first crest at 250 m: 2D %.3f m, 3D across the whole width %.3f m (ratio %.4f)\n", a2, a3, a3 / a2);
  EXPECT_NEAR(a3 / a2, 1.0, 0.03);
  EXPECT_GT(a2, 35.0);
  EXPECT_LT(a2, 65.0);
}

}  // namespace
}  // namespace cdmpm
