// test_interrupt.cpp - signals: SIGINT during the default scene ends the run at the end of a step
// with exit code 130, a checkpoint and summary.json status "interrupted"; --resume from there reaches the
// same final particle state as a straight run, bit for bit. SIGTERM gives 143. After the first signal the
// default action is back, so a second Ctrl-C kills at once.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <thread>

#include "cli_helpers.h"
#include "io/checkpoint.h"
#include "run/interrupt.h"

extern char** environ;

namespace cdmpm::testing {
namespace {

// Starts cdmpm with `args` in the background, stdout and stderr to `log`.
pid_t spawn_cdmpm(const std::vector<std::string>& args, const std::string& log) {
  std::vector<std::string> all = {CDMPM_BINARY};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&fa, 1, 2);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, CDMPM_BINARY, &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  return rc == 0 ? pid : -1;
}

// Waits until the run has written `lines` lines of probes.csv (it is stepping), at most 60 s.
bool wait_for_probe_lines(const std::string& csv, size_t lines) {
  for (int i = 0; i < 600; ++i) {
    const std::string text = read_bytes(csv);
    if (static_cast<size_t>(std::count(text.begin(), text.end(), '\n')) >= lines) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return false;
}

int wait_exit(pid_t pid, bool* signaled = nullptr) {
  int status = 0;
  waitpid(pid, &status, 0);
  if (signaled) *signaled = WIFSIGNALED(status);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

TEST(Interrupt, CtrlCLeavesAResumableCheckpointThatEndsBitForBitLikeAStraightRun) {
  TempDir dir;
  const std::vector<std::string> common = {source_path("scenes/calving_front_2d.json"), "--quiet", "--threads", "2",
                                           "--set", "time.end=0.5", "--set", "time.frame_interval=0.25",
                                           "--set", "output.frames=false"};
  auto args = [&](std::vector<std::string> a) { a.insert(a.begin() + 1, common.begin(), common.end()); return a; };
  const pid_t pid = spawn_cdmpm(args({"run", "--out", dir / "cut"}), dir / "cut.log");
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(wait_for_probe_lines(dir / "cut/probes.csv", 3));
  kill(pid, SIGINT);
  bool signaled = true;
  EXPECT_EQ(wait_exit(pid, &signaled), 130) << read_bytes(dir / "cut.log");
  EXPECT_FALSE(signaled);
  const auto s = read_json(dir / "cut/summary.json");
  EXPECT_EQ(s["status"], "interrupted");
  EXPECT_NE(s["reason"].get<std::string>().find("SIGINT"), std::string::npos);
  ASSERT_LT(s["sim_time"].get<double>(), 0.5);
  ASSERT_TRUE(fs::exists(dir / "cut/checkpoint.bin"));

  auto r = run_cdmpm(args({"run", "--resume", dir / "cut"}));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = run_cdmpm(args({"run", "--out", dir / "full"}));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  expect_same_particles<2>(dir / "cut/checkpoint.bin", dir / "full/checkpoint.bin");
  EXPECT_EQ(read_json(dir / "cut/summary.json")["steps"], read_json(dir / "full/summary.json")["steps"]);
  EXPECT_EQ(read_bytes(dir / "cut/probes.csv"), read_bytes(dir / "full/probes.csv"));
}

TEST(Interrupt, SigtermExitsWith143) {
  TempDir dir;
  const pid_t pid = spawn_cdmpm({"run", source_path("scenes/calving_front_2d.json"), "--quiet", "--out", dir / "out",
                                 "--set", "time.end=0.5", "--set", "time.frame_interval=0.25", "--set",
                                 "output.frames=false"},
                                dir / "log");
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(wait_for_probe_lines(dir / "out/probes.csv", 3));
  kill(pid, SIGTERM);
  EXPECT_EQ(wait_exit(pid), 143) << read_bytes(dir / "log");
  EXPECT_EQ(read_json(dir / "out/summary.json")["status"], "interrupted");
}

// In process: the first SIGINT only sets the flag and puts the default action back (a second one kills).
TEST(Interrupt, FirstSignalSetsTheFlagAndRestoresTheDefaultAction) {
  install_interrupt_handlers();
  struct sigaction now {};
  sigaction(SIGINT, nullptr, &now);
  EXPECT_NE(now.sa_handler, SIG_DFL);
  raise(SIGINT);
  EXPECT_EQ(interrupt_signal(), SIGINT);
  sigaction(SIGINT, nullptr, &now);
  EXPECT_EQ(now.sa_handler, SIG_DFL);
  signal(SIGTERM, SIG_DFL);
}

}  // namespace
}  // namespace cdmpm::testing
