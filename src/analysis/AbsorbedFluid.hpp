#pragma once
/// Which fluid particles a porous object has absorbed. A lattice-sampled solid particle s stands for its
/// lattice cell, the cube of edge 2r around x_s; fluid particle f is inside the object when it lies in the
/// cell of one of the object's particles: |x_f - x_s|_inf <= r. For an undeformed box this is exactly "inside
/// the box" (what tests/regression/PorousRegressionTest.cpp counts); a deformed object carries its cells along.

#include "analysis/PorousObjects.hpp"

#include <vector>

namespace poro {

/// For each object, the number of fluid particles at `fluid` inside it (each counted once per object; a particle
/// in two overlapping objects counts for both). A hash grid of cell size 2r over the solid particles keeps it
/// O(N). Non-finite fluid positions are inside nothing. `particles` holds the objects' sets, r > 0.
std::vector<std::size_t> countAbsorbedFluid(const std::vector<Vec3>& fluid, const ParticleSystem& particles,
                                            const std::vector<PorousObject>& objects, double particleRadius);

/// For each fluid particle at `fluid`, whether it lies inside any of the objects (the same test): the pore fluid,
/// which fluidSurface leaves out of the free surface.
std::vector<bool> absorbedFluid(const std::vector<Vec3>& fluid, const ParticleSystem& particles,
                                const std::vector<PorousObject>& objects, double particleRadius);

} // namespace poro
