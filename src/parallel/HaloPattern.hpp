#pragma once
/// Which particles a subdomain lends its neighbours (ARCHITECTURE.md "Decomposed runs"): every particle within the
/// reach (support radius plus skin) of another subdomain's bounding box. A box holds all of that subdomain's
/// particles, so every pair within the reach that straddles two subdomains is seen by both; ragged subdomains
/// (Hilbert cuts) get a few ghosts more than they need, never fewer.

#include "core/Types.hpp"

#include <vector>

namespace poro {

struct Box {
  Vec3 lo = Vec3::Constant(INFINITY);
  Vec3 hi = Vec3::Constant(-INFINITY);
  bool empty() const { return !(lo.x() <= hi.x()); }
  void add(const Vec3& x) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  /// Euclidean distance from x to the box (0 inside); infinite for an empty box.
  double distance(const Vec3& x) const;
};

Box boundingBox(const std::vector<const std::vector<Vec3>*>& positions);

/// For every rank q (boxes[q] its subdomain's box): the indices of `x` within `reach` of that box, ascending; empty for
/// `self` and for empty boxes.
std::vector<std::vector<Index>> haloSendLists(const std::vector<Vec3>& x, const std::vector<Box>& boxes, int self,
                                              double reach);

} // namespace poro
