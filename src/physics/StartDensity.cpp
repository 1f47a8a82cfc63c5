#include "physics/StartDensity.hpp"

#include "core/Parallel.hpp"
#include "physics/FieldNames.hpp"
#include "physics/VolumeFactors.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>

namespace poro {

namespace {

constexpr double kNotJudged = -std::numeric_limits<double>::infinity();

/// rho~ of every particle of set a as the check judges it; kNotJudged for Fixed porous particles.
std::vector<double> judgedDensities(const StepContext& ctx, std::size_t a, const PoreFluidDensityBias* poreBias) {
  const ParticleSet& set = ctx.particles[a];
  const auto& rho = set.real(field::rhoTilde);
  const std::int64_t* fixed = fixedFlags(set);
  std::vector<double> judged(set.size());
  std::vector<std::size_t> solids;
  if (poreBias)
    for (std::size_t t : ctx.dynamicSets)
      if (ctx.materials[t]) solids.push_back(t);
  const double volume = set.particleVolume;
  parallel::forEach(set.size(), [&](std::size_t i) {
    if (fixed && fixed[i]) {
      judged[i] = kNotJudged;
      return;
    }
    double solidW = 0.0; // sum_t (1 - phi_t) W_it: the solids' share of the volume around a fluid particle
    for (std::size_t t : solids) {
      const double share = 1.0 - ctx.materials[t]->porosity;
      const auto& xt = ctx.particles[t].x();
      for (Index j : ctx.search.list(a, t).of(i)) solidW += share * ctx.kernel.w(set.x()[i] - xt[j]);
    }
    judged[i] = solidW > 0.0 ? rho[i] - (*poreBias)(1.0 - volume * solidW) : rho[i];
  });
  return judged;
}

void writePoint(std::ostream& out, const Vec3& p) { out << '(' << p.x() << ", " << p.y() << ", " << p.z() << ')'; }

/// A length in units of r to 0.001 r, without round-off noise such as "-4.4e-16".
double inRadii(double length, double r) { return std::round(length / r * 1000.0) / 1000.0 + 0.0; }

/// ", 2.05 r from its nearest wall particle (id 12 of object 1, ...)" or nothing without walls in reach.
void describeNearestWall(std::ostream& out, const StepContext& ctx, std::size_t a, std::size_t i) {
  const Vec3& x = ctx.particles[a].x()[i];
  double best = std::numeric_limits<double>::infinity();
  std::size_t bestSet = 0, bestIndex = 0;
  for (std::size_t k : ctx.boundarySets)
    for (Index j : ctx.search.list(a, k).of(i)) {
      const double d = (x - ctx.particles[k].x()[j]).norm();
      if (d < best) best = d, bestSet = k, bestIndex = static_cast<std::size_t>(j);
    }
  const double r = ctx.particles.particleRadius();
  if (!std::isfinite(best)) {
    out << ", more than 4 r from every wall particle";
    return;
  }
  const ParticleSet& wall = ctx.particles[bestSet];
  out << ", " << inRadii(best, r) << " r from its nearest wall particle (id " << wall.integer(field::id)[bestIndex]
      << ", object " << wall.integer(field::objectId)[bestIndex]
      << ": the region of that index in system/particleDict, counting from 0), a gap of " << inRadii(best - 2.0 * r, r)
      << " r between the particles' surfaces";
}

} // namespace

std::vector<DensestParticle> densestAtStart(const StepContext& ctx, double limit) {
  // Without pressure.poreFluidDensity latticeCorrected the densities still hold the pore-lattice excess.
  std::unique_ptr<PoreFluidDensityBias> ownBias;
  const bool porous = std::any_of(ctx.materials.begin(), ctx.materials.end(), [](const auto* m) { return m; });
  if (porous && !ctx.poreFluidBias)
    ownBias = std::make_unique<PoreFluidDensityBias>(ctx.kernel, ctx.particles.particleVolume());
  std::vector<DensestParticle> result;
  for (std::size_t a : ctx.dynamicSets) {
    const bool fluid = ctx.particles[a].kind() == SetKind::Fluid;
    const std::vector<double> judged = judgedDensities(ctx, a, fluid ? ownBias.get() : nullptr);
    // Of densities equal to round-off (a lattice's symmetric places), the lowest id: the message then names the
    // same particle whatever order the sums ran in (the Morton order, FMA or not).
    const std::vector<std::int64_t>& id = ctx.particles[a].integer(field::id);
    DensestParticle d{a, 0, kNotJudged, 0};
    for (std::size_t i = 0; i < judged.size(); ++i) {
      if (judged[i] == kNotJudged) continue;
      const double roundOff = 1e-12 * std::abs(judged[i]);
      if (judged[i] > d.density + roundOff || (judged[i] >= d.density - roundOff && id[i] < id[d.index]))
        d.density = judged[i], d.index = i;
      if (judged[i] > limit) ++d.above;
    }
    if (d.density > kNotJudged) result.push_back(d);
  }
  return result;
}

std::string listDensest(const ParticleSystem& particles, const std::vector<DensestParticle>& densest) {
  std::ostringstream out;
  out.precision(6);
  for (std::size_t k = 0; k < densest.size(); ++k)
    out << (k ? ", " : "") << particles[densest[k].set].name() << ' ' << densest[k].density;
  return out.str();
}

std::string describeOverDense(const StepContext& ctx, const std::vector<DensestParticle>& densest, double limit) {
  std::ostringstream out;
  out.precision(4);
  bool first = true;
  double worst = 1.0;
  for (const DensestParticle& d : densest) {
    if (d.above == 0) continue;
    const ParticleSet& set = ctx.particles[d.set];
    if (first) {
      if (!set.source.empty()) out << set.source << ": ";
      out << d.above << ' ' << set.name() << " particle" << (d.above == 1 ? " starts" : "s start")
          << " denser than health.startDensity = " << limit
          << " allows (rho / rho^max, the normalised density of METHOD.md §3.3)";
    } else {
      out << "; so " << (d.above == 1 ? "does " : "do ") << d.above << ' ' << set.name() << " particle"
          << (d.above == 1 ? "" : "s");
      if (!set.source.empty()) out << " of " << set.source;
    }
    out << ": the densest, id " << set.integer(field::id)[d.index] << " at ";
    writePoint(out, set.x()[d.index]);
    out << ", starts at " << d.density;
    describeNearestWall(out, ctx, d.set, d.index);
    worst = std::max(worst, d.density);
    first = false;
  }
  const double r = ctx.particles.particleRadius();
  out << ". The first pressure solve would push them apart within one step, at speeds of order (rho / rho^max - 1) "
         "2r / deltaT = "
      << (worst - 1.0) * 2.0 * r / ctx.dt << " m/s here, the faster the smaller deltaT. Leave a gap of "
      << kStartWallGap
      << " r or more between the fluid and porous regions and the walls in system/particleDict (the tutorials' "
         "containers stand 0.1 r off the water; sampleParticles reports each region's gap), do not sample regions "
         "into each other (fluid through a porous body fills its pores at the full lattice), and run "
         "sampleParticles again; or raise health.startDensity in system/solverDict to start anyway.";
  return out.str();
}

} // namespace poro
