#include "parallel/HaloPattern.hpp"

#include <cmath>

namespace poro {

double Box::distance(const Vec3& x) const {
  if (empty()) return INFINITY;
  const Vec3 outside = (lo - x).cwiseMax(x - hi).cwiseMax(Vec3::Zero());
  return outside.norm();
}

Box boundingBox(const std::vector<const std::vector<Vec3>*>& positions) {
  Box box;
  for (const std::vector<Vec3>* x : positions)
    for (const Vec3& p : *x) box.add(p);
  return box;
}

std::vector<std::vector<Index>> haloSendLists(const std::vector<Vec3>& x, const std::vector<Box>& boxes, int self,
                                              double reach) {
  std::vector<std::vector<Index>> lists(boxes.size());
  for (std::size_t q = 0; q < boxes.size(); ++q) {
    if (static_cast<int>(q) == self || boxes[q].empty()) continue;
    for (std::size_t i = 0; i < x.size(); ++i)
      if (boxes[q].distance(x[i]) <= reach) lists[q].push_back(static_cast<Index>(i));
  }
  return lists;
}

} // namespace poro
