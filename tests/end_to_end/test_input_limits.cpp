// test_input_limits.cpp - hostile input, scene files: deep nesting (file, --set, parameter expressions), a
// directory or an unrepresentable number as the scene, escaping scene names, and a reused --out cleaned of the
// previous run's files. Each must end with exit 2 and a message naming the file, never a crash.
#include <gtest/gtest.h>

#include <fstream>

#include "cli_helpers.h"
#include "scene/json_limits.h"
#include "scene/parameters.h"
#include "scene/scene_loader.h"
#include "run/output_dir.h"

namespace cdmpm::testing {
namespace {

void write_file(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

std::string nested(size_t depth) { return std::string(depth, '[') + "1" + std::string(depth, ']'); }

// The default scene with `key` (a top-level key) set to the raw JSON text `value`.
std::string scene_with(const std::string& key, const std::string& value) {
  std::string text = read_bytes(source_path("scenes/hydrostatic_2d.json"));
  return "{\"" + key + "\": " + value + ", " + text.substr(text.find('{') + 1);
}

TEST(InputLimits, NestingDepthIgnoresBracketsInStrings) {
  EXPECT_EQ(json_nesting_depth("{\"a\": [1, {\"b\": []}]}"), 4u);
  EXPECT_EQ(json_nesting_depth("[\"[[[[\\\"[[[\", 2]"), 1u);
  EXPECT_EQ(json_nesting_depth("1"), 0u);
  EXPECT_EQ(json_nesting_depth(nested(100000)), kMaxJsonDepth + 1);  // stops counting past the limit
  EXPECT_NO_THROW(check_json_depth(nested(kMaxJsonDepth), "x"));
  EXPECT_THROW(check_json_depth(nested(kMaxJsonDepth + 1), "x"), SceneError);
}

TEST(InputLimits, DeeplyNestedSceneFileIsRefused) {
  TempDir dir;
  write_file(dir / "deep.json", scene_with("junk", nested(100000)));
  const auto r = run_cdmpm({"check", dir / "deep.json"});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(dir / "deep.json"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("256"), std::string::npos) << r.output;
}

TEST(InputLimits, DeeplyNestedSetValueIsRefused) {
  const auto r = run_cdmpm({"check", source_path("scenes/hydrostatic_2d.json"), "--set", "gravity=" + nested(30000)});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--set 'gravity'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("256"), std::string::npos) << r.output;
}

TEST(InputLimits, DeeplyNestedExpressionIsRefused) {
  const std::string scene = source_path("scenes/calving_front_2d.json");
  std::string power_chain = "1";
  for (int i = 0; i < 20000; ++i) power_chain += "^1";
  for (const std::string& e : {std::string(40000, '(') + "1" + std::string(40000, ')'), std::string(40000, '-') + "1",
                               power_chain, std::string(40000, '('), "sqrt(" + std::string(100, '(')}) {
    const auto r = run_cdmpm({"check", scene, "--set", "parameters.H== " + e});
    EXPECT_EQ(r.exit_code, 2) << r.output.substr(0, 300);
    EXPECT_NE(r.output.find("64 levels"), std::string::npos) << r.output.substr(0, 300);
    EXPECT_NE(r.output.find(scene), std::string::npos) << r.output.substr(0, 300);
  }
  // Nesting up to the limit is fine.
  const std::string deep_enough = std::string(60, '(') + "120" + std::string(60, ')');
  const auto r = run_cdmpm({"check", scene, "--set", "parameters.H== " + deep_enough});
  EXPECT_EQ(r.exit_code, 0) << r.output.substr(0, 300);
}

TEST(InputLimits, DirectoryAsSceneIsAnInputError) {
  TempDir dir;
  const auto r = run_cdmpm({"check", dir.path.string()});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("is a directory"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(dir.path.string()), std::string::npos) << r.output;
}

TEST(InputLimits, UnrepresentableNumberIsAnInputError) {
  TempDir dir;
  write_file(dir / "big.json", scene_with("junk", "1e999"));
  const auto r = run_cdmpm({"check", dir / "big.json"});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(dir / "big.json"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("1e999"), std::string::npos) << r.output;
}

TEST(InputLimits, SceneNamesCannotLeaveTheOutputFolder) {
  for (const char* name : {"../../x", "/tmp/x", "a/b", "..", ".hidden", "a\\\\b", ""}) {
    const auto r =
        run_cdmpm({"check", source_path("scenes/hydrostatic_2d.json"), "--set", std::string("name=") + name});
    EXPECT_EQ(r.exit_code, 2) << name << ": " << r.output;
    EXPECT_NE(r.output.find("name"), std::string::npos) << name << ": " << r.output;
  }
  const auto r = run_cdmpm({"check", source_path("scenes/hydrostatic_2d.json"), "--set", "name=run_2-b.c"});
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

TEST(InputLimits, ReusedOutputFolderIsCleanedOfThePreviousRun) {
  EXPECT_TRUE(is_run_output_file("particles_0042.vtu"));
  EXPECT_TRUE(is_run_output_file("summary.json"));
  EXPECT_FALSE(is_run_output_file("particles_.vtu"));
  EXPECT_FALSE(is_run_output_file("notes.txt"));
  TempDir dir;
  fs::create_directories(dir / "out");
  for (const char* f : {"particles_0099.vtu", "icebergs.csv", "waves.csv", "checkpoint.bin", "notes.txt"})
    write_file(dir / (std::string("out/") + f), "old");
  const auto r = run_cdmpm({"run", source_path("scenes/hydrostatic_2d.json"), "--out", dir / "out", "--quiet",
                            "--set", "time.end=0.2"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_FALSE(fs::exists(dir / "out/particles_0099.vtu"));
  EXPECT_FALSE(fs::exists(dir / "out/icebergs.csv"));  // this scene has no ice: no icebergs.csv of its own
  EXPECT_FALSE(fs::exists(dir / "out/waves.csv"));
  EXPECT_NE(read_bytes(dir / "out/checkpoint.bin"), "old");
  EXPECT_EQ(read_bytes(dir / "out/notes.txt"), "old");  // not a run's file: kept
  SKIP_IN_MPI_BUILD_LAYOUT();
  EXPECT_TRUE(fs::exists(dir / "out/particles_0002.vtu"));
  EXPECT_FALSE(fs::exists(dir / "out/particles_0003.vtu"));
}

}  // namespace
}  // namespace cdmpm::testing
