#include "parallel/DecomposeSettings.hpp"

#include "core/Dictionary.hpp"

namespace poro {

WeightedParticles::WeightedParticles(const ParticleSystem& particles, const DecomposeSettings& settings) {
  points.reserve(particles.particleCount());
  weights.reserve(particles.particleCount());
  classes.reserve(particles.particleCount());
  for (std::size_t s = 0; s < particles.size(); ++s) {
    const ParticleSet& set = particles[s];
    points.insert(points.end(), set.x().begin(), set.x().end());
    weights.insert(weights.end(), set.size(), settings.weightOf(set.kind()));
    classes.insert(classes.end(), set.size(), set.kind() == SetKind::Boundary ? -1 : static_cast<int>(set.kind()));
  }
}

DecomposeSettings readDecomposeSettings(const std::filesystem::path& caseDir) {
  const Dictionary dict = Dictionary::read((caseDir / "system" / "decomposeParDict").string());
  DecomposeSettings s;
  s.subdomains = static_cast<int>(dict.getInt("numberOfSubdomains", Range::closed(1, 65536)));
  s.method = partitionMethodFromName(dict.getWord("method", partitionMethodNames(), "recursiveBisection"));
  if (const auto weights = dict.optionalSubDict("weights")) {
    s.fluidWeight = weights->getReal("fluid", s.fluidWeight, Range::positive());
    s.porousWeight = weights->getReal("porous", s.porousWeight, Range::positive());
    s.boundaryWeight = weights->getReal("boundary", s.boundaryWeight, Range::positive());
    weights->checkUnknownKeys();
  }
  s.rebalanceThreshold = dict.getReal("rebalanceThreshold", s.rebalanceThreshold, Range::positive());
  dict.checkUnknownKeys();
  return s;
}

} // namespace poro
