#include "analysis/TimeSelection.hpp"

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "io/ProcessorDirectories.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace poro {

namespace fs = std::filesystem;

namespace {

/// The rule of io/TimeDirectory.cpp: a name that starts with a digit and is a finite number.
bool isTimeName(const std::string& name, double& value) {
  if (name.empty() || !std::isdigit(static_cast<unsigned char>(name[0]))) return false;
  char* end = nullptr;
  value = std::strtod(name.c_str(), &end);
  return end && *end == '\0' && std::isfinite(value);
}

bool sameTime(double a, double b) { return std::abs(a - b) <= 1e-10 * std::max(1.0, std::abs(b)); }

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

/// "0, 0.1, 0.2, ..., 1.5 (16 times)": enough to see what -time could have said.
std::string describeTimes(const std::vector<TimeCandidate>& candidates) {
  std::vector<std::string> names;
  for (const TimeCandidate& c : candidates)
    if (c.state == TimeCandidate::State::Complete) names.push_back(c.name);
  if (names.empty()) return "none";
  std::string text;
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (names.size() > 8 && k == 3) {
      text += ", ...";
      k = names.size() - 2;
      continue;
    }
    text += (k == 0 ? "" : ", ") + names[k];
  }
  return names.size() > 8 ? text + " (" + std::to_string(names.size()) + " times)" : text;
}

std::string whyUnreadable(const fs::path& caseDir, const TimeCandidate& c) {
  const std::string dir = (caseDir / c.name).string();
  if (c.state == TimeCandidate::State::Unfinished)
    return dir + ": unfinished time directory (being written, or left by a run killed while writing it); skipped";
  return dir + ": incomplete time directory (no uniform/time); skipped";
}

} // namespace

std::vector<TimeCandidate> scanTimeDirectories(const fs::path& caseDir) {
  std::vector<TimeCandidate> result;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(caseDir, ec)) {
    if (!entry.is_directory(ec)) continue;
    const std::string name = entry.path().filename().string();
    double value = 0.0;
    if (isTimeName(name, value)) {
      const bool complete = fs::exists(entry.path() / "uniform" / "time", ec);
      result.push_back({name, value, complete ? TimeCandidate::State::Complete : TimeCandidate::State::NoRunState});
    } else if (name.size() > 5 && name.front() == '.' && name.compare(name.size() - 4, 4, ".tmp") == 0 &&
               isTimeName(name.substr(1, name.size() - 5), value)) {
      result.push_back({name, value, TimeCandidate::State::Unfinished});
    }
  }
  std::sort(result.begin(), result.end(), [](const TimeCandidate& a, const TimeCandidate& b) {
    return a.time != b.time ? a.time < b.time : a.state < b.state;
  });
  return result;
}

TimeSelector TimeSelector::parse(const std::string& spec, const std::string& option) {
  TimeSelector selector;
  const auto fail = [&](const std::string& why) -> void {
    throw InputError("option " + option + " '" + spec + "': " + why +
                     "; expected a comma-separated list of times and ranges, e.g. 0.5, 0.5:2, :1, 2:");
  };
  const auto number = [&](const std::string& text) {
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || !end || *end != '\0' || !std::isfinite(value)) fail("'" + text + "' is not a time");
    return value;
  };
  std::size_t start = 0;
  while (start <= spec.size()) {
    const std::size_t comma = std::min(spec.find(',', start), spec.size());
    const std::string item = trim(spec.substr(start, comma - start));
    start = comma + 1;
    if (item.empty()) fail("empty item");
    const std::size_t colon = item.find(':');
    Item range{0.0, 0.0, colon == std::string::npos, item};
    if (range.single) {
      range.lo = range.hi = number(item);
    } else {
      const std::string lo = trim(item.substr(0, colon)), hi = trim(item.substr(colon + 1));
      range.lo = lo.empty() ? -std::numeric_limits<double>::infinity() : number(lo);
      range.hi = hi.empty() ? std::numeric_limits<double>::infinity() : number(hi);
      if (range.lo > range.hi) fail("range " + item + " starts after it ends");
    }
    selector.items_.push_back(range);
  }
  return selector;
}

bool TimeSelector::selects(double time) const {
  for (const Item& item : items_) {
    if (item.single ? sameTime(time, item.lo)
                    : (time >= item.lo || sameTime(time, item.lo)) && (time <= item.hi || sameTime(time, item.hi)))
      return true;
  }
  return false;
}

std::vector<std::string> TimeSelector::unmatchedValues(const std::vector<double>& times) const {
  std::vector<std::string> unmatched;
  for (const Item& item : items_)
    if (item.single && std::none_of(times.begin(), times.end(), [&](double t) { return sameTime(t, item.lo); }))
      unmatched.push_back(item.text);
  return unmatched;
}

TimeSelection selectTimes(const std::vector<TimeCandidate>& candidates, const std::optional<TimeSelector>& selector,
                          bool latestTime, const fs::path& caseDir) {
  if (candidates.empty())
    throw InputError(caseDir.string() + ": no time directories; run sampleParticles (and poroSph) first");
  std::vector<bool> chosen(candidates.size(), !selector && !latestTime);
  if (selector)
    for (std::size_t k = 0; k < candidates.size(); ++k) chosen[k] = selector->selects(candidates[k].time);

  TimeSelection selection;
  if (latestTime) {
    std::size_t latest = candidates.size();
    for (std::size_t k = 0; k < candidates.size(); ++k)
      if (candidates[k].state == TimeCandidate::State::Complete) latest = k;
    if (latest < candidates.size()) chosen[latest] = true;
    for (std::size_t k = latest == candidates.size() ? 0 : latest + 1; k < candidates.size(); ++k)
      if (!chosen[k]) selection.warnings.push_back(whyUnreadable(caseDir, candidates[k]));
  }
  std::vector<std::string> unreadable;
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    if (!chosen[k]) continue;
    if (candidates[k].state == TimeCandidate::State::Complete)
      selection.complete.push_back(candidates[k]);
    else
      unreadable.push_back(whyUnreadable(caseDir, candidates[k]));
  }
  selection.warnings.insert(selection.warnings.end(), unreadable.begin(), unreadable.end());
  if (selector) {
    std::vector<double> times;
    for (const TimeCandidate& c : candidates) times.push_back(c.time);
    for (const std::string& value : selector->unmatchedValues(times))
      selection.warnings.push_back("no time directory " + value + " in " + caseDir.string() + " (-time)");
  }

  if (selection.complete.empty()) {
    std::string message = caseDir.string() + ": no readable time directory ";
    message += selector ? "matches the -time selection" : latestTime ? "for -latestTime" : "in the case";
    for (const std::string& why : selection.warnings) message += "\n  " + why;
    throw InputError(message + "\nTime directories that can be read: " + describeTimes(candidates));
  }
  return selection;
}

std::vector<Arguments::Option> timeOptions(const std::string& verb) {
  return {{"time", "RANGES", "times to " + verb + ": 0.5 | 0.5:2 | :1 | 2: (inclusive) | a comma-separated list (default: all)"},
          {"latestTime", "", verb + " the latest time directory (with -time: in addition)"}};
}

TimeSelection selectTimes(const Arguments& args, const fs::path& caseDir) {
  std::optional<TimeSelector> selector;
  if (args.has("time")) selector = TimeSelector::parse(args.value("time"));
  TimeSelection selection = selectTimes(scanTimeDirectories(caseDir), selector, args.has("latestTime"), caseDir);
  for (const std::string& warning : selection.warnings) log::warning(warning);
  return selection;
}

TimeSelection selectTimesWithSubdomains(const Arguments& args, const fs::path& caseDir) {
  std::optional<TimeSelector> selector;
  if (args.has("time")) selector = TimeSelector::parse(args.value("time"));
  std::vector<TimeCandidate> candidates = scanTimeDirectories(caseDir);
  const std::vector<fs::path> processors = listProcessorDirectories(caseDir);
  if (!processors.empty()) {
    for (const TimeCandidate& t : scanTimeDirectories(processors.front())) {
      const bool own = std::any_of(candidates.begin(), candidates.end(), [&](const TimeCandidate& c) {
        return c.name == t.name && c.state == TimeCandidate::State::Complete;
      });
      if (!own && t.state == TimeCandidate::State::Complete) candidates.push_back(t);
    }
    std::sort(candidates.begin(), candidates.end(), [](const TimeCandidate& a, const TimeCandidate& b) {
      return a.time != b.time ? a.time < b.time : a.state < b.state;
    });
  }
  TimeSelection selection = selectTimes(candidates, selector, args.has("latestTime"), caseDir);
  for (const std::string& warning : selection.warnings) log::warning(warning);
  return selection;
}

InputError noneReadable(const fs::path& caseDir, std::size_t selected) {
  return InputError(caseDir.string() + ": none of the " + std::to_string(selected) +
                    " selected time directories could be read (see the warnings above)");
}

} // namespace poro
