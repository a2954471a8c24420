// The one random source of the project: splitmix64 (Steele, Lea and Flood,
// "Fast splittable pseudorandom number generators", 2014) with our own
// bounded draws. The same seed gives the same sequence on every machine and
// compiler: nothing here uses std::uniform_int_distribution or the other
// standard distributions, whose output is implementation-defined.
//
// Used by the formula generators (cnf/generate.hpp), the random lattice
// instances (lattice/random_instance.hpp), the fuzzer's per-formula seeds
// (verify/fuzz.hpp) and the solver's hashing keys; tests and fuzz targets
// draw from it too. Not for anything secret.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "common/assert.hpp"

namespace gridlock {

// One step of splitmix64's output function on a state that has just been
// advanced: a bijection of 64-bit words that mixes every input bit into
// every output bit. O(1).
constexpr uint64_t splitmix64_mix(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

// The seed of item `index` of a run seeded with `seed` (a fuzz campaign's
// formula i, a test's case t): any item can be redrawn from (seed, index)
// alone, and nearby (seed, index) pairs give unrelated seeds. O(1).
constexpr uint64_t derive_seed(uint64_t seed, uint64_t index) {
  return splitmix64_mix(seed * 0x9E3779B97F4A7C15ULL + index + 0x632BE59BD9B4E019ULL);
}

class Rng {
 public:
  // Any seed is valid, 0 included; the state is the seed itself.
  explicit constexpr Rng(uint64_t seed) : state_(seed) {}

  // The next 64-bit word, uniform over all 2^64 values. O(1).
  constexpr uint64_t next() {
    state_ += 0x9E3779B97F4A7C15ULL;
    return splitmix64_mix(state_);
  }

  // Uniform in [0, bound). Requires bound > 0 (GRIDLOCK_ASSERT). Rejection
  // sampling: words at or above the largest multiple of bound that fits in
  // UINT64_MAX are redrawn, so no residue is favoured. O(1) expected (fewer
  // than 2 words per draw in the worst case, bound just above 2^63).
  constexpr uint64_t below(uint64_t bound) {
    GRIDLOCK_ASSERT(bound > 0, "Rng::below needs bound > 0");
    const uint64_t limit = UINT64_MAX - UINT64_MAX % bound;
    uint64_t x = next();
    while (x >= limit) x = next();
    return x % bound;
  }

  // Uniform in [lo, hi]. Requires lo <= hi (GRIDLOCK_ASSERT); the full range
  // [INT64_MIN, INT64_MAX] is not supported (its size does not fit). O(1)
  // expected.
  constexpr int64_t between(int64_t lo, int64_t hi) {
    GRIDLOCK_ASSERT(lo <= hi, "Rng::between needs lo <= hi");
    const uint64_t size = static_cast<uint64_t>(hi) - static_cast<uint64_t>(lo) + 1;
    GRIDLOCK_ASSERT(size != 0, "Rng::between: the range has 2^64 values");
    return static_cast<int64_t>(static_cast<uint64_t>(lo) + below(size));
  }

  // A fair coin: the top bit of one word. O(1).
  constexpr bool coin() { return (next() >> 63) != 0; }

  // True with probability num / den. Requires 0 < den and num <= den
  // (GRIDLOCK_ASSERT). O(1) expected.
  constexpr bool bernoulli(uint64_t num, uint64_t den) {
    GRIDLOCK_ASSERT(den > 0 && num <= den, "Rng::bernoulli needs 0 <= num <= den, den > 0");
    return below(den) < num;
  }

  // A uniform permutation of v (Fisher–Yates, from the back: position i - 1
  // swaps with a uniform position in [0, i)). O(v.size()).
  template <class T>
  void shuffle(std::vector<T>& v) {
    for (size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[static_cast<size_t>(below(i))]);
  }

 private:
  uint64_t state_;
};

}  // namespace gridlock
