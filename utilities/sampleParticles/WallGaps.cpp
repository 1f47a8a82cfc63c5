#include "WallGaps.hpp"

#include "core/Log.hpp"
#include "physics/FieldNames.hpp"
#include "physics/StartDensity.hpp"
#include "sph/NeighbourSearch.hpp"

#include <cmath>
#include <limits>
#include <sstream>

namespace poro {

namespace {

/// A region's closest approach to a wall particle.
struct Approach {
  double distance = std::numeric_limits<double>::infinity(); ///< centre to centre [m]
  long long wallObject = -1;                                 ///< the wall particle's object id
};

/// "0.05 r (0.001 m)": the gap to 0.001 r, without round-off noise.
std::string describeGap(double gap, double r) {
  std::ostringstream out;
  out.precision(3);
  out << std::round(gap / r * 1000.0) / 1000.0 + 0.0 << " r (" << gap + 0.0 << " m)";
  return out.str();
}

} // namespace

void reportWallGaps(const ParticleSystem& particles, const ParticleDict& dict) {
  std::vector<std::size_t> walls;
  for (std::size_t s = 0; s < particles.size(); ++s)
    if (particles[s].kind() == SetKind::Boundary) walls.push_back(s);
  if (walls.empty()) return;
  const double r = particles.particleRadius();
  // Wall particles within H = 4r: a gap up to 2r is measured, beyond it the region is well clear.
  NeighbourSearch search(particles.supportRadius());
  std::vector<const std::vector<Vec3>*> positions;
  std::vector<std::vector<bool>> wanted(particles.size(), std::vector<bool>(particles.size(), false));
  for (std::size_t s = 0; s < particles.size(); ++s) {
    positions.push_back(&particles[s].x());
    if (particles[s].kind() != SetKind::Boundary)
      for (std::size_t k : walls) wanted[s][k] = true;
  }
  search.update(positions, wanted);

  std::vector<Approach> closest(dict.regions.size());
  for (std::size_t s = 0; s < particles.size(); ++s) {
    if (particles[s].kind() == SetKind::Boundary) continue;
    const auto& x = particles[s].x();
    const auto& object = particles[s].integer(field::objectId);
    for (std::size_t i = 0; i < x.size(); ++i) {
      Approach& a = closest[static_cast<std::size_t>(object[i])];
      for (std::size_t k : walls)
        for (Index j : search.list(s, k).of(i)) {
          const double d = (x[i] - particles[k].x()[j]).norm();
          if (d < a.distance) a = {d, particles[k].integer(field::objectId)[j]};
        }
    }
  }

  for (std::size_t n = 0; n < dict.regions.size(); ++n) {
    const ParticleRegion& region = dict.regions[n];
    if (region.phase == ParticleRegion::Phase::Boundary || region.phase == ParticleRegion::Phase::Rigid) continue;
    const Approach& a = closest[n];
    if (!std::isfinite(a.distance)) {
      log::info("region " + region.name + ": more than 2 r from every wall particle");
      continue;
    }
    const double gap = a.distance - 2.0 * r;
    const std::string& wall = dict.regions[static_cast<std::size_t>(a.wallObject)].name;
    log::info("region " + region.name + ": smallest gap to the walls " + describeGap(gap, r) + ", to region " + wall);
    if (gap >= (kStartWallGap - 1e-3) * r || region.fixed) continue;
    std::ostringstream msg;
    msg << region.where << ": region '" << region.name << "' comes within " << describeGap(gap, r)
        << " of the walls of region '" << wall << "' (the space between the particles' surfaces). Below "
        << kStartWallGap << " r its first layer starts denser than its density limit (rho/rho^max 1.047 in "
        << "lattice contact, 1.020 at 0.05 r, 1.010 at 0.067 r), which the first step blows apart, and poroSph "
        << "refuses a start above health.startDensity in system/solverDict (" << HealthSettings{}.startDensity
        << " by default: closer than about 0.08 r). Leave a gap of " << kStartWallGap << " r (" << kStartWallGap * r
        << " m) or more between the region and the wall surface.";
    log::warning(msg.str());
  }
}

} // namespace poro
