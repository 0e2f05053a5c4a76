// omp_wait_policy.cpp - see omp_wait_policy.h.
#include "parallel/omp_wait_policy.h"

#include <unistd.h>

#include <cstdlib>

namespace cdmpm {

void choose_omp_wait_policy(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") || std::getenv("GOMP_SPINCOUNT")) return;
  if (setenv(kOmpWaitVariable, kOmpWaitValue, 1) != 0) return;
  execv("/proc/self/exe", argv);
}

}  // namespace cdmpm
