// FlatMap64 (lattice/flat_map.hpp) against std::unordered_map, its naive
// twin: seeded random sequences of emplace, find and clear, with keys drawn
// from small and wide ranges (collisions in the probe sequence, growth,
// clear after growth). A failure prints the seed (GRIDLOCK_TEST_SEED replays).

#include <gtest/gtest.h>

#include <cstdint>
#include <unordered_map>

#include "common/random.hpp"
#include "lattice/flat_map.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

TEST(FlatMap64, AgreesWithUnorderedMap) {
  const uint64_t base = test::base_seed(8800);
  const int runs = test::scaled(300);
  for (int run = 0; run < runs; ++run) {
    const uint64_t seed = base + static_cast<uint64_t>(run);
    Rng rng(seed);
    FlatMap64 map;
    std::unordered_map<uint64_t, uint32_t> twin;
    if (rng.below(2) == 0) map.reserve(rng.below(100));
    const uint64_t range = rng.below(2) == 0 ? 64 : UINT64_MAX;  // small: many repeats
    const int steps = 200 + static_cast<int>(rng.below(2000));
    for (int s = 0; s < steps; ++s) {
      const uint64_t key = range == UINT64_MAX ? rng.next() : rng.below(range);
      const uint64_t op = rng.below(100);
      if (op < 60) {
        const auto value = static_cast<uint32_t>(rng.below(1000000));
        const auto got = map.emplace(key, value);
        const auto want = twin.emplace(key, value);
        ASSERT_EQ(got.second, want.second) << "seed " << seed << " step " << s;
        ASSERT_EQ(got.first, want.first->second) << "seed " << seed << " step " << s;
      } else if (op < 98) {
        auto it = twin.find(key);
        ASSERT_EQ(map.find(key), it == twin.end() ? FlatMap64::kAbsent : it->second) << "seed " << seed;
      } else {
        map.clear();
        twin.clear();
      }
      ASSERT_EQ(map.size(), twin.size()) << "seed " << seed << " step " << s;
    }
    for (const auto& [k, v] : twin) ASSERT_EQ(map.find(k), v) << "seed " << seed;
  }
}

}  // namespace
}  // namespace gridlock
