// ParticleSet: removing particles takes them out of every field and keeps the others in order; selecting and
// appending (a subdomain's share and the merge back) carry every field, role and constant; a dropped field is gone.

#include "sph/ParticleSet.hpp"

#include <gtest/gtest.h>

#include <algorithm>

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

TEST(ParticleSet, SelectAndAppendCarryEveryFieldRoleAndConstant) {
  ParticleSet set("sand", SetKind::Porous);
  auto& rest = set.addVec3("restPosition", Restart);
  auto& rotation = set.addMat3("rotation", Restart);
  auto& scratch = set.addReal("scratch");
  set.resize(5);
  set.particleVolume = 8e-6;
  set.mass = 0.004;
  set.restDensity = 1500.0;
  set.source = "0/porous.vtp";
  for (std::size_t i = 0; i < 5; ++i) {
    set.integer(field::id)[i] = static_cast<std::int64_t>(i);
    set.x()[i] = Vec3(1.0, 2.0, static_cast<double>(i));
    set.v()[i] = Vec3::Constant(-static_cast<double>(i));
    rest[i] = Vec3::Constant(0.5 * static_cast<double>(i));
    rotation[i] = Mat3::Identity() * static_cast<double>(i);
    scratch[i] = 3.0 * static_cast<double>(i);
  }
  ParticleSet piece = set.select({4, 1});
  EXPECT_EQ(piece.name(), "sand");
  EXPECT_EQ(piece.kind(), SetKind::Porous);
  EXPECT_EQ(piece.particleVolume, 8e-6);
  EXPECT_EQ(piece.mass, 0.004);
  EXPECT_EQ(piece.restDensity, 1500.0);
  EXPECT_EQ(piece.source, "0/porous.vtp");
  ASSERT_EQ(piece.size(), 2u);
  ASSERT_EQ(piece.fields().size(), set.fields().size());
  EXPECT_EQ(piece.info("rotation")->role, Restart);
  EXPECT_EQ(piece.info("scratch")->role, Scratch);
  EXPECT_EQ(piece.integer(field::id), (std::vector<std::int64_t>{4, 1}));
  EXPECT_EQ(piece.x()[0], set.x()[4]); // the shorthands point at the piece's own fields
  EXPECT_EQ(piece.v()[1], set.v()[1]);
  EXPECT_EQ(piece.mat3("rotation")[0], rotation[4]);
  EXPECT_EQ(piece.real("scratch")[1], scratch[1]);

  ParticleSet rest3 = set.select({0, 2, 3});
  piece.append(rest3);
  ASSERT_EQ(piece.size(), 5u);
  EXPECT_EQ(piece.integer(field::id), (std::vector<std::int64_t>{4, 1, 0, 2, 3}));
  EXPECT_EQ(piece.vec3("restPosition")[4], rest[3]);
  EXPECT_EQ(piece.x().size(), 5u);

  ParticleSet other("sand", SetKind::Porous);
  other.resize(1);
  EXPECT_THROW(piece.append(other), std::logic_error); // other fields
  EXPECT_THROW(set.select({5}), std::logic_error);
}

TEST(ParticleSet, PackedFieldsUnpackBitForBitIntoOtherSlots) {
  ParticleSet from("fluid", SetKind::Fluid);
  auto& stress = from.addMat3("stress");
  auto& pressure = from.addReal("pressure");
  from.resize(4);
  for (std::size_t i = 0; i < 4; ++i) {
    from.integer(field::id)[i] = static_cast<std::int64_t>(100 + i);
    from.x()[i] = Vec3(0.1 * static_cast<double>(i), 1.0 / 3.0, -2.0);
    stress[i] = Mat3::Random();
    pressure[i] = 1e5 / (1.0 + static_cast<double>(i));
  }
  std::vector<char> all, some;
  from.pack({3, 0}, {}, all);
  from.pack({3, 0}, {"pressure", "x"}, some);
  EXPECT_EQ(all.size(), 2 * (2 * 8 + 2 * 24 + 72 + 8));
  EXPECT_EQ(some.size(), 2 * (8 + 24));

  ParticleSet to("fluid", SetKind::Fluid);
  to.addMat3("stress");
  to.addReal("pressure");
  to.resize(3);
  EXPECT_EQ(to.unpack(all.data(), 2, 1, {}), all.size());
  EXPECT_EQ(to.integer(field::id), (std::vector<std::int64_t>{0, 103, 100}));
  EXPECT_EQ(to.mat3("stress")[1], stress[3]);
  EXPECT_EQ(to.x()[2], from.x()[0]);
  to.real("pressure")[1] = 0.0;
  to.x()[1] = Vec3::Zero();
  to.v()[1] = Vec3::Ones();
  EXPECT_EQ(to.unpack(some.data(), 2, 1, {"pressure", "x"}), some.size());
  EXPECT_EQ(to.real("pressure")[1], pressure[3]);
  EXPECT_EQ(to.x()[1], from.x()[3]);
  EXPECT_EQ(to.v()[1], Vec3::Ones()); // not in the message
  EXPECT_THROW(to.unpack(some.data(), 2, 2, {"pressure", "x"}), std::logic_error);
  EXPECT_THROW(from.pack({0}, {"density"}, some), std::logic_error);
}

// Two scratch arrays used at different times of a step share one storage: both names reach it, permutes and
// subdomain selections move it once, and it is neither listed nor packed twice.
TEST(ParticleSet, AScratchFieldSharingAnothersStorageIsOneArray) {
  ParticleSet set("fluid", SetKind::Fluid);
  auto& rhs = set.addVec3("rhs");
  set.share("acceleration", "rhs");
  auto& acceleration = set.addVec3("acceleration");
  EXPECT_EQ(&acceleration, &rhs);
  EXPECT_TRUE(set.has("acceleration"));
  set.resize(4);
  for (std::size_t i = 0; i < 4; ++i) acceleration[i] = Vec3::Constant(static_cast<double>(i));
  set.permute({3, 2, 1, 0});
  EXPECT_EQ(set.vec3("acceleration")[0], Vec3::Constant(3.0)) << "permuted once, not twice";
  const std::vector<std::string> names = set.fieldNames();
  EXPECT_EQ(std::count(names.begin(), names.end(), "acceleration"), 0);
  EXPECT_EQ(std::count(names.begin(), names.end(), "rhs"), 1);
  const ParticleSet part = set.select({1, 2});
  EXPECT_EQ(&part.vec3("acceleration"), &part.vec3("rhs"));
  EXPECT_EQ(part.vec3("acceleration")[0], Vec3::Constant(2.0));

  EXPECT_THROW(set.addVec3("acceleration", Restart), std::logic_error) << "a shared storage is scratch only";
  EXPECT_THROW(set.addReal("acceleration"), std::logic_error) << "of the storage's type";
  EXPECT_THROW(set.share("rhs", "acceleration"), std::logic_error) << "a registered name";
  set.addReal("pressure", Output);
  EXPECT_THROW(set.share("other", "pressure"), std::logic_error) << "a field written out";
  EXPECT_THROW(set.share("other", "missing"), std::logic_error);
}

TEST(ParticleSet, ADroppedFieldIsGoneFromEveryListAndTheOthersKeepTheirValues) {
  ParticleSet set("sponge", SetKind::Porous);
  set.addReal("pressure", Output);
  set.addReal("contactPressure", Restart);
  set.resize(3);
  set.real("pressure")[2] = 7.0;
  set.drop("contactPressure");
  EXPECT_FALSE(set.has("contactPressure"));
  const std::vector<std::string> names = set.fieldNames();
  EXPECT_EQ(std::count(names.begin(), names.end(), "contactPressure"), 0);
  EXPECT_EQ(set.real("pressure")[2], 7.0);
  set.resize(5); // the registry no longer resizes what is gone
  EXPECT_EQ(set.real("pressure").size(), 5u);
  set.drop("never registered"); // nothing to do
  set.addReal("contactPressure", Restart);
  EXPECT_EQ(set.real("contactPressure"), std::vector<Real>(5, 0.0)) << "registered anew, from zero";

  for (const char* kept : {field::x, field::v, field::id}) EXPECT_THROW(set.drop(kept), std::logic_error) << kept;
  set.addVec3("rhs");
  set.share("acceleration", "rhs");
  EXPECT_THROW(set.drop("rhs"), std::logic_error) << "the storage of a shared name";
}

} // namespace
} // namespace poro
