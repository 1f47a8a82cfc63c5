#pragma once
/// system/decomposeParDict (ARCHITECTURE.md "Decomposed runs"; template etc/caseDicts/decomposeParDict): how many
/// subdomains, how they are cut, and what a particle of each kind weighs in the cut.

#include "parallel/Partition.hpp"
#include "sph/ParticleSet.hpp"
#include "sph/ParticleSystem.hpp"

#include <filesystem>
#include <vector>

namespace poro {

struct DecomposeSettings {
  int subdomains = 1;
  PartitionMethod method = PartitionMethod::RecursiveBisection;
  /// Work of one particle relative to a fluid particle, by set kind: a least-squares fit of ms/step to the particle
  /// counts of the published sets and the dam break (bench/README.md) gives porous 1.76 and walls 0 within its noise;
  /// walls keep a little weight for their memory and search.
  double fluidWeight = 1.0;
  double porousWeight = 1.75;
  double boundaryWeight = 0.05;
  /// A parallel run cuts anew when the heaviest rank's weight exceeds the mean by more than this share.
  double rebalanceThreshold = 0.1;

  /// The weight of one particle of a set of this kind.
  double weightOf(SetKind kind) const {
    return kind == SetKind::Fluid ? fluidWeight : kind == SetKind::Porous ? porousWeight : boundaryWeight;
  }
};

/// Every particle of a system as a cut takes it: its position, its kind's weight, and a class by kind, so a cut can
/// give each rank its share of the fluid and of the porous particles (Partition.hpp). Walls have none: they are
/// only ever neighbours, computed in no phase of their own.
struct WeightedParticles {
  std::vector<Vec3> points;
  std::vector<double> weights;
  std::vector<int> classes;

  WeightedParticles(const ParticleSystem& particles, const DecomposeSettings& settings);
  /// Partition::build of these particles (of every process with `reductions`).
  Partition cut(int parts, PartitionMethod method, const Reductions& reductions = {}) const {
    return Partition::build(points, weights, parts, method, reductions, classes);
  }
};

/// Reads and validates `<caseDir>/system/decomposeParDict`; every error names the file, line and key.
DecomposeSettings readDecomposeSettings(const std::filesystem::path& caseDir);

} // namespace poro
