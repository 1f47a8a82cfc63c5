#pragma once
/// Prescribed rigid motion of a wall body (METHOD.md §6.2: boundaries are static or kinematically prescribed,
/// never unknowns): a translation d(t) and a rotation by the angle theta(t) about a fixed axis direction a
/// through the point c0 (given at the sampled position; it moves with the translation). A wall particle
/// sampled at X is at
///   x(t) = c0 + d(t) + R(theta(t), a) (X - c0).
/// d(t) and theta(t) are piecewise linear in time: between the points of a table they are interpolated,
/// before the first point they are the first point's, after the last they are the last point's plus
/// `velocityAfter` (t - t_last), resp. `angularSpeedAfter` (t - t_last). A wall keeps its shape, so its
/// Akinci volumes (computed once per body) stay right; wall particles carry no directional data (no normals)
/// that would have to turn with the body.
///
/// Keys, in the `motion:` block of a boundary region of system/particleDict, one of two forms:
///   velocity: [vx, vy, vz]          # [m/s] constant translation velocity and/or
///   angularVelocity: [wx, wy, wz]   # [rad/s] constant rotation, right-handed about the axis along it
///   origin: [x, y, z]               # [m] a point of that axis at the sampled position (with angularVelocity)
///   startTime: 1.5                  # both from startTime (default 0) until endTime (default: the end of the
///   endTime: 2.5                    #   run); at rest before and after
/// or
///   axis: [ax, ay, az]       # with angle in the table: the rotation axis (any length > 0) through origin,
///   origin: [x, y, z]        #   right-handed
///   table:                   # time [s], displacement [m] from the sampled position and/or angle [rad] about
///     - {time: 0, displacement: [0, 0, 0], angle: 0}   # axis, times increasing; linear in between, the last
///     - {time: 1, displacement: [0, -0.1, 0], angle: 1.57}  # point held afterwards
/// A table without axis translates only (displacement in every row); a table with axis needs angle in every
/// row and displacement in every row or in none (then 0).

#include "core/Types.hpp"

#include <string>
#include <vector>

namespace poro {
class Dictionary;

class WallMotion {
public:
  struct Point {
    double time = 0.0;                ///< [s]
    Vec3 displacement = Vec3::Zero(); ///< from the sampled position [m]
    double angle = 0.0;               ///< about the axis, right-handed [rad]
  };

  /// Where the motion puts the body at one time: x = origin + displacement + rotation (X - origin).
  struct Pose {
    Mat3 rotation = Mat3::Identity();
    Vec3 displacement = Vec3::Zero();
  };

  /// A translation. `table` holds at least one point with strictly increasing times (checked by read();
  /// assumed here); its angles are ignored.
  explicit WallMotion(std::vector<Point> table, const Vec3& velocityAfter = Vec3::Zero());
  /// A translation with a rotation about `axis` (non-zero, normalised here) through `origin`.
  WallMotion(std::vector<Point> table, const Vec3& origin, const Vec3& axis, const Vec3& velocityAfter = Vec3::Zero(),
             double angularSpeedAfter = 0.0);

  /// Reads and validates either form above from a `motion:` dictionary; unknown keys are errors.
  static WallMotion read(const Dictionary& motion);

  /// d(t) [m].
  Vec3 displacement(double t) const;
  /// theta(t) [rad] (0 without rotation).
  double angle(double t) const;
  bool rotates() const { return rotates_; }
  const Vec3& origin() const { return origin_; }
  const Vec3& axis() const { return axis_; } ///< unit vector

  Pose pose(double t) const;
  /// x(t) of the wall point sampled at `rest` [m].
  Vec3 position(const Vec3& rest, double t) const { return place(pose(t), rest); }
  Vec3 place(const Pose& pose, const Vec3& rest) const;
  /// (d(t + deltaT) - d(t)) / deltaT: the velocity that carries a translating wall from d(t) to d(t + deltaT) in
  /// one step, so walls and the particles they push move consistently within the step [m/s].
  Vec3 meanVelocity(double t, double deltaT) const;
  /// The same for the wall point sampled at `rest` of a body that may rotate: the chord velocity
  /// (x(t + deltaT) - x(t)) / deltaT between the poses `now` = pose(t) and `next` = pose(t + deltaT) [m/s].
  Vec3 meanVelocity(const Pose& now, const Pose& next, const Vec3& rest, double deltaT) const;
  /// Distance of the wall point sampled at `rest` from the rotation axis [m] (0 without rotation).
  double distanceFromAxis(const Vec3& rest) const;

  /// Largest speed of the motion [m/s] (for the log and the time step) of points at most `reach` [m] from
  /// the axis: the largest |d'| + |theta'| reach over the pieces of the law.
  double maxSpeed(double reach = 0.0) const;
  /// The same over the pieces of the law that overlap the times [from, to].
  double maxSpeed(double reach, double from, double to) const;

private:
  std::vector<Point> table_;
  Vec3 velocityAfter_;
  double angularSpeedAfter_ = 0.0;
  bool rotates_ = false;
  Vec3 origin_ = Vec3::Zero();
  Vec3 axis_ = Vec3::UnitZ();
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
