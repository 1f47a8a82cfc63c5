#pragma once
/// Which time directories a post-processing run reads, the OpenFOAM way: all of them, `-latestTime`, or
/// `-time` with a comma-separated list of times and ranges ("0.5", "0.5:2", ":1", "2:", "0,0.5:1").
/// Unlike io's listTimeDirectories it also sees the directories it cannot read, so they can be named.

#include "core/Arguments.hpp"
#include "core/Error.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace poro {

struct TimeCandidate {
  enum class State {
    Complete,   ///< has uniform/time
    NoRunState, ///< named like a time but without uniform/time (partial, or copied by hand)
    Unfinished  ///< `.<time>.tmp`: being written, or left by a run killed while writing it
  };
  std::string name; ///< the directory name (".0.5.tmp" for an unfinished one)
  double time = 0.0;
  State state = State::Complete;
};

/// Every directory of `caseDir` named by a time, complete or not, by increasing time.
std::vector<TimeCandidate> scanTimeDirectories(const std::filesystem::path& caseDir);

/// A parsed -time argument. Bounds are inclusive; a value matches a time within 1e-10 relative (timeName's
/// precision).
class TimeSelector {
public:
  /// Throws InputError naming the option for an empty item, a non-number or a range whose start exceeds its end.
  static TimeSelector parse(const std::string& spec, const std::string& option = "-time");
  bool selects(double time) const;
  /// The single values of the list ("0.5", not ranges) that none of `times` matches.
  std::vector<std::string> unmatchedValues(const std::vector<double>& times) const;

private:
  struct Item {
    double lo, hi;
    bool single;
    std::string text;
  };
  std::vector<Item> items_;
};

struct TimeSelection {
  std::vector<TimeCandidate> complete; ///< to read, by increasing time
  std::vector<std::string> warnings;   ///< selected directories that cannot be read, unmatched -time values
};

/// Applies -time (`selector`) and -latestTime to `candidates` (scanTimeDirectories order); with neither, all
/// are selected. -latestTime adds the latest complete directory, and warns about incomplete ones after it.
/// Throws InputError when nothing complete is selected; `caseDir` and the available times are named.
TimeSelection selectTimes(const std::vector<TimeCandidate>& candidates, const std::optional<TimeSelector>& selector,
                          bool latestTime, const std::filesystem::path& caseDir);

/// The -time and -latestTime options of a post-processing utility; `verb` says what it does with a time ("analyse").
std::vector<Arguments::Option> timeOptions(const std::string& verb);
/// selectTimes for a utility's -time and -latestTime (timeOptions), its warnings logged.
TimeSelection selectTimes(const Arguments& args, const std::filesystem::path& caseDir);
/// selectTimes over the times of a case that may be decomposed: its own time directories and, where it has none of
/// that time, processor0's (io/ProcessorDirectories.hpp), so a utility that reads both sees every time once.
TimeSelection selectTimesWithSubdomains(const Arguments& args, const std::filesystem::path& caseDir);
/// The InputError of a utility that could read none of the `selected` time directories (each named in a warning).
InputError noneReadable(const std::filesystem::path& caseDir, std::size_t selected);

} // namespace poro
