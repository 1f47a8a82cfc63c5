#include "physics/RunWarnings.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace poro {

void RunWarnings::record(Kind kind, long long step, double time, std::size_t particles) {
  Tally& t = tallies_[index(kind)];
  if (t.steps == 0) {
    t.firstStep = step;
    t.firstTime = time;
  }
  ++t.steps;
  t.lastStep = step;
  t.lastTime = time;
  // Removed particles are gone, so they add up; particles kept outside are the same ones step after step.
  const bool kept = kind == Kind::OutsideDomainKept || kind == Kind::RigidBodiesOutsideKept;
  t.particles = kept ? std::max(t.particles, particles) : t.particles + particles;
}

bool RunWarnings::any() const {
  return std::any_of(tallies_.begin(), tallies_.end(), [](const Tally& t) { return t.steps > 0; });
}

std::string RunWarnings::summary(std::size_t movingAtStart, std::size_t movingAtEnd) const {
  if (!any()) return {};
  std::ostringstream out;
  out << std::setprecision(6) << "Warnings over this run (each is given in full above):\n";
  const auto when = [&](const Tally& t) {
    out << " in " << t.steps << (t.steps == 1 ? " step, at" : " steps, from") << " step " << t.firstStep << " (time "
        << t.firstTime << " s)";
    if (t.steps > 1) out << " to step " << t.lastStep << " (time " << t.lastTime << " s)";
    out << '\n';
  };
  const auto line = [&](Kind kind, const std::string& what) {
    const Tally& t = tallies_[index(kind)];
    if (t.steps == 0) return;
    out << "  ";
    if (kind == Kind::OutsideDomainKept || kind == Kind::RigidBodiesOutsideKept)
      out << "up to " << t.particles << ' ';
    else if (t.particles > 0)
      out << t.particles << ' ';
    out << what;
    when(t);
  };
  line(Kind::PressureIterations, "pressure.maxIterations reached");
  line(Kind::ImplicitIterations, "implicit.maxIterations reached");
  line(Kind::NonFiniteRemoved, "particles with a NaN or infinite position or velocity deleted");
  line(Kind::LeftDomainRemoved, "particles left the domain and were deleted");
  line(Kind::OutsideDomainKept, "particles outside the domain kept in the run");
  line(Kind::RigidBodiesOutsideKept, "rigid bodies outside the domain kept in the run");
  line(Kind::StepAboveCourant, "minDeltaT above the CFL step (maxCourant)");
  if (particles(Kind::NonFiniteRemoved) + particles(Kind::LeftDomainRemoved) > 0)
    out << "  " << movingAtEnd << " of the " << movingAtStart << " fluid and porous particles of the start remain\n";
  return out.str();
}

} // namespace poro
