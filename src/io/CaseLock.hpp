#pragma once
/// One writer per case: poroSph, sampleParticles and fluidSurface write time directories and case.pvd, and
/// poroSph's start-up recovery deletes the temporary files a writer leaves, so a second one on the same case
/// would destroy the first one's output. Each takes an exclusive lock (flock) on `<case>/.poroSph.lock` for its
/// lifetime; the kernel releases it when the process ends, however it ends. The file keeps the holder's pid and
/// name for the message. Readers (saturationAnalysis, renderCase, ParaView) need no lock.

#include "core/Error.hpp"

#include <filesystem>
#include <string>

namespace poro {

class CaseLock {
public:
  /// Takes the lock for `application`, or throws InputError naming the case and the process that holds it.
  /// Throws OutputError when the lock file cannot be created (a read-only case).
  CaseLock(const std::filesystem::path& caseDir, const std::string& application);
  ~CaseLock();
  CaseLock(const CaseLock&) = delete;
  CaseLock& operator=(const CaseLock&) = delete;

  /// The lock file of a case.
  static std::filesystem::path file(const std::filesystem::path& caseDir);

private:
  int fd_ = -1;
};

} // namespace poro
