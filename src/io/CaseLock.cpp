#include "io/CaseLock.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace poro {

namespace {
/// What the file says about the holder ("poroSph, pid 1234"), or "" when it cannot be read.
std::string holderOf(int fd) {
  char text[256] = {};
  const ssize_t n = ::pread(fd, text, sizeof(text) - 1, 0);
  if (n <= 0) return "";
  std::string holder(text, static_cast<std::size_t>(n));
  while (!holder.empty() && (holder.back() == '\n' || holder.back() == '\r')) holder.pop_back();
  return holder;
}
} // namespace

std::filesystem::path CaseLock::file(const std::filesystem::path& caseDir) { return caseDir / ".poroSph.lock"; }

CaseLock::CaseLock(const std::filesystem::path& caseDir, const std::string& application) {
  if (!std::filesystem::is_directory(caseDir)) throw InputError(caseDir.string() + ": case directory not found");
  const std::filesystem::path path = file(caseDir);
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw OutputError(path.string() + ": cannot create the case's lock file (" + std::strerror(errno) + "); " +
                      application + " writes into the case and needs it writable");
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    const std::string holder = holderOf(fd_);
    ::close(fd_);
    fd_ = -1;
    if (error != EWOULDBLOCK)
      throw OutputError(path.string() + ": cannot lock the case (" + std::strerror(error) + ")");
    throw InputError(caseDir.string() + ": another program is writing this case (" +
                     (holder.empty() ? std::string("see ") + path.string() : holder) + "); " + application +
                     " would overwrite its time directories. Wait until it has finished, or stop it first");
  }
  // The note only serves a second writer's message: the lock holds without it.
  const std::string me = application + ", pid " + std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd_, 0) == 0) (void)!::pwrite(fd_, me.data(), me.size(), 0);
}

CaseLock::~CaseLock() {
  if (fd_ >= 0) ::close(fd_);
}

} // namespace poro
