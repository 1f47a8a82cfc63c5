#pragma once
/// Splitting weighted particles into subdomains (ARCHITECTURE.md "Decomposed runs"): each part gets an equal share
/// of the total weight (the work its particles cost) and as compact a region as the method gives, since the halo a
/// rank exchanges grows with its surface.
///   recursiveBisection  cuts the region's bounding box at the weighted median, recursively (parts in proportion
///                       n/2 : n - n/2), so every part is a box and neighbours share faces. It cuts the longest side
///                       unless another side's cut gives each class of particles (fluid, porous) a fairer share:
///                       the phases of a step weigh the classes differently (only porous particles carry the
///                       elastic solve), and ranks wait for each other after every phase, so a cut that balances
///                       the sum but gives one rank the water and the other the solid leaves each idle half the
///                       time;
///   hilbertCurve        orders space along a Hilbert curve (2^21 cells per side of the bounding box) and cuts it
///                       into n pieces of equal weight: ragged boundaries, but one number per cut.
/// A Partition is a function of position (the cuts), so a particle that moves is owned by the part its new position
/// lies in (migration), and the same cuts hold on every rank. The cuts are found from sums over all particles only,
/// so the particles may be spread over ranks (`Reductions`: a run) or all in one process (decomposePar), with the
/// same result. Deterministic: equal input gives equal cuts, whatever the thread or rank count.

#include "core/Types.hpp"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace poro {

enum class PartitionMethod { RecursiveBisection, HilbertCurve };

/// The dictionary word of a method ("recursiveBisection", "hilbertCurve") and back.
const char* toString(PartitionMethod method);
std::vector<std::string> partitionMethodNames();
PartitionMethod partitionMethodFromName(const std::string& name);

/// Element-wise sums, minima and maxima of a vector over every process holding particles, in place. The defaults
/// are for one process (nothing to combine).
struct Reductions {
  std::function<void(std::vector<double>&)> sum = [](std::vector<double>&) {};
  std::function<void(std::vector<double>&)> min = [](std::vector<double>&) {};
  std::function<void(std::vector<double>&)> max = [](std::vector<double>&) {};
};

class Partition {
public:
  /// Cuts the points of all processes (this one's `points`, `weights` > 0) into `parts` parts. Cuts fall between
  /// particle coordinates (a lattice layer is never split), each as close to its share of the weight as whole
  /// particles (or layers) allow. `classes` (one small number per point, < 0 for none; empty: one class)
  /// lets recursiveBisection choose the side to cut by the balance of each class (above).
  static Partition build(const std::vector<Vec3>& points, const std::vector<double>& weights, int parts,
                         PartitionMethod method, const Reductions& reductions = {},
                         const std::vector<int>& classes = {});

  int parts() const { return parts_; }
  /// The balance the cut gave (heaviest part over the mean, minus 1) when a run measured it, else negative: a run
  /// cuts anew only when the balance has drifted past it (parallel/mpi/RankGhosts.hpp).
  double imbalanceAtCut() const { return imbalanceAtCut_; }
  void setImbalanceAtCut(double imbalance) { imbalanceAtCut_ = imbalance; }
  /// The cuts as text, every number exact, and back: a parallel run writes them with each time directory, so a
  /// restart cuts as the run it continues (parse's errors name `file`).
  std::string text() const;
  static Partition parse(const std::string& text, const std::string& file);
  /// The part whose region holds x (any x: the regions tile space).
  int ownerOf(const Vec3& x) const;
  std::vector<int> owners(const std::vector<Vec3>& x) const;

private:
  struct Node {
    int axis = -1;  ///< -1: a leaf
    double cut = 0; ///< x[axis] < cut goes left
    int left = -1, right = -1;
    int part = 0; ///< a leaf's part
  };
  struct Weighted {
    const std::vector<Vec3>& points;
    const std::vector<double>& weights;
    const std::vector<int>& classes; ///< empty: one class; < 0: none
    int classCount;                  ///< the largest class over every process, plus 1
    const Reductions& reductions;
  };
  int buildNode(std::vector<std::size_t>& slots, const Weighted& in, int parts, int first);
  std::uint64_t keyOf(const Vec3& x) const;

  int parts_ = 1;
  PartitionMethod method_ = PartitionMethod::RecursiveBisection;
  std::vector<Node> nodes_;    ///< recursiveBisection: the cut tree, root first
  Vec3 origin_ = Vec3::Zero(); ///< hilbertCurve: the grid
  double cellSize_ = 1.0;
  std::vector<std::uint64_t> firstKey_; ///< hilbertCurve: part p holds keys [firstKey_[p], firstKey_[p + 1])
  double imbalanceAtCut_ = -1.0;
};

/// Position of a cell (i, j, k), each coordinate below 2^bits, along the 3-D Hilbert curve of that order: cells next
/// to each other on the curve share a face.
std::uint64_t hilbertIndex(std::uint32_t i, std::uint32_t j, std::uint32_t k, int bits);

} // namespace poro
