#include "io/OutputDirectory.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace poro {

namespace fs = std::filesystem;

std::string whyDirectoryFails(const fs::path& dir, const std::error_code& ec) {
  std::error_code ignored;
  fs::path existing = dir;
  while (!existing.empty() && !fs::exists(existing, ignored)) existing = existing.parent_path();
  if (existing.empty()) return dir.string() + ": cannot create directory (" + ec.message() + ")";
  if (!fs::is_directory(existing, ignored))
    return existing.string() + " is a file, not a directory, so " + dir.string() +
           " cannot be created: rename or remove the file";
  if (::access(existing.c_str(), W_OK) != 0)
    return existing.string() + ": no permission to create " + dir.lexically_relative(existing).string() +
           " in this directory (" + std::strerror(errno) + "); give the user write permission";
  return dir.string() + ": cannot create directory (" + ec.message() + ")";
}

} // namespace poro
