#include "render/ExecutableSearch.hpp"

#include <cstdlib>
#include <filesystem>
#include <sstream>

#include <unistd.h>

namespace poro {

std::string findOnPath(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::stringstream list(path ? path : "/usr/bin:/bin");
  for (std::string dir; std::getline(list, dir, ':');) {
    const std::string candidate = (std::filesystem::path(dir.empty() ? "." : dir) / name).string();
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return "";
}

} // namespace poro
