#include "physics/WallMotion.hpp"

#include "core/Dictionary.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace poro {

namespace {

std::string format(const Vec3& v) {
  std::ostringstream out;
  out << '[' << v.x() << ", " << v.y() << ", " << v.z() << ']';
  return out.str();
}

/// The velocity form: translation `velocity` and/or rotation `angularVelocity` from startTime to endTime.
WallMotion readVelocityForm(const Dictionary& motion) {
  if (motion.has("axis"))
    motion.fail("axis", "belongs to the table form (with angle in its rows); with angularVelocity the rotation axis "
                        "is the direction of angularVelocity");
  motion.markKnown("angularVelocity"); // for the "did you mean" hints of misspelt keys
  motion.markKnown("origin");
  const bool rotates = motion.has("angularVelocity");
  const Vec3 velocity = motion.getVec3("velocity", Vec3::Zero());
  const Vec3 omega = rotates ? motion.getVec3("angularVelocity") : Vec3::Zero();
  if (!rotates && motion.has("origin"))
    motion.fail("origin", "is the point the rotation axis goes through: give angularVelocity: [wx, wy, wz] too, or "
                          "leave origin out for a translation");
  const Vec3 origin = rotates ? motion.getVec3("origin") : Vec3::Zero();
  const double start = motion.getReal("startTime", 0.0, Range::nonNegative());
  motion.markKnown("endTime"); // for the "did you mean" hint of a misspelt key
  const bool ends = motion.has("endTime");
  const double end = ends ? motion.getReal("endTime") : start;
  if (ends && !(end > start)) {
    std::ostringstream msg;
    msg << "expected endTime > startTime (" << start << " s), got " << end << " s";
    motion.fail("endTime", msg.str());
  }
  motion.checkUnknownKeys();
  const double speed = omega.norm();
  std::vector<WallMotion::Point> table{{start, Vec3::Zero(), 0.0}};
  if (ends) table.push_back({end, velocity * (end - start), speed * (end - start)});
  const Vec3 after = ends ? Vec3::Zero() : velocity;
  if (speed == 0.0) return WallMotion(std::move(table), after); // no rotation: the axis is undefined and not needed
  return WallMotion(std::move(table), origin, omega, after, ends ? 0.0 : speed);
}

} // namespace

WallMotion::WallMotion(std::vector<Point> table, const Vec3& velocityAfter)
    : table_(std::move(table)), velocityAfter_(velocityAfter) {
  for (Point& p : table_) p.angle = 0.0;
}

WallMotion::WallMotion(std::vector<Point> table, const Vec3& origin, const Vec3& axis, const Vec3& velocityAfter,
                       double angularSpeedAfter)
    : table_(std::move(table)), velocityAfter_(velocityAfter), angularSpeedAfter_(angularSpeedAfter), rotates_(true),
      origin_(origin), axis_(axis.normalized()) {}

WallMotion WallMotion::read(const Dictionary& motion) {
  const bool hasTable = motion.has("table");
  const bool hasVelocity = motion.has("velocity") || motion.has("angularVelocity");
  if (hasTable && hasVelocity)
    motion.fail(motion.has("velocity") ? "velocity" : "angularVelocity",
                "give either velocity and/or angularVelocity (with startTime, endTime) or table, not both");
  if (!hasTable && !hasVelocity)
    motion.fail("table", "expected velocity: [vx, vy, vz] and/or angularVelocity: [wx, wy, wz] with origin: [x, y, z] "
                         "(with optional startTime and endTime), or table: a list of {time, displacement} (with "
                         "angle, axis and origin for a rotation)");
  if (!hasTable) return readVelocityForm(motion);

  // The table form: a rotation when axis is given (with origin), then every row has an angle.
  for (const char* key : {"startTime", "endTime"})
    if (motion.has(key)) motion.fail(key, "belongs to the velocity form; a table's times say when the wall moves");
  const bool rotates = motion.has("axis");
  if (motion.has("origin") != rotates)
    motion.fail(rotates ? "axis" : "origin",
                rotates ? "expected origin: [x, y, z] too, a point of the rotation axis at the sampled position"
                        : "is the point the rotation axis goes through: give axis: [ax, ay, az] too (and angle in the "
                          "table's rows), or leave origin out for a translation");
  Vec3 axis = Vec3::UnitZ(), origin = Vec3::Zero();
  if (rotates) {
    axis = motion.getVec3("axis");
    if (axis.norm() == 0.0) motion.fail("axis", "expected a non-zero vector to rotate about, got " + format(axis));
    origin = motion.getVec3("origin");
  }
  std::vector<Point> table;
  const std::vector<Dictionary> rows = motion.getDictList("table");
  if (rows.empty())
    motion.fail("table", rotates ? "expected at least one {time, angle} point, got an empty list"
                                 : "expected at least one {time, displacement} point, got an empty list");
  const bool displaced = !rotates || rows.front().has("displacement");
  for (const Dictionary& row : rows) {
    Point p;
    p.time = row.getReal("time");
    if (rotates) {
      p.angle = row.getReal("angle");
      if (row.has("displacement") != displaced)
        row.fail("displacement", displaced ? "expected displacement: [dx, dy, dz] in every row, as in the first"
                                           : "expected displacement in every row or in none, and the first has none");
    } else if (row.has("angle")) {
      row.fail("angle", "a rotation needs axis: [ax, ay, az] and origin: [x, y, z] in the motion block");
    }
    if (displaced) p.displacement = row.getVec3("displacement");
    if (!table.empty() && !(p.time > table.back().time)) {
      std::ostringstream msg;
      msg << "expected times increasing down the table, got " << p.time << " s after " << table.back().time << " s";
      row.fail("time", msg.str());
    }
    row.checkUnknownKeys();
    table.push_back(p);
  }
  motion.checkUnknownKeys();
  if (!rotates) return WallMotion(std::move(table));
  return WallMotion(std::move(table), origin, axis);
}

namespace {

/// The law at time t: the table interpolated, extrapolated after its end with the rates after it.
WallMotion::Point at(const std::vector<WallMotion::Point>& table, const Vec3& velocityAfter, double angularSpeedAfter,
                     double t) {
  if (t <= table.front().time) return table.front();
  if (t >= table.back().time) {
    const double since = t - table.back().time;
    return {t, table.back().displacement + since * velocityAfter, table.back().angle + since * angularSpeedAfter};
  }
  const auto next = std::upper_bound(table.begin(), table.end(), t,
                                     [](double time, const WallMotion::Point& p) { return time < p.time; });
  const WallMotion::Point& a = *(next - 1);
  const WallMotion::Point& b = *next;
  const double s = (t - a.time) / (b.time - a.time);
  return {t, a.displacement + s * (b.displacement - a.displacement), a.angle + s * (b.angle - a.angle)};
}

} // namespace

Vec3 WallMotion::displacement(double t) const { return at(table_, velocityAfter_, angularSpeedAfter_, t).displacement; }

double WallMotion::angle(double t) const { return at(table_, velocityAfter_, angularSpeedAfter_, t).angle; }

WallMotion::Pose WallMotion::pose(double t) const {
  const Point p = at(table_, velocityAfter_, angularSpeedAfter_, t);
  Pose result;
  result.displacement = p.displacement;
  if (rotates_) result.rotation = Eigen::AngleAxisd(p.angle, axis_).toRotationMatrix();
  return result;
}

Vec3 WallMotion::place(const Pose& pose, const Vec3& rest) const {
  // A translation alone stays X + d (no round-off through the origin).
  if (!rotates_) return rest + pose.displacement;
  return origin_ + pose.displacement + pose.rotation * (rest - origin_);
}

Vec3 WallMotion::meanVelocity(double t, double deltaT) const {
  return (displacement(t + deltaT) - displacement(t)) / deltaT;
}

Vec3 WallMotion::meanVelocity(const Pose& now, const Pose& next, const Vec3& rest, double deltaT) const {
  // The chord velocity, not omega x r: a wall particle given it ends the step exactly where the next step places
  // it (x(t) + deltaT v = x(t + deltaT) to round-off), as the fluid and porous particles integrated with their
  // own velocities do, so the density change and wall viscosity see the relative motion that really happens in
  // the step. omega x r is tangent at x(t) and would carry the particle off the circle by |omega|^2 r deltaT^2 / 2
  // per step; the chord is shorter than the arc (|v| <= |omega| r + |d'|), so maxSpeed bounds it. It also
  // handles a step across startTime, endTime or a corner of a table as meanVelocity(t, deltaT) does.
  if (!rotates_) return (next.displacement - now.displacement) / deltaT;
  return ((next.displacement - now.displacement) + (next.rotation - now.rotation) * (rest - origin_)) / deltaT;
}

double WallMotion::distanceFromAxis(const Vec3& rest) const {
  if (!rotates_) return 0.0;
  const Vec3 r = rest - origin_;
  return (r - r.dot(axis_) * axis_).norm();
}

double WallMotion::maxSpeed(double reach) const {
  return maxSpeed(reach, -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity());
}

double WallMotion::maxSpeed(double reach, double from, double to) const {
  double speed = 0.0;
  if (to >= table_.back().time) speed = velocityAfter_.norm() + angularSpeedAfter_ * reach;
  for (std::size_t i = 1; i < table_.size(); ++i) {
    const Point& a = table_[i - 1];
    const Point& b = table_[i];
    if (a.time > to || b.time < from) continue;
    const double dt = b.time - a.time;
    speed = std::max(speed, (b.displacement - a.displacement).norm() / dt + std::abs(b.angle - a.angle) / dt * reach);
  }
  return speed;
}

} // namespace poro
