// Shared helpers of the cnf tests: the SATLIB sample with its labels, and
// small random CNF formulas of every shape (for the oracles and to-lsat).
#pragma once

#include <string>
#include <vector>

#include "cnf/formula.hpp"
#include "cnf/generate.hpp"

namespace gridlock::test {

struct SatlibFile {
  std::string path;
  bool sat;  // the label from tests/data/satlib/README.md: uf* SAT, uuf* UNSAT
};

// All files of the three SATLIB folders, sorted by path (300 when complete).
std::vector<SatlibFile> satlib_files();

// A formula with n variables and these clauses (no comments).
Formula make_formula(int n, std::vector<std::vector<int>> clauses);

// A random CNF formula with n variables and m clauses whose lengths are
// uniform in [min_len, max_len]. Literals are drawn independently, so with
// `messy` clauses may repeat literals, hold a literal and its negation, or
// (min_len 0) be empty; without it each clause has distinct variables.
Formula random_cnf(Rng& rng, int n, int m, int min_len, int max_len, bool messy);

}  // namespace gridlock::test
