#pragma once
// Small fluid + porous particle systems for the porous-coupling tests (METHOD.md §3, §6.3-6.7).

#include "geometry/LatticeSampling.hpp"
#include "physics/FieldNames.hpp"
#include "physics/Solver.hpp"

#include <random>
#include <string>
#include <vector>

namespace poro::test {

inline constexpr double kR = 0.01;

inline PorousMaterial material(const std::string& name, double porosity, double solidDensity, bool compressible,
                               double drag = 0.0) {
  PorousMaterial m;
  m.name = name;
  m.porosity = porosity;
  m.solidDensity = solidDensity;
  m.bulkDensity = (1.0 - porosity) * solidDensity;
  m.compressible = compressible;
  m.dragViscosity = drag;
  return m;
}

/// Adds a set with the given positions, one object id for all of them and ids counted from `firstId`.
inline ParticleSet& addSet(ParticleSystem& ps, const std::string& name, SetKind kind, const std::vector<Vec3>& x,
                           std::int64_t object = 0, const Vec3& velocity = Vec3::Zero()) {
  ParticleSet& set = ps.add(name, kind);
  set.resize(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    set.x()[i] = x[i];
    set.v()[i] = velocity;
    set.integer(field::id)[i] = static_cast<std::int64_t>(i);
    set.integer(field::objectId)[i] = object;
  }
  return set;
}

/// Appends particles (another object) to an existing set.
inline void appendObject(ParticleSet& set, const std::vector<Vec3>& x, std::int64_t object) {
  const std::size_t n = set.size();
  set.resize(n + x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    set.x()[n + i] = x[i];
    set.integer(field::id)[n + i] = static_cast<std::int64_t>(n + i);
    set.integer(field::objectId)[n + i] = object;
  }
}

/// `x` with every coordinate moved by a uniform draw from [-amplitude, amplitude): a reproducible irregular lattice.
inline std::vector<Vec3> jittered(std::vector<Vec3> x, std::mt19937& rng, double amplitude) {
  std::uniform_real_distribution<double> jitter(-amplitude, amplitude);
  for (Vec3& p : x) p += Vec3(jitter(rng), jitter(rng), jitter(rng));
  return x;
}

inline TimeControl fixedStep(double dt) {
  TimeControl control;
  control.deltaT = dt;
  control.endTime = 1.0;
  control.writeInterval = 1.0;
  return control;
}

/// Eq. 4 as published (pressure.poreFluidDensity: paper): the hand formulas of METHOD.md §3.3 and §6.4 are
/// stated for it. PoroSPH's default also subtracts the pore-lattice excess (PoreFluidDensityBias.hpp).
inline SolverSettings eq4AsPublished() {
  SolverSettings settings;
  settings.pressure.latticeCorrectedPoreFluid = false;
  return settings;
}

inline FluidProperties weightless() {
  FluidProperties fluid;
  fluid.gravity.setZero();
  return fluid;
}

/// Index of the lattice point nearest to `p`.
inline std::size_t nearest(const std::vector<Vec3>& x, const Vec3& p) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < x.size(); ++i)
    if ((x[i] - p).squaredNorm() < (x[best] - p).squaredNorm()) best = i;
  return best;
}

/// A simple cubic lattice of spacing d filling [min, max] (centres min + d/2 + d k).
inline std::vector<Vec3> latticeOfSpacing(const Vec3& min, const Vec3& max, double d) {
  std::vector<Vec3> points;
  for (double x = min.x() + 0.5 * d; x < max.x(); x += d)
    for (double y = min.y() + 0.5 * d; y < max.y(); y += d)
      for (double z = min.z() + 0.5 * d; z < max.z(); z += d) points.emplace_back(x, y, z);
  return points;
}

/// Fluid on a jittered lattice inside an incompressible block ("sand") and a two-object compressible block
/// ("foam") with a Fixed bottom layer, all in a wall box: every kind of pair the pressure operator has.
inline ParticleSystem mixedSystem() {
  std::mt19937 rng(11);
  const double a = 0.3 * kR;
  ParticleSystem ps(kR);
  addSet(ps, "fluid", SetKind::Fluid, jittered(sampleBox(Vec3::Zero(), Vec3(0.16, 0.12, 0.12), kR), rng, a));
  addSet(ps, "sand", SetKind::Porous, jittered(sampleBox(Vec3::Zero(), Vec3(0.08, 0.08, 0.12), kR), rng, a));
  ParticleSet& foam =
      addSet(ps, "foam", SetKind::Porous, sampleBox(Vec3(0.08, 0.0, 0.0), Vec3(0.16, 0.04, 0.12), kR), 2);
  appendObject(foam, jittered(sampleBox(Vec3(0.08, 0.04, 0.0), Vec3(0.16, 0.08, 0.12), kR), rng, a), 3);
  addSet(ps, "boundary", SetKind::Boundary,
         sampleContainer(Vec3::Constant(-0.001), Vec3::Constant(0.161), kR, 2, {false, false, false, true, false, false}),
         9);
  return ps;
}

/// The materials of mixedSystem(), in this order: incompressible sand, compressible foam with a fixedBox.
inline std::vector<PorousMaterial> mixedMaterials() {
  PorousMaterial foam = material("foam", 0.7, 800.0, true);
  foam.fixedBox = std::make_pair(Vec3(0.0, -1.0, -1.0), Vec3(1.0, 0.02, 1.0));
  return {material("sand", 0.4, 2650.0, false), foam};
}

} // namespace poro::test
