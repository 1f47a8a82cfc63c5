#pragma once
/// system/decomposeParDict (ARCHITECTURE.md "Decomposed runs"; template etc/caseDicts/decomposeParDict): how many
/// subdomains, how they are cut, and what a particle of each kind weighs in the cut.

#include "parallel/Partition.hpp"

#include <filesystem>

namespace poro {

struct DecomposeSettings {
  int subdomains = 1;
  PartitionMethod method = PartitionMethod::RecursiveBisection;
  /// Work of one particle relative to a fluid particle, by set kind.
  double fluidWeight = 1.0;
  double porousWeight = 2.0;
  double boundaryWeight = 0.25;
};

/// Reads and validates `<caseDir>/system/decomposeParDict`; every error names the file, line and key.
DecomposeSettings readDecomposeSettings(const std::filesystem::path& caseDir);

} // namespace poro
