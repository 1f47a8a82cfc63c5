// ParticleSet: removing particles takes them out of every field and keeps the others in order.

#include "sph/ParticleSet.hpp"

#include <gtest/gtest.h>

namespace poro {
namespace {

TEST(ParticleSet, RemoveDeletesFromEveryFieldKeepingOrder) {
  ParticleSet set("fluid", SetKind::Fluid);
  auto& pressure = set.addReal("pressure", Output);
  auto& stress = set.addMat3("stress");
  set.resize(6);
  for (std::size_t i = 0; i < 6; ++i) {
    set.integer(field::id)[i] = static_cast<std::int64_t>(10 + i);
    set.x()[i] = Vec3::Constant(static_cast<double>(i));
    pressure[i] = 100.0 + static_cast<double>(i);
    stress[i] = Mat3::Identity() * static_cast<double>(i);
  }
  set.remove({0, 3, 5});
  ASSERT_EQ(set.size(), 3u);
  const std::vector<std::int64_t> ids{11, 12, 14};
  EXPECT_EQ(set.integer(field::id), ids);
  for (std::size_t k = 0; k < 3; ++k) {
    const double old = static_cast<double>(ids[k] - 10);
    EXPECT_EQ(set.x()[k], Vec3::Constant(old));
    EXPECT_EQ(set.v()[k], Vec3::Zero());
    EXPECT_EQ(pressure[k], 100.0 + old); // references stay valid
    EXPECT_EQ(stress[k], Mat3::Identity() * old);
  }
  set.remove({});
  EXPECT_EQ(set.size(), 3u);
  EXPECT_THROW(set.remove({1, 0}), std::logic_error);
  EXPECT_THROW(set.remove({7}), std::logic_error);
}

} // namespace
} // namespace poro
