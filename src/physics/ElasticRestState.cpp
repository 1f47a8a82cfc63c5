#include "physics/ElasticRestState.hpp"

#include "core/Parallel.hpp"
#include "physics/FieldNames.hpp"
#include "sph/NeighbourSearch.hpp"
#include "sph/ParticleSet.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace poro {

namespace {
constexpr double kDeterminantThreshold = 1e-9; // METHOD.md §8: below it L = I
} // namespace

bool ElasticRestState::update(const ParticleSet& set, const CubicKernel& kernel) {
  const auto& ids = set.integer(field::id);
  if (!volume_.empty() && ids == ids_) return false;
  build(set, kernel);
  return true;
}

void ElasticRestState::build(const ParticleSet& set, const CubicKernel& kernel) {
  const std::size_t n = set.size();
  const auto& rest = set.vec3(field::restPosition);
  const auto& ids = set.integer(field::id);
  const auto& objects = set.integer(field::objectId);
  ids_ = ids;

  NeighbourSearch search(kernel.supportRadius());
  search.update({&rest}, {{true}});
  const NeighbourList& all = search.list(0, 0);

  // N0: same object only (two bodies of one material that start in contact are not glued), by persistent id.
  std::vector<std::vector<Index>> lists(n);
  parallel::forEach(n, [&](std::size_t s) {
    for (Index t : all.of(s))
      if (objects[static_cast<std::size_t>(t)] == objects[s]) lists[s].push_back(t);
    std::sort(lists[s].begin(), lists[s].end(),
              [&](Index a, Index b) { return ids[static_cast<std::size_t>(a)] < ids[static_cast<std::size_t>(b)]; });
  });
  offsets_.assign(n + 1, 0);
  for (std::size_t s = 0; s < n; ++s) offsets_[s + 1] = offsets_[s] + static_cast<std::int64_t>(lists[s].size());
  neighbours_.resize(static_cast<std::size_t>(offsets_[n]));
  gradients_.resize(neighbours_.size());
  volume_.resize(n);
  shepard_.resize(n);
  correction_.resize(n);
  inverts_.resize(n);
  gradientSum_.resize(n);
  parallel::forEach(n, [&](std::size_t s) {
    double shepard = kernel.w0();
    std::size_t pair = begin(s);
    for (Index t : lists[s]) {
      const Vec3 xst = rest[s] - rest[static_cast<std::size_t>(t)];
      shepard += kernel.w(xst);
      const Vec3 g = kernel.grad(xst);
      neighbours_[pair] = t;
      gradients_[pair++] = {static_cast<float>(g.x()), static_cast<float>(g.y()), static_cast<float>(g.z())};
    }
    shepard_[s] = shepard;
    volume_[s] = 1.0 / shepard;
  });
  // Every V0 is known now: sum the moments of the weighted gradients exactly as the terms will read them (rounded).
  parallel::forEach(n, [&](std::size_t s) {
    Mat3 moment = Mat3::Zero();
    Vec3 sum = Vec3::Zero();
    for (std::size_t pair = begin(s); pair < end(s); ++pair) {
      const std::size_t t = static_cast<std::size_t>(neighbours_[pair]);
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
      const std::size_t t = static_cast<std::size_t>(neighbours_[pair]);
      const Vec3 g = correction_[t] * gradient(pair);
      moment += volume_[t] * g * g.transpose();
    }
    neighbourMoment_[s] = {static_cast<float>(moment(0, 0)), static_cast<float>(moment(1, 1)),
                           static_cast<float>(moment(2, 2)), static_cast<float>(moment(0, 1)),
                           static_cast<float>(moment(0, 2)), static_cast<float>(moment(1, 2))};
  });
}

} // namespace poro
