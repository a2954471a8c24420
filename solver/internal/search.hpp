// The two exact searches behind solve_discrete (solver/solve.hpp), on a
// ConstraintSystem alone: they know nothing of geometry, so tests and
// benchmarks can also run them on systems written by hand.
//
// Both answer: is there an order of all couplings 0..k-1 such that no step
// collides (step_collides on every constraint the running coupling touches)?
// Neither checks the answer against the simulator; solve_discrete does.
#pragma once

#include <cstdint>
#include <cstdio>  // std::FILE (PairsProof)
#include <functional>
#include <optional>
#include <vector>

#include "common/limits.hpp"
#include "solver/internal/constraints.hpp"
#include "solver/solve.hpp"

namespace gridlock {

// Wall clock, node budget and stop requests shared by the searches and the
// set-up of solve_discrete; throws LimitReached (common/limits.hpp).
class SearchBudget {
 public:
  using LimitReached = gridlock::LimitReached;
  explicit SearchBudget(const SolveOptions& opt) : opt_(opt), deadline_(opt.seconds) {}
  // Counts one node; throws LimitReached when a limit is hit. The clock is
  // read at every node (a search node costs far more than a clock read), so
  // --timeout is honoured to within one node.
  void tick(SolveStats& st) {
    ++st.states;
    if (opt_.max_states != 0 && st.states > opt_.max_states) throw LimitReached{};
    deadline_.check();
    if (opt_.on_progress) show_progress(st);
  }
  // Time and stop check without counting a node: for long loops inside one
  // node and for the set-up (constraint building).
  void check() const { deadline_.check(); }
  // check() every 64th call: for loops whose steps are too cheap to read
  // the clock at each one, but that may run for seconds inside one node.
  void poll() {
    if ((++polls_ & 63) == 0) deadline_.check();
  }
  const Deadline& deadline() const { return deadline_; }
  double elapsed() const { return deadline_.elapsed(); }
  // Depth of the current search path, shown by the progress line.
  void set_depth(size_t depth) { depth_ = depth; }
  // The node limit (0: none), for external solvers given it as a parameter.
  uint64_t max_states() const { return opt_.max_states; }
  // Reports WHAT through SolveOptions::on_progress (if set), at most twice
  // a second: for a computation that cannot tick, e.g. one call of an
  // external solver (then only from one thread at a time).
  void show_activity(const char* what) {
    if (!opt_.on_progress) return;
    const double t = elapsed();
    if (t - last_shown_ < 0.5) return;
    last_shown_ = t;
    SolveProgress p;
    p.states = states_seen_, p.depth = depth_, p.seconds = t, p.activity = what;
    report(p);
  }
  // The last report (finished = true), if any was made: the listener may
  // erase what it drew.
  void clear_progress() {
    if (!reported_) return;
    SolveProgress p;
    p.states = states_seen_, p.depth = depth_, p.seconds = elapsed(), p.finished = true;
    reported_ = false;
    opt_.on_progress(p);
  }
  // True when a limit is already exceeded (time, stop request, or nodes,
  // counting `extra` nodes not yet ticked). For loops that cannot tick per
  // node: an external solver's callback.
  bool exhausted(const SolveStats& st, uint64_t extra = 0) const {
    if (opt_.max_states != 0 && st.states + extra > opt_.max_states) return true;
    return deadline_.expired();
  }
  // check() that also counts the node limit.
  void check(const SolveStats& st) const {
    if (exhausted(st)) throw LimitReached{};
  }

 private:
  void show_progress(const SolveStats& st) {
    states_seen_ = st.states;
    const double t = elapsed();
    if (t - last_shown_ < 0.5) return;
    last_shown_ = t;
    SolveProgress p;
    p.states = st.states, p.depth = depth_, p.seconds = t;
    report(p);
  }
  void report(const SolveProgress& p) {
    reported_ = true;
    opt_.on_progress(p);
  }
  SolveOptions opt_;
  Deadline deadline_;
  size_t depth_ = 0;
  uint64_t polls_ = 0;
  double last_shown_ = 0;
  uint64_t states_seen_ = 0;
  bool reported_ = false;
};

struct SearchOutcome {
  Verdict status = Verdict::Unknown;
  std::vector<CouplingId> order;
};

// Depth-first search over sets of done couplings, any system.
// Memo of refuted states (exact bitsets, Zobrist-hashed); safe moves (a
// coupling whose every constraint it only lowers, or that can never collide
// again once it is done, is performed without branching); stubborn sets
// (only the enabled couplings of a set closed under "may interfere" are
// branched on; a closed set with none enabled proves a dead end).
SearchOutcome search_states(const ConstraintSystem& sys, SearchBudget& budget, SolveStats& st);

// What a test may watch inside the learning precedence search.
struct PrecedenceHooks {
  // Called with every nogood learned, as the clause it adds: at least one
  // of these (a, b), "a before b", holds in every collision-free order.
  std::function<void(const std::vector<std::pair<CouplingId, CouplingId>>&)> on_learned;
  // Called with every cycle of set literals the search meets (at level 0
  // or once everything is set), as its edges (a, b) in path order: no
  // total order has all of them. A NO certificate needs these before the
  // nogoods learned from them (docs/certificates.md).
  std::function<void(const std::vector<std::pair<CouplingId, CouplingId>>&)> on_cycle;
};

// Precedence search with learning, gap systems only (docs/solver.md,
// "Precedence search (learning)"): CDCL over the literals "a before b" for
// couplings that share a gap, with the gap constraints propagated as
// weighted sums and cycles refused by an incrementally kept topological
// order. Statistics: decisions, refuted = conflicts, propagations = implied
// literals, states = decisions + conflicts. hooks (optional) for tests.
// Throws std::invalid_argument for a system with more forms.
SearchOutcome search_precedence(const ConstraintSystem& sys, SearchBudget& budget, SolveStats& st,
                                const PrecedenceHooks* hooks = nullptr);

// SAT back end, gap systems only: the system as clauses over order literals
// "a before b" for couplings sharing a gap (one weighted at-most-K counter per
// narrower and gap), solved by CaDiCaL incrementally; cycles among the order
// literals of a model are excluded lazily, one clause per cycle found, until
// a model is acyclic (its topological order is the answer) or the clauses are
// unsatisfiable (NO). Statistics: decisions = solve calls, refuted =
// conflicts, propagations = cycle clauses, states = both.
// Throws std::invalid_argument for a system with more forms.
SearchOutcome search_sat(const ConstraintSystem& sys, SearchBudget& budget, SolveStats& st);

// SAT back end for any system (docs/solver.md, "Engine pairs"): one-form
// constraints as the sat engine encodes them; a constraint of more forms
// over at most 8 couplings as one clause per cube of colliding patterns
// (the running coupling and which of the others ran before it, decided by
// step_collides), larger ones lazily, pattern by pattern, as an acyclic
// model's order meets them; order literals, transitivity and lazy cycle
// clauses from solver/internal/order_sat.hpp. Statistics as search_sat, propagations
// also counting lazy pattern clauses. eager_limit: constraints of more
// couplings than this are handled lazily (tests use 0 to run the lazy path
// on every multi-form constraint).
constexpr size_t kPairsEagerLimit = 8;
SearchOutcome search_pairs(const ConstraintSystem& sys, SearchBudget& budget, SolveStats& st,
                           size_t eager_limit = kPairsEagerLimit);

// What a NO of the pairs engine rests on: every clause it gave CaDiCaL,
// over order literals (a, b) = "a before b", with its reason, and
// CaDiCaL's DRAT proof of their unsatisfiability (text, over the variables
// of var_pair). solver/no_certificate.cpp writes it as a certificate of
// kind pairs (docs/certificates.md).
struct PairsProof {
  struct Axiom {
    uint32_t constraint = kNone;  // kNone: a cycle clause; else the pair constraint that collides
    CouplingId runner = kNone;    // the coupling whose step collides (pair constraints)
    std::vector<std::pair<CouplingId, CouplingId>> lits;  // the clause: one of them holds
  };
  std::vector<Axiom> axioms;
  std::FILE* drat = nullptr;                                // set by the caller: CaDiCaL writes here
  std::vector<std::pair<CouplingId, CouplingId>> var_pair;  // var_pair[v]: variable v true means first < second
};

// The pairs engine in proof mode: one-form constraints as pattern clauses
// too (no counters), no forced-closure clauses, every clause recorded in
// proof. Same verdicts as search_pairs; somewhat slower.
SearchOutcome search_pairs_proof(const ConstraintSystem& sys, SearchBudget& budget, SolveStats& st, PairsProof& proof);

// solve_discrete (solver/solve.hpp) keeping its constraint system: when
// `kept` holds one, it must be the one this prep builds (the same engine
// family: gap constraints for a horizontal-only instance, pair constraints
// otherwise) and is used as it is; when empty and the run builds one, it
// is left there. So a second engine on the same instance (the precedence
// engine writing a NO certificate's log after the SAT engine decided,
// solver/no_certificate.cpp) does not build the same constraints again.
SolveResult solve_discrete_kept(const PreparedInstance& prep, const SolveOptions& opt, Simulator* replay,
                                std::optional<ConstraintSystem>& kept);

}  // namespace gridlock
