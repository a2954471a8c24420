// The chronological precedence search: the twin of the learning precedence
// engine (solver/search_precedence.cpp) in tests and bench/solver_learn_bench
// (no CLI command uses it, so it is not part of the library).
#pragma once

#include "solver/internal/search.hpp"

namespace gridlock {

// No learning: a transitively closed partial order on the couplings not yet
// done, safe moves, branching on requirements (docs/solver.md,
// "Chronological precedence search"). Gap systems only; throws
// std::invalid_argument for a system with more forms. Exponential in the
// number of couplings in the worst case.
SearchOutcome search_precedence_chronological(const ConstraintSystem& sys, SearchBudget& budget, SolveStats& st);

}  // namespace gridlock
