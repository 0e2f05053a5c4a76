// interrupt.h - SIGINT/SIGTERM end a run cleanly at the end of the current time step.
//
// install_interrupt_handlers() makes the first SIGINT or SIGTERM only set an atomic flag, which the runner's
// time loop reads once per step: the run then writes a checkpoint and summary.json (status "interrupted")
// and exits with 128 + the signal number (130 for SIGINT, 143 for SIGTERM), and can be resumed. The handler
// is installed with SA_RESETHAND, so the default action is back after the first signal: a second Ctrl-C
// kills the program at once.
#pragma once

namespace cdmpm {

void install_interrupt_handlers();

// The number of the first SIGINT/SIGTERM received since the handlers were installed, 0 if none.
int interrupt_signal();

// "SIGINT", "SIGTERM" or "a signal".
const char* interrupt_signal_name(int signal);

}  // namespace cdmpm
