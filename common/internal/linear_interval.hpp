// The set of times t at which a conjunction of linear inequalities in one
// variable holds, exactly: every a_i + b_i t > 0 (or >= 0) over rationals.
//
// Such a set is always an interval (convex): bounded below by the largest
// -a_i / b_i with b_i > 0 and above by the smallest a_i / (-b_i) with
// b_i < 0; a constraint with b_i = 0 either always holds or empties it.
// The simulator (lattice/simulate.cpp: when do two moving rectangles start
// to overlap), the discrete solver's step test (solver/constraints.cpp: does
// a step collide for some progress in (0, 1)) and Colliding Schedule's pair
// tests (collide/lp_elimination.cpp: one variable left after elimination)
// all ask this question; this is its one implementation.
//
// Coef is the coefficients' type:
//  - int64_t: bounds are compared by one 128-bit cross product each side
//    (|a|, |b| < 2^63, so every product fits): the hot paths' case;
//  - __int128: bounds are compared by Euclid on the continued fractions
//    (compare_fractions), exact for every 128-bit value, O(log) steps.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <type_traits>

#include "common/int_math.hpp"

namespace gridlock {

// num / den with den > 0.
struct Fraction {
  __int128 num = 0, den = 1;
};

// Compares n1/d1 with n2/d2 (d1, d2 > 0) exactly, for any 128-bit values:
// -1, 0 or 1. No product is formed: the floors first, then the reciprocals
// of the fractional parts (their continued fractions). O(log max(d1, d2)).
inline int compare_fractions(__int128 n1, __int128 d1, __int128 n2, __int128 d2) {
  int flip = 1;
  for (int guard = 0; guard < 400; ++guard) {
    const __int128 q1 = floor_div(n1, d1), q2 = floor_div(n2, d2);
    if (q1 != q2) return q1 < q2 ? -flip : flip;
    const __int128 r1 = n1 - q1 * d1, r2 = n2 - q2 * d2;  // 0 <= r < d
    if (r1 == 0 || r2 == 0) {
      if (r1 == 0 && r2 == 0) return 0;
      return (r1 == 0 ? -1 : 1) * flip;
    }
    // r1/d1 < r2/d2  <=>  d1/r1 > d2/r2: compare the reciprocals, flipped.
    n1 = d1, d1 = r1, n2 = d2, d2 = r2;
    flip = -flip;
  }
  throw std::logic_error("compare_fractions did not terminate");
}
inline int compare_fractions(const Fraction& x, const Fraction& y) {
  return compare_fractions(x.num, x.den, y.num, y.den);
}

// The interval {t : a_i + b_i t > 0 (or >= 0) for every constraint added},
// built one constraint at a time. O(1) per constraint for int64_t
// coefficients, O(log) for __int128 ones (see above).
template <class Coef>
class LinearInterval {
  static_assert(std::is_same_v<Coef, int64_t> || std::is_same_v<Coef, __int128>,
                "LinearInterval<int64_t> or LinearInterval<__int128>");

 public:
  // One end of the interval; absent when the interval is unbounded there.
  struct End {
    bool present = false;
    bool strict = false;  // open end (the end itself is not in the set)
    Fraction at;
  };

  // The whole line.
  LinearInterval() = default;
  // The open window (lo, hi). Requires den > 0 for both.
  LinearInterval(Fraction lo, Fraction hi) : lo_{true, true, lo}, hi_{true, true, hi} {}

  // Intersects with {t : a + b t > 0} (strict) or {t : a + b t >= 0}.
  // Returns false when the constraint alone leaves nothing (b = 0 and it
  // fails), so a caller may stop there; true does not mean non-empty (the
  // ends are compared only by empty(), once, not at every constraint).
  bool add(Coef a, Coef b, bool strict = true) {
    if (b == 0) {
      if (strict ? a <= 0 : a < 0) empty_ = true;
    } else if (b > 0) {  // t > -a/b
      const Fraction c{-static_cast<__int128>(a), b};
      const int cmp = lo_.present ? compare(c, lo_.at) : 1;
      if (cmp > 0 || (cmp == 0 && strict)) lo_ = End{true, strict, c};
    } else {  // t < a/(-b)
      const Fraction c{a, -static_cast<__int128>(b)};
      const int cmp = hi_.present ? compare(c, hi_.at) : -1;
      if (cmp < 0 || (cmp == 0 && strict)) hi_ = End{true, strict, c};
    }
    return !empty_;
  }

  // True iff no t satisfies every constraint added. O(1) compare.
  bool empty() const {
    if (empty_) return true;
    if (!lo_.present || !hi_.present) return false;
    const int cmp = compare(lo_.at, hi_.at);
    return cmp > 0 || (cmp == 0 && (lo_.strict || hi_.strict));
  }
  // True iff the set holds more than one point (an open sub-interval).
  bool has_interior() const {
    if (empty_) return false;
    return !lo_.present || !hi_.present || compare(lo_.at, hi_.at) < 0;
  }
  const End& lower() const { return lo_; }
  const End& upper() const { return hi_; }

 private:
  static int compare(const Fraction& x, const Fraction& y) {
    if constexpr (std::is_same_v<Coef, int64_t>) {
      const __int128 l = x.num * y.den, r = y.num * x.den;
      return l < r ? -1 : (l > r ? 1 : 0);
    } else {
      return compare_fractions(x, y);
    }
  }
  End lo_, hi_;
  bool empty_ = false;
};

}  // namespace gridlock
