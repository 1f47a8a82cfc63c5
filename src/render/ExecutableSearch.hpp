#pragma once
/// Finding the helper programs renderCase runs (xvfb-run, ffmpeg), which PoroSPH does not install.

#include <string>

namespace poro {

/// The first executable file `name` in the directories of PATH (/usr/bin:/bin without PATH; an empty entry is the
/// current directory, as for the shell), or "" when there is none.
std::string findOnPath(const std::string& name);

} // namespace poro
