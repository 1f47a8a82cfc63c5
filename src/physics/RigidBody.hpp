#pragma once
/// A rigid body coupled both ways to fluid and porous particles (issue 24). Its particles are boundary particles
/// (METHOD.md §6.2: Akinci volumes computed once at the sampled rest position, which rigid motion keeps right)
/// placed by its pose exactly as a moving wall's (physics/WallMotion.hpp):
///   x = c + R (X - c0),   c0 the centre of mass as sampled, c the current one.
/// The reactions of the forces its particles exert on fluid and porous particles (physics/RigidBodyForces.hpp)
/// plus gravity drive it (Newton-Euler, symplectic Euler as the particles, METHOD.md §6.8):
///   v += dt F / M,  L += dt tau,  omega = I_w^-1 L with I_w = R I_body R^T,  c += dt v,  R = exp(dt omega) R,
/// R re-orthonormalised through a unit quaternion every step. Without torque L is exact; the energy error of
/// the first-order rotation update stays bounded (tests/unit/physics/RigidBodyTest.cpp states it).
///
/// Mass and inertia come from the sampled particles: M = density N (2r)^3 (or `mass`), each particle a cube of
/// side 2r and mass M/N, so I_body = sum m (|r|^2 1 - r r^T) + M (2r)^2 / 6 1 about c0 — exact for a box filled
/// by the lattice, and within the lattice's staircase error for spheres and surfaces.
///
/// Keys of a `phase: rigid` region of system/particleDict (shape box, sphere or surface, as fluid and porous):
///   density: 500                 # [kg/m^3] > 0, or
///   mass: 1.2                    # [kg] > 0 (exactly one of the two)
///   velocity: [0, 0, 0]          # initial velocity of the centre of mass [m/s], default 0
///   angularVelocity: [0, 0, 0]   # initial angular velocity [rad/s], default 0
///   fixedTranslation: [x, z]     # world directions the centre of mass does not move along, default none
///   fixedRotation: false         # true: the body does not turn
///   fixedAxis: [0, 0, 1]         # the body turns only about this world direction (non-zero), default free
///   releaseTime: 1.2             # [s] >= 0: held where it was sampled until then (a weight let go), default 0

#include "core/Types.hpp"
#include "physics/RunState.hpp"
#include "physics/WallMotion.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace poro {
class Dictionary;

class RigidBody {
public:
  struct Spec {
    std::string name;
    std::string where;      ///< "file:line" of the region, for messages
    long long objectId = 0; ///< the index of its region in system/particleDict
    double density = 0.0;   ///< [kg/m^3], 0 when mass is given
    double mass = 0.0;      ///< [kg], 0 when density is given
    Vec3 velocity = Vec3::Zero();
    Vec3 angularVelocity = Vec3::Zero();
    std::array<bool, 3> fixedTranslation{};
    bool fixedRotation = false;
    std::optional<Vec3> fixedAxis; ///< unit vector
    double releaseTime = 0.0;      ///< [s] held in place before it; its initial velocities apply from then on
  };

  /// Reads and validates the rigid-body keys above from a region (its other keys are the caller's; this does not
  /// check for unknown keys).
  static Spec read(const Dictionary& region, long long objectId);

  /// The body of `rest`, its particles' sampled positions, each of volume (2 particleRadius)^3.
  RigidBody(Spec spec, const std::vector<Vec3>& rest, double particleRadius);

  const Spec& spec() const { return spec_; }
  /// Whether the body is still held in place at time t (before its releaseTime): it neither moves nor integrates.
  bool heldAt(double t) const { return t < spec_.releaseTime; }
  const std::string& name() const { return spec_.name; }
  long long objectId() const { return spec_.objectId; }
  double mass() const { return mass_; }
  const Vec3& restCentre() const { return restCentre_; } ///< c0 [m]
  const Mat3& bodyInertia() const { return inertia_; }   ///< about c0 in the sampled orientation [kg m^2]
  Mat3 worldInertia(const RigidBodyState& s) const { return s.rotation * inertia_ * s.rotation.transpose(); }

  /// The state as sampled: at c0, unrotated, with the region's initial velocities (constrained).
  RigidBodyState initialState() const;
  /// One symplectic Euler step under `force` [N] (gravity included) and `torque` about the centre [N m].
  void integrate(RigidBodyState& s, const Vec3& force, const Vec3& torque, double dt) const;
  /// omega = I_w^-1 L under the rotation constraints.
  Vec3 angularVelocityOf(const RigidBodyState& s) const;
  /// Kinetic energy [J].
  double kineticEnergy(const RigidBodyState& s) const;

  /// The pose as a wall's: x = c0 + displacement + rotation (X - c0).
  WallMotion::Pose pose(const RigidBodyState& s) const { return {s.rotation, s.centre - restCentre_}; }
  Vec3 place(const RigidBodyState& s, const Vec3& rest) const;
  /// The chord velocity of the particle sampled at `rest` from the pose of `s` to the pose it reaches in dt with
  /// its current velocities (as WallMotion::meanVelocity between two poses).
  Vec3 chordVelocity(const RigidBodyState& s, const Vec3& rest, double dt) const;

private:
  void constrain(RigidBodyState& s) const;
  Spec spec_;
  double mass_ = 0.0;
  Vec3 restCentre_ = Vec3::Zero();
  Mat3 inertia_ = Mat3::Zero();
  Mat3 inverseInertia_ = Mat3::Zero();
};

/// exp of the skew matrix of `rotationVector` (Rodrigues): the rotation by |w| about w.
Mat3 rotationOf(const Vec3& rotationVector);

} // namespace poro
