#include "surface/PorousVolumes.hpp"

#include "core/Parallel.hpp"
#include "physics/ElasticRestState.hpp"
#include "physics/FieldNames.hpp"
#include "sph/Kernel.hpp"
#include "sph/ParticleSet.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace poro {

std::vector<double> deformedVolumes(const ParticleSet& set, double particleRadius) {
  const double lattice = 8.0 * particleRadius * particleRadius * particleRadius;
  std::vector<double> volumes(set.size(), lattice);
  if (!set.has(field::restPosition) || !set.has(field::objectId) || set.size() == 0) return volumes;
  const CubicKernel kernel(4.0 * particleRadius);
  ElasticRestState rest;
  rest.update(set, kernel);
  const auto& x = set.x();
  parallel::forEach(set.size(), [&](std::size_t s) {
    Mat3 f = Mat3::Zero();
    for (std::size_t pair = rest.begin(s); pair < rest.end(s); ++pair) {
      const std::size_t t = static_cast<std::size_t>(rest.neighbour(pair));
      f += (x[t] - x[s]) * (rest.correction(s) * rest.weightedGradient(pair)).transpose();
    }
    // Fewer than three rest neighbours cannot give a gradient: L_s = I then, and F would be meaningless.
    const double det = rest.end(s) - rest.begin(s) >= 3 ? f.determinant() : 1.0;
    volumes[s] = lattice * std::clamp(std::abs(det), 0.05, 20.0);
  });
  return volumes;
}

} // namespace poro
