#pragma once
/// Particle clouds on the sampling lattice (spacing 2r, V = (2r)^3) for the surface tests.

#include "surface/ColourField.hpp"

#include <functional>

namespace poro::test {

/// The lattice points r + 2r (i, j, k) with i, j, k in [0, n) that `keep` accepts, each with volume (2r)^3 and
/// velocity `v`.
inline ParticleCloud latticeCloud(double r, int nx, int ny, int nz, const Vec3& v = Vec3::Zero(),
                                  const std::function<bool(const Vec3&)>& keep = nullptr) {
  ParticleCloud cloud;
  ParticleField velocity{"v", 3, {}};
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const Vec3 x = Vec3(r, r, r) + 2.0 * r * Vec3(i, j, k);
        if (keep && !keep(x)) continue;
        cloud.positions.push_back(x);
        cloud.volumes.push_back(8.0 * r * r * r);
        for (int c = 0; c < 3; ++c) velocity.values.push_back(v[c]);
      }
  cloud.fields.push_back(velocity);
  return cloud;
}

} // namespace poro::test
