#pragma once
/// The volume-factor table of METHOD.md §3.2 and the pressure coupling h_ab of §6.7, per ordered pair of
/// dynamic sets. f(a<-b) weights every neighbour sum of the density, its change, the pressure diagonal and
/// the pressure acceleration; h_ab = f(b<-a) m_b/m_a for b of the same phase as a, else 0.
///
/// | a \ b   | fluid | porous, same object | porous, other object or material |
/// | fluid   | 1     | 1 - phi_b           | 1 - phi_b                        |
/// | porous  | 0     | c_a                 | 1                                |

#include "physics/StepContext.hpp"

#include <cstdint>
#include <vector>

namespace poro {

struct SetCoupling {
  std::size_t other = 0;    ///< set index b
  double factor = 0.0;      ///< f(a<-b) (for a porous set with itself: pairs of different objects)
  double ownFactor = 0.0;   ///< f(a<-b) for pairs of one object (a porous set with itself only)
  bool byObject = false;    ///< the factor depends on whether a and b share an object id
  double coupling = 0.0;    ///< h_ab (for a porous set with itself: pairs of different objects)
  double ownCoupling = 0.0; ///< h_ab for pairs of one object
  bool samePhase = false;   ///< b's a^p reacts to pi_a: b enters Q_a (METHOD.md §6.3)

  double factorOf(bool sameObject) const { return byObject && sameObject ? ownFactor : factor; }
  double couplingOf(bool sameObject) const { return byObject && sameObject ? ownCoupling : coupling; }
};

/// f(a<-a), the self term of the density (1 for fluid, c_a for porous).
double selfFactor(const StepContext& ctx, std::size_t a);

/// Every dynamic set b with f(a<-b) != 0 or h_ab != 0, in dynamic-set order.
std::vector<SetCoupling> couplingsOf(const StepContext& ctx, std::size_t a);

/// The Fixed flags of a set (METHOD.md §4.2), or null when the set has none (fluid).
const std::int64_t* fixedFlags(const ParticleSet& set);

/// The fluid set among the dynamic sets, or -1.
long fluidSetOf(const StepContext& ctx);

} // namespace poro
