// floor_div and ceil_div (common/int_math.hpp) against their definitions:
// every small numerator and denominator, signs included, by search for the
// quotient; and the int64 edges checked by the defining inequalities in
// 128-bit arithmetic.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "common/int_math.hpp"

namespace gridlock {
namespace {

using i128 = __int128;

// The largest q with q * b <= a (b > 0) or q * b >= a (b < 0): floor(a / b), by search.
int64_t floor_by_search(int64_t a, int64_t b) {
  for (int64_t q = 100; q >= -100; --q)
    if (b > 0 ? q * b <= a : q * b >= a) return q;
  ADD_FAILURE() << "no quotient for " << a << " / " << b;
  return 0;
}

// The smallest q with q * b >= a (b > 0) or q * b <= a (b < 0): ceil(a / b).
int64_t ceil_by_search(int64_t a, int64_t b) {
  for (int64_t q = -100; q <= 100; ++q)
    if (b > 0 ? q * b >= a : q * b <= a) return q;
  ADD_FAILURE() << "no quotient for " << a << " / " << b;
  return 0;
}

TEST(IntMath, SmallValuesMatchTheDefinition) {
  for (int64_t a = -60; a <= 60; ++a)
    for (int64_t b = -13; b <= 13; ++b) {
      if (b == 0) continue;
      EXPECT_EQ(floor_div(a, b), floor_by_search(a, b)) << a << " / " << b;
      EXPECT_EQ(ceil_div(a, b), ceil_by_search(a, b)) << a << " / " << b;
      EXPECT_EQ(floor_div<i128>(a, b), floor_by_search(a, b)) << a << " / " << b;
      EXPECT_EQ(ceil_div<i128>(a, b), ceil_by_search(a, b)) << a << " / " << b;
      EXPECT_EQ(floor_div<int>(static_cast<int>(a), static_cast<int>(b)), floor_by_search(a, b));
    }
}

TEST(IntMath, Int64EdgesSatisfyTheDefiningInequalities) {
  const std::vector<int64_t> values = {INT64_MIN,  INT64_MIN + 1, INT64_MIN / 2, -1000000007, -3, -2, -1, 0, 1, 2, 3,
                                       1000000007, INT64_MAX / 2, INT64_MAX - 1, INT64_MAX};
  for (int64_t a : values)
    for (int64_t b : values) {
      if (b == 0 || (a == INT64_MIN && b == -1)) continue;
      const i128 f = floor_div(a, b), c = ceil_div(a, b);
      // floor: f*b <= a < (f+1)*b for b > 0, mirrored for b < 0; ceil likewise.
      if (b > 0) {
        EXPECT_TRUE(f * b <= a && a < (f + 1) * b) << a << " / " << b;
        EXPECT_TRUE(c * b >= a && a > (c - 1) * b) << a << " / " << b;
      } else {
        EXPECT_TRUE(f * b >= a && a > (f + 1) * b) << a << " / " << b;
        EXPECT_TRUE(c * b <= a && a < (c - 1) * b) << a << " / " << b;
      }
      EXPECT_EQ(c - f, a % b == 0 ? 0 : 1) << a << " / " << b;
    }
  EXPECT_EQ(floor_div<int64_t>(INT64_MIN, 1), INT64_MIN);
  EXPECT_EQ(ceil_div<int64_t>(INT64_MAX, -1), -INT64_MAX);
  EXPECT_EQ(floor_div<int64_t>(INT64_MIN, 2), INT64_MIN / 2);
  EXPECT_EQ(floor_div<int64_t>(INT64_MIN + 1, 2), INT64_MIN / 2);
  EXPECT_EQ(ceil_div<int64_t>(INT64_MAX, 2), INT64_MAX / 2 + 1);
  EXPECT_EQ(floor_div<int64_t>(-7, INT64_MAX), -1);
  EXPECT_EQ(ceil_div<int64_t>(7, INT64_MIN), 0);
}

TEST(IntMath, Wide128BitQuotients) {
  const i128 big = static_cast<i128>(INT64_MAX) * 3 + 1;
  EXPECT_TRUE(floor_div<i128>(-big, 3) == -static_cast<i128>(INT64_MAX) - 1);
  EXPECT_TRUE(ceil_div<i128>(-big, 3) == -static_cast<i128>(INT64_MAX));
  EXPECT_TRUE(floor_div<i128>(big, -3) == -static_cast<i128>(INT64_MAX) - 1);
  EXPECT_TRUE(min_value<i128>() < -big);
  EXPECT_TRUE(floor_div<i128>(min_value<i128>(), 2) == min_value<i128>() / 2);
}

#ifdef GRIDLOCK_ENABLE_ASSERT
TEST(IntMathDeathTest, BrokenRequiresStop) {
  EXPECT_DEATH(floor_div<int64_t>(1, 0), "floor_div needs b != 0");
  EXPECT_DEATH(ceil_div<int64_t>(INT64_MIN, -1), "min / -1 overflows");
}
#endif

}  // namespace
}  // namespace gridlock
