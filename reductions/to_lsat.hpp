// CNF -> LSAT<=3 (cnf/lsat.hpp, LsatForm::AtMost3): equisatisfiable, linear
// size, with assignment maps both ways. The construction and its proof are in
// docs/formulas.md ("3-SAT to LSAT<=3"); in short:
//
//  1. normalise: drop repeated literals within a clause, drop tautologies
//     and clauses with the same literals as an earlier one (unless
//     ToLsatOptions::keep_duplicates), split a clause of s > 3 literals into s - 2 clauses with s - 3 fresh
//     chain variables (l1 l2 a1)(-a1 l3 a2)...(-a_{s-3} l_{s-1} l_s), and
//     replace an empty clause by (u)(-u) for a fresh u;
//  2. a variable whose two literals each occur at most once is kept as it is;
//  3. every other variable x (occurring p times positively, q negatively) gets
//     a path of k = p + q - [p > 0 and q > 0] variables w_1 .. w_k tied by
//     the implications (-w_i w_{i+1}); the pivot w_s, s = max(p, 1), is x
//     itself. The j-th positive occurrence is given w_j, the j-th negative
//     one -w_{s+j-1}: positives sit before the pivot and negatives after it,
//     so w_j true forces x true and -w_{s+j-1} true forces x false. w_i's
//     positive literal is in path clause i-1 and its negative literal in
//     path clause i, so each path clause meets at most one occurrence, and
//     the two ends (w_1 for the first positive occurrence, -w_k for the last
//     negative one) meet nothing: they are free;
//  4. in each clause, free literals are written as they are, and so is the
//     first other path literal; each further one is replaced by a fresh y
//     with the link (-y path-literal).
//
// Every output clause then meets at most one other, in exactly one literal.
// The output's variables 1..n are the input's variables with the same
// meaning, so lift_to_source is truncation.
//
// Sizes, with n, m the input's counts, A the chain variables, e the empty
// clauses, m' the clauses after step 1 (excluding the (u)(-u) pairs and the
// dropped duplicates; A counts only the kept long clauses), X the
// variables of step 3 with their path lengths k_x, and d the number of links
// (sum over clauses of max(0, r - 1), r = literals in the clause of
// variables in X that are not a free end):
//   variables = n + A + sum_{x in X} (k_x - 1) + d + e
//   clauses   = m' + sum_{x in X} (k_x - 1) + d + 2e
// For a 3-CNF with m clauses of 3 distinct literals: at most 5m + n
// variables and 6m clauses (docs/formulas.md compares it with the cycle
// construction this replaced: about 15% fewer variables on random 3-SAT).
//
// An input that already is LSAT<=3 is returned unchanged (identity maps)
// unless ToLsatOptions::passthrough is false.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "cnf/formula.hpp"
#include "common/input_too_large.hpp"

namespace gridlock {

struct ToLsatOptions {
  // true: an input that is already LSAT<=3 is passed through unchanged.
  // false: always build the construction (tests exercise it on every input).
  bool passthrough = true;
  // false (the default): a clause with the same set of literals as an
  // earlier one is dropped in step 1 (smaller output, same models).
  bool keep_duplicates = false;
};

struct ToLsatStats {
  bool identity = false;  // passed through unchanged
  int in_vars = 0;
  size_t in_clauses = 0;
  size_t repeated_literals = 0;   // literals dropped as repeats within a clause
  size_t tautologies = 0;         // clauses dropped as always true
  size_t duplicate_clauses = 0;   // clauses dropped as repeats of an earlier one (as literal sets)
  size_t empty_clauses = 0;       // e: each became (u)(-u)
  size_t split_clauses = 0;       // clauses of more than 3 literals
  size_t chain_vars = 0;          // A
  size_t normalised_clauses = 0;  // m'
  size_t cycle_vars = 0;          // |X|
  size_t copies = 0;              // sum of k_x (path variables, the pivots x included)
  size_t links = 0;               // d
  int out_vars = 0;
  size_t out_clauses = 0;
};

class LsatReduction {
 public:
  // The LSAT<=3 formula. Its comments describe the reduction and its sizes.
  const Formula& output() const { return out_; }
  const ToLsatStats& stats() const { return stats_; }
  int source_vars() const { return source_vars_; }

  // An assignment of the input (indexed 1..source_vars) from one of the
  // output (size >= output().num_vars + 1; throws std::invalid_argument
  // otherwise): the values of variables 1..source_vars. If `out` satisfies
  // output(), the result satisfies the input. O(n).
  std::vector<bool> lift_to_source(const std::vector<bool>& out) const;

  // An assignment of the output (indexed 1..output().num_vars) from one of
  // the input (size >= source_vars + 1; throws otherwise): copies take their
  // variable's value, each y the value of the literal it stands for, chain
  // variable a_j is true iff the first j + 1 literals of its clause are all
  // false, u is false. If `in` satisfies the input, the result satisfies
  // output(). O(size of output).
  std::vector<bool> lift_to_target(const std::vector<bool>& in) const;

 private:
  friend class LsatBuilder;

  // How lift_to_target values an output variable above source_vars.
  struct Recipe {
    enum Kind : uint8_t { Copy, Occurrence, Chain, False } kind = False;
    int lit = 0;  // Copy: the variable copied; Occurrence: the input literal
  };
  struct ChainRecord {  // a split clause: its literals and its chain variables
    std::vector<int> lits;
    int first_var = 0;  // chain variables first_var .. first_var + lits.size() - 4
  };

  Formula out_;
  ToLsatStats stats_;
  int source_vars_ = 0;
  std::vector<Recipe> recipe_;  // indexed by output variable; entries <= source_vars unused
  std::vector<ChainRecord> chains_;
};

// Builds the reduction of `in` (clauses of any length, including empty and
// tautological ones). Requires validate(in) empty (throws
// std::invalid_argument); throws InputTooLarge (common/input_too_large.hpp)
// if the output would have more than INT_MAX variables. Time and memory O(n + L) for L literal
// occurrences (plus O(L log L) for the LSAT<=3 pass-through test and the
// duplicate test).
LsatReduction reduce_to_lsat(const Formula& in, const ToLsatOptions& opt = {});

}  // namespace gridlock
