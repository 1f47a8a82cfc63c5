#include "parallel/DecomposeSettings.hpp"

#include "core/Dictionary.hpp"

namespace poro {

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
