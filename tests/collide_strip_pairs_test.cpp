// strip_pair (collide/internal/strip_pairs.hpp), the query the motion-class
// test asks per strip, against its naive twin (every pair) on seeded
// random point sets: clustered coordinates so that every bound is met
// with equality often, A and B distinct or the same set. A failure prints
// the seed (GRIDLOCK_TEST_SEED replays).
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "collide/internal/strip_pairs.hpp"
#include "common/random.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

std::vector<StripPoint> points(Rng& rng, size_t count, uint32_t first_id, int64_t span) {
  std::vector<StripPoint> out(count);
  for (size_t i = 0; i < count; ++i) {
    out[i].x = rng.between(-span, span);
    out[i].u = rng.between(-span, span);
    out[i].v = rng.between(-span, span);
    out[i].id = first_id + static_cast<uint32_t>(i);
  }
  return out;
}

// Does (a, b) meet the query's bounds?
bool meets(const StripPoint& a, const StripPoint& b, int64_t x_lo, int64_t x_hi, __int128 u_min, __int128 v_max) {
  return a.id != b.id && a.x - b.x >= x_lo && a.x - b.x <= x_hi && a.u - b.u > u_min && a.v - b.v < v_max;
}

TEST(StripPairs, AgreesWithEveryPairOnRandomSets) {
  const uint64_t seed0 = test::base_seed(91000);
  const int cases = test::scaled(5000);
  int found = 0, same_found = 0;
  for (int i = 0; i < cases; ++i) {
    const uint64_t seed = seed0 + static_cast<uint64_t>(i);
    Rng rng(seed);
    const int64_t span = 1 + static_cast<int64_t>(rng.below(rng.below(2) ? 4 : 40));
    const bool same = rng.below(3) == 0;
    const std::vector<StripPoint> A = points(rng, rng.below(30), 0, span);
    const std::vector<StripPoint> B = same ? A : points(rng, rng.below(30), 1000, span);
    const int64_t x_lo = rng.between(-span, span), x_hi = x_lo + static_cast<int64_t>(rng.below(2 * span + 1)) - 1;
    const __int128 u_min = rng.between(-2 * span, 2 * span), v_max = rng.between(-2 * span, 2 * span);
    const std::string where = "seed " + std::to_string(seed) +
                              "; replay with GRIDLOCK_TEST_SEED=" + std::to_string(seed);
    const auto fast = strip_pair(A, B, x_lo, x_hi, u_min, v_max);
    const auto naive = strip_pair_naive(A, B, x_lo, x_hi, u_min, v_max);
    ASSERT_EQ(fast.has_value(), naive.has_value()) << where;
    if (!fast) continue;
    ++found;
    same_found += same;
    // The pair returned meets every bound (A's point first).
    const StripPoint *a = nullptr, *b = nullptr;
    for (const StripPoint& p : A)
      if (p.id == fast->first) a = &p;
    for (const StripPoint& p : B)
      if (p.id == fast->second) b = &p;
    ASSERT_TRUE(a && b) << where;
    ASSERT_TRUE(meets(*a, *b, x_lo, x_hi, u_min, v_max)) << where;
  }
  std::cout << "[ info ] " << cases << " queries, " << found << " with a pair (" << same_found << " within one set)\n";
  EXPECT_GT(found, cases / 5);
  EXPECT_LT(found, cases - cases / 5);
  EXPECT_GT(same_found, cases / 50);
}

}  // namespace
}  // namespace gridlock
