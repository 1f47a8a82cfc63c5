#include "render/HeadlessDisplay.hpp"

#include "core/Error.hpp"
#include "render/ExecutableSearch.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

namespace poro {

namespace {

const char* const kMarker = "POROSPH_UNDER_XVFB";

} // namespace

void ensureDisplay(int argc, char* argv[]) {
  const char* display = std::getenv("DISPLAY");
  if (display && *display) return;
  if (std::getenv(kMarker))
    throw Error("xvfb-run started no X display (DISPLAY is still unset); try: xvfb-run -a " + std::string(argv[0]));
  const std::string xvfbRun = findOnPath("xvfb-run");
  if (xvfbRun.empty())
    throw Error("no X display (DISPLAY is unset) and no xvfb-run: VTK renders through an X server even off screen. "
                "Install a virtual one (apt-get install xvfb xauth; ./Allrun does) or set DISPLAY");
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::string program = ec ? std::string(argv[0]) : self.string();
  std::vector<std::string> words{xvfbRun, "-a", "-s", "-screen 0 1920x1080x24 -nolisten tcp", program};
  for (int k = 1; k < argc; ++k) words.emplace_back(argv[k]);
  std::vector<char*> args;
  for (std::string& w : words) args.push_back(w.data());
  args.push_back(nullptr);
  ::setenv(kMarker, "1", 1);
  ::execv(xvfbRun.c_str(), args.data());
  throw Error("cannot run " + xvfbRun + ": " + std::strerror(errno));
}

} // namespace poro
