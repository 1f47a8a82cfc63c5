#include "physics/RigidBody.hpp"

#include "core/Dictionary.hpp"
#include "core/Error.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <sstream>

namespace poro {

RigidBody::Spec RigidBody::read(const Dictionary& region, long long objectId) {
  Spec spec;
  spec.name = region.getString("name");
  spec.where = region.where("phase");
  spec.objectId = objectId;
  const bool density = region.has("density"), mass = region.has("mass");
  if (density == mass)
    region.fail(density ? "mass" : "density",
                density ? "give either density or mass of a rigid body, not both"
                        : "a rigid body needs its density: [kg/m^3] (or its mass: [kg]), a number > 0");
  if (density) spec.density = region.getReal("density", Range::positive());
  if (mass) spec.mass = region.getReal("mass", Range::positive());
  spec.velocity = region.getVec3("velocity", Vec3::Zero());
  spec.angularVelocity = region.getVec3("angularVelocity", Vec3::Zero());
  for (const std::string& axis : region.getWordList("fixedTranslation", {"x", "y", "z"}))
    spec.fixedTranslation[static_cast<std::size_t>(axis[0] - 'x')] = true;
  spec.fixedRotation = region.getBool("fixedRotation", false);
  spec.releaseTime = region.getReal("releaseTime", 0.0, Range::atLeast(0.0));
  region.markKnown("fixedAxis");
  if (region.has("fixedAxis")) {
    if (spec.fixedRotation)
      region.fail("fixedAxis", "a body with fixedRotation: true does not turn at all; give one of the two");
    const Vec3 axis = region.getVec3("fixedAxis");
    if (!(axis.norm() > 0.0)) region.fail("fixedAxis", "expected a non-zero direction to turn about, got [0, 0, 0]");
    spec.fixedAxis = axis.normalized();
  }
  return spec;
}

RigidBody::RigidBody(Spec spec, const std::vector<Vec3>& rest, double particleRadius) : spec_(std::move(spec)) {
  const double n = static_cast<double>(rest.size());
  if (rest.empty()) throw InputError(spec_.where + ": rigid region '" + spec_.name + "' has no particle");
  const double cell = 2.0 * particleRadius;
  mass_ = spec_.mass > 0.0 ? spec_.mass : spec_.density * n * cell * cell * cell;
  for (const Vec3& x : rest) restCentre_ += x;
  restCentre_ /= n;
  const double m = mass_ / n;
  inertia_ = Mat3::Identity() * (mass_ * cell * cell / 6.0); // each particle a cube of side 2r
  for (const Vec3& x : rest) {
    const Vec3 r = x - restCentre_;
    inertia_ += m * (r.squaredNorm() * Mat3::Identity() - r * r.transpose());
  }
  inverseInertia_ = inertia_.inverse();
}

RigidBodyState RigidBody::initialState() const {
  RigidBodyState s;
  s.name = spec_.name;
  s.centre = restCentre_;
  s.velocity = spec_.velocity;
  s.angularMomentum = inertia_ * spec_.angularVelocity;
  constrain(s);
  return s;
}

void RigidBody::constrain(RigidBodyState& s) const {
  for (int d = 0; d < 3; ++d)
    if (spec_.fixedTranslation[static_cast<std::size_t>(d)]) s.velocity[d] = 0.0;
  if (spec_.fixedRotation) s.angularMomentum.setZero();
  if (spec_.fixedAxis) s.angularMomentum = s.angularMomentum.dot(*spec_.fixedAxis) * *spec_.fixedAxis;
  s.angularVelocity = angularVelocityOf(s);
}

Vec3 RigidBody::angularVelocityOf(const RigidBodyState& s) const {
  if (spec_.fixedRotation) return Vec3::Zero();
  if (spec_.fixedAxis) { // a hinge: only L . a turns the body, about a, with the moment of inertia a^T I_w a
    const Vec3& a = *spec_.fixedAxis;
    return (a.dot(s.angularMomentum) / a.dot(worldInertia(s) * a)) * a;
  }
  return s.rotation * (inverseInertia_ * (s.rotation.transpose() * s.angularMomentum));
}

double RigidBody::kineticEnergy(const RigidBodyState& s) const {
  return 0.5 * mass_ * s.velocity.squaredNorm() + 0.5 * angularVelocityOf(s).dot(s.angularMomentum);
}

Mat3 rotationOf(const Vec3& w) {
  const double angle = w.norm();
  if (angle == 0.0) return Mat3::Identity();
  return Eigen::AngleAxisd(angle, w / angle).toRotationMatrix();
}

void RigidBody::integrate(RigidBodyState& s, const Vec3& force, const Vec3& torque, double dt) const {
  s.velocity += dt / mass_ * force;
  s.angularMomentum += dt * torque;
  constrain(s); // also omega at the current orientation
  s.centre += dt * s.velocity;
  const Eigen::Quaterniond q(Eigen::Matrix3d(rotationOf(dt * s.angularVelocity) * s.rotation));
  s.rotation = q.normalized().toRotationMatrix(); // re-orthonormalised
  s.angularVelocity = angularVelocityOf(s);
}

Vec3 RigidBody::place(const RigidBodyState& s, const Vec3& rest) const {
  return s.centre + s.rotation * (rest - restCentre_);
}

Vec3 RigidBody::chordVelocity(const RigidBodyState& s, const Vec3& rest, double dt) const {
  const Mat3 next = rotationOf(dt * s.angularVelocity) * s.rotation;
  return s.velocity + (next - s.rotation) * (rest - restCentre_) / dt;
}

} // namespace poro
