// Exact integer helpers: the one floor and ceiling division of the project,
// for every signed integer type the code divides in (int64_t, and __int128
// where products of two 64-bit values are divided). C++'s `/` truncates
// toward zero; geometry on the lattice needs floor (which cell holds a
// coordinate) and ceiling (the least integer above a bound).
#pragma once

#include <limits>
#include <type_traits>

#include "common/assert.hpp"

namespace gridlock {

// The signed integer types, __int128 included (std::is_signed_v is false for
// it in strict standard modes).
template <class T>
concept SignedInteger = (std::is_integral_v<T> && std::is_signed_v<T>) || std::is_same_v<T, __int128>;

// The least value of T. O(1).
template <SignedInteger T>
constexpr T min_value() {
  if constexpr (std::is_same_v<T, __int128>) {
    return static_cast<T>(static_cast<unsigned __int128>(1) << 127);
  } else {
    return std::numeric_limits<T>::min();
  }
}

// floor(a / b), exactly. Requires b != 0 and not (a = min and b = -1), whose
// quotient does not fit (GRIDLOCK_ASSERT). O(1).
template <SignedInteger T>
constexpr T floor_div(T a, T b) {
  GRIDLOCK_ASSERT(b != 0, "floor_div needs b != 0");
  GRIDLOCK_ASSERT(!(b == -1 && a == min_value<T>()), "floor_div: min / -1 overflows");
  const T q = a / b;
  // Truncation rounded up exactly when there is a remainder and the signs differ.
  return (a % b != 0 && ((a < 0) != (b < 0))) ? q - 1 : q;
}

// ceil(a / b), exactly. Same requirements as floor_div. O(1).
template <SignedInteger T>
constexpr T ceil_div(T a, T b) {
  GRIDLOCK_ASSERT(b != 0, "ceil_div needs b != 0");
  GRIDLOCK_ASSERT(!(b == -1 && a == min_value<T>()), "ceil_div: min / -1 overflows");
  const T q = a / b;
  // Truncation rounded down exactly when there is a remainder and the signs agree.
  return (a % b != 0 && ((a < 0) == (b < 0))) ? q + 1 : q;
}

}  // namespace gridlock
