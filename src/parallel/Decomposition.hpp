#pragma once
/// A case's particles split into subdomains and merged back (utilities/decomposePar, utilities/reconstructPar;
/// ARCHITECTURE.md "Decomposed runs"). Every set is cut by one partition of all particles, walls included, so a
/// subdomain holds the walls next to its fluid and solids, and every field of the registry travels with its particle.

#include "parallel/DecomposeSettings.hpp"
#include "sph/ParticleSystem.hpp"

#include <string>
#include <vector>

namespace poro {

struct DecompositionSummary {
  /// particles[p][s]: particles of set s (`particles`' order) in subdomain p.
  std::vector<std::vector<std::size_t>> particles;
  std::vector<double> weights; ///< per subdomain, DecomposeSettings' weights summed
  /// Largest subdomain weight over the mean, minus 1 (0: perfect balance).
  double imbalance = 0.0;
  /// Per subdomain: its particles within the support radius of a particle of another subdomain (what a halo
  /// exchange would send).
  std::vector<std::size_t> boundaryParticles;
};

struct DecomposedParticles {
  std::vector<ParticleSystem> pieces; ///< one per subdomain, every set of the input in its order (possibly empty)
  DecompositionSummary summary;
};

/// Splits `particles` into settings.subdomains pieces. Each particle keeps its slot order within its set.
DecomposedParticles decomposeParticles(const ParticleSystem& particles, const DecomposeSettings& settings);

/// Merges pieces back into one system: the sets of all pieces (a set missing from a piece has no particles there),
/// ordered as `setOrder` names them (ParticleSystem order, which the caller knows from the materials), each sorted by
/// id. `names` (one per piece) name the pieces in errors: a set `setOrder` does not name, a set of one name but another
/// kind or other fields, another particle radius, and a particle id found twice are InputErrors.
ParticleSystem mergePieces(std::vector<ParticleSystem>&& pieces, const std::vector<std::string>& names,
                           const std::vector<std::string>& setOrder);

} // namespace poro
