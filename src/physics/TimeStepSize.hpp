#pragma once
/// CFL step size (METHOD.md §6.9): dt = clamp(maxCourant 2r / max|v|, minDeltaT, maxDeltaT), optionally
/// scaled by 0.9 after more than 10 and by 1.1 after fewer than 5 pressure sweeps (still clamped).

#include "physics/TimeControl.hpp"

namespace poro {

/// @param maxSpeed largest particle speed [m/s] (0 if everything is at rest)
/// @param spacing particle diameter 2r [m]
/// @param previousDeltaT the step just taken [s], scaled by iteration control
/// @param pressureSweeps sweeps of the step just taken
double cflStepSize(const TimeControl& control, double maxSpeed, double spacing, double previousDeltaT,
                   int pressureSweeps);

/// Step size for the coming step that lands exactly on `target` (a write time or endTime) when it is
/// near: the remaining time split into equal steps no larger than `deltaT`.
double stepTowards(double time, double target, double deltaT);

} // namespace poro
