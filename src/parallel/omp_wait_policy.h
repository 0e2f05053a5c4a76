// omp_wait_policy.h - OpenMP threads that share their cores with other work must not spin.
//
// GNU OpenMP (libgomp) lets an idle thread spin at each barrier for up to GOMP_SPINCOUNT iterations (300,000
// by default, a few hundred microseconds) before it sleeps. When the cores are busy with other processes a
// spinning thread takes the time slice of the thread it waits for, and `--threads 2` ran 20-40 times slower
// than `--threads 1` on a loaded machine. libgomp reads its environment in a library constructor, before
// main() runs, so the only way to change the policy from inside the program is to set the variable and
// execute the program again: choose_omp_wait_policy() does so once, at the start of main(), unless the user
// set OMP_WAIT_POLICY or GOMP_SPINCOUNT (which are then respected as given). The choice is a short spin,
// GOMP_SPINCOUNT=1000 (a few microseconds), then sleep: on idle cores the threads are still awake for the next
// parallel region of the step (a fully passive wait made `--threads 2` 1.3 times slower than `--threads 1`
// there), and on loaded cores they give their time slice up almost at once (docs/performance.md).
#pragma once

namespace cdmpm {

// The variable and value set when the user set neither OMP_WAIT_POLICY nor GOMP_SPINCOUNT.
inline constexpr const char* kOmpWaitVariable = "GOMP_SPINCOUNT";
inline constexpr const char* kOmpWaitValue = "1000";

// Sets kOmpWaitVariable=kOmpWaitValue and re-executes /proc/self/exe with `argv` if the user set neither
// variable. Returns (without a change of policy) if the re-execution fails.
void choose_omp_wait_policy(char** argv);

}  // namespace cdmpm
