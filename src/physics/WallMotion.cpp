#include "physics/WallMotion.hpp"

#include "core/Dictionary.hpp"

#include <algorithm>
#include <sstream>

namespace poro {

WallMotion::WallMotion(std::vector<Point> table, const Vec3& velocityAfter)
    : table_(std::move(table)), velocityAfter_(velocityAfter) {}

WallMotion WallMotion::read(const Dictionary& motion) {
  const bool hasTable = motion.has("table");
  if (hasTable == motion.has("velocity"))
    motion.fail(hasTable ? "velocity" : "table",
                hasTable ? "give either velocity (with startTime, endTime) or table, not both"
                         : "expected velocity: [vx, vy, vz] (with optional startTime and endTime) or table: a list "
                           "of {time, displacement}");
  if (!hasTable) {
    const Vec3 velocity = motion.getVec3("velocity");
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
    if (!ends) return WallMotion({{start, Vec3::Zero()}}, velocity);
    return WallMotion({{start, Vec3::Zero()}, {end, velocity * (end - start)}});
  }
  std::vector<Point> table;
  const std::vector<Dictionary> rows = motion.getDictList("table");
  if (rows.empty()) motion.fail("table", "expected at least one {time, displacement} point, got an empty list");
  for (const Dictionary& row : rows) {
    Point p{row.getReal("time"), row.getVec3("displacement")};
    if (!table.empty() && !(p.time > table.back().time)) {
      std::ostringstream msg;
      msg << "expected times increasing down the table, got " << p.time << " s after " << table.back().time << " s";
      row.fail("time", msg.str());
    }
    row.checkUnknownKeys();
    table.push_back(p);
  }
  motion.checkUnknownKeys();
  return WallMotion(std::move(table));
}

Vec3 WallMotion::displacement(double t) const {
  if (t <= table_.front().time) return table_.front().displacement;
  if (t >= table_.back().time) return table_.back().displacement + (t - table_.back().time) * velocityAfter_;
  const auto next = std::upper_bound(table_.begin(), table_.end(), t,
                                     [](double time, const Point& p) { return time < p.time; });
  const Point& a = *(next - 1);
  const Point& b = *next;
  const double s = (t - a.time) / (b.time - a.time);
  return a.displacement + s * (b.displacement - a.displacement);
}

Vec3 WallMotion::meanVelocity(double t, double deltaT) const {
  return (displacement(t + deltaT) - displacement(t)) / deltaT;
}

double WallMotion::maxSpeed() const {
  double speed = velocityAfter_.norm();
  for (std::size_t i = 1; i < table_.size(); ++i)
    speed = std::max(speed, (table_[i].displacement - table_[i - 1].displacement).norm() /
                                (table_[i].time - table_[i - 1].time));
  return speed;
}

} // namespace poro
