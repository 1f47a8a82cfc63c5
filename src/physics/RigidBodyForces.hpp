#pragma once
/// The forces fluid and porous particles exert on rigid bodies (physics/RigidBody.hpp): the reaction of the wall
/// pressure term of Eq. (7) (METHOD.md §6.7), a^p_a += -V_k pi_a gradW_ak for every boundary neighbour k, so
/// particle a pushes the body's particle k with +m_a V_k pi_a gradW_ak — equal and opposite, momentum is
/// conserved. The contact pressure of porous solids (physics/WallContact.hpp) acts the same way. The wall
/// viscosity's reaction comes from the implicit solve (ImplicitTerm::addWallReactions) as forces on the wall
/// particles. Explicit in the body: the step's final pi and implicit velocities at the positions x^n.

#include "core/Types.hpp"
#include "physics/StepContext.hpp"

#include <vector>

namespace poro {

struct Wrench {
  Vec3 force = Vec3::Zero();  ///< [N]
  Vec3 torque = Vec3::Zero(); ///< about the body's centre [N m]
};

/// One wrench per body: the bodies' particles are boundary particles whose objectId is objectIds[b]; torques are
/// about centres[b]. A serial sum in a fixed order, so a restarted run sums bit for bit as an uninterrupted one.
/// `wallForces` (by boundary set, by particle, as ImplicitSolver::wallReactions) adds further forces on the
/// bodies' particles; empty adds none.
std::vector<Wrench> rigidBodyWrenches(const StepContext& ctx, const std::vector<long long>& objectIds,
                                      const std::vector<Vec3>& centres,
                                      const std::vector<std::vector<Vec3>>& wallForces = {});

} // namespace poro
