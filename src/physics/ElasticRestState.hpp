#pragma once
/// Rest state of an elastic porous set (METHOD.md §4.1), built from the initial positions X and object ids:
///   N0(s): neighbours of s within H at X with the same object id, ordered by persistent id;
///   V0_s = 1/(W(0) + sum_{t in N0(s)} W(X_s - X_t))                 (Shepard rest volume);
///   L_s = (sum_{t in N0(s)} V0_t gradW(X_s - X_t) (x) (X_t - X_s))^-1 (kernel-gradient correction, I if
///         |det| <= 1e-9);
///   G0_s = sum_{t in N0(s)} V0_t gradW(X_s - X_t);
///   S_s = sum_{t in N0(s)} V0_t (L_t gradW(X_s - X_t)) (x) (L_t gradW(X_s - X_t)).
/// Every term uses the rest gradients weighted by the neighbour's rest volume; L_s and G0_s are formed from
/// the stored (rounded) gradients, so L_s inverts exactly the moment the terms sum.
/// Everything is a function of X, ids and object ids, summed in persistent-id order, so a rebuild after a
/// Morton sort, a particle removal or a restart gives the same numbers bit for bit.

#include "core/Types.hpp"
#include "sph/Kernel.hpp"
#include "sph/PackedIndices.hpp"

#include <cstdint>
#include <vector>

namespace poro {
class ParticleSet;

class ElasticRestState {
public:
  /// Rebuilds from the set's X, id and objectId fields when the particles were reordered or removed since
  /// the last build (or never built). Returns true if it rebuilt.
  bool update(const ParticleSet& set, const CubicKernel& kernel);

  std::size_t size() const { return volume_.size(); }
  /// N0(s) as indices into the set's current order, and V0_t gradW(X_s - X_t) per pair.
  std::size_t begin(std::size_t s) const { return static_cast<std::size_t>(offsets_[s]); }
  std::size_t end(std::size_t s) const { return static_cast<std::size_t>(offsets_[s + 1]); }
  Index neighbour(std::size_t pair) const { return *neighbours_.at(pair); }
  Vec3 weightedGradient(std::size_t pair) const {
    return volume_[static_cast<std::size_t>(neighbour(pair))] * gradient(pair);
  }
  /// gradW(X_s - X_t) per pair, without the volume: for sums that fold V0_t into a per-particle factor.
  Vec3 gradient(std::size_t pair) const {
    const PairGradient& g = gradientTable_[gradientIndex(pair)];
    return Vec3(g.x, g.y, g.z);
  }
  /// Where pair's rest gradient sits among the stored ones (its code, or the pair itself when each keeps its own), and
  /// how many are stored: a term can keep its own per-gradient rest values beside them.
  std::size_t gradientIndex(std::size_t pair) const { return gradientCodes_.empty() ? pair : gradientCodes_[pair]; }
  std::size_t storedGradients() const { return gradientTable_.size(); }
  /// How many distinct rest gradients the pairs share (a lattice-sampled body: a few dozen), or 0 where there
  /// were too many to share and every pair keeps its own.
  std::size_t sharedGradients() const { return gradientCodes_.empty() ? 0 : gradientTable_.size(); }
  double volume(std::size_t s) const { return volume_[s]; }
  double inverseVolume(std::size_t s) const { return shepard_[s]; }
  const Mat3& correction(std::size_t s) const { return correction_[s]; }
  /// True where L_s is the inverse of the rest moment (false where it fell back to I).
  bool inverts(std::size_t s) const { return inverts_[s] != 0; }
  const Vec3& gradientSum(std::size_t s) const { return gradientSum_[s]; }
  /// S_s = sum_{t in N0(s)} V0_t (L_t gradW)(L_t gradW)^T at rest, in single precision: the neighbours' share of
  /// the implicit solve's preconditioner (Elasticity::addDiagonal), which needs no more.
  Mat3 neighbourMoment(std::size_t s) const {
    const SymmetricBlock& m = neighbourMoment_[s];
    Mat3 result;
    result << m.xx, m.xy, m.xz, m.xy, m.yy, m.yz, m.xz, m.yz, m.zz;
    return result;
  }

private:
  void build(const ParticleSet& set, const CubicKernel& kernel);
  /// Gives every array's memory back.
  void giveBackMemory();

  /// The ids in their order at the last build, as a 64-bit fingerprint (orderFingerprint()) and a count: a reorder,
  /// a removal or a restart changes them. Two different orders give the same fingerprint with a chance of 2^-64;
  /// the ids themselves would take 8 bytes per particle.
  std::uint64_t idsFingerprint_ = 0;
  std::size_t idsCount_ = 0;
  /// 32 bits, like NeighbourList's: N0 is part of a list the search holds.
  std::vector<std::uint32_t> offsets_;
  PackedIndices neighbours_; ///< 3 bytes each, like the lists at H

  /// gradW(X_s - X_t) per pair in single precision, like the other pair data (PairFactor), and V0_t applied in
  /// double when read: the two directions of a pair stay exact opposites, so elastic pair forces cancel.
  struct PairGradient {
    float x, y, z;
  };
  void storeGradients(const std::vector<Vec3>& rest, const CubicKernel& kernel);
  /// The rest offsets of a lattice-sampled body take a few dozen values, and so do their rounded gradients: the
  /// pairs keep 2-byte codes into a table of the distinct values instead of 12 bytes each (31 MB less for the
  /// published Seep's block at r = 1 cm, and less to read in every CG iteration). The values are the same bits.
  /// A body with more distinct values than codes (an irregular sampling) keeps one entry per pair, codes empty.
  std::vector<PairGradient> gradientTable_;
  std::vector<std::uint16_t> gradientCodes_;
  std::vector<double> volume_;
  std::vector<double> shepard_; ///< 1/V0_s
  std::vector<Mat3> correction_;
  std::vector<char> inverts_;
  std::vector<Vec3> gradientSum_;
  struct SymmetricBlock {
    float xx, yy, zz, xy, xz, yz;
  };
  std::vector<SymmetricBlock> neighbourMoment_;
};

} // namespace poro
