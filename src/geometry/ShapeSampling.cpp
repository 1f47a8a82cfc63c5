#include "geometry/ShapeSampling.hpp"

#include "core/Parallel.hpp"
#include "geometry/LatticeSampling.hpp"

#include <algorithm>
#include <cmath>

namespace poro {

namespace {

/// Rows per parallel task: enough to amortise handing out a task, few enough that the tasks spread evenly over
/// the threads (rows through the middle of a body cost more than rows near its edge).
constexpr std::size_t kRowsPerTask = 8;

/// One row's crossings (sorted) and near-surface intervals (sorted and merged), walked in increasing x.
class RowCursor {
public:
  explicit RowCursor(RowCrossings& row) : row_(row) {
    std::sort(row.crossings.begin(), row.crossings.end());
    auto& near = row.nearSurface;
    std::sort(near.begin(), near.end());
    std::size_t merged = 0;
    for (std::size_t k = 0; k < near.size(); ++k) {
      if (merged > 0 && near[k].first <= near[merged - 1].second)
        near[merged - 1].second = std::max(near[merged - 1].second, near[k].second);
      else
        near[merged++] = near[k];
    }
    near.resize(merged);
  }

  /// Whether x lies inside, by the parity of the crossings below it. x must not decrease from call to call.
  bool inside(double x) {
    while (crossing_ < row_.crossings.size() && row_.crossings[crossing_] < x) ++crossing_;
    return crossing_ % 2 == 1;
  }

  /// Whether x may lie within the tolerance of the surface. x must not decrease from call to call.
  bool nearSurface(double x) {
    const auto& near = row_.nearSurface;
    while (interval_ < near.size() && near[interval_].second < x) ++interval_;
    return interval_ < near.size() && near[interval_].first <= x;
  }

private:
  const RowCrossings& row_;
  std::size_t crossing_ = 0, interval_ = 0;
};

/// Asks `shape` for the crossings of every row of `lattice` and lets classify(y, z, cursor, points) append the
/// row's points; rows run in parallel, and the result is in lattice order whatever the number of threads.
template <class Classify>
std::vector<Vec3> sampleRows(const ClosedShape& shape, const BoxLattice& lattice, double tolerance,
                             const Classify& classify) {
  const auto ny = static_cast<std::size_t>(lattice.count[1]), nz = static_cast<std::size_t>(lattice.count[2]);
  const std::size_t rows = ny * nz, tasks = (rows + kRowsPerTask - 1) / kRowsPerTask;
  // How many points a block of rows keeps is known only once it is classified, so each task fills a vector of
  // its own (an allocation inside the loop body, which this pre-processing step affords).
  std::vector<std::vector<Vec3>> blocks(tasks);
  parallel::forEachTask(tasks, [&](std::size_t task) {
    RowCrossings row;         // reused by the task's rows
    std::vector<Vec3> points; // moved in at the end: neighbouring vectors' headers share a cache line
    for (std::size_t r = task * kRowsPerTask; r < std::min(rows, (task + 1) * kRowsPerTask); ++r) {
      const double y = lattice.coordinate(1, lattice.first + static_cast<long long>(r % ny));
      const double z = lattice.coordinate(2, lattice.first + static_cast<long long>(r / ny));
      row.clear();
      shape.crossRow(y, z, tolerance, row);
      RowCursor cursor(row);
      classify(y, z, cursor, points);
    }
    blocks[task] = std::move(points);
  });
  std::size_t total = 0;
  for (const auto& block : blocks) total += block.size();
  std::vector<Vec3> points;
  points.reserve(total);
  for (auto& block : blocks) {
    points.insert(points.end(), block.begin(), block.end());
    std::vector<Vec3>().swap(block); // at most one block's worth of memory twice
  }
  return points;
}

} // namespace

std::vector<Vec3> sampleInside(const ClosedShape& shape, double particleRadius) {
  const BoxLattice lattice = boxLattice(shape.boxMin(), shape.boxMax(), particleRadius);
  const double tolerance = kOnSurfaceTolerance * lattice.spacing;
  const long long end = lattice.first + lattice.count[0];
  return sampleRows(shape, lattice, tolerance, [&](double y, double z, RowCursor& cursor, std::vector<Vec3>& out) {
    for (long long i = lattice.first; i < end; ++i) {
      const Vec3 p(lattice.coordinate(0, i), y, z);
      if (cursor.inside(p.x()) && !(cursor.nearSurface(p.x()) && shape.distance(p) <= tolerance)) out.push_back(p);
    }
  });
}

std::vector<Vec3> sampleWallBody(const ClosedShape& shape, double particleRadius, int layers, WallSide side) {
  const BoxLattice lattice =
      boxLattice(shape.boxMin(), shape.boxMax(), particleRadius, side == WallSide::Outside ? layers : 0);
  const double tolerance = kOnSurfaceTolerance * lattice.spacing;
  const double thickness = layers * lattice.spacing;
  const long long end = lattice.first + lattice.count[0];
  return sampleRows(shape, lattice, tolerance, [&](double y, double z, RowCursor& cursor, std::vector<Vec3>& out) {
    for (long long i = lattice.first; i < end;) {
      const Vec3 p(lattice.coordinate(0, i), y, z);
      if (cursor.inside(p.x()) != (side == WallSide::Inside)) {
        ++i;
        continue;
      }
      const double d = shape.distance(p);
      if (d > tolerance && d < thickness) out.push_back(p);
      // The next `skip` points are still at least `thickness` away (the distance changes by at most one spacing
      // per point); the margin keeps round-off in the quotient from skipping a point at exactly that distance.
      const double skip = std::floor((d - thickness) / lattice.spacing - 1e-6);
      i += 1 + (skip > 0.0 ? static_cast<long long>(std::min(skip, static_cast<double>(end - i))) : 0);
    }
  });
}

} // namespace poro
