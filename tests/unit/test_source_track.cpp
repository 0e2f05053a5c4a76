// test_source_track.cpp - the reader and the interpolation of recorded calving sources (io/source_track.h); the
// replayed bodies: tests/engine/test_replay.cpp; the Eqip Sermia replay in 3D: tests/validation/test_eqip_replay.cpp.
// What is asserted:
//   - the reader refuses malformed files naming the file and the line, and bounds the lattice before storing it;
//   - the interpolation is exact for a field it can represent: u = t (a + b X + c Z) is bilinear in X, Z and linear
//     in t, so between records and nodes it is reproduced to round-off, and it is held after the last record.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_helpers.h"
#include "source_track_files.h"
#include "io/source_track.h"
#include "scene/scene_loader.h"
#include "sim/simulation.h"

namespace cdmpm {
namespace {

using json = nlohmann::json;

TEST(SourceTrack, InterpolationIsExactForABilinearFieldAndHeldAfterTheLastRecord) {
  testing::TempDir dir;
  const double a[2] = {0.5, -0.25}, b[2] = {0.01, 0.02}, c[2] = {-0.03, 0.005};
  SourceTrack s = read_source_track(write_file(dir, "t.txt", linear_track(5, 4, -20, -10, 5, {0, 0.5, 2}, a, b, c, -5)));
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
  ASSERT_NO_THROW(read_source_track(write_file(dir, "good.txt", good)));
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
    const std::string path = write_file(dir, k.name + ".txt", k.text);
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

}  // namespace
}  // namespace cdmpm
