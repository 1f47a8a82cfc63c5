#include "physics/VolumeFactors.hpp"

#include "physics/FieldNames.hpp"

namespace poro {

double selfFactor(const StepContext& ctx, std::size_t a) {
  const PorousMaterial* material = ctx.materials[a];
  return material ? material->ownFactor() : 1.0;
}

std::vector<SetCoupling> couplingsOf(const StepContext& ctx, std::size_t a) {
  std::vector<SetCoupling> result;
  const ParticleSet& setA = ctx.particles[a];
  const PorousMaterial* materialA = ctx.materials[a];
  for (std::size_t b : ctx.dynamicSets) {
    const ParticleSet& setB = ctx.particles[b];
    const PorousMaterial* materialB = ctx.materials[b];
    SetCoupling c;
    c.other = b;
    if (!materialA) {
      if (!materialB) { // fluid-fluid, Eq. 7 line 1
        c.factor = 1.0;
        c.coupling = 1.0;
        c.samePhase = true;
      } else { // the solid acts as a boundary of volume (1 - phi) V: Eq. 4, Eq. 7 line 2
        c.factor = 1.0 - materialB->porosity;
      }
    } else {
      if (!materialB) continue; // solids do not see fluid in the pressure system
      c.samePhase = true;
      c.factor = 1.0;                     // bodies do not interpenetrate
      c.coupling = setB.mass / setA.mass; // f(b<-a) = 1 across objects and materials
      if (a == b) {
        c.byObject = true;
        c.ownFactor = materialA->ownFactor(); // Eq. 3 (own body)
        c.ownCoupling = c.ownFactor;          // f(b<-a) = c, equal masses
      }
    }
    result.push_back(c);
  }
  return result;
}

const std::int64_t* fixedFlags(const ParticleSet& set) {
  return set.has(field::fixed) ? set.integer(field::fixed).data() : nullptr;
}

long fluidSetOf(const StepContext& ctx) {
  for (std::size_t a : ctx.dynamicSets)
    if (ctx.particles[a].kind() == SetKind::Fluid) return static_cast<long>(a);
  return -1;
}

} // namespace poro
