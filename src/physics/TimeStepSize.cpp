#include "physics/TimeStepSize.hpp"

#include <algorithm>
#include <cmath>

namespace poro {

double cflStepSize(const TimeControl& control, double maxSpeed, double spacing, double previousDeltaT,
                   int pressureSweeps) {
  if (!control.adjustTimeStep) return control.deltaT;
  double dt = maxSpeed > 0.0 ? control.maxCourant * spacing / maxSpeed : control.maxDeltaT;
  if (control.iterationControl) {
    const double scaled = pressureSweeps > 10  ? 0.9 * previousDeltaT
                          : pressureSweeps < 5 ? 1.1 * previousDeltaT
                                               : previousDeltaT;
    dt = std::min(dt, scaled);
  }
  return std::clamp(dt, control.minDeltaT, control.maxDeltaT);
}

double stepTowards(double time, double target, double deltaT) {
  const double remaining = target - time;
  if (remaining <= 0.0) return deltaT;
  const double steps = std::ceil(remaining / deltaT * (1.0 - 1e-9));
  return remaining / std::max(steps, 1.0);
}

} // namespace poro
