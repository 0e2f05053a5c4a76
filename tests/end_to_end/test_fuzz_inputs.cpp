// test_fuzz_inputs.cpp - seeded hostile inputs run through the cdmpm program. Each case must end with
// exit 2 (bad input; 1 for I/O where noted) and a message on stderr, never a signal, never a hang (each run
// under `timeout`, 20 s) and never more than 2 GiB of address space (`ulimit -v`; not in a sanitizer build,
// whose shadow memory needs more). Scenes go through `cdmpm check`, checkpoints through `cdmpm run --resume`
// of the small hydrostatic scene. Classes of input generated (mutations of the shipped scenes):
//   1. deep nesting: a value replaced by arrays or objects nested 257 .. 100,000 levels        -> exit 2
//   2. unrepresentable numbers: 1e999, -1e999, NaN, Infinity, 1e400 as raw JSON text          -> exit 2
//   3. wrong types: a value replaced by null, true, {}, [[]], a plain string, another scalar   -> exit 2
//   4. unknown keys added to an object of the scene                                           -> exit 2
//   5. huge arrays (10^5 .. 10^6 numbers) where a scalar is expected                          -> exit 2
//   6. extreme numbers: -1, 0, 1e308, -1e308, 1e-300, 5e-324 in place of a number             -> exit 0 or 2
//   7. random byte flips (1 .. 8 bytes) and truncations of the scene text                     -> exit 0 or 2
//   8. hostile --set: deep nesting, missing or huge path components, 1e999, expressions nested
//      40,000 levels, unknown functions, circular parameters, 100 kB strings (an argument of a command
//      line is at most 128 kB)                                                                -> exit 2
//   9. corrupted checkpoints: byte flips, truncations, forged length fields and forged values
//      (NaN/far positions, material ids, masses, J, time) with a recomputed CRC              -> exit 2
// Exit 0 is allowed only for classes 6 and 7, where a mutation can leave a valid scene, and for forged
// checkpoint doubles that stay finite (a velocity of 1e299 loads; the run then goes unstable: exit 3).
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <random>

#include "cli_helpers.h"
#include "io/checkpoint_format.h"

namespace cdmpm::testing {
namespace {

using json = nlohmann::json;

struct Outcome {
  int code = -1;  // exit code; >= 124 for a timeout or a signal (timeout's convention)
  std::string output;
};

// Runs cdmpm under a time and memory limit. CDMPM_FUZZ_BINARY, if set, names the program to run instead of
// this build's (e.g. a CDMPM_SANITIZE build of it, without the memory limit, which its shadow memory exceeds).
Outcome run_limited(const std::vector<std::string>& args, const TempDir& dir) {
  const char* other = std::getenv("CDMPM_FUZZ_BINARY");
  std::string cmd;
#ifndef CDMPM_SANITIZE
  if (!other) cmd = "ulimit -v 2097152; ";
#endif
  cmd += "exec timeout -k 2 20 " + quote(other ? other : CDMPM_BINARY);
  for (const auto& a : args) cmd.append(" ").append(quote(a));
  cmd.append(" > ").append(quote(dir / "log.txt")).append(" 2>&1");
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), read_bytes(dir / "log.txt")};
}

// Checks one case's outcome: `allowed` exit codes, and a message with every refusal.
void expect_outcome(const Outcome& o, std::initializer_list<int> allowed, const std::string& what) {
  EXPECT_TRUE(std::find(allowed.begin(), allowed.end(), o.code) != allowed.end())
      << what << ": exit " << o.code << (o.code >= 124 ? " (signal or timeout)" : "") << ": "
      << o.output.substr(0, 400);
  const bool message = o.output.find("error") != std::string::npos || o.output.find("unstable") != std::string::npos;
  if (o.code != 0) {
    EXPECT_TRUE(message) << what << ": " << o.output.substr(0, 400);
  }
}

// JSON pointers of every leaf value of `j` (not inside "parameters", whose new keys would be new parameters).
std::vector<json::json_pointer> leaves(const json& j) {
  std::vector<json::json_pointer> out;
  const json flat = j.flatten();
  for (const auto& [path, v] : flat.items())
    if (path.rfind("/parameters", 0) != 0) out.emplace_back(path);
  return out;
}

// JSON pointers of every object of `j` but "parameters" and "materials" (whose keys are names).
std::vector<json::json_pointer> objects(const json& j, const json::json_pointer& at = json::json_pointer()) {
  std::vector<json::json_pointer> out;
  const json& v = j[at];
  if (v.is_object()) out.push_back(at);
  if (v.is_structured())
    for (const auto& [key, child] : v.items())
      if (!(at.empty() && (key == "parameters" || key == "materials")) && child.is_structured())
        for (auto& p : objects(j, at / key)) out.push_back(p);
  return out;
}

class FuzzInputs : public ::testing::Test {
 protected:
  std::mt19937_64 rng{19};
  TempDir dir;
  std::vector<json> scenes;
  void SetUp() override {
    for (const char* s : {"hydrostatic_2d", "calving_front_2d", "dam_break_3d", "sliding_block_2d"})
      scenes.push_back(read_json(source_path(std::string("scenes/") + s + ".json")));
  }
  size_t pick(size_t n) { return std::uniform_int_distribution<size_t>(0, n - 1)(rng); }
  const json& any_scene() { return scenes[pick(scenes.size())]; }
  // Writes `text` as a scene file and checks it.
  Outcome check_text(const std::string& text) {
    std::ofstream(dir / "scene.json", std::ios::binary | std::ios::trunc) << text;
    return run_limited({"check", dir / "scene.json"}, dir);
  }
  // The scene with a random leaf replaced by the raw JSON `raw`.
  std::string replace_leaf(const json& scene, const std::string& raw) {
    json j = scene;
    const auto all = leaves(j);
    j[all[pick(all.size())]] = "@@RAW@@";
    std::string text = j.dump();
    return text.replace(text.find("\"@@RAW@@\""), 9, raw);
  }
  std::string nested(size_t depth) {
    const bool arrays = pick(2) == 0;
    std::string open, close;
    for (size_t i = 0; i < depth; ++i) {
      open += arrays ? "[" : "{\"a\":";
      close += arrays ? "]" : "}";
    }
    return open + "1" + close;
  }
};

TEST_F(FuzzInputs, HostileScenes) {
  int cases = 0;
  for (int i = 0; i < 25; ++i, ++cases) {  // 1. deep nesting
    const size_t depth = i % 3 == 0 ? 100000 : 257 + pick(5000);
    expect_outcome(check_text(replace_leaf(any_scene(), nested(depth))), {2}, "nesting " + std::to_string(depth));
  }
  const std::vector<std::string> unrepresentable = {"1e999", "-1e999", "NaN", "Infinity", "1e400", "-Infinity"};
  for (int i = 0; i < 20; ++i, ++cases) {  // 2.
    const std::string raw = unrepresentable[pick(unrepresentable.size())];
    expect_outcome(check_text(replace_leaf(any_scene(), raw)), {2}, "number " + raw);
  }
  for (int i = 0; i < 50; ++i, ++cases) {  // 3. wrong types
    json j = any_scene();
    const auto all = leaves(j);
    const auto at = all[pick(all.size())];
    const json old = j[at];
    std::vector<json> others = {nullptr, json::object(), json::array({json::array()}), "not a value"};
    if (!old.is_boolean()) others.push_back(true);
    if (old.is_boolean() || (old.is_string() && old.get<std::string>().rfind("=", 0) != 0)) others.push_back(12.5);
    j[at] = others[pick(others.size())];
    expect_outcome(check_text(j.dump()), {2}, "type at " + at.to_string() + " = " + j[at].dump());
  }
  for (int i = 0; i < 30; ++i, ++cases) {  // 4. unknown keys
    json j = any_scene();
    const auto objs = objects(j);
    const auto at = objs[pick(objs.size())];
    j[at]["zz_unknown_" + std::to_string(pick(1000))] = 1;
    expect_outcome(check_text(j.dump()), {2}, "unknown key in " + at.to_string());
  }
  for (int i = 0; i < 10; ++i, ++cases) {  // 5. huge arrays
    const size_t n = i % 2 ? 1000000 : 100000;
    std::string raw = "[";
    for (size_t k = 0; k < n; ++k) raw += k ? ",1.5" : "1.5";
    raw += "]";
    json j = any_scene();
    const auto all = leaves(j);
    const auto at = all[pick(all.size())];
    if (j[at.parent_pointer()].is_array()) j[at.parent_pointer()] = "@@RAW@@";  // replaces a whole short array
    else j[at] = "@@RAW@@";
    std::string text = j.dump();
    expect_outcome(check_text(text.replace(text.find("\"@@RAW@@\""), 9, raw)), {2}, "huge array " + at.to_string());
  }
  const std::vector<std::string> extremes = {"-1", "0", "1e308", "-1e308", "1e-300", "5e-324", "-0.0", "2147483648"};
  for (int i = 0; i < 50; ++i, ++cases) {  // 6.
    const std::string raw = extremes[pick(extremes.size())];
    expect_outcome(check_text(replace_leaf(any_scene(), raw)), {0, 2}, "extreme " + raw);
  }
  for (int i = 0; i < 60; ++i, ++cases) {  // 7. byte flips and truncations
    std::string text = any_scene().dump(2);
    if (i % 4 == 3) {
      text.resize(pick(text.size()));
    } else {
      for (size_t k = 0, n = 1 + pick(8); k < n; ++k) text[pick(text.size())] = static_cast<char>(pick(256));
    }
    expect_outcome(check_text(text), {0, 2}, "flipped/truncated text");
  }
  EXPECT_GE(cases, 245);
}

TEST_F(FuzzInputs, HostileSetValues) {
  const std::string scene = source_path("scenes/calving_front_2d.json");
  std::string chain = "1";
  for (int i = 0; i < 20000; ++i) chain += "^1";
  std::vector<std::string> sets = {
      "gravity=" + std::string(30000, '[') + std::string(30000, ']'), "time=" + nested(300),
      "materials.water=" + nested(1000),
      "time.end=1e999", "time.end=NaN", "time.end=-1e999", "domain.dx=[" + std::string(100000, '1') + "]",
      "parameters.H== " + std::string(40000, '(') + "1" + std::string(40000, ')'),
      "parameters.H== " + std::string(40000, '-') + "1", "parameters.H== " + chain,
      "parameters.H== nosuch(1)", "parameters.H== H", "parameters.H==", "parameters.H== 1/0",
      "nosuch.key=1", "bodies.999999999.material=ice", "bodies.99999999999999999999.x=1", "bodies.x=1",
      ".=1", "a..b=1", "=1", "time.end", "time.end.x=1", "name=../../x", "name=/tmp/x",
      "name=" + std::string(100000, 'n'), "materials.water.density=" + std::string(100000, '7'),
      "materials.water.density=\"" + std::string(100000, 'x') + "\"",
      "time.frame_interval=" + std::string(5000, '['),
  };
  std::string long_path;
  for (int i = 0; i < 10000; ++i) long_path += "time.";
  sets.push_back(long_path + "end=1");
  for (int i = 0; i < 12; ++i) {  // random bytes as a value of a random known key
    std::string v;
    for (size_t k = 0, n = 1 + pick(40); k < n; ++k) v += static_cast<char>(1 + pick(255));
    sets.push_back(std::string(i % 2 ? "time.end=" : "domain.dx=") + "{" + v);
  }
  for (const auto& s : sets)
    expect_outcome(run_limited({"check", scene, "--set", s}, dir), {2}, "--set " + s.substr(0, 60));
}

TEST_F(FuzzInputs, CorruptedCheckpoints) {
  const std::string scene = source_path("scenes/hydrostatic_2d.json");
  const auto first = run_limited({"run", scene, "--out", dir / "run", "--quiet", "--set", "time.end=0.1"}, dir);
  ASSERT_EQ(first.code, 0) << first.output;
  const std::string good = read_bytes(dir / "run/checkpoint.bin");
  auto with_crc = [](std::string d) {
    const uint32_t crc = crc32_update(0, d.data(), d.size() - 4);
    std::memcpy(d.data() + d.size() - 4, &crc, 4);
    return d;
  };
  auto resume = [&](const std::string& data, const std::string& what) {
    fs::remove_all(dir / "resume");
    fs::copy(dir / "run", dir / "resume");
    std::ofstream(dir / "resume/checkpoint.bin", std::ios::binary | std::ios::trunc) << data;
    expect_outcome(run_limited({"run", scene, "--resume", dir / "resume", "--quiet", "--set", "time.end=0.15"}, dir),
                   {2}, what);
  };
  for (int i = 0; i < 30; ++i) {  // byte flips
    std::string d = good;
    const size_t pos = pick(d.size());
    d[pos] = static_cast<char>(d[pos] ^ (1 + pick(255)));
    resume(d, "flip at " + std::to_string(pos));
  }
  for (int i = 0; i < 20; ++i) resume(good.substr(0, pick(good.size())), "truncated");
  for (int i = 0; i < 20; ++i) {  // forged: 8 bytes of 0xff (lengths, counts) or a NaN/huge double, CRC fixed
    std::string d = good;
    const size_t pos = i < 10 ? 8 + pick(200) : pick(d.size() - 12);
    std::memset(d.data() + pos, i % 2 ? 0xff : 0x7f, 8);
    std::ofstream(dir / "probe.bin", std::ios::binary) << with_crc(d);
    fs::remove_all(dir / "resume");
    fs::copy(dir / "run", dir / "resume");
    fs::copy_file(dir / "probe.bin", dir / "resume/checkpoint.bin", fs::copy_options::overwrite_existing);
    const auto r = run_limited({"run", scene, "--resume", dir / "resume", "--quiet", "--set", "time.end=0.15"}, dir);
    // A forged double that stays finite (a huge velocity, say) may load: the run then ends, or goes unstable (3).
    expect_outcome(r, {0, 2, 3}, "forged bytes at " + std::to_string(pos));
  }
}

}  // namespace
}  // namespace cdmpm::testing
