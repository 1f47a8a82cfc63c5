#include "parallel/Decomposition.hpp"

#include "core/Error.hpp"
#include "sph/NeighbourSearch.hpp"

#include <algorithm>
#include <numeric>

namespace poro {

namespace {

/// Per subdomain, its particles with a neighbour (within H) in another subdomain.
std::vector<std::size_t> countBoundaryParticles(const std::vector<Vec3>& points, const std::vector<int>& owner,
                                                int parts, double supportRadius) {
  std::vector<std::size_t> count(static_cast<std::size_t>(parts), 0);
  if (parts == 1 || points.empty()) return count;
  NeighbourSearch search(supportRadius);
  search.update({&points}, {{true}});
  const NeighbourList& list = search.list(0, 0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto range = list.of(i);
    if (std::any_of(range.begin(), range.end(),
                    [&](Index j) { return owner[static_cast<std::size_t>(j)] != owner[i]; }))
      ++count[static_cast<std::size_t>(owner[i])];
  }
  return count;
}

} // namespace

DecomposedParticles decomposeParticles(const ParticleSystem& particles, const DecomposeSettings& settings) {
  const int parts = settings.subdomains;
  const WeightedParticles weighted(particles, settings);
  const std::vector<Vec3>& points = weighted.points;
  const std::vector<int> owner = weighted.cut(parts, settings.method).owners(points);

  DecomposedParticles result;
  DecompositionSummary& summary = result.summary;
  summary.particles.assign(static_cast<std::size_t>(parts), std::vector<std::size_t>(particles.size(), 0));
  summary.weights.assign(static_cast<std::size_t>(parts), 0.0);
  result.pieces.reserve(static_cast<std::size_t>(parts));
  for (int p = 0; p < parts; ++p) result.pieces.emplace_back(particles.particleRadius());
  std::size_t first = 0; // the set's first particle in `points`
  for (std::size_t s = 0; s < particles.size(); ++s) {
    const ParticleSet& set = particles[s];
    std::vector<std::vector<Index>> slots(static_cast<std::size_t>(parts));
    for (std::size_t i = 0; i < set.size(); ++i)
      slots[static_cast<std::size_t>(owner[first + i])].push_back(static_cast<Index>(i));
    for (std::size_t p = 0; p < slots.size(); ++p) {
      summary.particles[p][s] = slots[p].size();
      summary.weights[p] += static_cast<double>(slots[p].size()) * settings.weightOf(set.kind());
      result.pieces[p].add(set.select(slots[p]));
    }
    first += set.size();
  }
  const double total = std::accumulate(summary.weights.begin(), summary.weights.end(), 0.0);
  if (total > 0.0)
    summary.imbalance = *std::max_element(summary.weights.begin(), summary.weights.end()) / (total / parts) - 1.0;
  summary.boundaryParticles = countBoundaryParticles(points, owner, parts, particles.supportRadius());
  return result;
}

ParticleSystem mergePieces(std::vector<ParticleSystem>&& pieces, const std::vector<std::string>& names,
                           const std::vector<std::string>& setOrder) {
  if (pieces.empty()) throw std::logic_error("mergePieces: no pieces");
  ParticleSystem merged(pieces.front().particleRadius());
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    if (pieces[p].particleRadius() != merged.particleRadius())
      throw InputError(names[p] + ": particle radius " + std::to_string(pieces[p].particleRadius()) + ", but " +
                       names.front() + " has " + std::to_string(merged.particleRadius()) +
                       "; the pieces are not of one case");
    for (std::size_t s = 0; s < pieces[p].size(); ++s)
      if (std::find(setOrder.begin(), setOrder.end(), pieces[p][s].name()) == setOrder.end())
        throw InputError(names[p] + ": particle set '" + pieces[p][s].name() + "' is not one of this case's");
  }
  for (const std::string& name : setOrder) {
    ParticleSet* into = nullptr;
    std::string intoPiece;
    std::vector<std::size_t> pieceOf; // the piece of every merged particle, for errors
    for (std::size_t p = 0; p < pieces.size(); ++p) {
      ParticleSet* set = pieces[p].find(name);
      if (!set) continue;
      pieceOf.insert(pieceOf.end(), set->size(), p);
      if (!into) {
        into = &merged.add(std::move(*set));
        intoPiece = names[p];
        continue;
      }
      if (set->kind() != into->kind())
        throw InputError(names[p] + ": set '" + name + "' is " + toString(set->kind()) + ", but in " + intoPiece +
                         " it is " + toString(into->kind()));
      try {
        into->append(*set);
      } catch (const std::logic_error&) {
        throw InputError(names[p] + ": set '" + name + "' has other fields than in " + intoPiece +
                         "; the pieces were not written by one decomposition or run");
      }
    }
    if (!into) continue;
    // By id: the order every reconstruction of these particles gives, however they were spread over subdomains.
    const auto& ids = into->integer(field::id);
    std::vector<Index> order(into->size());
    std::iota(order.begin(), order.end(), Index{0});
    std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) { return ids[a] < ids[b]; });
    for (std::size_t k = 1; k < order.size(); ++k)
      if (ids[order[k]] == ids[order[k - 1]])
        throw InputError(names[pieceOf[order[k]]] + ": particle id " + std::to_string(ids[order[k]]) + " of set '" +
                         name + "' is also in " + names[pieceOf[order[k - 1]]] +
                         "; the pieces overlap (a copied or stale processor directory?)");
    into->permute(order);
  }
  return merged;
}

} // namespace poro
