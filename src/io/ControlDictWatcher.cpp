#include "io/ControlDictWatcher.hpp"

#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "core/Log.hpp"

#include <fstream>
#include <sstream>

namespace poro {

namespace fs = std::filesystem;

namespace {

fs::file_time_type modificationTime(const fs::path& file) {
  std::error_code ec;
  const auto time = fs::last_write_time(file, ec);
  return ec ? fs::file_time_type{} : time;
}

const char* toString(TimeControl::StopAt s) {
  switch (s) {
  case TimeControl::StopAt::EndTime: return "endTime";
  case TimeControl::StopAt::WriteNow: return "writeNow";
  case TimeControl::StopAt::NoWriteNow: return "noWriteNow";
  case TimeControl::StopAt::NextWrite: return "nextWrite";
  }
  return "?";
}

const char* toString(TimeControl::WriteControl w) {
  return w == TimeControl::WriteControl::TimeStep ? "timeStep" : "runTime";
}

template <class T> void compare(std::ostringstream& out, const char* key, const T& before, const T& after) {
  if (!(before == after)) out << "  " << key << ' ' << before << " -> " << after << '\n';
}

ControlSettings settingsFrom(const Dictionary& dict) {
  ControlSettings settings{TimeControl::read(dict), OutputSettings::read(dict)};
  dict.checkUnknownKeys();
  return settings;
}

} // namespace

ControlSettings readControlDict(const fs::path& caseDir) {
  return settingsFrom(Dictionary::read((caseDir / "system" / "controlDict").string()));
}

ControlDictWatcher::ControlDictWatcher(const fs::path& caseDir)
    : caseDir_(caseDir), file_(caseDir / "system" / "controlDict"), seen_(modificationTime(file_)) {}

std::optional<std::string> ControlDictWatcher::changedText() {
  const auto time = modificationTime(file_);
  if (time == seen_) return std::nullopt;
  seen_ = time;
  std::ifstream in(file_, std::ios::binary);
  if (!in) {
    log::warning(file_.string() + " changed but cannot be read; the run goes on with its current settings");
    return std::nullopt;
  }
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::optional<ControlSettings> ControlDictWatcher::settingsOf(const std::string& text) const {
  try {
    return settingsFrom(Dictionary::parse(text, file_.string()));
  } catch (const InputError& e) {
    log::warning(std::string("system/controlDict changed but is not valid; the run goes on with its current "
                             "settings until the file is corrected:\n") +
                 e.what());
    return std::nullopt;
  }
}

std::optional<ControlSettings> ControlDictWatcher::poll() {
  const std::optional<std::string> text = changedText();
  return text ? settingsOf(*text) : std::nullopt;
}

std::string describeChanges(const ControlSettings& before, const ControlSettings& after) {
  const TimeControl& a = before.control;
  const TimeControl& b = after.control;
  std::ostringstream out;
  out.precision(10);
  compare(out, "endTime", a.endTime, b.endTime);
  compare(out, "deltaT", a.deltaT, b.deltaT);
  compare(out, "adjustTimeStep", a.adjustTimeStep, b.adjustTimeStep);
  compare(out, "iterationControl", a.iterationControl, b.iterationControl);
  compare(out, "maxCourant", a.maxCourant, b.maxCourant);
  compare(out, "minDeltaT", a.minDeltaT, b.minDeltaT);
  compare(out, "maxDeltaT", a.maxDeltaT, b.maxDeltaT);
  compare(out, "writeControl", std::string(toString(a.writeControl)), std::string(toString(b.writeControl)));
  compare(out, "writeInterval", a.writeInterval, b.writeInterval);
  compare(out, "stopAt", std::string(toString(a.stopAt)), std::string(toString(b.stopAt)));
  compare(out, "runTimeModifiable", a.runTimeModifiable, b.runTimeModifiable);
  compare(out, "purgeWrite", before.output.purgeWrite, after.output.purgeWrite);
  compare(out, "writeFormat", std::string(before.output.binary ? "binary" : "ascii"),
          std::string(after.output.binary ? "binary" : "ascii"));
  return out.str();
}

} // namespace poro
