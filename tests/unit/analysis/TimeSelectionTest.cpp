// -time, -latestTime and the time directories a case holds, including those that cannot be read.

#include "analysis/TimeSelection.hpp"
#include "../io/ScratchDirectory.hpp"
#include "core/Error.hpp"

#include <gtest/gtest.h>

namespace poro::test {
namespace {

namespace fs = std::filesystem;

TEST(TimeSelector, RangesListsAndSingleTimes) {
  const TimeSelector range = TimeSelector::parse("0.5:2");
  EXPECT_TRUE(range.selects(0.5));
  EXPECT_TRUE(range.selects(1.0));
  EXPECT_TRUE(range.selects(2.0));
  EXPECT_FALSE(range.selects(0.4));
  EXPECT_FALSE(range.selects(2.1));
  EXPECT_TRUE(TimeSelector::parse(":1").selects(0.0));
  EXPECT_FALSE(TimeSelector::parse(":1").selects(1.5));
  EXPECT_TRUE(TimeSelector::parse("2:").selects(1e9));
  const TimeSelector list = TimeSelector::parse("0, 0.3 ,1:1.5");
  EXPECT_TRUE(list.selects(0.0));
  EXPECT_TRUE(list.selects(0.1 + 0.2)); // 0.30000000000000004: a time is matched within 1e-10
  EXPECT_TRUE(list.selects(1.25));
  EXPECT_FALSE(list.selects(0.5));
  EXPECT_EQ(list.unmatchedValues({0.0, 0.5, 1.0}), std::vector<std::string>{"0.3"});
}

TEST(TimeSelector, MalformedSpecificationsNameTheOption) {
  for (const std::string bad : {"", "a", "2:1", "0.5,", ",1", "1:x", "nan", "1:2:3"}) {
    try {
      TimeSelector::parse(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const InputError& e) {
      EXPECT_TRUE(contains(e.what(), "-time '" + bad + "'"));
    }
  }
}

/// 0 and 0.5 complete, 1 without uniform/time, .1.5.tmp unfinished, and directories that are no time.
void makeTimes(const ScratchDirectory& dir) {
  for (const std::string name : {"0", "0.5", "1", ".1.5.tmp", "constant", "1x", ".hidden"})
    fs::create_directories(dir / name);
  for (const std::string name : {"0", "0.5"}) {
    fs::create_directories(dir / name / "uniform");
    writeAll(dir / name / "uniform" / "time", "time: " + name + "\n");
  }
  writeAll(dir / "2", "a file, not a directory");
}

TEST(TimeSelection, ScanSeesIncompleteAndUnfinishedDirectories) {
  ScratchDirectory dir;
  makeTimes(dir);
  const auto times = scanTimeDirectories(dir.path());
  ASSERT_EQ(times.size(), 4u);
  EXPECT_EQ(times[0].name, "0");
  EXPECT_EQ(times[1].name, "0.5");
  EXPECT_EQ(times[2].name, "1");
  EXPECT_EQ(times[2].state, TimeCandidate::State::NoRunState);
  EXPECT_EQ(times[3].name, ".1.5.tmp");
  EXPECT_EQ(times[3].state, TimeCandidate::State::Unfinished);
  EXPECT_DOUBLE_EQ(times[3].time, 1.5);
}

TEST(TimeSelection, AllTimesWarnAboutTheUnreadableOnesByName) {
  ScratchDirectory dir;
  makeTimes(dir);
  const TimeSelection all = selectTimes(scanTimeDirectories(dir.path()), std::nullopt, false, dir.path());
  ASSERT_EQ(all.complete.size(), 2u);
  ASSERT_EQ(all.warnings.size(), 2u);
  EXPECT_TRUE(contains(all.warnings[0], (dir / "1").string() + ": incomplete time directory (no uniform/time)"));
  EXPECT_TRUE(contains(all.warnings[1], (dir / ".1.5.tmp").string() + ": unfinished time directory"));
}

TEST(TimeSelection, LatestTimeIsTheLatestCompleteOne) {
  ScratchDirectory dir;
  makeTimes(dir);
  const TimeSelection latest = selectTimes(scanTimeDirectories(dir.path()), std::nullopt, true, dir.path());
  ASSERT_EQ(latest.complete.size(), 1u);
  EXPECT_EQ(latest.complete[0].name, "0.5");
  EXPECT_EQ(latest.warnings.size(), 2u); // the later, unreadable ones
  const auto both = selectTimes(scanTimeDirectories(dir.path()), TimeSelector::parse("0"), true, dir.path());
  EXPECT_EQ(both.complete.size(), 2u);
}

TEST(TimeSelection, RangeWithUnmatchedValueWarns) {
  ScratchDirectory dir;
  makeTimes(dir);
  const auto selection =
      selectTimes(scanTimeDirectories(dir.path()), TimeSelector::parse("0.5,0.7"), false, dir.path());
  ASSERT_EQ(selection.complete.size(), 1u);
  ASSERT_EQ(selection.warnings.size(), 1u);
  EXPECT_TRUE(contains(selection.warnings[0], "no time directory 0.7"));
}

TEST(TimeSelection, NothingReadableIsAnInputErrorThatSaysWhy) {
  ScratchDirectory dir;
  makeTimes(dir);
  const auto times = scanTimeDirectories(dir.path());
  try {
    selectTimes(times, TimeSelector::parse("0.7"), false, dir.path());
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "matches the -time selection"));
    EXPECT_TRUE(contains(e.what(), "no time directory 0.7"));
    EXPECT_TRUE(contains(e.what(), "can be read: 0, 0.5"));
  }
  try {
    selectTimes(times, TimeSelector::parse("1"), false, dir.path());
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "no uniform/time"));
  }
  ScratchDirectory empty;
  try {
    selectTimes(scanTimeDirectories(empty.path()), std::nullopt, false, empty.path());
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "no time directories; run sampleParticles"));
  }
}

} // namespace
} // namespace poro::test
