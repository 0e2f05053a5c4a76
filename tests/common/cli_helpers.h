// cli_helpers.h - helpers for end-to-end tests: run the cdmpm program, read probes.csv and summary.json.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "io/checkpoint.h"
#include "io/csv_table.h"

namespace cdmpm::testing {

namespace fs = std::filesystem;

struct CliResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};

// Placed before a test's checks of the one-process output layout (a frame as particles_NNNN.vtu, the checkpoint's
// index naming its pieces), so that the checks above it run in both builds: a program built with MPI writes per-rank
// pieces even as one process (particles_NNNN.pvtu with particles_NNNN_r0.vtu, checkpoint_a_r0.bin;
// docs/architecture.md), which the tests labelled mpi check instead.
#ifdef CDMPM_MPI
#define SKIP_IN_MPI_BUILD_LAYOUT() \
  GTEST_SKIP() << "reads the one-process output layout; a program built with MPI writes per-rank pieces (tests labelled mpi)"
#else
#define SKIP_IN_MPI_BUILD_LAYOUT() static_cast<void>(0)
#endif

inline std::string source_path(const std::string& rel) { return std::string(CDMPM_SOURCE_DIR) + "/" + rel; }

// "key=value" for an override (--set, load_scene), the value with 17 significant digits (a double round trip).
inline std::string set_value(const std::string& key, double value) {
  std::ostringstream os;
  os.precision(17);
  os << key << '=' << value;
  return os.str();
}

// A fresh, empty temporary directory, removed when the object dies.
struct TempDir {
  fs::path path;
  TempDir() {
    std::random_device rd;
    path = fs::temp_directory_path() / ("cdmpm_test_" + std::to_string(rd()) + std::to_string(rd()));
    fs::create_directories(path);
  }
  ~TempDir() { std::error_code ec; fs::remove_all(path, ec); }
  std::string operator/(const std::string& s) const { return (path / s).string(); }
};

inline std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// Runs `program` with `args` (each quoted for the shell); returns its exit code and its stdout and stderr.
inline CliResult run_program(const std::string& program, const std::vector<std::string>& args) {
  TempDir log;
  std::string cmd = quote(program);
  // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on " " + quote(a).
  for (const auto& a : args) cmd.append(" ").append(quote(a));
  cmd.append(" > ").append(quote(log / "out.txt")).append(" 2>&1");
  const int status = std::system(cmd.c_str());
  CliResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(log / "out.txt");
  std::stringstream ss;
  ss << in.rdbuf();
  r.output = ss.str();
  return r;
}

inline CliResult run_cdmpm(const std::vector<std::string>& args) { return run_program(CDMPM_BINARY, args); }

// Runs `scene` with the arguments `common` three ways, for a bitwise comparison: into dir/full to t_end on
// `threads` threads, into dir/other to t_end on `other_threads`, and into dir/half to t_half, then resumed there
// to t_end on `threads`. Returns the first failing run's output, or "" if all three exit with 0.
inline std::string run_straight_other_threads_and_resumed(const TempDir& dir, const std::string& scene,
                                                          const std::vector<std::string>& common,
                                                          const std::string& threads, const std::string& other_threads,
                                                          const std::string& t_half, const std::string& t_end) {
  auto args = [&](std::vector<std::string> a) { a.insert(a.end(), common.begin(), common.end()); return a; };
  const std::vector<std::vector<std::string>> runs = {
      {"run", scene, "--out", dir / "full", "--threads", threads, "--set", "time.end=" + t_end},
      {"run", scene, "--out", dir / "other", "--threads", other_threads, "--set", "time.end=" + t_end},
      {"run", scene, "--out", dir / "half", "--threads", threads, "--set", "time.end=" + t_half},
      {"run", scene, "--resume", dir / "half", "--threads", threads, "--set", "time.end=" + t_end}};
  for (const auto& a : runs) {
    const CliResult r = run_cdmpm(args(a));
    if (r.exit_code != 0) return r.output.empty() ? "exit code " + std::to_string(r.exit_code) : r.output;
  }
  return "";
}

// probes.csv as column name -> values.
inline std::map<std::string, std::vector<double>> read_probes(const std::string& path) {
  const CsvTable table = read_csv_table(path);
  std::map<std::string, std::vector<double>> cols;
  for (const std::string& name : table.header) cols[name] = table.numbers(name);
  return cols;
}

inline nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

inline std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Expects the particle states of checkpoints a and b to be bitwise identical.
template <int dim>
inline void expect_same_particles(const std::string& a, const std::string& b) {
  Particles<dim> pa, pb;
  read_checkpoint(a, pa);
  read_checkpoint(b, pb);
  ASSERT_EQ(pa.size(), pb.size());
  auto same = [](const auto& x, const auto& y) {
    return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0;
  };
  EXPECT_TRUE(same(pa.id, pb.id));
  EXPECT_TRUE(same(pa.x, pb.x));
  EXPECT_TRUE(same(pa.v, pb.v));
  EXPECT_TRUE(same(pa.C, pb.C));
  EXPECT_TRUE(same(pa.mass, pb.mass));
  EXPECT_TRUE(same(pa.J, pb.J));
  EXPECT_TRUE(same(pa.material, pb.material));
  EXPECT_TRUE(same(pa.F, pb.F));
  EXPECT_TRUE(same(pa.alpha, pb.alpha));
}

}  // namespace cdmpm::testing
