#pragma once
/// Where a run stands: what uniform/time stores (METHOD.md §7), and the rigid bodies' poses and momenta
/// (uniform/rigidBodies).

#include "core/Types.hpp"

#include <string>
#include <vector>

namespace poro {

/// The dynamic state of one rigid body (physics/RigidBody.hpp): its pose and velocities. The particle sampled
/// at X is at centre + rotation (X - c0), c0 the centre of mass as sampled.
struct RigidBodyState {
  std::string name;                    ///< the region's name in system/particleDict
  Vec3 centre = Vec3::Zero();          ///< centre of mass [m]
  Mat3 rotation = Mat3::Identity();    ///< orientation from the sampled one (orthonormal)
  Vec3 velocity = Vec3::Zero();        ///< of the centre of mass [m/s]
  Vec3 angularMomentum = Vec3::Zero(); ///< about the centre of mass, world frame [kg m^2/s]
  Vec3 angularVelocity = Vec3::Zero(); ///< world frame [rad/s], I_world^-1 L under the constraints
};

struct RunState {
  double time = 0.0;
  long long step = 0;
  double nextDeltaT = 0.0;                   ///< the step size of the coming step [s]
  double lastDeltaT = 0.0;                   ///< the step size of the step just taken [s], 0 before the first
  std::vector<RigidBodyState> rigidBodies{}; ///< in system/particleDict order; empty without rigid regions
};

} // namespace poro
