// Ctrl-C (SIGINT), SIGTERM and SIGHUP during a command: the command stops at its next check and
// removes what it had begun to write. A second signal ends the program at once.
#pragma once

#include <csignal>

namespace tsk::cli {

// Installs the handlers (the program does; tests running commands in-process do not), but for
// signals ignored when the program started.
void catch_interrupts();

// True once one of the signals came.
bool interrupted();

// Throws Cancelled once one of the signals came.
void stop_if_interrupted();

// Catches SIGINT for as long as it lives: a run called from Python, whose own handler cannot run
// while the run holds its thread. Unlike catch_interrupts, a second signal does not end the
// program, and the handler found is put back, the signal forgotten, when the scope ends; while it
// lives, interrupted() tells whether SIGINT came.
class InterruptScope {
 public:
  InterruptScope();
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;

 private:
  struct sigaction previous_;
};

}  // namespace tsk::cli
