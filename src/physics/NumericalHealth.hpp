#pragma once
/// Health checks after each step (solverDict health): particles whose position or velocity is not finite,
/// and particles that left the domain. Finding them is cheap when all is well (one parallel count per set);
/// listing them is serial and only happens when something is wrong.

#include "physics/SolverSettings.hpp"
#include "sph/ParticleSystem.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace poro {

/// Particles of one set that failed a check, by index in set order (ascending).
struct Offenders {
  std::size_t set = 0;
  std::vector<std::size_t> particles;
};

/// Sets among `sets` with particles whose position or velocity has a NaN or inf.
std::vector<Offenders> findNonFinite(const ParticleSystem& particles, const std::vector<std::size_t>& sets);
/// Sets among `sets` with particles outside `domain`.
std::vector<Offenders> findOutside(const ParticleSystem& particles, const std::vector<std::size_t>& sets,
                                   const Domain& domain);
std::size_t count(const std::vector<Offenders>& offenders);

/// The default domain: the bounding box of the boundary sets' particles where they are (but those of the objects
/// `notWalls`: rigid bodies, which are checked against it) and of `swept` (boxes that moving walls sweep, e.g. the
/// circles of rotating ones), grown by its longest side in every direction; none without such particles.
/// `overRanks` (a parallel run) makes the box every rank's before it grows; every rank must call it.
std::optional<Domain> wallDomain(const ParticleSystem& particles, const std::vector<std::size_t>& boundarySets,
                                 const std::vector<Domain>& swept = {},
                                 const std::function<void(Vec3& lo, Vec3& hi)>& overRanks = {},
                                 const std::vector<long long>& notWalls = {});

/// "2 fluid particles: id 17 at (0.1, 0.2, 0.3), id 18 at (...)", listing at most five; `position` gives the
/// position to show for particle i of set s (e.g. the last finite one).
std::string describe(const ParticleSystem& particles, const std::vector<Offenders>& offenders,
                     const std::function<Vec3(std::size_t set, std::size_t i)>& position);

/// Deletes the offenders from their sets.
void removeParticles(ParticleSystem& particles, const std::vector<Offenders>& offenders);

} // namespace poro
