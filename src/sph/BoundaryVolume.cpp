#include "sph/BoundaryVolume.hpp"

#include "core/Parallel.hpp"
#include "sph/NeighbourSearch.hpp"

namespace poro {

void computeBoundaryVolumes(ParticleSet& boundary, const CubicKernel& kernel) {
  auto& volume = boundary.addReal(kBoundaryVolumeField, Output);
  const auto& x = boundary.x();
  const auto& body = boundary.integer(field::objectId);
  NeighbourSearch search(kernel.supportRadius());
  search.update({&x}, {{true}});
  const NeighbourList& list = search.list(0, 0);
  parallel::forEach(boundary.size(), [&](std::size_t k) {
    double sum = kernel.w0();
    for (Index c : list.of(k))
      if (body[static_cast<std::size_t>(c)] == body[k]) sum += kernel.w(x[k] - x[static_cast<std::size_t>(c)]);
    volume[k] = 1.0 / sum;
  });
}

} // namespace poro
