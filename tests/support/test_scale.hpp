// How many random cases a randomized test runs: base * GRIDLOCK_TEST_SCALE
// (default 1; the sanitizer run in CI, scripts/test.sh, uses 0.3), at least 1.
#pragma once

#include <cstdlib>
#include <string>

namespace gridlock::test {

inline int scaled(int base) {
  const char* s = std::getenv("GRIDLOCK_TEST_SCALE");
  double f = s ? std::atof(s) : 1.0;
  int n = static_cast<int>(base * (f > 0 ? f : 1.0));
  return n < 1 ? 1 : n;
}

// The seed of a randomized test: GRIDLOCK_TEST_SEED if set (to replay a
// failure printed by a test), else the given default.
inline uint64_t base_seed(uint64_t dflt) {
  const char* s = std::getenv("GRIDLOCK_TEST_SEED");
  return s ? std::strtoull(s, nullptr, 10) : dflt;
}

}  // namespace gridlock::test
