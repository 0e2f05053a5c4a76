// test_absorbing_layer_cli.cpp - the program refuses a bad "absorbing_layer" boundary with exit code 2, naming the
// file and the key. Its reflection: tests/validation/test_absorbing_layer.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cli_helpers.h"
#include "scene/scene_loader.h"
#include "validation/linear_dispersion.h"

namespace cdmpm::testing {
namespace {

// The program refuses a bad layer with exit code 2, naming the file and the key, and writes nothing.
TEST(AbsorbingBoundary, CliRefusesBadLayerWithExitCode2) {
  TempDir dir;
  for (const std::string set : {"boundaries.1.width=-6", "boundaries.1.face=y+", "boundaries.1.sponge=1"}) {
    const CliResult r = run_cdmpm({"run", source_path("scenes/absorbing_solitary_2d.json"), "--out", dir / "x",
                                   "--set", set, "--quiet"});
    EXPECT_EQ(r.exit_code, 2) << set << "\n" << r.output;
    const std::string key = set.substr(0, set.find('='));
    EXPECT_NE(r.output.find("absorbing_solitary_2d.json"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(key.substr(std::string("boundaries.1.").size())), std::string::npos) << r.output;
  }
}

}  // namespace
}  // namespace cdmpm::testing
