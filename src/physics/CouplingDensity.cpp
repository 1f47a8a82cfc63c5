#include "physics/CouplingDensity.hpp"

#include "physics/FieldNames.hpp"

namespace poro {

double couplingPorosityFloor(double porosity) { return std::max(0.05 * porosity, 0.01); }

MixtureDensity::MixtureDensity(const ParticleSet& fluid, const PorousMaterial& material)
    : density_(fluid.real(field::density).data()), localPorosity_(fluid.real(field::localPorosity).data()),
      floor_(couplingPorosityFloor(material.porosity)) {}

CouplingSolidDensity::CouplingSolidDensity(const StepContext& ctx, std::size_t solidSet) {
  if (ctx.compatibility.restCouplingSolidDensity)
    rest_ = ctx.materials[solidSet]->bulkDensity;
  else
    current_ = ctx.particles[solidSet].real(field::density).data();
}

} // namespace poro
