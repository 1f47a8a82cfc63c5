#pragma once
/// The run's tally of the warnings its steps give (solve limits reached, particles deleted or kept outside the
/// domain), so that a log ends with what went wrong over the whole run and when, not with "End" alone after
/// thousands of lines in which a warning is easily missed.

#include <array>
#include <cstddef>
#include <string>

namespace poro {

class RunWarnings {
public:
  enum class Kind {
    PressureIterations,     ///< pressure.maxIterations reached
    ImplicitIterations,     ///< implicit.maxIterations reached
    NonFiniteRemoved,       ///< NaN or inf: particles deleted (health.nonFinite remove)
    LeftDomainRemoved,      ///< particles left the domain and were deleted (health.leavingDomain remove)
    OutsideDomainKept,      ///< particles outside the domain, kept (health.leavingDomain warn)
    RigidBodiesOutsideKept, ///< rigid bodies outside the domain, kept (health.leavingDomain warn)
    StepAboveCourant,       ///< adjustTimeStep: the CFL step fell below minDeltaT, which the step took instead
  };
  /// A step that warned of `kind`; `particles` is how many particles of the whole run it concerns (0 for the solves).
  /// Every rank of a parallel run records the same.
  void record(Kind kind, long long step, double time, std::size_t particles = 0);

  /// How many steps warned of `kind`.
  long long steps(Kind kind) const { return tallies_[index(kind)].steps; }
  /// Particles deleted (the removals), or the most particles or bodies outside at once (the kinds that keep them).
  std::size_t particles(Kind kind) const { return tallies_[index(kind)].particles; }
  bool any() const;

  /// The lines the log ends with, one per kind that warned; empty when none did. `movingAtStart` and `movingAtEnd`
  /// count the fluid and porous particles of the whole run, so that a run that lost most of them says so.
  std::string summary(std::size_t movingAtStart, std::size_t movingAtEnd) const;

private:
  static constexpr std::size_t kKinds = 7;
  static std::size_t index(Kind kind) { return static_cast<std::size_t>(kind); }
  struct Tally {
    long long steps = 0;
    std::size_t particles = 0;
    long long firstStep = 0, lastStep = 0;
    double firstTime = 0.0, lastTime = 0.0;
  };
  std::array<Tally, kKinds> tallies_{};
};

} // namespace poro
