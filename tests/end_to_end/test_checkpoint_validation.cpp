// test_checkpoint_validation.cpp - hostile input, checkpoints: any single byte flipped and any truncation is refused
// (CRC-32), length fields forged with a valid checksum are refused before any allocation, forged values
// (NaN or far positions, bad material ids, non-positive mass or J, bad time, frame names leaving the folder)
// are refused, and --resume with another scene (--set materials.water.density=500) names the section that
// differs. All through CheckpointError in process, and exit 2 through the program.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>

#include "cli_helpers.h"
#include "io/checkpoint.h"
#include "io/checkpoint_format.h"
#include "io/scene_fingerprint.h"
#include "scene/scene_loader.h"

namespace cdmpm::testing {
namespace {

const std::string kScene = source_path("scenes/hydrostatic_2d.json");

// One run of the hydrostatic scene to t = 0.1 s, shared by the tests of this file.
class CheckpointValidation : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir;
    const auto r = run_cdmpm({"run", kScene, "--out", *dir_ / "run", "--quiet", "--set", "time.end=0.1"});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    bytes_ = read_bytes(*dir_ / "run/checkpoint.bin");
  }
  static void TearDownTestSuite() { delete dir_; }
  static std::string write(const std::string& name, const std::string& data) {
    std::ofstream(*dir_ / name, std::ios::binary) << data;
    return *dir_ / name;
  }
  // Reads and validates `path` against the scene; rethrows what they throw.
  static void load(const std::string& path) {
    const Scene scene = load_scene(kScene, {"time.end=0.1"});
    Particles<2> p;
    const CheckpointMeta m = read_checkpoint(path, p);
    validate_checkpoint(path, m, p, scene);
  }
  // `data` with its trailing CRC-32 recomputed, as a forger would.
  static std::string with_crc(std::string data) {
    const uint32_t crc = crc32_update(0, data.data(), data.size() - 4);
    std::memcpy(data.data() + data.size() - 4, &crc, 4);
    return data;
  }
  // The checkpoint after `edit` of its metadata and particles, written with a valid checksum.
  static std::string forged(const std::function<void(CheckpointMeta&, Particles<2>&)>& edit) {
    Particles<2> p;
    CheckpointMeta m = read_checkpoint(*dir_ / "run/checkpoint.bin", p);
    edit(m, p);
    write_checkpoint(*dir_ / "forged.bin", p, m);
    return *dir_ / "forged.bin";
  }
  static inline TempDir* dir_ = nullptr;
  static inline std::string bytes_;
};

TEST_F(CheckpointValidation, TheRunsOwnCheckpointLoads) {
  EXPECT_EQ(bytes_.substr(0, 8), "CDMPMCKA");
  EXPECT_NO_THROW(load(*dir_ / "run/checkpoint.bin"));
}

TEST_F(CheckpointValidation, AnySingleByteFlipIsRefused) {
  const size_t n = bytes_.size();
  for (size_t k = 0; k < 400; ++k) {
    const size_t pos = k < 100 ? k : (k * 7919) % n;  // the whole header, then spread over the file
    std::string data = bytes_;
    data[pos] = static_cast<char>(data[pos] ^ (1 + k % 255));
    EXPECT_THROW(load(write("flip.bin", data)), CheckpointError) << "byte " << pos << " of " << n;
  }
}

TEST_F(CheckpointValidation, AnyTruncationIsRefused) {
  const size_t n = bytes_.size();
  for (size_t k = 0; k < 300; ++k) {
    const size_t len = k < 100 ? k : n - 1 - (k * 104729) % n;
    EXPECT_THROW(load(write("cut.bin", bytes_.substr(0, len))), CheckpointError) << "length " << len << " of " << n;
  }
}

// Eight 0xff bytes at every offset of the header and many later ones, checksum recomputed: a length field
// becomes huge and must be refused before it is allocated; any other field may load or be refused.
TEST_F(CheckpointValidation, ForgedLengthsAreRefusedBeforeAllocating) {
  const size_t n = bytes_.size();
  int refused = 0;
  for (size_t k = 0; k < 600; ++k) {
    const size_t pos = k < 400 ? k : 400 + (k * 7919) % (n - 412);
    if (pos + 8 > n - 4) continue;
    std::string data = bytes_;
    std::memset(data.data() + pos, 0xff, 8);
    try {
      load(write("forged_len.bin", with_crc(data)));
    } catch (const CheckpointError&) {
      ++refused;
    } catch (const std::exception& e) {
      ADD_FAILURE() << "offset " << pos << ": " << e.what();
    }
  }
  EXPECT_GT(refused, 300);
}

TEST_F(CheckpointValidation, ForgedValuesAreRefused) {
  const double nan = std::nan("");
  const std::vector<std::pair<std::string, std::function<void(CheckpointMeta&, Particles<2>&)>>> cases = {
      {"NaN position", [&](auto&, auto& p) { p.x[3][0] = nan; }},
      {"far position", [](auto&, auto& p) { p.x[7][1] = 1e30; }},
      {"material id", [](auto&, auto& p) { p.material[5] = 7; }},
      {"zero mass", [](auto&, auto& p) { p.mass[1] = 0; }},
      {"negative J", [](auto&, auto& p) { p.J[2] = -1; }},
      {"NaN J", [&](auto&, auto& p) { p.J[2] = nan; }},
      {"NaN velocity", [&](auto&, auto& p) { p.v[0][1] = nan; }},
      {"NaN time", [&](auto& m, auto&) { m.time = nan; }},
      {"negative time", [](auto& m, auto&) { m.time = -1; }},
      {"negative frame index", [](auto& m, auto&) { m.frame_index = -4; }},
      {"frame outside the folder", [](auto& m, auto&) { m.frames.back().second = "../../x.vtu"; }},
      {"other scene", [](auto& m, auto&) { m.scene_fingerprint[0].second ^= 1; }},
  };
  for (const auto& [what, edit] : cases) {
    const std::string path = forged(edit);
    EXPECT_THROW(load(path), CheckpointError) << what;
  }
}

TEST_F(CheckpointValidation, FingerprintIgnoresOnlyTheResumableKeys) {
  const SceneFingerprint a = scene_fingerprint(load_scene(kScene));
  EXPECT_EQ(fingerprint_difference(a, scene_fingerprint(load_scene(
                                          kScene, {"time.end=9", "time.frame_interval=0.5", "probes.interval=0.2"}))),
            "");
  EXPECT_EQ(fingerprint_difference(a, scene_fingerprint(load_scene(kScene, {"materials.water.density=500"}))),
            "materials.water differs");
  EXPECT_EQ(fingerprint_difference(a, scene_fingerprint(load_scene(kScene, {"time.cfl=0.3"}))), "time.cfl differs");
}

TEST_F(CheckpointValidation, ProgramRefusesCorruptCheckpointsAndAnotherScene) {
  auto resume = [&](const std::string& data, std::vector<std::string> extra = {}) {
    fs::remove_all(*dir_ / "resume");
    fs::copy(*dir_ / "run", *dir_ / "resume");
    std::ofstream(*dir_ / "resume/checkpoint.bin", std::ios::binary | std::ios::trunc) << data;
    std::vector<std::string> args = {"run", kScene, "--resume", *dir_ / "resume", "--quiet", "--set", "time.end=0.2"};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_cdmpm(args);
  };
  auto r = resume(bytes_);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  for (size_t pos : {size_t(9), size_t(100), bytes_.size() / 2, bytes_.size() - 1}) {
    std::string data = bytes_;
    data[pos] = static_cast<char>(data[pos] ^ 0x40);
    r = resume(data);
    EXPECT_EQ(r.exit_code, 2) << pos << ": " << r.output;
    EXPECT_NE(r.output.find("checkpoint is corrupt"), std::string::npos) << r.output;
  }
  r = resume(bytes_.substr(0, bytes_.size() / 3));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  r = resume(bytes_, {"--set", "materials.water.density=500"});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("materials.water differs"), std::string::npos) << r.output;
  // A forged probes.csv size (valid checksum) must not grow probes.csv.
  const std::string big = read_bytes(forged([](auto& m, auto&) { m.probes_csv_bytes = uint64_t(1) << 40; }));
  r = resume(big);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_LT(fs::file_size(*dir_ / "resume/probes.csv"), 1u << 20);
}

}  // namespace
}  // namespace cdmpm::testing
