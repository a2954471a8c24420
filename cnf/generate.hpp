// Seeded formula generators. The same parameters and seed give the same
// formula, byte for byte, on every machine and compiler: the only randomness
// is the project's one generator, Rng (common/random.hpp: splitmix64 with our
// own bounded draws; std::uniform_int_distribution is implementation-defined,
// so it is never used). Each generator records its name, parameters and seed
// in the formula's comments; `gridlock cnf gen` adds the command line.
//
// Invalid parameters throw std::invalid_argument with a message fit for a
// user (the command line reports it as a usage error).
#pragma once

#include <cstdint>
#include <vector>

#include "cnf/formula.hpp"
#include "common/random.hpp"

namespace gridlock {

// Uniform random k-SAT (SATLIB's model): m clauses, each of k distinct
// variables drawn uniformly from 1..n with uniform signs, independently.
// Requires 1 <= k <= n, m >= 0. Time O(m k) expected.
struct KSatParams {
  int n = 0;
  int m = 0;
  int k = 3;
  uint64_t seed = 1;
};
Formula random_ksat(const KSatParams& p);

// Clause count for a clause/variable ratio: round(ratio * n), for "--ratio".
// Requires ratio >= 0 and a result that fits an int.
int clauses_for_ratio(int n, double ratio);

// A random LSAT formula (cnf/lsat.hpp) with n variables and m clauses whose
// lengths are uniform in [min_len, max_len] (3, 3: the paper's exact form;
// 1, 3: LSAT<=3). Each clause has distinct variables; a random number of
// clause pairs share one literal (the only intersections LSAT allows); every
// other literal occurrence is a literal used nowhere else. Lengths are
// shortened (toward min_len) only when m clauses would not fit otherwise.
// Requires 1 <= min_len <= max_len <= 3, max_len <= n, and
// m <= lsat_max_clauses(n, min_len). Exact-3 LSAT formulas are all
// satisfiable (docs/formulas.md); shorter clauses make unsatisfiable ones
// possible but rare at random. Time O(n + m) expected.
struct LsatParams {
  int n = 0;
  int m = 0;
  int min_len = 3;
  int max_len = 3;
  uint64_t seed = 1;
};
Formula random_lsat(const LsatParams& p);

// The largest m for which an LSAT formula with n variables and m clauses of
// at least min_len literals exists: m * min_len - floor(m / 2) <= 2n
// (each literal at most twice, and only the one shared literal of a
// clause pair counts twice). About 4n/5 for min_len 3.
int lsat_max_clauses(int n, int min_len);

// Planted-solution k-SAT: a hidden assignment drawn uniformly, then m clauses
// drawn as in random_ksat but redrawn while the hidden assignment falsifies
// them. Satisfiable by construction; the hidden assignment is recorded in a
// comment ("planted: 1 -2 3 ...") and, if planted != nullptr, returned there
// (indexed 1..n). Requires 1 <= k <= n, m >= 0. Time O(m k) expected.
struct PlantedParams {
  int n = 0;
  int m = 0;
  int k = 3;
  uint64_t seed = 1;
};
Formula planted_ksat(const PlantedParams& p, std::vector<bool>* planted = nullptr);

}  // namespace gridlock
