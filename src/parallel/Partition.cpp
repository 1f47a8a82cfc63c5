#include "parallel/Partition.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace poro {

namespace {

using Slots = std::vector<std::size_t>;

/// How many of the first points of `order` make up the share `target` of their weight: the count whose weight is
/// closest to it, at least `minLeft` and leaving at least `minRight`.
std::size_t weightedCut(const Slots& order, std::size_t begin, std::size_t end, const std::vector<double>& weights,
                        double target, std::size_t minLeft, std::size_t minRight) {
  double total = 0.0;
  for (std::size_t k = begin; k < end; ++k) total += weights[order[k]];
  const double wanted = target * total;
  std::size_t best = minLeft;
  double sum = 0.0, bestMiss = INFINITY;
  for (std::size_t count = 0; count <= end - begin; ++count) {
    if (count >= minLeft && count + minRight <= end - begin) {
      const double miss = std::abs(sum - wanted);
      if (miss < bestMiss) {
        bestMiss = miss;
        best = count;
      }
    }
    if (count < end - begin) sum += weights[order[begin + count]];
  }
  return best;
}

/// Recursive coordinate bisection of order[begin, end) into `parts` parts numbered from `first`.
void bisect(const std::vector<Vec3>& points, const std::vector<double>& weights, Slots& order, std::size_t begin,
            std::size_t end, int parts, int first, std::vector<int>& owner) {
  if (parts == 1 || end - begin <= 1) {
    for (std::size_t k = begin; k < end; ++k) owner[order[k]] = first;
    return;
  }
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (std::size_t k = begin; k < end; ++k) {
    lo = lo.cwiseMin(points[order[k]]);
    hi = hi.cwiseMax(points[order[k]]);
  }
  int axis = 0;
  (hi - lo).maxCoeff(&axis);
  const auto byAxis = [&](std::size_t a, std::size_t b) {
    return points[a][axis] < points[b][axis] || (points[a][axis] == points[b][axis] && a < b);
  };
  std::sort(order.begin() + static_cast<std::ptrdiff_t>(begin), order.begin() + static_cast<std::ptrdiff_t>(end),
            byAxis);
  const int left = parts / 2;
  const std::size_t count = end - begin;
  // Each side keeps at least one point per part while there are enough points.
  const std::size_t minLeft = std::min<std::size_t>(static_cast<std::size_t>(left), count / 2);
  const std::size_t minRight = std::min<std::size_t>(static_cast<std::size_t>(parts - left), count - minLeft);
  const std::size_t cut = begin + weightedCut(order, begin, end, weights, static_cast<double>(left) / parts,
                                              minLeft, minRight);
  bisect(points, weights, order, begin, cut, left, first, owner);
  bisect(points, weights, order, cut, end, parts - left, first + left, owner);
}

void hilbertSplit(const std::vector<Vec3>& points, const std::vector<double>& weights, int parts, double cellSize,
                  std::vector<int>& owner) {
  const std::size_t n = points.size();
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (const Vec3& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  // The curve's order covers the largest extent; beyond 2^21 cells per side the cells grow instead (63-bit keys).
  const double cells = std::max(1.0, std::ceil((hi - lo).maxCoeff() / cellSize) + 1.0);
  int bits = 1;
  while (bits < 21 && std::ldexp(1.0, bits) < cells) ++bits;
  const double size = std::max(cellSize, (hi - lo).maxCoeff() / (std::ldexp(1.0, bits) - 1.0));
  std::vector<std::pair<std::uint64_t, std::size_t>> keys(n);
  const auto cell = [&](double x, double origin) {
    return static_cast<std::uint32_t>(std::min(std::ldexp(1.0, bits) - 1.0, std::floor((x - origin) / size)));
  };
  for (std::size_t i = 0; i < n; ++i)
    keys[i] = {hilbertIndex(cell(points[i].x(), lo.x()), cell(points[i].y(), lo.y()), cell(points[i].z(), lo.z()),
                            bits),
               i};
  std::sort(keys.begin(), keys.end());
  Slots order(n);
  for (std::size_t k = 0; k < n; ++k) order[k] = keys[k].second;
  // Cut the curve part by part: each cut takes its share of what is left, so rounding does not pile up at the end.
  std::size_t begin = 0;
  for (int p = 0; p < parts; ++p) {
    const int left = parts - p;
    std::size_t end = n;
    if (left > 1) {
      const std::size_t remaining = n - begin;
      const std::size_t minLeft = std::min<std::size_t>(1, remaining);
      const std::size_t minRight = std::min<std::size_t>(static_cast<std::size_t>(left - 1), remaining - minLeft);
      end = begin + weightedCut(order, begin, n, weights, 1.0 / left, minLeft, minRight);
    }
    for (std::size_t k = begin; k < end; ++k) owner[order[k]] = p;
    begin = end;
  }
}

} // namespace

const char* toString(PartitionMethod method) {
  return method == PartitionMethod::RecursiveBisection ? "recursiveBisection" : "hilbertCurve";
}

std::vector<std::string> partitionMethodNames() { return {"recursiveBisection", "hilbertCurve"}; }

PartitionMethod partitionMethodFromName(const std::string& name) {
  if (name == "recursiveBisection") return PartitionMethod::RecursiveBisection;
  if (name == "hilbertCurve") return PartitionMethod::HilbertCurve;
  throw std::logic_error("unknown partition method '" + name + "'");
}

std::uint64_t hilbertIndex(std::uint32_t i, std::uint32_t j, std::uint32_t k, int bits) {
  // Skilling's transform (AIP Conf. Proc. 707, 2004) of the coordinates into the "transposed" Hilbert index, whose
  // bits, interleaved from the most significant, are the index.
  std::uint32_t x[3] = {i, j, k};
  const std::uint32_t top = 1u << (bits - 1);
  for (std::uint32_t q = top; q > 1; q >>= 1) {
    const std::uint32_t p = q - 1;
    for (auto& c : x) {
      if (c & q) {
        x[0] ^= p;
      } else {
        const std::uint32_t t = (x[0] ^ c) & p;
        x[0] ^= t;
        c ^= t;
      }
    }
  }
  x[1] ^= x[0];
  x[2] ^= x[1];
  std::uint32_t t = 0;
  for (std::uint32_t q = top; q > 1; q >>= 1)
    if (x[2] & q) t ^= q - 1;
  for (auto& c : x) c ^= t;
  std::uint64_t index = 0;
  for (int b = bits - 1; b >= 0; --b)
    for (const std::uint32_t c : x) index = (index << 1) | ((c >> b) & 1u);
  return index;
}

std::vector<int> partitionPoints(const std::vector<Vec3>& points, const std::vector<double>& weights, int parts,
                                 PartitionMethod method, double cellSize) {
  if (weights.size() != points.size()) throw std::logic_error("partitionPoints: one weight per point expected");
  if (parts < 1) throw std::logic_error("partitionPoints: at least one part expected");
  std::vector<int> owner(points.size(), 0);
  if (points.empty() || parts == 1) return owner;
  if (method == PartitionMethod::HilbertCurve) {
    hilbertSplit(points, weights, parts, cellSize, owner);
  } else {
    Slots order(points.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    bisect(points, weights, order, 0, order.size(), parts, 0, owner);
  }
  return owner;
}

} // namespace poro
