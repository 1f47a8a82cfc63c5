// io/CaseLock.hpp: one writer per case; the second is refused with the case and the holder named.

#include "io/CaseLock.hpp"
#include "ScratchDirectory.hpp"

#include <gtest/gtest.h>

#include <optional>
#include <unistd.h>

namespace poro {
namespace {

std::string refusal(const std::filesystem::path& dir, const std::string& application) {
  try {
    CaseLock second(dir, application);
  } catch (const InputError& e) {
    return e.what();
  }
  return "not refused";
}

TEST(CaseLock, ASecondWriterIsRefusedUntilTheFirstEnds) {
  const test::ScratchDirectory scratch;
  std::optional<CaseLock> first;
  first.emplace(scratch.path(), "poroSph");
  const std::string message = refusal(scratch.path(), "sampleParticles");
  EXPECT_NE(message.find(scratch.path().string() + ": another program is writing this case (poroSph, pid " +
                         std::to_string(::getpid()) + ")"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("sampleParticles would overwrite"), std::string::npos) << message;
  first.reset(); // the process ends or the lock goes out of scope: the next writer may start
  EXPECT_EQ(refusal(scratch.path(), "fluidSurface"), "not refused");
}

TEST(CaseLock, AMissingCaseIsNamed) {
  const test::ScratchDirectory scratch;
  EXPECT_NE(refusal(scratch.path() / "nowhere", "poroSph").find("nowhere: case directory not found"),
            std::string::npos);
}

} // namespace
} // namespace poro
