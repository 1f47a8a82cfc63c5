#include "physics/NumericalHealth.hpp"

#include "core/Parallel.hpp"
#include "physics/FieldNames.hpp"

#include <algorithm>
#include <sstream>

namespace poro {

namespace {

template <class Bad>
std::vector<Offenders> find(const ParticleSystem& particles, const std::vector<std::size_t>& sets, const Bad& bad) {
  std::vector<Offenders> result;
  for (std::size_t s : sets) {
    const std::size_t n = particles[s].size();
    if (parallel::sum<std::size_t>(n, [&](std::size_t i) -> std::size_t { return bad(s, i) ? 1 : 0; }) == 0)
      continue;
    Offenders found{s, {}};
    for (std::size_t i = 0; i < n; ++i)
      if (bad(s, i)) found.particles.push_back(i);
    result.push_back(std::move(found));
  }
  return result;
}

} // namespace

std::vector<Offenders> findNonFinite(const ParticleSystem& particles, const std::vector<std::size_t>& sets) {
  return find(particles, sets, [&](std::size_t s, std::size_t i) {
    return !(particles[s].x()[i].allFinite() && particles[s].v()[i].allFinite());
  });
}

std::vector<Offenders> findOutside(const ParticleSystem& particles, const std::vector<std::size_t>& sets,
                                   const Domain& domain) {
  return find(particles, sets, [&](std::size_t s, std::size_t i) { return !domain.contains(particles[s].x()[i]); });
}

std::size_t count(const std::vector<Offenders>& offenders) {
  std::size_t n = 0;
  for (const auto& o : offenders) n += o.particles.size();
  return n;
}

std::optional<Domain> wallDomain(const ParticleSystem& particles, const std::vector<std::size_t>& boundarySets,
                                 const std::vector<Domain>& swept,
                                 const std::function<void(Vec3& lo, Vec3& hi)>& overRanks,
                                 const std::vector<long long>& notWalls) {
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (std::size_t s : boundarySets) {
    const auto& x = particles[s].x();
    const std::int64_t* object = notWalls.empty() ? nullptr : particles[s].integer(field::objectId).data();
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (object && std::find(notWalls.begin(), notWalls.end(), object[i]) != notWalls.end()) continue;
      lo = lo.cwiseMin(x[i]);
      hi = hi.cwiseMax(x[i]);
    }
  }
  if (lo.x() <= hi.x())
    for (const Domain& d : swept) {
      lo = lo.cwiseMin(d.min);
      hi = hi.cwiseMax(d.max);
    }
  if (overRanks) overRanks(lo, hi);
  if (!(lo.x() <= hi.x())) return std::nullopt;
  const double grow = (hi - lo).maxCoeff();
  return Domain{(lo.array() - grow).matrix(), (hi.array() + grow).matrix()};
}

std::string describe(const ParticleSystem& particles, const std::vector<Offenders>& offenders,
                     const std::function<Vec3(std::size_t set, std::size_t i)>& position) {
  constexpr std::size_t kListed = 5;
  std::ostringstream out;
  out.precision(6);
  for (std::size_t k = 0; k < offenders.size(); ++k) {
    const Offenders& o = offenders[k];
    const ParticleSet& set = particles[o.set];
    const auto& id = set.integer(field::id);
    out << (k ? "; " : "") << o.particles.size() << ' ' << set.name() << " particle"
        << (o.particles.size() == 1 ? "" : "s") << ": ";
    for (std::size_t j = 0; j < std::min(kListed, o.particles.size()); ++j) {
      const std::size_t i = o.particles[j];
      const Vec3 p = position(o.set, i);
      out << (j ? ", " : "") << "id " << id[i] << " at (" << p.x() << ", " << p.y() << ", " << p.z() << ')';
    }
    if (o.particles.size() > kListed) out << ", ...";
  }
  return out.str();
}

void removeParticles(ParticleSystem& particles, const std::vector<Offenders>& offenders) {
  for (const Offenders& o : offenders) particles[o.set].remove(o.particles);
}

} // namespace poro
