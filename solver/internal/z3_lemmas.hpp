// The theory lemmas of a Z3 proof, as clauses of difference bounds: what a
// continuous NO certificate needs from Z3 (solver/internal/continuous_sat.hpp,
// ContinuousProof). Z3 (with proof=true) proves unsatisfiability by
// resolution over the input clauses and its theory lemmas (th-lemma steps:
// "these arithmetic facts cannot hold together"); the rest of its proof is
// propositional and rewriting. So the input clauses plus the theory lemmas
// are propositionally unsatisfiable, and a SAT solver can redo that part
// with a proof format that a small checker reads (DRAT).
#pragma once

#include <cstdint>
#include <vector>

#include <z3++.h>

#include "lattice/rational.hpp"

namespace gridlock {

// t_x - t_y <= v (< v if strict), x and y the numbers N of Z3 real
// constants named "tN".
struct DiffLiteral {
  uint32_t x = 0, y = 0;
  Rational v;
  bool strict = false;
};

// Every theory lemma of `proof` (a proof of false from the solver's
// assertions) as a clause: the negations of its premises' facts and the
// literals of its conclusion. Every literal must be a comparison (<=, <,
// >=, >, possibly negated) whose two sides differ by c * (tX - tY) plus a
// constant, c != 0 (Z3 rewrites x - y <= v into x + -1*y <= v and the
// like); else std::runtime_error names the literal. Each distinct lemma
// once. Time: linear in the proof's DAG size.
std::vector<std::vector<DiffLiteral>> z3_theory_lemmas(const z3::expr& proof);

}  // namespace gridlock
