#pragma once
/// Splitting weighted particles into subdomains (ARCHITECTURE.md "Decomposed runs"): each part gets an equal share
/// of the total weight (the work its particles cost) and as compact a region as the method gives, since the halo a
/// rank exchanges grows with its surface.
///   recursiveBisection  cuts the longest side of the region's bounding box at the weighted median, recursively
///                       (parts in proportion n/2 : n - n/2), so every part is a box and neighbours share faces;
///   hilbertCurve        orders the particles along a Hilbert curve through cells of the given size and cuts the
///                       curve into n pieces of equal weight: cheaper, less regular boundaries.
/// Both are deterministic: equal input gives equal parts, whatever the thread count.

#include "core/Types.hpp"

#include <string>
#include <vector>

namespace poro {

enum class PartitionMethod { RecursiveBisection, HilbertCurve };

/// The dictionary word of a method ("recursiveBisection", "hilbertCurve") and back.
const char* toString(PartitionMethod method);
std::vector<std::string> partitionMethodNames();
PartitionMethod partitionMethodFromName(const std::string& name);

/// The part (0 .. parts - 1) of every point. `weights` are > 0, one per point; `cellSize` > 0 is the Hilbert curve's
/// resolution (the support radius: finer gains nothing, as a cell's particles are neighbours anyway). With fewer
/// points than parts the last parts are empty; otherwise every part gets at least one point.
std::vector<int> partitionPoints(const std::vector<Vec3>& points, const std::vector<double>& weights, int parts,
                                 PartitionMethod method, double cellSize);

/// Position of a cell (i, j, k), each coordinate below 2^bits, along the 3-D Hilbert curve of that order: cells next
/// to each other on the curve share a face.
std::uint64_t hilbertIndex(std::uint32_t i, std::uint32_t j, std::uint32_t k, int bits);

} // namespace poro
