// Independent SAT oracles for tests and fuzzing: no code shared with
// CaDiCaL, simple enough to trust by reading.
//   exhaustive_sat  tries every assignment (num_vars <= 24): the reference;
//   dpll_sat        DPLL with unit propagation and a decision budget: for
//                   the larger but easy formulas reductions produce.
#pragma once

#include <cstdint>

#include "cnf/formula.hpp"
#include "cnf/sat_solver.hpp"

namespace gridlock {

// The largest num_vars exhaustive_sat accepts.
constexpr int kExhaustiveMaxVars = 24;

// Tries the assignments in counting order (variable v is bit v-1) and returns
// the first that satisfies f (status Sat, model indexed 1..num_vars), or
// Unsat. Requires validate(f) empty and num_vars <= kExhaustiveMaxVars
// (throws std::invalid_argument otherwise). Time O(2^n * L) worst case.
// lim.seconds (> 0) bounds the wall clock (checked every 65536
// assignments; a stop request, common/limits.hpp, ends it too): then
// Unknown. lim.conflicts does not apply (the command line refuses it).
SatResult exhaustive_sat(const Formula& f, const SatLimits& lim = {});

// Number of satisfying assignments over all num_vars variables (variables in
// no clause double the count). Same requirements. Time O(2^n * L).
uint64_t count_models(const Formula& f);

// Chronological-backtracking DPLL: unit propagation to a fixpoint by
// through occurrence lists, branching on a literal of a shortest open clause
// (that literal true first, then false). No learning, no restarts: the point
// is being obviously right, not fast. Gives Unknown after max_decisions
// decisions, or after lim.conflicts (>= 0) conflicts, or when lim.seconds
// (> 0) of wall clock have passed or a stop is requested (checked at every
// decision and conflict). Requires validate(f) empty (throws
// std::invalid_argument). Time O(decisions * L) plus propagation; memory
// O(L + n).
SatResult dpll_sat(const Formula& f, uint64_t max_decisions = 1000000, const SatLimits& lim = {});

}  // namespace gridlock
