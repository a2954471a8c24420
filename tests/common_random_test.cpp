// The one generator (common/random.hpp): its sequence pinned (splitmix64's
// published first outputs for seed 0), its bounded draws in range with exact
// counts on fixed seeds (any change of the draws moves them), and the random
// lattice instances still the ones they were before the generator was shared.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <sstream>
#include <vector>

#include "common/random.hpp"
#include "lattice/grid_format.hpp"
#include "lattice/random_instance.hpp"

namespace gridlock {
namespace {

TEST(Random, Splitmix64KnownAnswers) {
  // The reference implementation (Vigna, splitmix64.c) from state 0.
  Rng zero(0);
  EXPECT_EQ(zero.next(), 0xE220A8397B1DCDAFULL);
  EXPECT_EQ(zero.next(), 0x6E789E6AA1B965F4ULL);
  EXPECT_EQ(zero.next(), 0x06C45D188009454FULL);
  Rng other(1234567);
  EXPECT_EQ(other.next(), 0x599ED017FB08FC85ULL);
  EXPECT_EQ(other.next(), 0x2C73F08458540FA5ULL);
}

TEST(Random, DeriveSeedKnownAnswers) {
  // The fuzzer's formula seeds (verify/fuzz.hpp) since its first campaign.
  EXPECT_EQ(derive_seed(1, 0), 0x5CC60547776902BAULL);
  EXPECT_EQ(derive_seed(1, 1), 0x41F9D639C82CABA3ULL);
  EXPECT_EQ(derive_seed(2026, 12345), 0x272EFBF81F9DB336ULL);
  static_assert(derive_seed(1, 0) == 0x5CC60547776902BAULL, "usable at compile time");
}

TEST(Random, BelowExactCountsOnAFixedSeed) {
  Rng rng(5);
  std::array<int, 6> count{};
  for (int i = 0; i < 60000; ++i) {
    const uint64_t v = rng.below(6);
    ASSERT_LT(v, 6U);
    ++count[v];
  }
  EXPECT_EQ(count, (std::array<int, 6>{10116, 9840, 9917, 10021, 10088, 10018}));
  for (int c : count) EXPECT_NEAR(c, 10000, 500);  // 5 sigma is about 450
  Rng one(3);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(one.below(1), 0U);
  // Just above 2^63: about half of all words are rejected.
  Rng big(17);
  const uint64_t bound = (uint64_t{1} << 63) + 1;
  EXPECT_EQ(big.below(bound), 7220676901988789713ULL);
  EXPECT_EQ(big.below(bound), 6056616057409641356ULL);
  EXPECT_EQ(big.below(bound), 4130155771025092611ULL);
}

TEST(Random, BetweenCoinBernoulliExactCounts) {
  Rng rng(7);
  std::array<int, 7> count{};
  for (int i = 0; i < 70000; ++i) {
    const int64_t v = rng.between(-3, 3);
    ASSERT_GE(v, -3);
    ASSERT_LE(v, 3);
    ++count[static_cast<size_t>(v + 3)];
  }
  EXPECT_EQ(count, (std::array<int, 7>{9989, 10068, 9957, 9955, 9948, 9901, 10182}));
  Rng coin(9);
  int heads = 0;
  for (int i = 0; i < 10000; ++i) heads += coin.coin() ? 1 : 0;
  EXPECT_EQ(heads, 4973);
  Rng b(11);
  int yes = 0;
  for (int i = 0; i < 10000; ++i) yes += b.bernoulli(30, 100) ? 1 : 0;
  EXPECT_EQ(yes, 2925);
  Rng edge(1);
  for (int i = 0; i < 100; ++i) {
    EXPECT_FALSE(edge.bernoulli(0, 7));
    EXPECT_TRUE(edge.bernoulli(7, 7));
  }
  Rng wide(2);
  for (int i = 0; i < 100; ++i) {
    const int64_t v = wide.between(INT64_MIN + 1, INT64_MAX);
    EXPECT_GT(v, INT64_MIN);
    EXPECT_EQ(wide.between(INT64_MAX, INT64_MAX), INT64_MAX);
  }
}

TEST(Random, ShufflePinnedAndAPermutation) {
  Rng rng(13);
  std::vector<int> v(10);
  std::iota(v.begin(), v.end(), 0);
  rng.shuffle(v);
  EXPECT_EQ(v, (std::vector<int>{8, 1, 2, 4, 9, 3, 7, 0, 6, 5}));
  // Every permutation of 3 elements, about equally often.
  Rng many(21);
  std::array<int, 6> seen{};
  for (int t = 0; t < 6000; ++t) {
    std::vector<int> p{0, 1, 2};
    many.shuffle(p);
    std::vector<int> sorted = p;
    std::sort(sorted.begin(), sorted.end());
    ASSERT_EQ(sorted, (std::vector<int>{0, 1, 2}));
    ++seen[(static_cast<size_t>(p[0]) * 2) + (p[1] > p[2] ? 1 : 0)];
  }
  for (int s : seen) EXPECT_NEAR(s, 1000, 150);  // about 5 sigma
  std::vector<int> empty;
  many.shuffle(empty);
  EXPECT_TRUE(empty.empty());
}

// random_instance moved from its own splitmix64 to Rng: the same parameters
// and seeds still give the same instances, byte for byte (FNV-1a of the
// written instances, taken with the generator of commit 8255798).
TEST(Random, LatticeInstancesUnchangedByTheSharedGenerator) {
  uint64_t h = 1469598103934665603ULL;
  for (uint64_t seed = 0; seed < 40; ++seed) {
    RandomInstanceParams p;
    p.nodes = static_cast<uint32_t>(6 + seed % 9);
    p.ops = static_cast<uint32_t>(2 + seed % 4);
    p.max_coupling = static_cast<uint32_t>(1 + seed % 3);
    p.extra_edge_percent = static_cast<uint32_t>((seed % 5) * 20);
    p.horizontal_only = seed % 7 == 0;
    p.path_shape = seed % 6 == 1;
    p.spread = static_cast<uint32_t>(seed % 4);
    std::ostringstream out;
    write_instance(out, random_instance(p, seed));
    for (unsigned char c : out.str()) {
      h ^= c;
      h *= 1099511628211ULL;
    }
  }
  EXPECT_EQ(h, 0xF123BE9DB885AD30ULL);
}

}  // namespace
}  // namespace gridlock
