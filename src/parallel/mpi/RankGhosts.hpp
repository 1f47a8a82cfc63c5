#pragma once
/// The ranks of a parallel run as a time step sees them (physics/GhostExchange.hpp): migration by a Partition that
/// stays fixed for the run, the halo of HaloExchange and the communicator's reductions.

#include "parallel/Partition.hpp"
#include "parallel/mpi/Communicator.hpp"
#include "parallel/mpi/HaloExchange.hpp"
#include "physics/GhostExchange.hpp"

namespace poro {

class RankGhosts final : public GhostExchange {
public:
  /// `reach`: how far from a subdomain's box its ghosts lie (the support radius: the lists are searched every step).
  RankGhosts(const Communicator& comm, Partition partition, double reach)
      : comm_(comm), partition_(std::move(partition)), reach_(reach) {}

  void update(ParticleSystem& particles) override;
  void drop(ParticleSystem& particles) override { halo_.dropGhosts(particles); }
  std::size_t owned(std::size_t set) const override { return halo_.owned(set); }
  void refresh(ParticleSystem& particles, const std::vector<std::string>& names) const override {
    halo_.refresh(particles, names, comm_);
  }
  double sum(double value) const override { return comm_.sum(value); }
  double max(double value) const override { return comm_.max(value); }
  int rank() const override { return comm_.rank(); }
  int ranks() const override { return comm_.size(); }

  /// Particles that left this rank in the last update.
  std::size_t migrated() const { return migrated_; }

private:
  const Communicator& comm_;
  Partition partition_;
  double reach_;
  HaloExchange halo_;
  std::size_t migrated_ = 0;
};

} // namespace poro
