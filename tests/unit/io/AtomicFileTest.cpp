#include "io/AtomicFile.hpp"

#include "core/Error.hpp"
#include "ScratchDirectory.hpp"

#include <gtest/gtest.h>

#include <cstring>

#include <sys/stat.h>
#include <unistd.h>

namespace poro {
namespace {

using test::readAll;
using test::ScratchDirectory;
using test::contains;

TEST(AtomicFile, WritesContentAndLeavesNoTemporary) {
  ScratchDirectory dir;
  const auto file = dir / "case.pvd";
  const std::string content("binary\0content\nwith a NUL", 25);
  writeFileAtomically(file, content);
  EXPECT_EQ(readAll(file), content);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"case.pvd"});
}

TEST(AtomicFile, ReplacesExistingContent) {
  ScratchDirectory dir;
  const auto file = dir / "time";
  test::writeAll(file, "old content that is longer than the new one\n");
  writeFileAtomically(file, "new\n");
  EXPECT_EQ(readAll(file), "new\n");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"time"});
}

TEST(AtomicFile, TemporaryIsAHiddenSiblingWithThePid) {
  const auto temporary = temporarySibling("/a/b/fluid.vtp");
  EXPECT_EQ(temporary.parent_path(), "/a/b");
  EXPECT_EQ(temporary.filename().string(), ".fluid.vtp.tmp." + std::to_string(::getpid()));
}

TEST(AtomicFile, MissingDirectoryIsAnOutputErrorWithTheOsReason) {
  ScratchDirectory dir;
  const auto file = dir / "no/such/dir/case.pvd";
  try {
    writeFileAtomically(file, "x");
    FAIL() << "expected OutputError";
  } catch (const OutputError& e) {
    EXPECT_TRUE(contains(e.what(), file.string()));
    EXPECT_TRUE(contains(e.what(), std::strerror(ENOENT)));
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(AtomicFile, ParentThatIsAFileIsAnOutputError) {
  ScratchDirectory dir;
  test::writeAll(dir / "plain", "not a directory");
  EXPECT_THROW(writeFileAtomically(dir / "plain" / "case.pvd", "x"), OutputError);
}

TEST(AtomicFile, ReadOnlyDirectoryIsAnOutputError) {
  if (::geteuid() == 0) GTEST_SKIP() << "root ignores directory permissions";
  ScratchDirectory dir;
  const auto readOnly = dir / "readOnly";
  std::filesystem::create_directory(readOnly);
  std::filesystem::permissions(readOnly, std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
  try {
    writeFileAtomically(readOnly / "case.pvd", "x");
    FAIL() << "expected OutputError";
  } catch (const OutputError& e) {
    EXPECT_TRUE(contains(e.what(), (readOnly / "case.pvd").string()));
    EXPECT_TRUE(contains(e.what(), std::strerror(EACCES)));
  }
}

TEST(AtomicFile, RenameReplacesAnExistingDirectory) {
  ScratchDirectory dir;
  std::filesystem::create_directories(dir / "new/uniform");
  test::writeAll(dir / "new/uniform/time", "new");
  std::filesystem::create_directories(dir / "0.1/uniform");
  test::writeAll(dir / "0.1/stale.vtp", "stale");
  renameAtomically(dir / "new", dir / "0.1");
  EXPECT_EQ(readAll(dir / "0.1/uniform/time"), "new");
  EXPECT_FALSE(std::filesystem::exists(dir / "0.1/stale.vtp"));
  EXPECT_FALSE(std::filesystem::exists(dir / "new"));
}

TEST(AtomicFile, RenameToAFreeName) {
  ScratchDirectory dir;
  std::filesystem::create_directory(dir / "a");
  renameAtomically(dir / "a", dir / "b");
  EXPECT_TRUE(std::filesystem::is_directory(dir / "b"));
  EXPECT_FALSE(std::filesystem::exists(dir / "a"));
}

TEST(AtomicFile, RenameOfAMissingSourceIsAnOutputError) {
  ScratchDirectory dir;
  std::filesystem::create_directory(dir / "keep");
  try {
    renameAtomically(dir / "missing", dir / "keep");
    FAIL() << "expected OutputError";
  } catch (const OutputError& e) {
    EXPECT_TRUE(contains(e.what(), (dir / "missing").string()));
  }
  EXPECT_TRUE(std::filesystem::is_directory(dir / "keep")) << "target must survive a failed rename";
}

TEST(AtomicFile, AFailedReplaceKeepsTheOldDirectory) {
  // A rename across file systems fails after the target was dealt with: the old directory must still be there
  // (it used to be deleted first, so an output error lost a time directory).
  const std::filesystem::path otherDevice = "/dev/shm";
  ScratchDirectory dir;
  struct stat a {}, b {};
  if (::stat(otherDevice.c_str(), &a) != 0 || ::stat(dir.path().c_str(), &b) != 0 || a.st_dev == b.st_dev)
    GTEST_SKIP() << "needs " << otherDevice << " on another file system than " << dir.path();
  const auto from = otherDevice / ("porosph-new-" + std::to_string(::getpid()));
  std::filesystem::create_directories(from);
  test::writeAll(from / "fluid.vtp", "new");
  std::filesystem::create_directories(dir / "0.2");
  test::writeAll(dir / "0.2/fluid.vtp", "old");
  EXPECT_THROW(renameAtomically(from, dir / "0.2"), OutputError);
  std::filesystem::remove_all(from);
  EXPECT_EQ(readAll(dir / "0.2/fluid.vtp"), "old");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"0.2"}) << "nothing left aside";
}

} // namespace
} // namespace poro
