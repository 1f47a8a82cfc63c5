#include "physics/TimeControl.hpp"

#include "core/Dictionary.hpp"

#include <algorithm>
#include <sstream>

namespace poro {

TimeControl TimeControl::read(const Dictionary& dict) {
  TimeControl t;
  t.startFrom = dict.getWord("startFrom", {"startTime", "latestTime"}, "startTime") == "latestTime"
                    ? StartFrom::LatestTime
                    : StartFrom::StartTime;
  t.startTime = dict.getReal("startTime", 0.0, Range::nonNegative());
  t.endTime = dict.getReal("endTime", Range::positive());
  if (t.endTime <= t.startTime) {
    std::ostringstream msg;
    msg << "expected endTime > startTime (" << t.startTime << "), got " << t.endTime;
    dict.fail("endTime", msg.str());
  }
  t.adjustTimeStep = dict.getBool("adjustTimeStep", false);
  t.iterationControl = dict.getBool("iterationControl", false);
  t.maxCourant = dict.getReal("maxCourant", t.maxCourant, Range{0.0, 1.0, true, false});
  t.minDeltaT = dict.getReal("minDeltaT", t.minDeltaT, Range::positive());
  t.maxDeltaT = dict.getReal("maxDeltaT", t.maxDeltaT, Range::positive());
  if (t.minDeltaT > t.maxDeltaT) {
    std::ostringstream msg;
    msg << "expected minDeltaT <= maxDeltaT (" << t.maxDeltaT << "), got " << t.minDeltaT;
    dict.fail("minDeltaT", msg.str());
  }
  t.deltaT = dict.getReal("deltaT", Range::positive());
  if (t.adjustTimeStep && (t.deltaT < t.minDeltaT || t.deltaT > t.maxDeltaT)) {
    std::ostringstream msg;
    msg << "expected deltaT within [minDeltaT, maxDeltaT] = [" << t.minDeltaT << ", " << t.maxDeltaT
        << "] with adjustTimeStep, got " << t.deltaT;
    dict.fail("deltaT", msg.str());
  }
  t.writeControl = dict.getWord("writeControl", {"timeStep", "runTime"}, "runTime") == "timeStep"
                       ? WriteControl::TimeStep
                       : WriteControl::RunTime;
  if (t.writeControl == WriteControl::TimeStep)
    t.writeInterval = static_cast<double>(dict.getInt("writeInterval", Range::atLeast(1)));
  else
    t.writeInterval = dict.getReal("writeInterval", Range::positive());
  // With adjustable steps every step lands on the next write time (Solver::stepSizeFor), so a shorter interval
  // would silently force steps below minDeltaT.
  if (t.adjustTimeStep && t.writeControl == WriteControl::RunTime && t.writeInterval < t.minDeltaT) {
    std::ostringstream msg;
    msg << "expected writeInterval >= minDeltaT (" << t.minDeltaT << " s) with adjustTimeStep, got "
        << t.writeInterval << ": steps land on write times, so they would be shorter than minDeltaT";
    dict.fail("writeInterval", msg.str());
  }
  const double span = t.endTime - t.startTime;
  const double shortestStep = t.adjustTimeStep ? t.minDeltaT : t.deltaT;
  if (span < shortestStep) {
    std::ostringstream msg;
    msg << "expected endTime at least " << (t.adjustTimeStep ? "minDeltaT" : "deltaT") << " (" << shortestStep
        << " s) after startTime (" << t.startTime << " s), got " << t.endTime << ": the run would take no step";
    dict.fail("endTime", msg.str());
  }
  // A step count no machine finishes, or a step too small to change t at all (a run that never ends).
  constexpr double kMaxSteps = 1e10;
  if (!t.adjustTimeStep && (span / t.deltaT > kMaxSteps || t.endTime + t.deltaT == t.endTime)) {
    std::ostringstream msg;
    msg << "expected deltaT of at least " << span / kMaxSteps << " s (" << kMaxSteps
        << " steps from startTime to endTime), got " << t.deltaT;
    dict.fail("deltaT", msg.str());
  }
  const std::string stopAt = dict.getWord("stopAt", {"endTime", "writeNow", "noWriteNow", "nextWrite"}, "endTime");
  t.stopAt = stopAt == "writeNow"     ? StopAt::WriteNow
             : stopAt == "noWriteNow" ? StopAt::NoWriteNow
             : stopAt == "nextWrite"  ? StopAt::NextWrite
                                      : StopAt::EndTime;
  t.runTimeModifiable = dict.getBool("runTimeModifiable", true);
  return t;
}

double TimeControl::endSlack() const {
  return adjustTimeStep ? 1e-9 * std::max(1.0, endTime) : 0.5 * deltaT;
}

} // namespace poro
