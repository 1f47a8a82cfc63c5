#pragma once
/// An X display for VTK's OpenGL rendering. Debian's VTK 9.1 renders off screen only through GLX, so it needs an
/// X server even when no window opens (without one it aborts with "bad X server connection"). On a machine without
/// a display (CI, ssh) the program runs itself again under `xvfb-run -a`, a virtual X server.

namespace poro {

/// Returns when DISPLAY is set. Otherwise replaces the process by `xvfb-run -a <this program> <argv...>` (marking
/// the environment so it happens once); throws Error saying what to install when xvfb-run is missing or the
/// virtual display did not come up.
void ensureDisplay(int argc, char* argv[]);

} // namespace poro
