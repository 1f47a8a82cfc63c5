#include "surface/ShepardInterpolation.hpp"

#include "core/Error.hpp"
#include "core/Parallel.hpp"
#include "sph/Kernel.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace poro {

ShepardInterpolation::ShepardInterpolation(const ParticleCloud& cloud, double supportRadius, const std::string& where)
    : cloud_(cloud), h_(supportRadius) {
  Vec3 lo = Vec3::Constant(HUGE_VAL), hi = Vec3::Constant(-HUGE_VAL);
  for (const Vec3& p : cloud.positions)
    if (p.allFinite()) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  if (!(lo.x() <= hi.x())) return;
  // Cells of the support radius over the particles' extent: far-flung particles (a diverged run) or a tiny support
  // would ask for more cells than memory holds; refused before allocating, as ColourField refuses its grid.
  double cells = 1.0;
  for (int a = 0; a < 3; ++a) cells *= std::floor((hi[a] - lo[a]) / h_) + 1.0;
  if (!(cells <= kMaxShepardCells)) {
    std::ostringstream msg;
    msg << where << ": the particles span [" << lo.transpose() << "] to [" << hi.transpose() << "], " << cells
        << " cells of the kernel support " << h_ << " m, more than the " << kMaxShepardCells
        << " the interpolation of their fields takes; particles this far apart are a diverged run, or raise "
           "kernelRadius";
    throw InputError(msg.str());
  }
  origin_ = lo;
  for (int a = 0; a < 3; ++a)
    dims_[static_cast<std::size_t>(a)] = static_cast<std::int64_t>(std::floor((hi[a] - lo[a]) / h_)) + 1;
  const auto cellOf = [&](const Vec3& p) {
    std::int64_t c[3];
    for (int a = 0; a < 3; ++a)
      c[a] = std::clamp<std::int64_t>(static_cast<std::int64_t>((p[a] - origin_[a]) / h_), 0,
                                      dims_[static_cast<std::size_t>(a)] - 1);
    return static_cast<std::size_t>((c[2] * dims_[1] + c[1]) * dims_[0] + c[0]);
  };
  start_.assign(static_cast<std::size_t>(dims_[0] * dims_[1] * dims_[2]) + 1, 0);
  for (const Vec3& p : cloud.positions)
    if (p.allFinite()) ++start_[cellOf(p) + 1];
  for (std::size_t c = 0; c + 1 < start_.size(); ++c) start_[c + 1] += start_[c];
  order_.resize(start_.back());
  std::vector<std::size_t> next(start_.begin(), start_.end() - 1);
  for (std::size_t p = 0; p < cloud.positions.size(); ++p)
    if (cloud.positions[p].allFinite()) order_[next[cellOf(cloud.positions[p])]++] = p;
}

std::vector<double> ShepardInterpolation::at(const std::vector<Vec3>& points, const ParticleField& field) const {
  // The sums live on the stack (no allocation inside the parallel loop): scalars and vectors only.
  if (field.components < 1 || field.components > 3)
    throw std::invalid_argument("ShepardInterpolation::at: field '" + field.name + "' has " +
                                std::to_string(field.components) + " components; 1 to 3 are supported");
  const auto k = static_cast<std::size_t>(field.components);
  if (field.values.size() != cloud_.positions.size() * k)
    throw std::invalid_argument("ShepardInterpolation::at: field '" + field.name + "' has " +
                                std::to_string(field.values.size()) + " values for " +
                                std::to_string(cloud_.positions.size()) + " particles of " + std::to_string(k) +
                                " components");
  std::vector<double> values(points.size() * k, 0.0);
  if (order_.empty()) return values;
  const CubicKernel kernel(h_);
  parallel::forEach(points.size(), [&](std::size_t q) {
    const Vec3& x = points[q];
    std::int64_t c[3];
    for (int a = 0; a < 3; ++a) c[a] = static_cast<std::int64_t>(std::floor((x[a] - origin_[a]) / h_));
    double weights = 0.0;
    double sum[3] = {0.0, 0.0, 0.0};
    for (std::int64_t z = std::max<std::int64_t>(0, c[2] - 1); z <= std::min(dims_[2] - 1, c[2] + 1); ++z)
      for (std::int64_t y = std::max<std::int64_t>(0, c[1] - 1); y <= std::min(dims_[1] - 1, c[1] + 1); ++y)
        for (std::int64_t xx = std::max<std::int64_t>(0, c[0] - 1); xx <= std::min(dims_[0] - 1, c[0] + 1); ++xx) {
          const auto cell = static_cast<std::size_t>((z * dims_[1] + y) * dims_[0] + xx);
          for (std::size_t n = start_[cell]; n < start_[cell + 1]; ++n) {
            const std::size_t p = order_[n];
            const double w = cloud_.volumes[p] * kernel.w((x - cloud_.positions[p]).norm());
            if (w <= 0.0) continue;
            weights += w;
            for (std::size_t i = 0; i < k; ++i) sum[i] += w * field.values[p * k + i];
          }
        }
    if (weights > 0.0)
      for (std::size_t i = 0; i < k; ++i) values[q * k + i] = sum[i] / weights;
  });
  return values;
}

} // namespace poro
