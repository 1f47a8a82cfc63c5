// Decomposition (parallel/Decomposition.hpp): every particle lands in exactly one subdomain with all its fields, the
// interface count is the lattice's, and merging the pieces gives the input back (by id) or names what is wrong.

#include "parallel/Decomposition.hpp"

#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

namespace poro {
namespace {

/// Fills `set` with n particles at pseudo-random positions in [0, 1]^3, ids from `firstId` in shuffled order and a
/// value in every field derived from the id.
void fill(ParticleSet& set, std::size_t n, std::int64_t firstId, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  set.resize(n);
  std::vector<std::int64_t> ids(n);
  std::iota(ids.begin(), ids.end(), firstId);
  std::shuffle(ids.begin(), ids.end(), rng);
  for (std::size_t i = 0; i < n; ++i) {
    set.integer(field::id)[i] = ids[i];
    set.x()[i] = Vec3(u(rng), u(rng), u(rng));
    set.v()[i] = Vec3::Constant(static_cast<double>(ids[i]));
  }
}

ParticleSystem threeSets() {
  ParticleSystem particles(0.02);
  fill(particles.add("fluid", SetKind::Fluid), 700, 0, 1);
  ParticleSet& sand = particles.add("sand", SetKind::Porous);
  auto& rotation = sand.addMat3("rotation", Restart);
  auto& material = sand.addInt("materialId", Restart);
  fill(sand, 300, 700, 2);
  for (std::size_t i = 0; i < sand.size(); ++i) {
    rotation[i] = Mat3::Identity() * static_cast<double>(sand.integer(field::id)[i]);
    material[i] = 1;
  }
  fill(particles.add("boundary", SetKind::Boundary), 400, 1000, 3);
  return particles;
}

TEST(Decomposition, LatticeOctantsHaveTheLatticeInterface) {
  // 20^3 particles at spacing 1 (r = 0.5, H = 2) cut into 2 x 2 x 2 blocks: a block's interface particles are those
  // in its layers next to the three inner cut planes, 10^3 - 9^3 = 271.
  ParticleSystem particles(0.5);
  ParticleSet& fluid = particles.add("fluid", SetKind::Fluid);
  fluid.resize(8000);
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j)
      for (int k = 0; k < 20; ++k) fluid.x()[static_cast<std::size_t>(400 * i + 20 * j + k)] = Vec3(i, j, k);
  DecomposeSettings settings;
  settings.subdomains = 8;
  const DecomposedParticles d = decomposeParticles(particles, settings);
  ASSERT_EQ(d.pieces.size(), 8u);
  EXPECT_EQ(d.summary.imbalance, 0.0);
  for (std::size_t p = 0; p < 8; ++p) {
    EXPECT_EQ(d.summary.particles[p][0], 1000u);
    EXPECT_EQ(d.summary.boundaryParticles[p], 271u) << "subdomain " << p;
    EXPECT_EQ(d.summary.weights[p], 1000.0 * settings.fluidWeight);
  }
}

TEST(Decomposition, SplitsEverySetAndMergesBackByIdBitForBit) {
  for (const PartitionMethod method : {PartitionMethod::RecursiveBisection, PartitionMethod::HilbertCurve}) {
    const ParticleSystem particles = threeSets();
    DecomposeSettings settings;
    settings.subdomains = 3;
    settings.method = method;
    DecomposedParticles d = decomposeParticles(particles, settings);
    ASSERT_EQ(d.pieces.size(), 3u);
    for (std::size_t s = 0; s < particles.size(); ++s) {
      std::size_t total = 0;
      for (const ParticleSystem& piece : d.pieces) {
        ASSERT_EQ(piece.size(), particles.size());
        EXPECT_EQ(piece[s].name(), particles[s].name());
        EXPECT_EQ(piece.particleRadius(), particles.particleRadius());
        total += piece[s].size();
      }
      EXPECT_EQ(total, particles[s].size()) << particles[s].name();
    }
    // Weights: fluid 1, porous 1.75, walls 0.05 per particle.
    const double weight = std::accumulate(d.summary.weights.begin(), d.summary.weights.end(), 0.0);
    EXPECT_DOUBLE_EQ(weight, 700.0 + 1.75 * 300.0 + 0.05 * 400.0);
    EXPECT_LT(d.summary.imbalance, 2.0 / (weight / 3.0) * 2.0); // within two of the heaviest particles

    const ParticleSystem merged =
        mergePieces(std::move(d.pieces), {"p0", "p1", "p2"}, {"fluid", "sand", "other", "boundary", "rigid"});
    ASSERT_EQ(merged.size(), 3u);
    for (std::size_t s = 0; s < 3; ++s) {
      const ParticleSet& original = particles[s];
      const ParticleSet& back = merged[s];
      EXPECT_EQ(back.name(), original.name());
      ASSERT_EQ(back.size(), original.size());
      for (std::size_t i = 0; i < back.size(); ++i) {
        const std::int64_t id = back.integer(field::id)[i];
        if (i > 0) {
          EXPECT_LT(back.integer(field::id)[i - 1], id);
        }
        const auto& ids = original.integer(field::id);
        const std::size_t at = static_cast<std::size_t>(std::find(ids.begin(), ids.end(), id) - ids.begin());
        ASSERT_LT(at, ids.size());
        EXPECT_EQ(back.x()[i], original.x()[at]);
        EXPECT_EQ(back.v()[i], original.v()[at]);
        if (original.has("rotation")) {
          EXPECT_EQ(back.mat3("rotation")[i], original.mat3("rotation")[at]);
        }
      }
    }
  }
}

TEST(Decomposition, MergeNamesOverlappingPiecesAndForeignSets) {
  const ParticleSystem particles = threeSets();
  DecomposeSettings settings;
  settings.subdomains = 2;
  {
    DecomposedParticles d = decomposeParticles(particles, settings);
    d.pieces.push_back(std::move(d.pieces[1])); // a stale copy of processor1
    d.pieces[1] = std::move(decomposeParticles(particles, settings).pieces[1]);
    try {
      mergePieces(std::move(d.pieces), {"processor0/0.5", "processor1/0.5", "processor2/0.5"},
                  {"fluid", "sand", "boundary"});
      FAIL() << "overlapping pieces merged";
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("processor2/0.5"), std::string::npos) << message;
      EXPECT_NE(message.find("also in processor1/0.5"), std::string::npos) << message;
    }
  }
  DecomposedParticles d = decomposeParticles(particles, settings);
  try {
    mergePieces(std::move(d.pieces), {"a", "b"}, {"fluid", "boundary"});
    FAIL() << "a set outside the case's order merged";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'sand'"), std::string::npos) << e.what();
  }
}

} // namespace
} // namespace poro
