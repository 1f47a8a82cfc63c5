// Halo pattern: distances to a subdomain box, and the particles lent to each other subdomain (those within the reach
// of its box, never to the subdomain itself or to an empty one).

#include "parallel/HaloPattern.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace poro {
namespace {

TEST(HaloPattern, BoxDistanceIsEuclideanOutsideAndZeroInside) {
  Box box;
  EXPECT_TRUE(box.empty());
  EXPECT_EQ(box.distance(Vec3::Zero()), INFINITY);
  box.add(Vec3(0, 0, 0));
  box.add(Vec3(1, 2, 3));
  EXPECT_FALSE(box.empty());
  EXPECT_EQ(box.distance(Vec3(0.5, 1, 1)), 0.0);
  EXPECT_DOUBLE_EQ(box.distance(Vec3(-3, 1, 1)), 3.0);
  EXPECT_DOUBLE_EQ(box.distance(Vec3(4, 6, 3)), 5.0);            // 3-4-5 past a corner edge
  EXPECT_DOUBLE_EQ(box.distance(Vec3(2, 3, 4)), std::sqrt(3.0)); // past the corner
}

TEST(HaloPattern, LendsWhatLiesWithinReachOfEachOtherBox) {
  const std::vector<Vec3> x{Vec3(0.96, 0.5, 0.5), Vec3(0.5, 0.5, 0.5), Vec3(1.0, 0.5, 0.5), Vec3(0.98, 0.0, 0.0)};
  std::vector<Box> boxes(4);
  boxes[0].add(Vec3(0, 0, 0)); // this rank
  boxes[0].add(Vec3(1, 1, 1));
  boxes[1].add(Vec3(1.05, 0, 0)); // the neighbour along x
  boxes[1].add(Vec3(2, 1, 1));
  boxes[3].add(Vec3(1.05, -1, -1)); // below and beside, across an edge: only the particle at the edge is near
  boxes[3].add(Vec3(2, -0.02, -0.02));
  const auto lists = haloSendLists(x, boxes, 0, 0.1);
  ASSERT_EQ(lists.size(), 4u);
  EXPECT_TRUE(lists[0].empty());
  EXPECT_EQ(lists[1], (std::vector<Index>{0, 2, 3}));
  EXPECT_TRUE(lists[2].empty());                // an empty subdomain
  EXPECT_EQ(lists[3], (std::vector<Index>{3})); // 0.076 from that edge; particle 2 is 0.52 off in y
}

} // namespace
} // namespace poro
