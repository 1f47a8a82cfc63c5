#pragma once
// A synthetic particle system with known answers for the analysis tests: a 4x4x4 lattice "block" (soil,
// phi = 0.4, objectId 1) with one saturation per y layer, a 2x2x2 lattice (sand, phi = 0.6, objectId 3, not
// named by the region list) and fluid particles placed inside, on the faces of and outside the lattices.

#include "analysis/AnalysisSettings.hpp"
#include "physics/FieldNames.hpp"
#include "sph/ParticleSystem.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace poro::test {

inline constexpr double kR = 0.01;
/// Saturation of the block's y layers j = 0..3 (y = r + 2r j).
inline constexpr double kLayerSaturation[4] = {0.0, 0.25, 0.75, 1.0};
inline constexpr double kSandSaturation = 0.2;

inline PorousMaterial material(const std::string& name, double porosity) {
  PorousMaterial m;
  m.name = name;
  m.porosity = porosity;
  m.bulkDensity = m.solidDensity = 1000.0;
  return m;
}

inline AnalysisSettings syntheticSettings() {
  AnalysisSettings settings;
  settings.particleRadius = kR;
  settings.fluidDensity = 1000.0;
  settings.materials = {material("soil", 0.4), material("sand", 0.6)};
  settings.regionNames = {"column", "block", "tank"}; // objectId 3 has no name: "object3"
  return settings;
}

/// Lattice points r + 2r k + offset, k = 0..n-1 per axis.
inline std::vector<Vec3> lattice(int n, const Vec3& offset) {
  std::vector<Vec3> points;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) points.push_back(offset + Vec3(kR + 2 * kR * i, kR + 2 * kR * j, kR + 2 * kR * k));
  return points;
}

inline ParticleSet& addSet(ParticleSystem& ps, const std::string& name, SetKind kind, const std::vector<Vec3>& x,
                           std::int64_t object) {
  ParticleSet& set = ps.add(name, kind);
  set.resize(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    set.x()[i] = x[i];
    set.integer(field::id)[i] = static_cast<std::int64_t>(i);
    set.integer(field::objectId)[i] = object;
  }
  return set;
}

/// Block [0, 0.08]^3 and sand lattice [0.5, 0.54] x [0, 0.04]^2.
inline const Vec3 kSandOffset(0.5, 0.0, 0.0);

/// Fluid inside the block: 7 in its interior, one on the face x = 0, one on the far corner, one on a corner
/// shared by 8 lattice cells (counted once).
inline std::vector<Vec3> fluidInBlock() {
  std::vector<Vec3> x;
  for (int i = 0; i < 7; ++i) x.emplace_back(0.005 + 0.01 * i, 0.04, 0.04);
  x.emplace_back(0.0, 0.04, 0.04);
  x.emplace_back(0.08, 0.08, 0.08);
  x.emplace_back(0.02, 0.02, 0.02);
  return x;
}
inline std::vector<Vec3> fluidInSand() {
  return {kSandOffset + Vec3(0.01, 0.01, 0.01), kSandOffset + Vec3(0.03, 0.02, 0.035),
          kSandOffset + Vec3(0.04, 0.04, 0.04)};
}
/// Just outside, far away, and not a position at all.
inline std::vector<Vec3> fluidOutside() {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return {Vec3(-0.001, 0.04, 0.04), Vec3(0.04, 0.0801, 0.04), Vec3(0.3, 0.3, 0.3),
          kSandOffset + Vec3(0.0401, 0.02, 0.02), Vec3(nan, 0.0, 0.0)};
}

/// The whole system; `withFields` = false leaves out saturation and density (a time 0 of sampleParticles).
inline ParticleSystem syntheticSystem(bool withFields = true) {
  ParticleSystem ps(kR);
  std::vector<Vec3> fluid = fluidInBlock();
  for (const auto& group : {fluidInSand(), fluidOutside()}) fluid.insert(fluid.end(), group.begin(), group.end());
  addSet(ps, "fluid", SetKind::Fluid, fluid, 0);
  ParticleSet& soil = addSet(ps, "soil", SetKind::Porous, lattice(4, Vec3::Zero()), 1);
  ParticleSet& sand = addSet(ps, "sand", SetKind::Porous, lattice(2, kSandOffset), 3);
  addSet(ps, "boundary", SetKind::Boundary, lattice(2, Vec3(0.0, -0.04, 0.0)), 2);
  if (withFields) {
    auto& s = soil.addReal(field::saturation, Output);
    for (std::size_t i = 0; i < soil.size(); ++i) s[i] = kLayerSaturation[(i / 4) % 4];
    auto& t = sand.addReal(field::saturation, Output);
    for (double& v : t) v = kSandSaturation;
    auto& rho = ps[0].addReal(field::density, Output);
    for (double& v : rho) v = 1000.0;
  }
  for (std::int64_t& m : soil.addInt(field::materialId, Restart)) m = 0; // index in syntheticSettings().materials
  for (std::int64_t& m : sand.addInt(field::materialId, Restart)) m = 1;
  return ps;
}

} // namespace poro::test
