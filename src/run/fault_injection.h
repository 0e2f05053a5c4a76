// fault_injection.h - a failure injected by the tests of failure handling (tests/mpi/fail_on_rank.sh,
// docs/architecture.md "Distributed runs"): with CDMPM_TEST_FAIL_RANK=R and CDMPM_TEST_FAIL_STEP=N in the
// environment, rank R (0 in one process) throws std::bad_alloc at the end of step N, as a failed allocation there
// would. Unset (every normal run), nothing happens. Malformed values are an input error (exit code 2).
#pragma once

#include <cstdlib>
#include <new>
#include <string>

#ifdef CDMPM_MPI
#include "parallel/communicator.h"
#endif
#include "scene/scene_reader.h"

namespace cdmpm {

class FaultInjection {
 public:
  static FaultInjection from_environment() {
    FaultInjection f;
    const char* rank = std::getenv("CDMPM_TEST_FAIL_RANK");
    const char* step = std::getenv("CDMPM_TEST_FAIL_STEP");
    if (!rank && !step) return f;
    if (!rank || !step)
      throw SceneError("CDMPM_TEST_FAIL_RANK and CDMPM_TEST_FAIL_STEP: expected both (a rank and a step, integers >= 0)");
    f.rank_ = parse("CDMPM_TEST_FAIL_RANK", rank);
    f.step_ = parse("CDMPM_TEST_FAIL_STEP", step);
    return f;
  }
  // Throws std::bad_alloc on the chosen rank at the end of the chosen step.
  void after_step(long long step) const {
#ifdef CDMPM_MPI
    const int me = mpi::rank();
#else
    const int me = 0;
#endif
    if (step_ >= 0 && step == step_ && me == rank_) throw std::bad_alloc();
  }

 private:
  static long long parse(const char* name, const char* text) {
    char* end = nullptr;
    const long long v = std::strtoll(text, &end, 10);
    if (*text == '\0' || *end != '\0' || v < 0)
      throw SceneError(std::string(name) + ": expected an integer >= 0, got '" + text + "'");
    return v;
  }
  long long rank_ = -1, step_ = -1;
};

}  // namespace cdmpm
