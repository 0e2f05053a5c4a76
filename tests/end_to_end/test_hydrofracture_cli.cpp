// test_hydrofracture_cli.cpp - water pressure in damaged ice (the material key "hydrofracture") through the
// program: it exits with 2 on a non-physical water density, naming the key, and writes nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <type_traits>

#include "cli_helpers.h"
#include "material/stress.h"
#include "scene/scene_loader.h"
#include "scene_builders.h"

namespace cdmpm {
namespace {

TEST(HydrofractureCli, NonPhysicalWaterDensityExitsWithTwoNamingTheKey) {
  using testing::CliResult, testing::TempDir, testing::run_cdmpm;
  TempDir dir;
  std::ofstream(dir / "bad.json") << testing::hydrofracture_ice_scene({{"water_level", 250}, {"water_density", -1}}).dump();
  const CliResult bad = run_cdmpm({"run", dir / "bad.json", "--out", dir / "bad", "--quiet"});
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("materials.ice.hydrofracture.water_density"), std::string::npos) << bad.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "bad"));
}

}  // namespace
}  // namespace cdmpm
