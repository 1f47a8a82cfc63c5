// A run killed or failing while it writes a time directory leaves every earlier one complete, and the next
// start cleans up what it left (io/TimeDirectory.hpp: recoverInterruptedWrites).

#include "io/TimeDirectory.hpp"

#include "core/Error.hpp"
#include "physics/FieldNames.hpp"
#include "ScratchDirectory.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

#include <sys/wait.h>
#include <unistd.h>

namespace poro {
namespace {

using test::readAll;
using test::ScratchDirectory;

ParticleSystem twoParticles() {
  ParticleSystem ps(0.01);
  ParticleSet& fluid = ps.add("fluid", SetKind::Fluid);
  fluid.resize(2);
  fluid.x()[1] = Vec3(0.02, 0, 0);
  fluid.integer(field::id) = {0, 1};
  return ps;
}

/// A process id that no longer runs: a child that has exited and been reaped.
pid_t deadProcess() {
  const pid_t child = ::fork();
  if (child == 0) std::_Exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  return child;
}

bool has(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

TEST(TimeDirectoryRecovery, RestoresATimeDirectoryCaughtBeingReplaced) {
  ScratchDirectory dir;
  std::filesystem::create_directories(dir / ".0.2.old/uniform");
  test::writeAll(dir / ".0.2.old/uniform/time", "time: 0.2\nstep: 2\ndeltaT: 0.1\n");
  test::writeAll(dir / ".0.2.old/fluid.vtp", "old");
  recoverInterruptedWrites(dir.path());
  EXPECT_EQ(readAll(dir / "0.2/fluid.vtp"), "old");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"0.2"});
}

TEST(TimeDirectoryRecovery, DropsTheOldCopyWhenTheNewDirectoryIsComplete) {
  ScratchDirectory dir;
  for (const char* d : {".0.2.old/uniform", "0.2/uniform"}) std::filesystem::create_directories(dir / d);
  test::writeAll(dir / ".0.2.old/fluid.vtp", "old");
  test::writeAll(dir / "0.2/fluid.vtp", "new");
  test::writeAll(dir / "0.2/uniform/time", "time: 0.2\nstep: 2\ndeltaT: 0.1\n");
  recoverInterruptedWrites(dir.path());
  EXPECT_EQ(readAll(dir / "0.2/fluid.vtp"), "new");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"0.2"});
}

TEST(TimeDirectoryRecovery, RemovesUnfinishedDirectoriesAndStalePvdTemporaries) {
  ScratchDirectory dir;
  std::filesystem::create_directories(dir / ".0.3.tmp/uniform");
  const std::string stale = ".case.pvd.tmp." + std::to_string(deadProcess());
  const std::string live = ".case.pvd.tmp." + std::to_string(::getppid()); // a running writer keeps its file
  test::writeAll(dir / stale, "<VTKFile");
  test::writeAll(dir / live, "<VTKFile");
  test::writeAll(dir / "case.pvd", "<VTKFile");
  recoverInterruptedWrites(dir.path());
  const auto names = dir.entries();
  EXPECT_FALSE(has(names, ".0.3.tmp"));
  EXPECT_FALSE(has(names, stale));
  EXPECT_TRUE(has(names, live));
  EXPECT_TRUE(has(names, "case.pvd"));
}

TEST(TimeDirectoryRecovery, AFailedReplaceKeepsTheOldDirectoryAndRemovesTheNewOne) {
  // An immutable old directory cannot be exchanged: the write fails with an output error, and both the old
  // directory and nothing else remain (it used to delete the old files first and keep the complete .0.tmp).
  ScratchDirectory dir;
  TimeWriter::writeAll(dir.path(), twoParticles(), RunState{}, false);
  const std::string before = readAll(dir / "0/fluid.vtp");
  const std::string lock = "chattr +i '" + (dir / "0").string() + "' 2>/dev/null";
  if (std::system(lock.c_str()) != 0) GTEST_SKIP() << "chattr +i is not available here (needs root and ext4)";
  ParticleSystem moved = twoParticles();
  moved.find("fluid")->x()[0] = Vec3(0, 0.5, 0);
  EXPECT_THROW(TimeWriter::writeAll(dir.path(), moved, RunState{}, false), OutputError);
  const std::string unlock = "chattr -i '" + (dir / "0").string() + "'";
  ASSERT_EQ(std::system(unlock.c_str()), 0);
  EXPECT_EQ(readAll(dir / "0/fluid.vtp"), before);
  EXPECT_FALSE(has(dir.entries(), ".0.tmp"));
}

} // namespace
} // namespace poro
