#include "physics/ElasticRestState.hpp"

#include "core/Memory.hpp"
#include "core/Parallel.hpp"
#include "physics/FieldNames.hpp"
#include "sph/NeighbourSearch.hpp"
#include "sph/ParticleSet.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

namespace poro {

namespace {
constexpr double kDeterminantThreshold = 1e-9; // METHOD.md §8: below it L = I
constexpr std::size_t kDistinctBlock = 4096;   // particles whose distinct rest gradients are gathered together

/// Orders gradients by their bits: equal values are the same bits (-0 and 0 stay apart, as stored).
template <class G> bool bitsBefore(const G& a, const G& b) {
  static_assert(sizeof(G) == 3 * sizeof(std::uint32_t));
  std::array<std::uint32_t, 3> x, y;
  std::memcpy(x.data(), &a, sizeof(G));
  std::memcpy(y.data(), &b, sizeof(G));
  return x < y;
}

template <class G> void sortUnique(std::vector<G>& values) {
  std::sort(values.begin(), values.end(), bitsBefore<G>);
  values.erase(std::unique(values.begin(), values.end(), [](const G& a, const G& b) { return !bitsBefore(a, b); }),
               values.end());
}
/// Sum over i of a mix of (ids[i], i), modulo 2^64: a change of order or of any id changes it but with a chance of
/// 2^-64. The mix is SplitMix64's finaliser (Steele, Lea, Flood 2014), which spreads every input bit over the word.
std::uint64_t orderFingerprint(const std::vector<std::int64_t>& ids) {
  const auto mix = [](std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  };
  return parallel::sum<std::uint64_t>(ids.size(), [&](std::size_t i) {
    return mix(mix(static_cast<std::uint64_t>(ids[i])) + 0x9e3779b97f4a7c15ULL * (i + 1));
  });
}
} // namespace

bool ElasticRestState::update(const ParticleSet& set, const CubicKernel& kernel) {
  const auto& ids = set.integer(field::id);
  const std::uint64_t fingerprint = orderFingerprint(ids);
  if (!volume_.empty() && ids.size() == idsCount_ && fingerprint == idsFingerprint_) return false;
  build(set, kernel);
  idsFingerprint_ = fingerprint;
  idsCount_ = ids.size();
  return true;
}

void ElasticRestState::build(const ParticleSet& set, const CubicKernel& kernel) {
  const std::size_t n = set.size();
  const auto& rest = set.vec3(field::restPosition);
  const auto& ids = set.integer(field::id);
  const auto& objects = set.integer(field::objectId);

  // The old state goes first (a rebuild follows a Morton sort, a removal or a restart), and N0 is written straight
  // into its pairs: no state is held twice, nor the lists a second time per particle. The rebuild comes on top of
  // everything a step holds, and every sortInterval steps.
  giveBackMemory();
  {
    NeighbourSearch search(kernel.supportRadius());
    search.update({&rest}, {{true}});
    const NeighbourList& all = search.list(0, 0);
    // N0: same object only (two bodies of one material that start in contact are not glued), by persistent id.
    offsets_.assign(n + 1, 0);
    parallel::forEach(n, [&](std::size_t s) {
      std::uint32_t count = 0;
      for (Index t : all.of(s)) count += objects[static_cast<std::size_t>(t)] == objects[s];
      offsets_[s + 1] = count;
    });
    for (std::size_t s = 0; s < n; ++s) offsets_[s + 1] += offsets_[s];
    neighbours_.setWidthFor(n);
    neighbours_.resize(offsets_[n]);
    parallel::forEach(n, [&](std::size_t s) {
      thread_local std::vector<Index> same;
      same.clear();
      for (Index t : all.of(s))
        if (objects[static_cast<std::size_t>(t)] == objects[s]) same.push_back(t);
      std::sort(same.begin(), same.end(),
                [&](Index a, Index b) { return ids[static_cast<std::size_t>(a)] < ids[static_cast<std::size_t>(b)]; });
      neighbours_.store(begin(s), same.data(), same.data() + same.size());
    });
  }
  volume_.resize(n);
  shepard_.resize(n);
  correction_.resize(n);
  inverts_.resize(n);
  gradientSum_.resize(n);
  parallel::forEach(n, [&](std::size_t s) {
    double shepard = kernel.w0();
    for (std::size_t pair = begin(s); pair < end(s); ++pair)
      shepard += kernel.w(rest[s] - rest[static_cast<std::size_t>(neighbour(pair))]);
    shepard_[s] = shepard;
    volume_[s] = 1.0 / shepard;
  });
  storeGradients(rest, kernel);
  // Every V0 is known now: sum the moments of the weighted gradients exactly as the terms will read them (rounded).
  parallel::forEach(n, [&](std::size_t s) {
    Mat3 moment = Mat3::Zero();
    Vec3 sum = Vec3::Zero();
    for (std::size_t pair = begin(s); pair < end(s); ++pair) {
      const std::size_t t = static_cast<std::size_t>(neighbour(pair));
      const Vec3 weighted = weightedGradient(pair);
      moment += weighted * (rest[t] - rest[s]).transpose();
      sum += weighted;
    }
    inverts_[s] = std::abs(moment.determinant()) > kDeterminantThreshold;
    correction_[s] = inverts_[s] ? Mat3(moment.inverse()) : Mat3::Identity();
    gradientSum_[s] = sum;
  });
  neighbourMoment_.resize(n); // every L is known now
  parallel::forEach(n, [&](std::size_t s) {
    Mat3 moment = Mat3::Zero();
    for (std::size_t pair = begin(s); pair < end(s); ++pair) {
      const std::size_t t = static_cast<std::size_t>(neighbour(pair));
      const Vec3 g = correction_[t] * gradient(pair);
      moment += volume_[t] * g * g.transpose();
    }
    neighbourMoment_[s] = {static_cast<float>(moment(0, 0)), static_cast<float>(moment(1, 1)),
                           static_cast<float>(moment(2, 2)), static_cast<float>(moment(0, 1)),
                           static_cast<float>(moment(0, 2)), static_cast<float>(moment(1, 2))};
  });
}

void ElasticRestState::giveBackMemory() {
  memory::freeAll(offsets_);
  neighbours_.release();
  memory::freeAll(gradientTable_);
  memory::freeAll(gradientCodes_);
  memory::freeAll(volume_);
  memory::freeAll(shepard_);
  memory::freeAll(correction_);
  memory::freeAll(inverts_);
  memory::freeAll(gradientSum_);
  memory::freeAll(neighbourMoment_);
}

void ElasticRestState::storeGradients(const std::vector<Vec3>& rest, const CubicKernel& kernel) {
  const std::size_t n = size();
  const std::size_t pairs = neighbours_.size();
  const auto rounded = [&](std::size_t s, std::size_t pair) {
    const Vec3 g = kernel.grad(rest[s] - rest[static_cast<std::size_t>(neighbour(pair))]);
    return PairGradient{static_cast<float>(g.x()), static_cast<float>(g.y()), static_cast<float>(g.z())};
  };
  // The distinct values, block by block (a fixed blocking: the outcome does not depend on the thread count), then
  // merged. A block's buffer is made distinct whenever it has doubled since the last time (from kBuffered values
  // on), so it holds about twice the distinct values, not every pair's: the rebuild follows a sort, on top of
  // everything a step holds (a thread's block took 1.6 MB at a lattice's 26 rest pairs per particle).
  constexpr std::size_t kCodes = std::size_t(1) << 16;
  constexpr std::size_t kBuffered = 4096;
  const std::size_t blocks = (n + kDistinctBlock - 1) / kDistinctBlock;
  std::vector<std::vector<PairGradient>> distinct(blocks);
  parallel::forEach(blocks, [&](std::size_t b) {
    std::vector<PairGradient>& values = distinct[b];
    std::size_t sortAt = kBuffered;
    for (std::size_t s = b * kDistinctBlock; s < std::min(n, (b + 1) * kDistinctBlock); ++s) {
      for (std::size_t pair = begin(s); pair < end(s); ++pair) values.push_back(rounded(s, pair));
      if (values.size() > sortAt) {
        sortUnique(values);
        if (values.size() > kCodes) break; // more than there are codes: the merge below gives up too
        sortAt = std::max(kBuffered, 2 * values.size());
      }
    }
    sortUnique(values);
    values.shrink_to_fit();
  });
  std::vector<PairGradient> table;
  for (std::vector<PairGradient>& values : distinct) {
    table.insert(table.end(), values.begin(), values.end());
    memory::freeAll(values);
    sortUnique(table);
    if (table.size() > kCodes) break;
  }
  if (table.size() > kCodes) { // every pair keeps its own
    memory::freeAll(gradientCodes_);
    gradientTable_.resize(pairs);
    parallel::forEach(n, [&](std::size_t s) {
      for (std::size_t pair = begin(s); pair < end(s); ++pair) gradientTable_[pair] = rounded(s, pair);
    });
    return;
  }
  gradientTable_ = std::move(table);
  gradientCodes_.resize(pairs);
  parallel::forEach(n, [&](std::size_t s) {
    for (std::size_t pair = begin(s); pair < end(s); ++pair) {
      const PairGradient g = rounded(s, pair);
      gradientCodes_[pair] = static_cast<std::uint16_t>(
          std::lower_bound(gradientTable_.begin(), gradientTable_.end(), g, bitsBefore<PairGradient>) -
          gradientTable_.begin());
    }
  });
}

} // namespace poro
