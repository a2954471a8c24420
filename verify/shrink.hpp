// Shrinking a failing formula (delta debugging), so that a counterexample
// found by `gridlock fuzz` is reported as small as it can be made.
#pragma once

#include <cstddef>
#include <functional>

#include "cnf/formula.hpp"

namespace gridlock {

struct ShrinkStats {
  size_t tries = 0;  // calls of the predicate
  size_t steps = 0;  // successful reductions
};

// Requires still_fails(f). Returns g with still_fails(g), reached from f by
// steps that each keep the failure: dropping chunks of clauses (ddmin, from
// halves down to single clauses), dropping single literals (no clause becomes
// empty), fixing a variable to true or false (satisfied clauses vanish,
// falsified literals go; skipped if a clause would become empty), and
// renumbering the variables that remain to 1..k. The result is 1-minimal for
// each of these steps. Predicate calls: O(m^2 + m * len + n) in the worst
// case for m clauses and n variables; usually far fewer. Deterministic.
Formula shrink_formula(const Formula& f, const std::function<bool(const Formula&)>& still_fails,
                       ShrinkStats* stats = nullptr);

// Renumbers the variables that occur to 1..k in order of first occurrence
// (clauses and literal order unchanged, comments kept).
Formula compact_variables(const Formula& f);

}  // namespace gridlock
