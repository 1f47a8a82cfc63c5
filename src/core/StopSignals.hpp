#pragma once
/// SIGINT, SIGTERM and SIGHUP (a closed terminal) as a polite request to stop: the handler only records the
/// signal; the time loop finishes its step, writes a time directory and exits (a killed run keeps a
/// restartable state). A second signal while the first is pending ends the process at once: time
/// directories are written under a temporary name and renamed when complete, so earlier ones stay intact.

namespace poro::signals {

/// Installs the handlers for SIGINT, SIGTERM and SIGHUP (one that is ignored, as nohup ignores SIGHUP, stays so).
void installStopHandlers();
/// The signal that asked the run to stop, or 0.
int stopRequested();
/// "SIGINT", "SIGTERM", "SIGHUP" or "a signal".
const char* name(int signal);

} // namespace poro::signals
