#pragma once
/// The ranks of a parallel run as a time step sees them (physics/GhostExchange.hpp): migration by a Partition, cut
/// anew when the balance drifts past decomposeParDict's rebalanceThreshold, the halo of HaloExchange and the
/// communicator's reductions.

#include "core/Timer.hpp"
#include "parallel/DecomposeSettings.hpp"
#include "parallel/Partition.hpp"
#include "parallel/mpi/Communicator.hpp"
#include "parallel/mpi/HaloExchange.hpp"
#include "physics/GhostExchange.hpp"

#include <string>

namespace poro {

class RankGhosts final : public GhostExchange {
public:
  /// `reach`: how far from a subdomain's box its ghosts lie (the support radius plus the Verlet skin);
  /// `rest`: the sets that lend by rest position too (elastic bodies).
  RankGhosts(const Communicator& comm, Partition partition, const DecomposeSettings& settings, double reach,
             RestHalo rest = {})
      : comm_(comm), partition_(std::move(partition)), settings_(settings), reach_(reach), rest_(std::move(rest)) {}

  /// Re-partitions first when the heaviest rank's weight exceeds the mean by more than the threshold.
  void update(ParticleSystem& particles) override;
  void drop(ParticleSystem& particles) override { halo_.dropGhosts(particles); }
  bool reattach(ParticleSystem& particles) override;
  std::size_t owned(std::size_t set) const override { return halo_.owned(set); }
  void refresh(ParticleSystem& particles, const std::vector<std::string>& names) const override {
    const Stopwatch watch(seconds_);
    halo_.refresh(particles, names, comm_);
  }
  double sum(double value) const override {
    const Stopwatch watch(seconds_);
    return comm_.sum(value);
  }
  void sum(std::vector<double>& values) const override {
    const Stopwatch watch(seconds_);
    comm_.sum(values);
  }
  std::vector<double> gather(const std::vector<double>& values) const override {
    const Stopwatch watch(seconds_);
    return comm_.allGatherVaried(values);
  }
  double max(double value) const override {
    const Stopwatch watch(seconds_);
    return comm_.max(value);
  }
  int rank() const override { return comm_.rank(); }
  int ranks() const override { return comm_.size(); }

  Load load() const override {
    const double mean = updates_ ? imbalanceSum_ / static_cast<double>(updates_) : 0.0;
    return {particles_, ghosts_, imbalance_, seconds_, migrationSeconds_, mean, largestImbalance_, repartitions_};
  }
  const Partition& partition() const { return partition_; }

private:
  /// Adds the wall time of its scope to `total` (the exchanges' share of a step).
  class Stopwatch {
  public:
    explicit Stopwatch(double& total) : total_(total) {}
    ~Stopwatch() { total_ += timer_.seconds(); }
    Stopwatch(const Stopwatch&) = delete;
    Stopwatch& operator=(const Stopwatch&) = delete;

  private:
    double& total_;
    Timer timer_;
  };

  /// The halo of the current positions; counts the load.
  void buildHalo(ParticleSystem& particles);
  /// This rank's weight (decomposeParDict's weights summed over its particles).
  double weightOf(const ParticleSystem& particles) const;

  const Communicator& comm_;
  Partition partition_;
  DecomposeSettings settings_;
  double reach_;
  RestHalo rest_;
  HaloExchange halo_;
  mutable double seconds_ = 0.0;
  double migrationSeconds_ = 0.0;
  std::size_t particles_ = 0, ghosts_ = 0, updates_ = 0, repartitions_ = 0;
  double imbalance_ = 0.0, imbalanceSum_ = 0.0, largestImbalance_ = 0.0;
};

} // namespace poro
