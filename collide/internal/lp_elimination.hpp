// Exact linear programming in at most two variables, for the pair tests of
// Colliding Schedule (collide/zonotope.cpp, collide/subset_sums.cpp):
// constraints a0 v0 + a1 v1 + c (>, >=) 0 in 128-bit integers, one variable
// eliminated by Fourier-Motzkin, the last one's interval from the kernel
// (common/internal/linear_interval.hpp), witness values on the 2^-20 grid, and the
// vertices of the closed feasible polygon. Internal to collide/ (not
// installed).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "common/internal/linear_interval.hpp"

namespace gridlock::pairs {

using i128 = __int128;

// a0 v0 + a1 v1 + c  (> 0 if strict, >= 0 otherwise)
struct Lin {
  i128 a[2] = {0, 0};
  i128 c = 0;
  bool strict = true;
};

// Feasible set of one variable from constraints a v + c (>, >=) 0 (a[1] == 0),
// exactly (common/internal/linear_interval.hpp). O(c log) for c constraints.
LinearInterval<i128> interval_of(const std::vector<Lin>& cons);

// Fourier-Motzkin: eliminates v1, returns the constraints on v0 alone.
// O(c^2) constraints out for c in.
std::vector<Lin> eliminate_v1(const std::vector<Lin>& cons);

constexpr int kScaleBits = 20;
constexpr int64_t kScale = int64_t{1} << kScaleBits;

// Picks an integer m in [0, kScale] with a*m + c (>, >=) 0 for all given
// (a, c, strict), preferring multiples of large powers of two (so that the
// values, as m / 2^20, have small denominators). nullopt if none.
std::optional<int64_t> pick_scaled(const std::vector<Lin>& cons);

// gcd(|a|, |b|); gcd(0, 0) = 0. O(log).
i128 gcd128(i128 a, i128 b);

// The vertices (n0/d, n1/d) of cl J, J the set the constraints (nv
// variables) describe: pairs of constraint lines that meet in a point
// satisfying every constraint (non-strict). O(c^3), c <= 10.
std::vector<std::array<i128, 3>> closure_vertices(const std::vector<Lin>& cons, int nv);

}  // namespace gridlock::pairs
