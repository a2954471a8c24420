// LinearInterval and compare_fractions (common/internal/linear_interval.hpp) against
// a naive reference: the solution set of one-variable linear constraints is
// decided by evaluating every constraint exactly at each breakpoint -a/b, at
// the midpoints between consecutive breakpoints and beyond the outermost.
// Thousands of seeded random systems (GRIDLOCK_TEST_SEED replays), with both
// coefficient types, with and without a window.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "common/internal/linear_interval.hpp"
#include "common/random.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

using i128 = __int128;

struct Con {
  int64_t a = 0, b = 0;
  bool strict = true;
};

// a + b (n/d) (>, >=) 0 exactly, d > 0: sign of a d + b n.
bool holds(const Con& c, const Fraction& t) {
  const i128 v = static_cast<i128>(c.a) * t.den + static_cast<i128>(c.b) * t.num;
  return c.strict ? v > 0 : v >= 0;
}
bool holds_all(const std::vector<Con>& cs, const Fraction& t) {
  return std::all_of(cs.begin(), cs.end(), [&](const Con& c) { return holds(c, t); });
}
int cross(const Fraction& x, const Fraction& y) {
  const i128 l = x.num * y.den, r = y.num * x.den;
  return l < r ? -1 : (l > r ? 1 : 0);
}

// What the reference knows about the set: is it empty, does it have an
// interior, and its infimum and supremum (absent = unbounded).
struct Reference {
  bool empty = true, interior = false;
  bool has_inf = false, has_sup = false;
  Fraction inf, sup;
};

Reference reference(const std::vector<Con>& cs) {
  std::vector<Fraction> bp;
  for (const Con& c : cs)
    if (c.b != 0) bp.push_back(c.b > 0 ? Fraction{-c.a, c.b} : Fraction{c.a, -static_cast<i128>(c.b)});
  std::sort(bp.begin(), bp.end(), [](const Fraction& x, const Fraction& y) { return cross(x, y) < 0; });
  bp.erase(std::unique(bp.begin(), bp.end(), [](const Fraction& x, const Fraction& y) { return cross(x, y) == 0; }),
           bp.end());
  // Candidates in increasing order, each marked: breakpoint or not.
  std::vector<std::pair<Fraction, bool>> cand;
  if (bp.empty()) {
    cand.push_back({Fraction{0, 1}, false});
  } else {
    cand.push_back({Fraction{bp.front().num - bp.front().den, bp.front().den}, false});
    for (size_t i = 0; i < bp.size(); ++i) {
      cand.push_back({bp[i], true});
      if (i + 1 < bp.size())
        cand.push_back(
            {Fraction{bp[i].num * bp[i + 1].den + bp[i + 1].num * bp[i].den, 2 * bp[i].den * bp[i + 1].den}, false});
    }
    cand.push_back({Fraction{bp.back().num + bp.back().den, bp.back().den}, false});
  }
  Reference r;
  size_t first = cand.size(), last = 0;
  for (size_t i = 0; i < cand.size(); ++i) {
    if (!holds_all(cs, cand[i].first)) continue;
    r.empty = false;
    if (!cand[i].second) r.interior = true;
    first = std::min(first, i);
    last = i;
  }
  if (r.empty) return r;
  // The infimum: the first satisfied candidate if a breakpoint, else the
  // breakpoint before it (if any); likewise the supremum.
  if (cand[first].second) r.has_inf = true, r.inf = cand[first].first;
  else if (first > 0) r.has_inf = true, r.inf = cand[first - 1].first;
  if (cand[last].second) r.has_sup = true, r.sup = cand[last].first;
  else if (last + 1 < cand.size()) r.has_sup = true, r.sup = cand[last + 1].first;
  return r;
}

template <class Coef>
void expect_matches(const std::vector<Con>& cs, uint64_t seed) {
  LinearInterval<Coef> iv;
  for (const Con& c : cs) iv.add(c.a, c.b, c.strict);
  const Reference r = reference(cs);
  ASSERT_EQ(iv.empty(), r.empty) << "seed " << seed;
  if (r.empty) return;
  EXPECT_EQ(iv.has_interior(), r.interior) << "seed " << seed;
  ASSERT_EQ(iv.lower().present, r.has_inf) << "seed " << seed;
  ASSERT_EQ(iv.upper().present, r.has_sup) << "seed " << seed;
  if (r.has_inf) {
    EXPECT_EQ(compare_fractions(iv.lower().at, r.inf), 0) << "seed " << seed;
    EXPECT_EQ(iv.lower().strict, !holds_all(cs, r.inf)) << "seed " << seed;
  }
  if (r.has_sup) {
    EXPECT_EQ(compare_fractions(iv.upper().at, r.sup), 0) << "seed " << seed;
    EXPECT_EQ(iv.upper().strict, !holds_all(cs, r.sup)) << "seed " << seed;
  }
}

std::vector<Con> random_system(Rng& rng, int64_t range) {
  std::vector<Con> cs(1 + rng.below(6));
  for (Con& c : cs) {
    c.a = rng.between(-range, range);
    c.b = rng.bernoulli(1, 6) ? 0 : rng.between(-range, range);
    c.strict = !rng.bernoulli(1, 3);
  }
  return cs;
}

TEST(LinearInterval, MatchesTheNaiveReferenceOnRandomSystems) {
  const uint64_t base = test::base_seed(22);
  for (int i = 0; i < test::scaled(20000); ++i) {
    const uint64_t seed = derive_seed(base, static_cast<uint64_t>(i));
    Rng rng(seed);
    const std::vector<Con> cs = random_system(rng, i % 2 == 0 ? 6 : 1000000);
    expect_matches<int64_t>(cs, seed);
    expect_matches<i128>(cs, seed);
    if (HasFailure()) return;
  }
}

// The window form (lo, hi) is the same as two more strict constraints.
TEST(LinearInterval, WindowIsTwoStrictConstraints) {
  const uint64_t base = test::base_seed(23);
  for (int i = 0; i < test::scaled(5000); ++i) {
    const uint64_t seed = derive_seed(base, static_cast<uint64_t>(i));
    Rng rng(seed);
    std::vector<Con> cs = random_system(rng, 8);
    for (Con& c : cs) c.strict = true;
    const int64_t span = rng.between(1, 9);
    LinearInterval<int64_t> win(Fraction{0, 1}, Fraction{span, 1});
    for (const Con& c : cs) win.add(c.a, c.b);
    cs.push_back({0, 1, true});      // t > 0
    cs.push_back({span, -1, true});  // t < span
    const Reference r = reference(cs);
    ASSERT_EQ(win.empty(), r.empty) << "seed " << seed;
    if (!r.empty) {
      EXPECT_EQ(compare_fractions(win.lower().at, r.inf), 0) << "seed " << seed;
    }
  }
}

TEST(LinearInterval, ConstantConstraintEmptiesAtOnce) {
  LinearInterval<int64_t> iv;
  EXPECT_TRUE(iv.add(1, 2));
  EXPECT_FALSE(iv.add(0, 0));  // 0 > 0 fails
  EXPECT_TRUE(iv.empty());
  LinearInterval<int64_t> closed;
  EXPECT_TRUE(closed.add(0, 0, false));  // 0 >= 0 holds
  EXPECT_FALSE(closed.empty());
  EXPECT_FALSE(closed.lower().present);
}

TEST(LinearInterval, Int64ExtremesDoNotOverflow) {
  // t > -INT64_MIN / 1 = 2^63 and t < INT64_MAX / 1: empty; with the
  // reversed order of sizes, a point-free open gap of width one ulp-free.
  LinearInterval<int64_t> iv;
  iv.add(INT64_MIN, 1);
  iv.add(INT64_MAX, -1);
  EXPECT_TRUE(iv.empty());
  LinearInterval<int64_t> wide;
  wide.add(INT64_MAX, 1);   // t > -(2^63 - 1)
  wide.add(INT64_MAX, -1);  // t < 2^63 - 1
  EXPECT_FALSE(wide.empty());
  EXPECT_TRUE(wide.has_interior());
}

// compare_fractions against cross products where those fit, and against
// its own symmetry and scaling where they do not.
TEST(CompareFractions, MatchesCrossProductsAndScales) {
  const uint64_t base = test::base_seed(24);
  for (int i = 0; i < test::scaled(20000); ++i) {
    const uint64_t seed = derive_seed(base, static_cast<uint64_t>(i));
    Rng rng(seed);
    const int64_t r = i % 2 == 0 ? 20 : INT64_MAX / 2;
    const Fraction x{rng.between(-r, r), rng.between(1, r)}, y{rng.between(-r, r), rng.between(1, r)};
    ASSERT_EQ(compare_fractions(x, y), cross(x, y)) << "seed " << seed;
    // Scaled by a large factor, products of 128-bit values would overflow.
    const i128 m = rng.between(1, INT64_MAX >> 4);  // |x| * m < 2^122, m * m beyond 2^118
    EXPECT_EQ(compare_fractions(Fraction{x.num * m, x.den * m}, y), cross(x, y)) << "seed " << seed;
    EXPECT_EQ(compare_fractions(Fraction{x.num * m, x.den * m}, Fraction{y.num * m, y.den * m}), cross(x, y))
        << "seed " << seed;
    EXPECT_EQ(compare_fractions(y, x), -cross(x, y)) << "seed " << seed;
  }
  const i128 huge = (static_cast<i128>(1) << 125) + 1;
  EXPECT_EQ(compare_fractions(huge, huge - 1, huge - 1, huge - 2), -1);  // 1 + 1/(h-1) < 1 + 1/(h-2)
  EXPECT_EQ(compare_fractions(-huge, huge - 1, -huge + 1, huge - 2), 1);
  EXPECT_EQ(compare_fractions(huge, huge, 1, 1), 0);
}

}  // namespace
}  // namespace gridlock
