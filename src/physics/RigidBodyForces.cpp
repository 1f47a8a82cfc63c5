#include "physics/RigidBodyForces.hpp"

#include "physics/FieldNames.hpp"
#include "physics/VolumeFactors.hpp"
#include "physics/WallContact.hpp"
#include "sph/BoundaryVolume.hpp"

#include <Eigen/Geometry>

#include <algorithm>

namespace poro {

std::vector<Wrench> rigidBodyWrenches(const StepContext& ctx, const std::vector<long long>& objectIds,
                                      const std::vector<Vec3>& centres,
                                      const std::vector<std::vector<Vec3>>& wallForces) {
  std::vector<Wrench> result(objectIds.size());
  if (objectIds.empty()) return result;
  const long long largest = *std::max_element(objectIds.begin(), objectIds.end());
  std::vector<int> bodyOf(static_cast<std::size_t>(largest) + 1, -1);
  for (std::size_t b = 0; b < objectIds.size(); ++b)
    bodyOf[static_cast<std::size_t>(objectIds[b])] = static_cast<int>(b);
  for (std::size_t a : ctx.dynamicSets) {
    const ParticleSet& set = ctx.particles[a];
    const auto& x = set.x();
    const auto& pi = set.real(field::pi);
    const double* kappa = hasWallContact(set) ? set.real(field::contactPressure).data() : nullptr;
    const std::int64_t* fixed = fixedFlags(set);
    for (std::size_t k : ctx.boundarySets) {
      const ParticleSet& wall = ctx.particles[k];
      const auto& xk = wall.x();
      const auto& volume = wall.real(kBoundaryVolumeField);
      const auto& object = wall.integer(field::objectId);
      const NeighbourList& list = ctx.search.list(a, k);
      const auto& factors = ctx.gradients.of(a, k);
      for (std::size_t i = 0; i < ctx.owned(a); ++i) {        // a parallel run's ghosts are their owners' to count
        const double push = pi[i] + (kappa ? kappa[i] : 0.0); // the wall terms of pi and of wall contact
        if ((fixed && fixed[i]) || push == 0.0) continue;
        std::size_t q = list.offset(i);
        for (Index kIndex : list.of(i)) {
          const std::size_t kk = static_cast<std::size_t>(kIndex);
          const double s = factors[q++];
          const long long id = object[kk];
          if (id < 0 || id > largest || bodyOf[static_cast<std::size_t>(id)] < 0) continue;
          Wrench& w = result[static_cast<std::size_t>(bodyOf[static_cast<std::size_t>(id)])];
          // gradW_ak = s (x_a - x_k); the particle feels -V_k (pi_a + kappa_a) gradW_ak per unit mass.
          const Vec3 f = (set.mass * volume[kk] * push * s) * (x[i] - xk[kk]);
          w.force += f;
          w.torque += (xk[kk] - centres[static_cast<std::size_t>(bodyOf[static_cast<std::size_t>(id)])]).cross(f);
        }
      }
    }
  }
  for (std::size_t w = 0; w < wallForces.size(); ++w) {
    const ParticleSet& wall = ctx.particles[ctx.boundarySets[w]];
    const auto& object = wall.integer(field::objectId);
    for (std::size_t k = 0; k < wallForces[w].size(); ++k) {
      const long long id = object[k];
      if (id < 0 || id > largest || bodyOf[static_cast<std::size_t>(id)] < 0) continue;
      const std::size_t b = static_cast<std::size_t>(bodyOf[static_cast<std::size_t>(id)]);
      result[b].force += wallForces[w][k];
      result[b].torque += (wall.x()[k] - centres[b]).cross(wallForces[w][k]);
    }
  }
  return result;
}

} // namespace poro
