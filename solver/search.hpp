// The two exact searches behind solve_discrete (solver/solve.hpp), on a
// ConstraintSystem alone: they know nothing of geometry, so tests and
// benchmarks can also run them on systems written by hand.
//
// Both answer: is there an order of all couplings 0..k-1 such that no step
// collides (step_collides on every constraint the running coupling touches)?
// Neither checks the answer against the simulator; solve_discrete does.
#pragma once

#include <chrono>
#include <cstdint>
#include <vector>

#include "solver/constraints.hpp"
#include "solver/solve.hpp"

namespace gridlock {

// Wall clock and node budget shared by the searches; throws LimitReached.
class SearchBudget {
 public:
  struct LimitReached {};
  explicit SearchBudget(const SolveOptions& opt)
      : opt_(opt), start_(std::chrono::steady_clock::now()) {}
  // Counts one node; throws LimitReached when a limit is hit. The clock is
  // read every 256 nodes.
  void tick(SolveStats& st) {
    ++st.states;
    if (opt_.max_states != 0 && st.states > opt_.max_states) throw LimitReached{};
    if (opt_.seconds > 0 && (st.states & 255) == 0 && elapsed() > opt_.seconds) throw LimitReached{};
  }
  // True when a limit is already exceeded, counting `extra` nodes not yet
  // ticked (reads the clock). For loops that cannot tick per node (set-up,
  // an external solver's callback).
  bool exhausted(const SolveStats& st, uint64_t extra = 0) const {
    if (opt_.max_states != 0 && st.states + extra > opt_.max_states) return true;
    return opt_.seconds > 0 && elapsed() > opt_.seconds;
  }
  void check(const SolveStats& st) const {
    if (exhausted(st)) throw LimitReached{};
  }
  double elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  SolveOptions opt_;
  std::chrono::steady_clock::time_point start_;
};

struct SearchOutcome {
  SolveResult::Status status = SolveResult::Status::Unknown;
  std::vector<CouplingId> order;
};

// Depth-first search over sets of done couplings, any system.
// Memo of refuted states (exact bitsets, Zobrist-hashed); safe moves (a
// coupling whose every constraint it only lowers, or that can never collide
// again once it is done, is performed without branching); stubborn sets
// (only the enabled couplings of a set closed under "may interfere" are
// branched on; a closed set with none enabled proves a dead end).
SearchOutcome search_states(const ConstraintSystem& sys, SearchBudget& budget, SolveStats& st);

// Precedence search, gap systems only (every constraint one form; then a
// step collides iff the state after it has a positive form, so only states
// matter). Throws std::invalid_argument for a system with more forms.
SearchOutcome search_precedence(const ConstraintSystem& sys, SearchBudget& budget, SolveStats& st);

// SAT back end, gap systems only: the system as clauses over order literals
// "a before b" for couplings sharing a gap (one weighted at-most-K counter per
// narrower and gap), solved by CaDiCaL incrementally; cycles among the order
// literals of a model are excluded lazily, one clause per cycle found, until
// a model is acyclic (its topological order is the answer) or the clauses are
// unsatisfiable (NO). Statistics: decisions = solve calls, refuted =
// conflicts, propagations = cycle clauses, states = both.
// Throws std::invalid_argument for a system with more forms.
SearchOutcome search_sat(const ConstraintSystem& sys, SearchBudget& budget, SolveStats& st);

}  // namespace gridlock
