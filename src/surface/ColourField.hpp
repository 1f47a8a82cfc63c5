#pragma once
/// The colour field of a particle cloud on a grid, the level set whose contour is its surface (the approach of
/// Zhu & Bridson 2005 and splashsurf): c(x) = sum_j V_j W(x - x_j) with the cubic kernel of support H
/// (sph/Kernel.hpp). Inside a lattice of spacing 2r with V_j = (2r)^3, c = 1 up to the lattice sum's ripple;
/// across a flat face it falls from 1 to 0, through 1/2 on the face itself (midway between the last layer and
/// the first empty one, by symmetry), so c = 0.5 is a surface that encloses the particles' volume; edges and
/// corners are rounded over about H. Fields are not spread onto the grid: ShepardInterpolation reads them at the
/// surface's points, a few hundred thousand instead of every grid point.

#include "surface/ScalarGrid.hpp"

#include <string>
#include <vector>

namespace poro {

/// A per-particle quantity to read off at the surface, e.g. the velocity (3 components) or the saturation (1).
struct ParticleField {
  std::string name;
  int components = 1;
  std::vector<double> values; ///< values[p components + c]
};

struct ParticleCloud {
  std::vector<Vec3> positions;
  std::vector<double> volumes; ///< V_j [m^3]
  std::vector<ParticleField> fields;
};

/// Grids larger than this many points are refused.
inline constexpr double kMaxGridPoints = 2.0e8;

/// c on a grid of the given spacing that reaches H + 2 spacings beyond every finite particle, so that c = 0 on its
/// border and every contour closes. Slabs of the grid are filled in parallel, each point summing its particles in
/// a fixed order, so the result does not depend on the thread count. No finite particle: a grid with no points. A
/// grid above kMaxGridPoints (4 bytes each) throws InputError starting with `where` (the surfaceDict key).
ScalarGrid colourField(const ParticleCloud& cloud, double supportRadius, double spacing, const std::string& where);

} // namespace poro
