// Random gap systems (every constraint one form) for the engines' tests:
// one generator with the shapes the tests draw, so that each test keeps
// its own random stream (solver_sat, solver_learn, solver_order_sat_twin).
#pragma once

#include <cstdint>

#include "common/random.hpp"
#include "solver/internal/constraints.hpp"

namespace gridlock::test {

struct GapSystemShape {
  int64_t max_gaps = 7;          // gaps: uniform in 1..max_gaps
  int64_t max_size = 0;          // couplings per gap: 2..max_size (0: k)
  bool sometimes_three = false;  // a coin first: heads, at most 3 per gap
  int64_t min_base = -4;         // bases in [min_base, 0]
  int64_t max_coef = 3;          // coefficients in [-max_coef, max_coef] \ {0}
};

// k >= 2 couplings; gaps over distinct sorted couplings. O(gaps * k).
ConstraintSystem random_gap_system(Rng& rng, size_t k, const GapSystemShape& shape);

}  // namespace gridlock::test
