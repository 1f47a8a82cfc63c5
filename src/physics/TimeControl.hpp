#pragma once
/// The time keys of system/controlDict (METHOD.md §6.9, §9; ARCHITECTURE.md): run length, step size
/// control and write schedule. Output format keys are read by io::OutputSettings from the same file.

#include <string>

namespace poro {
class Dictionary;

struct TimeControl {
  enum class StartFrom { StartTime, LatestTime };
  enum class WriteControl { TimeStep, RunTime };
  /// OpenFOAM's stopAt: run to endTime, or stop after the current step writing it (writeNow), not writing
  /// it (noWriteNow), or at the next write time (nextWrite). Set while running, with runTimeModifiable.
  enum class StopAt { EndTime, WriteNow, NoWriteNow, NextWrite };

  StartFrom startFrom = StartFrom::StartTime;
  double startTime = 0.0;        ///< [s]
  double endTime = 0.0;          ///< [s], > startTime, required
  double deltaT = 0.0;           ///< initial or fixed step [s], > 0, required
  bool adjustTimeStep = false;   ///< CFL-adaptive step
  bool iterationControl = false; ///< scale the step by pressure iteration count
  double maxCourant = 0.2;       ///< per particle diameter, (0, 1]
  double minDeltaT = 1e-4;       ///< [s]
  double maxDeltaT = 5e-3;       ///< [s]
  WriteControl writeControl = WriteControl::RunTime;
  double writeInterval = 0.0; ///< seconds (runTime) or steps (timeStep), > 0, required
  StopAt stopAt = StopAt::EndTime;
  bool runTimeModifiable = true; ///< re-read system/controlDict when it changes while running

  /// Reads and validates the time keys (does not check for unknown keys: the file has output keys too).
  /// Refuses settings that would run no step or an unbounded number of them, and write intervals that
  /// adjustable steps could only meet by going below minDeltaT.
  static TimeControl read(const Dictionary& dict);

  /// How close to endTime a run counts as finished: fixed steps accumulate round-off in t (half a step);
  /// adjustable steps land on endTime exactly.
  double endSlack() const;
  /// True when a run at `time` has nothing left to do.
  bool endTimeReached(double time) const { return !(time < endTime - endSlack()); }
};

} // namespace poro
