#include "io/AtomicFile.hpp"

#include "core/Error.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

namespace poro {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(const fs::path& path, const std::string& what, int error) {
  throw OutputError(path.string() + ": " + what + " (" + std::strerror(error) + ")");
}

void removeQuietly(const fs::path& path) {
  std::error_code ignored;
  fs::remove(path, ignored);
}

/// Writes all of `size` bytes, retrying on short writes and EINTR; returns 0 or the errno.
int writeAll(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t written = ::write(fd, data, size);
    if (written < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    data += written;
    size -= static_cast<std::size_t>(written);
  }
  return 0;
}

int fsyncRetrying(int fd) {
  while (::fsync(fd) != 0) {
    if (errno != EINTR) return errno;
  }
  return 0;
}

/// Makes the rename itself durable; failure here is not worth an error (the data are on disk).
void syncDirectory(const fs::path& dir) {
  const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  fsyncRetrying(fd);
  ::close(fd);
}

/// Where renameAtomically puts an old target aside on file systems without exchange (recoverInterruptedWrites).
fs::path asideName(const fs::path& path) { return path.parent_path() / ("." + path.filename().string() + ".old"); }

} // namespace

fs::path temporarySibling(const fs::path& path) {
  return path.parent_path() / ("." + path.filename().string() + ".tmp." + std::to_string(::getpid()));
}

void commitTemporaryFile(const fs::path& temporary, const fs::path& path) {
  const int fd = ::open(temporary.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    const int error = errno;
    removeQuietly(temporary);
    fail(path, "cannot reopen temporary file " + temporary.string(), error);
  }
  const int syncError = fsyncRetrying(fd);
  ::close(fd);
  if (syncError != 0) {
    removeQuietly(temporary);
    fail(path, "cannot flush to disk", syncError);
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const int error = errno;
    removeQuietly(temporary);
    fail(path, "cannot replace file", error);
  }
  syncDirectory(path.parent_path());
}

void writeFileAtomically(const fs::path& path, const std::string& content) {
  const fs::path temporary = temporarySibling(path);
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) fail(path, "cannot create file", errno);
  int error = writeAll(fd, content.data(), content.size());
  if (error == 0) error = fsyncRetrying(fd);
  // close() can report a deferred write error (NFS), so its result counts too.
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error != 0) {
    removeQuietly(temporary);
    fail(path, "cannot write file", error);
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    error = errno;
    removeQuietly(temporary);
    fail(path, "cannot replace file", error);
  }
  syncDirectory(path.parent_path());
}

void renameAtomically(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  if (!fs::exists(from, ec)) {
    throw OutputError(from.string() + ": cannot rename to " + to.string() + " (" +
                      (ec ? ec.message() : std::string(std::strerror(ENOENT))) + ")");
  }
  const auto cannot = [&](const std::string& what, int error) {
    throw OutputError(from.string() + ": cannot " + what + " " + to.string() + " (" + std::strerror(error) + ")");
  };
  if (!fs::exists(fs::symlink_status(to, ec))) {
    if (std::rename(from.c_str(), to.c_str()) != 0) cannot("rename to", errno);
    syncDirectory(to.parent_path());
    return;
  }
  // Never a moment without a complete `to`: exchange the two in one step (Linux), then delete the old one.
  if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_EXCHANGE) == 0) {
    syncDirectory(to.parent_path());
    fs::remove_all(from, ec); // now the old content; a kill before this leaves it to recoverInterruptedWrites
    return;
  }
  if (errno != EINVAL && errno != ENOSYS) cannot("exchange with", errno); // EXDEV: no rename could do it either
  // A file system without exchange: put the old one aside, move the new one in, delete the old one. A kill in
  // between leaves `.<name>.old`, which recoverInterruptedWrites restores when `to` is missing.
  const fs::path aside = asideName(to);
  fs::remove_all(aside, ec);
  if (std::rename(to.c_str(), aside.c_str()) != 0) cannot("move aside", errno);
  if (std::rename(from.c_str(), to.c_str()) != 0) {
    const int error = errno;
    if (std::rename(aside.c_str(), to.c_str()) != 0) // put the old one back: a failed replace keeps it
      cannot("rename to (the old one stays as " + aside.filename().string() + ", restored at the next start)", error);
    cannot("rename to", error);
  }
  syncDirectory(to.parent_path());
  fs::remove_all(aside, ec);
}

} // namespace poro
