#include "physics/FluidProperties.hpp"

#include "core/Dictionary.hpp"

namespace poro {

FluidProperties FluidProperties::read(const Dictionary& dict) {
  FluidProperties p;
  p.density = dict.getReal("density", p.density, Range::positive());
  p.viscosity = dict.getReal("viscosity", p.viscosity, Range::nonNegative());
  p.boundaryViscosity = dict.getReal("boundaryViscosity", p.boundaryViscosity, Range::nonNegative());
  p.gravity = dict.getVec3("gravity", p.gravity);
  dict.checkUnknownKeys();
  return p;
}

} // namespace poro
