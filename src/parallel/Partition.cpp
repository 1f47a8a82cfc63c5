#include "parallel/Partition.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace poro {

namespace {

constexpr int kHilbertBits = 21; // 3 x 21 bits: the largest order whose index fits 63 bits

double reduced(const std::function<void(std::vector<double>&)>& reduce, double value) {
  std::vector<double> v{value};
  reduce(v);
  return v.front();
}

/// The better of two cuts: the one whose weight below is closer to the target (the lower one on a tie).
template <class T> T closer(T a, double weightA, T b, double weightB, double target) {
  return std::abs(weightA - target) <= std::abs(weightB - target) ? a : b;
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

Partition Partition::build(const std::vector<Vec3>& points, const std::vector<double>& weights, int parts,
                           PartitionMethod method, const Reductions& reductions, const std::vector<int>& classes) {
  if (weights.size() != points.size()) throw std::logic_error("Partition::build: one weight per point expected");
  if (!classes.empty() && classes.size() != points.size())
    throw std::logic_error("Partition::build: one class per point expected");
  if (parts < 1) throw std::logic_error("Partition::build: at least one part expected");
  Partition p;
  p.parts_ = parts;
  p.method_ = method;
  if (method == PartitionMethod::RecursiveBisection) {
    std::vector<std::size_t> slots(points.size());
    std::iota(slots.begin(), slots.end(), std::size_t{0});
    const double largestClass =
        reduced(reductions.max, classes.empty() ? 0.0 : *std::max_element(classes.begin(), classes.end()));
    p.buildNode(slots, {points, weights, classes, static_cast<int>(largestClass) + 1, reductions}, parts, 0);
    return p;
  }
  // Hilbert curve: the grid spans every process's points.
  std::vector<double> lo(3, INFINITY), hi(3, -INFINITY);
  for (const Vec3& x : points)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], x[a]);
      hi[a] = std::max(hi[a], x[a]);
    }
  reductions.min(lo);
  reductions.max(hi);
  double extent = 0.0;
  for (int a = 0; a < 3; ++a) extent = std::max(extent, hi[a] - lo[a]);
  p.origin_ = lo[0] <= hi[0] ? Vec3(lo[0], lo[1], lo[2]) : Vec3::Zero();
  p.cellSize_ = extent > 0.0 ? extent / (std::ldexp(1.0, kHilbertBits) - 1.0) : 1.0;
  std::vector<std::pair<std::uint64_t, double>> keyed(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) keyed[i] = {p.keyOf(points[i]), weights[i]};
  std::sort(keyed.begin(), keyed.end());
  std::vector<double> below(keyed.size() + 1, 0.0); // below[k]: weight of the first k keys
  for (std::size_t k = 0; k < keyed.size(); ++k) below[k + 1] = below[k] + keyed[k].second;
  const auto weightBelow = [&](std::uint64_t key) {
    const auto at =
        std::lower_bound(keyed.begin(), keyed.end(), key,
                         [](const std::pair<std::uint64_t, double>& k, std::uint64_t v) { return k.first < v; });
    return below[static_cast<std::size_t>(at - keyed.begin())];
  };
  const double total = reduced(reductions.sum, below.back());
  // Every cut at once: bisection on the key, one reduction of all cuts' weights per halving.
  const std::size_t cuts = static_cast<std::size_t>(parts - 1);
  std::vector<std::uint64_t> a(cuts, 0), b(cuts, std::uint64_t{1} << (3 * kHilbertBits));
  std::vector<double> weightA(cuts, 0.0), weightB(cuts, total), target(cuts);
  for (std::size_t c = 0; c < cuts; ++c) target[c] = total * static_cast<double>(c + 1) / parts;
  for (int halving = 0; halving < 3 * kHilbertBits; ++halving) {
    std::vector<std::uint64_t> mid(cuts);
    std::vector<double> weight(cuts);
    for (std::size_t c = 0; c < cuts; ++c) {
      mid[c] = a[c] + (b[c] - a[c]) / 2;
      weight[c] = weightBelow(mid[c]);
    }
    reductions.sum(weight);
    for (std::size_t c = 0; c < cuts; ++c) {
      if (b[c] - a[c] <= 1) continue;
      if (weight[c] < target[c]) {
        a[c] = mid[c];
        weightA[c] = weight[c];
      } else {
        b[c] = mid[c];
        weightB[c] = weight[c];
      }
    }
  }
  p.firstKey_.assign(1, 0);
  for (std::size_t c = 0; c < cuts; ++c)
    p.firstKey_.push_back(std::max(p.firstKey_.back(), closer(a[c], weightA[c], b[c], weightB[c], target[c])));
  return p;
}

int Partition::buildNode(std::vector<std::size_t>& slots, const Weighted& in, int parts, int first) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  if (parts == 1) {
    nodes_[static_cast<std::size_t>(index)].part = first;
    return index;
  }
  const auto& points = in.points;
  const auto& weights = in.weights;
  const Reductions& reductions = in.reductions;
  // Each class's weight, then the weight of the points in none (class < 0) last.
  const std::size_t unclassed = static_cast<std::size_t>(in.classCount);
  const auto classOf = [&](std::size_t i) {
    const int c = in.classes.empty() ? 0 : in.classes[i];
    return c < 0 ? unclassed : static_cast<std::size_t>(c);
  };
  std::vector<double> lo(3, INFINITY), hi(3, -INFINITY);
  std::vector<double> classWeight(unclassed + 1, 0.0);
  for (const std::size_t i : slots) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], points[i][a]);
      hi[a] = std::max(hi[a], points[i][a]);
    }
    classWeight[classOf(i)] += weights[i];
  }
  reductions.min(lo);
  reductions.max(hi);
  reductions.sum(classWeight);
  const double total = std::accumulate(classWeight.begin(), classWeight.end(), 0.0);
  classWeight.pop_back();
  const int left = parts / 2;
  const double target = total * left / parts;

  // The weighted median along `axis`, moved into the middle of the gap between the coordinates on either side, so
  // that a particle that moves a little stays where it was.
  const auto cutAlong = [&](int axis) {
    if (!(lo[axis] <= hi[axis])) return 0.0; // no process holds points here
    const auto weightBelow = [&](double cut) {
      double w = 0.0;
      for (const std::size_t i : slots)
        if (points[i][axis] < cut) w += weights[i];
      return reduced(reductions.sum, w);
    };
    // Bisection on the coordinate, weight(< a) < target <= weight(< b), down to 1e-9 of the box: coordinates closer
    // than that count as one layer (about 30 halvings, each one reduction).
    double a = lo[axis], b = std::nextafter(hi[axis], INFINITY);
    double weightA = 0.0, weightB = total;
    const double resolution = 1e-9 * (b - a);
    while (b - a > resolution) {
      const double mid = a + 0.5 * (b - a);
      if (!(mid > a && mid < b)) break;
      const double w = weightBelow(mid);
      (w < target ? a : b) = mid;
      (w < target ? weightA : weightB) = w;
    }
    double cut = closer(a, weightA, b, weightB, target);
    double below = -INFINITY, above = INFINITY;
    for (const std::size_t i : slots) {
      const double x = points[i][axis];
      if (x < cut)
        below = std::max(below, x);
      else
        above = std::min(above, x);
    }
    below = reduced(reductions.max, below);
    above = reduced(reductions.min, above);
    if (std::isfinite(below) && std::isfinite(above)) {
      const double middle = below + 0.5 * (above - below);
      cut = middle > below ? middle : above;
    }
    return cut;
  };
  // How far the cut leaves a class that carries a tenth of the weight or more from its share: the largest
  // |class weight below / class weight - left / parts|.
  const auto classMiss = [&](int axis, double cut) {
    std::vector<double> below(unclassed + 1, 0.0);
    for (const std::size_t i : slots)
      if (points[i][axis] < cut) below[classOf(i)] += weights[i];
    reductions.sum(below);
    double miss = 0.0;
    for (std::size_t c = 0; c < classWeight.size(); ++c)
      if (classWeight[c] >= 0.1 * total)
        miss = std::max(miss, std::abs(below[c] / classWeight[c] - static_cast<double>(left) / parts));
    return miss;
  };

  std::array<int, 3> byLength{0, 1, 2}; // longest side first (the smaller interface), the lower axis on a tie
  std::stable_sort(byLength.begin(), byLength.end(), [&](int a, int b) { return hi[a] - lo[a] > hi[b] - lo[b]; });
  int axis = byLength[0];
  double cut = 0.0;
  int mixed = 0; // classes carrying a tenth of the weight or more
  for (const double w : classWeight) mixed += w >= 0.1 * total ? 1 : 0;
  if (mixed < 2) {
    cut = cutAlong(axis);
  } else {
    // The longest side whose cut misses no class's share by more than 5 % beyond the best side's: a layer's
    // granularity on a short side does not outweigh its larger interface.
    std::array<double, 3> cuts{}, misses{};
    for (const int a : byLength) {
      cuts[static_cast<std::size_t>(a)] = cutAlong(a);
      misses[static_cast<std::size_t>(a)] = classMiss(a, cuts[static_cast<std::size_t>(a)]);
    }
    const double best = *std::min_element(misses.begin(), misses.end());
    for (const int a : byLength)
      if (misses[static_cast<std::size_t>(a)] <= best + 0.05) {
        axis = a;
        cut = cuts[static_cast<std::size_t>(a)];
        break;
      }
  }
  std::vector<std::size_t> leftSlots, rightSlots;
  for (const std::size_t i : slots) (points[i][axis] < cut ? leftSlots : rightSlots).push_back(i);
  slots.clear();
  slots.shrink_to_fit();
  const int l = buildNode(leftSlots, in, left, first);
  const int r = buildNode(rightSlots, in, parts - left, first + left);
  Node& node = nodes_[static_cast<std::size_t>(index)];
  node.axis = axis;
  node.cut = cut;
  node.left = l;
  node.right = r;
  return index;
}

std::uint64_t Partition::keyOf(const Vec3& x) const {
  std::uint32_t cell[3];
  const double last = std::ldexp(1.0, kHilbertBits) - 1.0;
  for (int a = 0; a < 3; ++a) {
    const double c = std::floor((x[a] - origin_[a]) / cellSize_);
    cell[a] = static_cast<std::uint32_t>(c > 0.0 ? std::min(c, last) : 0.0); // outside the grid (or NaN): its edge
  }
  return hilbertIndex(cell[0], cell[1], cell[2], kHilbertBits);
}

int Partition::ownerOf(const Vec3& x) const {
  if (method_ == PartitionMethod::HilbertCurve) {
    if (firstKey_.empty()) return 0;
    const std::uint64_t key = keyOf(x);
    return static_cast<int>(std::upper_bound(firstKey_.begin(), firstKey_.end(), key) - firstKey_.begin()) - 1;
  }
  std::size_t n = 0;
  while (nodes_[n].axis >= 0)
    n = static_cast<std::size_t>(x[nodes_[n].axis] < nodes_[n].cut ? nodes_[n].left : nodes_[n].right);
  return nodes_[n].part;
}

namespace {
std::string exact(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}
} // namespace

std::string Partition::text() const {
  std::ostringstream out;
  out << "# The partition of this parallel run (parallel/Partition.hpp): a restart cuts the same way.\n"
      << toString(method_) << " " << parts_ << " " << exact(imbalanceAtCut_) << "\n";
  if (method_ == PartitionMethod::RecursiveBisection) {
    out << nodes_.size() << "\n";
    for (const Node& n : nodes_)
      out << n.axis << " " << exact(n.cut) << " " << n.left << " " << n.right << " " << n.part << "\n";
  } else {
    out << exact(origin_.x()) << " " << exact(origin_.y()) << " " << exact(origin_.z()) << " " << exact(cellSize_)
        << "\n"
        << firstKey_.size() << "\n";
    for (const std::uint64_t key : firstKey_) out << key << "\n";
  }
  return out.str();
}

Partition Partition::parse(const std::string& text, const std::string& file) {
  std::istringstream in(text);
  std::string line;
  while (in.peek() == '#') std::getline(in, line);
  const auto fail = [&](const std::string& what) {
    throw InputError(file + ": " + what +
                     "; the file is damaged. Restart from a reconstructed time instead "
                     "(reconstructPar, then decomposePar -force)");
  };
  Partition p;
  std::string method;
  std::size_t count = 0;
  if (!(in >> method >> p.parts_ >> p.imbalanceAtCut_) || p.parts_ < 1) fail("no method, part count and balance");
  if (method != "recursiveBisection" && method != "hilbertCurve") fail("unknown method '" + method + "'");
  p.method_ = partitionMethodFromName(method);
  if (p.method_ == PartitionMethod::RecursiveBisection) {
    if (!(in >> count) || count == 0) fail("no cut tree");
    p.nodes_.resize(count);
    for (Node& n : p.nodes_)
      if (!(in >> n.axis >> n.cut >> n.left >> n.right >> n.part)) fail("a node of the cut tree is cut short");
    for (std::size_t k = 0; k < count; ++k) { // children come after their parent: the walk down always ends
      const Node& n = p.nodes_[k];
      if (n.axis > 2 ||
          (n.axis >= 0 && (n.left <= static_cast<int>(k) || n.right <= static_cast<int>(k) ||
                           static_cast<std::size_t>(n.left) >= count || static_cast<std::size_t>(n.right) >= count)))
        fail("node " + std::to_string(k) + " of the cut tree points outside it");
      if (n.axis < 0 && (n.part < 0 || n.part >= p.parts_)) fail("a part number out of range");
    }
  } else {
    double x = 0, y = 0, z = 0;
    if (!(in >> x >> y >> z >> p.cellSize_ >> count) || !(p.cellSize_ > 0.0) ||
        count != static_cast<std::size_t>(p.parts_))
      fail("no grid or no cut per part");
    p.origin_ = Vec3(x, y, z);
    p.firstKey_.resize(count);
    for (std::uint64_t& key : p.firstKey_)
      if (!(in >> key)) fail("a cut of the curve is missing");
  }
  return p;
}

std::vector<int> Partition::owners(const std::vector<Vec3>& x) const {
  std::vector<int> result(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) result[i] = ownerOf(x[i]);
  return result;
}

} // namespace poro
