// NO certificates: the text that `gridlock certify` (certify/, a checker
// that shares none of this code) reads to confirm a NO without trusting
// the solvers. Format and why each kind proves NO: docs/certificates.md.
//
// Discrete: a coupling that breaks a cycle (its face walk), or, for
// horizontal-only instances, the learning precedence engine's log: every
// cycle of order literals it met ("o" lines) and every nogood it learned
// ("l" lines), ending with the empty clause; for other instances the pairs
// engine's clauses ("x" colliding pair patterns, "o" cycles) and CaDiCaL's
// lemmas ("l"). Continuous, horizontal-only:
// running everything at once collides (paper, linear-time theorem): the
// final configuration has a negative gap or a cycle that does not close.
#pragma once

#include <cstdint>
#include <string>

#include "lattice/prepared.hpp"
#include "solver/continuous.hpp"
#include "solver/solve.hpp"

namespace gridlock {

struct CertifiedSolve {
  SolveResult result;
  std::string certificate;  // result NO: the certificate, or empty (then why_none says why)
  std::string why_none;
};

// solve_discrete(prep, opt, replay), and with every NO a certificate when one can be
// written: always for a cycle breaker; for a horizontal-only instance from
// the precedence engine (engine Auto runs it instead of the SAT engine, so
// the search runs once; after a NO of another engine it runs again, with
// the same limits, to write the log); for any other instance from the pairs
// engine in proof mode (kind pairs: its clauses with their reasons and
// CaDiCaL's DRAT proof), run again after the NO with the same limits.
// why_none says why there is none (a limit reached). Same exceptions as
// solve_discrete; std::logic_error if the second run disagrees.
CertifiedSolve solve_discrete_certified(const PreparedInstance& prep, const SolveOptions& opt,
                                        Simulator* replay = nullptr);

struct CertifiedContinuous {
  ContinuousResult result;
  std::string certificate;  // result NO: the certificate, or empty (then why_none says why)
  std::string why_none;
};

// solve_continuous(inst, opt, engine), and with every NO a certificate when
// one can be written: horizontal-only instances as continuous_no_certificate;
// others from the learning engine's proof (solve_continuous_proved, kind
// bounds: its clauses with their reasons, the theory lemmas of Z3's proof
// and CaDiCaL's DRAT proof that they are unsatisfiable). The search runs
// once, with Z3's proofs on (about 2.5x slower than without). why_none:
// a NO the learning engine did not find (Z3 on the clamped encoding) or
// one it cannot write yet (docs/certificates.md). Same exceptions as
// solve_continuous; std::logic_error if CaDiCaL finds the proof's clauses
// satisfiable (a bug).
CertifiedContinuous solve_continuous_certified(const Instance& inst, const SolveOptions& opt,
                                               ContinuousEngine engine = ContinuousEngine::Auto);

// Continuous model, horizontal-only instances: if running everything at
// once collides (check_gaps), the certificate naming why the final
// configuration is invalid; empty if it does not collide. O(n + e).
// Requires inst.horizontal_only().
std::string continuous_no_certificate(const Instance& inst);

}  // namespace gridlock
