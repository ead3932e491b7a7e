#include "cli/interrupt.h"

#include <atomic>
#include <csignal>

#include "core/base/errors.h"

namespace tsk::cli {
namespace {

// Set from the signal handler, read by any thread: a lock-free atomic is safe for both.
std::atomic<bool> signalled{false};
static_assert(std::atomic<bool>::is_always_lock_free, "the signal handler needs a lock-free flag");

extern "C" void on_signal(int signal) {
  signalled.store(true);
  std::signal(signal, SIG_DFL);  // the next one ends the program
}

extern "C" void on_signal_in_scope(int) {
  signalled.store(true);
}

}  // namespace

void catch_interrupts() {
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) {
    // A signal the program was started ignoring stays ignored: nohup's SIGHUP, the SIGINT of a
    // job a script sent to the background.
    if (std::signal(signal, on_signal) == SIG_IGN) std::signal(signal, SIG_IGN);
  }
}

bool interrupted() {
  return signalled.load();
}

void stop_if_interrupted() {
  if (interrupted()) throw Cancelled();
}

InterruptScope::InterruptScope() {
  signalled.store(false);
  struct sigaction catcher = {};
  catcher.sa_handler = on_signal_in_scope;
  sigemptyset(&catcher.sa_mask);
  sigaction(SIGINT, &catcher, &previous_);
}

InterruptScope::~InterruptScope() {
  sigaction(SIGINT, &previous_, nullptr);
  signalled.store(false);
}

}  // namespace tsk::cli
