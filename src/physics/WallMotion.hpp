#pragma once
/// Prescribed rigid translation of a wall body (METHOD.md §6.2: boundaries are static or kinematically
/// prescribed, never unknowns). The displacement d(t) from the sampled position is piecewise linear in time:
/// between the points of a table it is interpolated, before the first point it is the first point's, after the
/// last it is the last point's plus `velocityAfter` (t - t_last). A wall keeps its shape, so its Akinci
/// volumes (computed once per body) stay right.
///
/// Keys, in the `motion:` block of a boundary region of system/particleDict, one of two forms:
///   velocity: [vx, vy, vz]   # [m/s] constant velocity from startTime (default 0) until endTime (default: the
///   startTime: 1.5           #   end of the run); at rest before and after
///   endTime: 2.5
/// or
///   table:                   # time [s] and displacement [m] from the sampled position, times increasing;
///     - {time: 0, displacement: [0, 0, 0]}     # linear in between, the last displacement held afterwards
///     - {time: 1, displacement: [0, -0.1, 0]}

#include "core/Types.hpp"

#include <string>
#include <vector>

namespace poro {
class Dictionary;

class WallMotion {
public:
  struct Point {
    double time = 0.0; ///< [s]
    Vec3 displacement = Vec3::Zero(); ///< from the sampled position [m]
  };

  /// `table` holds at least one point with strictly increasing times (checked by read(); assumed here).
  explicit WallMotion(std::vector<Point> table, const Vec3& velocityAfter = Vec3::Zero());

  /// Reads and validates either form above from a `motion:` dictionary; unknown keys are errors.
  static WallMotion read(const Dictionary& motion);

  /// d(t) [m].
  Vec3 displacement(double t) const;
  /// (d(t + deltaT) - d(t)) / deltaT: the velocity that carries the wall from d(t) to d(t + deltaT) in one
  /// step, so walls and the particles they push move consistently within the step [m/s].
  Vec3 meanVelocity(double t, double deltaT) const;
  /// Largest speed of the motion [m/s] (for the log and the time step).
  double maxSpeed() const;

private:
  std::vector<Point> table_;
  Vec3 velocityAfter_;
};

/// The motion of one wall body: the boundary particles whose objectId is `objectId` (the index of their region
/// in system/particleDict).
struct ObjectMotion {
  long long objectId = 0;
  std::string region; ///< the region's name, for messages
  std::string where;  ///< "file:line" of its motion block, for messages
  WallMotion motion;
};

} // namespace poro
