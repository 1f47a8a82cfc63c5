#pragma once
/// SIGINT and SIGTERM as a polite request to stop: the handler only records the signal; the time loop
/// finishes its step, writes a time directory and exits (a killed run keeps a restartable state).

namespace poro::signals {

/// Installs the handlers for SIGINT and SIGTERM.
void installStopHandlers();
/// The signal that asked the run to stop, or 0.
int stopRequested();
/// "SIGINT", "SIGTERM" or the number.
const char* name(int signal);

} // namespace poro::signals
