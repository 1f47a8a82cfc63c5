#include "core/StopSignals.hpp"

#include <csignal>

namespace poro::signals {

namespace {
volatile std::sig_atomic_t requested = 0;

extern "C" void recordSignal(int signal) { requested = signal; }
} // namespace

void installStopHandlers() {
  std::signal(SIGINT, recordSignal);
  std::signal(SIGTERM, recordSignal);
}

int stopRequested() { return requested; }

const char* name(int signal) {
  switch (signal) {
  case SIGINT:
    return "SIGINT";
  case SIGTERM:
    return "SIGTERM";
  default:
    return "a signal";
  }
}

} // namespace poro::signals
