#include "core/StopSignals.hpp"

#include <csignal>
#include <cstring>

#include <unistd.h>

namespace poro::signals {

namespace {
volatile std::sig_atomic_t requested = 0;

/// Async-signal-safe: write(2) and _exit(2) only.
void say(const char* text) {
  const ssize_t ignored = ::write(2, text, std::strlen(text));
  (void)ignored;
}

extern "C" void recordSignal(int signal) {
  if (requested != 0) { // the user insists: stop now, without finishing the step
    say("\nSecond stop signal: stopping at once. Earlier time directories are intact; continue with "
        "startFrom latestTime in system/controlDict.\n");
    ::_exit(128 + signal);
  }
  requested = signal;
  say("\nStop requested: finishing the current step and writing it (signal again to stop at once).\n");
}
} // namespace

void installStopHandlers() {
  constexpr int kStopSignals[] = {SIGINT, SIGTERM, SIGHUP};
  struct sigaction action {};
  action.sa_handler = recordSignal;
  sigemptyset(&action.sa_mask);
  for (int signal : kStopSignals) sigaddset(&action.sa_mask, signal); // one handler at a time: the second waits
  action.sa_flags = SA_RESTART; // a stop request must not fail a write(2) in progress with EINTR
  for (int signal : kStopSignals) {
    struct sigaction before {};
    // A signal ignored by whoever started us (nohup ignores SIGHUP) stays ignored.
    if (sigaction(signal, nullptr, &before) == 0 && before.sa_handler == SIG_IGN) continue;
    sigaction(signal, &action, nullptr);
  }
}

int stopRequested() { return requested; }

const char* name(int signal) {
  switch (signal) {
  case SIGINT:
    return "SIGINT";
  case SIGTERM:
    return "SIGTERM";
  case SIGHUP:
    return "SIGHUP";
  default:
    return "a signal";
  }
}

} // namespace poro::signals
