#pragma once
/// Wall-clock timers and a per-phase time accumulator for the step breakdown.

#include <chrono>
#include <utility>
#include <string>
#include <vector>

namespace poro {

/// Stopwatch on the steady clock, in seconds.
class Timer {
public:
  Timer() : start_(Clock::now()) {}
  void reset() { start_ = Clock::now(); }
  double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point start_;
};

/// Accumulates wall time per named phase in first-use order (search, density, implicit, pressure, ...).
class PhaseTimes {
public:
  /// Adds seconds to a phase.
  void add(const std::string& phase, double seconds);
  /// Phases in the order they were first added, with accumulated seconds.
  const std::vector<std::pair<std::string, double>>& phases() const { return phases_; }
  double total() const;
  void clear() { phases_.clear(); }

private:
  std::vector<std::pair<std::string, double>> phases_;
};

/// Times a scope into a PhaseTimes entry.
class ScopedPhase {
public:
  ScopedPhase(PhaseTimes& times, std::string phase) : times_(times), phase_(std::move(phase)) {}
  ~ScopedPhase() { times_.add(phase_, timer_.seconds()); }
  ScopedPhase(const ScopedPhase&) = delete;
  ScopedPhase& operator=(const ScopedPhase&) = delete;

private:
  PhaseTimes& times_;
  std::string phase_;
  Timer timer_;
};

} // namespace poro
