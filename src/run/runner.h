// runner.h - drives a simulation from t = 0 (or a checkpoint) to the scene's end time: picks each time step,
// lands on output times exactly, has the output files written (run/run_files.h), shows progress
// (run/progress.h), stops with status "unstable" and a clear reason if the state goes bad, and writes
// summary.json (run/summary.h).
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace cdmpm {

struct RunOptions {
  std::string out_dir;
  int threads = 0;       // 0 = OpenMP default
  bool resume = false;   // continue from out_dir/checkpoint.bin
  bool progress = true;  // progress line on stderr
  long long max_steps = 0;  // stop (status completed) after this many steps of this run; 0: run to the end time
  bool gather_output = false;  // distributed run: frames and checkpoint gathered on rank 0, not per-rank pieces (--gather-output)
  std::vector<std::string> command_line;  // recorded in run.json and summary.json
};

struct RunResult {
  std::string status;  // "completed", "unstable" or "interrupted" (SIGINT/SIGTERM, run/interrupt.h)
  std::string reason;
  int exit_code = 0;   // 0 completed, 3 unstable, 128 + signal number interrupted (130 SIGINT, 143 SIGTERM)
};

// Exceptions: CheckpointError (io/checkpoint_format.h) for a checkpoint that is corrupt or of another scene,
// std::runtime_error for I/O problems (unwritable output).
RunResult run_scene(const Scene& scene, const RunOptions& options);

}  // namespace cdmpm
