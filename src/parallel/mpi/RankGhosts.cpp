#include "parallel/mpi/RankGhosts.hpp"

#include "core/Log.hpp"
#include "parallel/mpi/Migration.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace poro {

double RankGhosts::weightOf(const ParticleSystem& particles) const {
  double w = 0.0;
  for (std::size_t s = 0; s < particles.size(); ++s)
    w += static_cast<double>(particles[s].size()) * settings_.weightOf(particles[s].kind());
  return w;
}

void RankGhosts::update(ParticleSystem& particles) {
  const Stopwatch watch(seconds_);
  const Stopwatch migrating(migrationSeconds_);
  halo_.dropGhosts(particles);
  migrate(particles, partition_, comm_);
  // The balance after the particles went where the cut sends them; a new cut is a function of the positions alone,
  // so a restarted run makes the same decision at the same step.
  const double mine = weightOf(particles);
  const double heaviest = comm_.max(mine);
  const double mean = comm_.sum(mine) / comm_.size();
  double imbalance = mean > 0.0 ? heaviest / mean - 1.0 : 0.0;
  // Past what the cut itself gave (a cut never splits a lattice layer, so a small subdomain can not do better).
  if (partition_.imbalanceAtCut() < 0.0) partition_.setImbalanceAtCut(imbalance);
  if (imbalance > partition_.imbalanceAtCut() + settings_.rebalanceThreshold) {
    partition_ = WeightedParticles(particles, settings_).cut(comm_.size(), settings_.method, reductionsOver(comm_));
    const std::size_t moved =
        static_cast<std::size_t>(comm_.sum(static_cast<double>(migrate(particles, partition_, comm_))));
    const double after = comm_.max(weightOf(particles)) / mean - 1.0;
    partition_.setImbalanceAtCut(after);
    const std::vector<double> counts = comm_.allGather({static_cast<double>(particles.particleCount())});
    std::ostringstream msg;
    msg << std::setprecision(3) << "Re-partitioned: the heaviest rank was " << 100.0 * imbalance
        << " % over the mean (rebalanceThreshold " << 100.0 * settings_.rebalanceThreshold
        << " % past the last cut's), now " << 100.0 * after << " %; " << moved
        << " particles moved; particles per rank:";
    for (const double n : counts) msg << " " << static_cast<long long>(n);
    log::info(msg.str());
    imbalance = after;
    ++repartitions_;
  }
  imbalance_ = imbalance;
  imbalanceSum_ += imbalance;
  largestImbalance_ = std::max(largestImbalance_, imbalance);
  ++updates_;
  buildHalo(particles);
}

bool RankGhosts::reattach(ParticleSystem& particles) {
  const Stopwatch watch(seconds_);
  if (comm_.min(halo_.restorable(particles) ? 1.0 : 0.0) > 0.0) {
    halo_.restore(particles, comm_);
    return true;
  }
  const Stopwatch building(migrationSeconds_);
  halo_.dropGhosts(particles);
  buildHalo(particles);
  return false;
}

void RankGhosts::buildHalo(ParticleSystem& particles) {
  halo_.build(particles, reach_, comm_, rest_);
  particles_ = ghosts_ = 0;
  for (std::size_t s = 0; s < particles.size(); ++s) {
    particles_ += halo_.owned(s);
    ghosts_ += halo_.ghosts(s);
  }
}

} // namespace poro
