#pragma once
/// runTimeModifiable: re-reads system/controlDict while a run goes on, as OpenFOAM does, so that endTime,
/// writeInterval, stopAt, the step keys and the output keys change without a restart.

#include "io/OutputSettings.hpp"
#include "physics/TimeControl.hpp"

#include <filesystem>
#include <optional>
#include <string>

namespace poro {

struct ControlSettings {
  TimeControl control;
  OutputSettings output;
};

/// Reads and validates the whole of system/controlDict (unknown keys are errors).
ControlSettings readControlDict(const std::filesystem::path& caseDir);

class ControlDictWatcher {
public:
  /// Watches caseDir/system/controlDict, whose current content the run already uses.
  explicit ControlDictWatcher(const std::filesystem::path& caseDir);

  /// The new settings when the file changed since the last look. A file that no longer reads or validates
  /// is reported as a warning and ignored once (the run keeps its settings), so a typo made while a long run
  /// goes on cannot end it.
  std::optional<ControlSettings> poll();
  /// poll() in two halves, for a parallel run whose rank 0 looks and shares the text with every rank, so that all
  /// of them apply the same settings after the same step: the file's text when it changed since the last look, and
  /// the settings of such a text (nothing, with the warning above, when it does not validate).
  std::optional<std::string> changedText();
  std::optional<ControlSettings> settingsOf(const std::string& text) const;

private:
  std::filesystem::path caseDir_, file_;
  std::filesystem::file_time_type seen_{};
};

/// One line per changed key ("endTime 2 -> 3"), empty when nothing the run uses changed.
std::string describeChanges(const ControlSettings& before, const ControlSettings& after);

} // namespace poro
