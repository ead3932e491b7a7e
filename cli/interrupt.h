// Ctrl-C (SIGINT), SIGTERM and SIGHUP during a command: the command stops at its next check and
// removes what it had begun to write. A second signal ends the program at once.
#pragma once

namespace tsk::cli {

// Installs the handlers (the program does; tests running commands in-process do not), but for
// signals ignored when the program started.
void catch_interrupts();

// True once one of the signals came.
bool interrupted();

// Throws Cancelled once one of the signals came.
void stop_if_interrupted();

}  // namespace tsk::cli
