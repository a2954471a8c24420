// The exact solver of Discrete Collision-free Schedule (docs/model.md, "Couplings
// and schedules"): is there an order of all couplings, run one at a time,
// that performs every operation with no collision?
//
// Any instance: all four directions, expansions, contractions, growths,
// cycles, couplings of any size. The problem is NP-complete (paper,
// Theorem "Discrete Collision-free Schedule is NP-complete"), so the search is
// exponential in the worst case; docs/solver.md explains the pruning rules,
// why each keeps the answer exact, and measured figures.
//
// Pipeline:
//  1. a coupling whose operations sum to a non-zero vector around some face
//     (FaceNets::coupling_breaks_cycle) collides whenever it runs: NO at once;
//  2. the collision constraints (solver/internal/constraints.hpp): gap constraints for
//     horizontal-only instances, pair constraints otherwise;
//  3. one of two exact searches over "the set of couplings done":
//     - Precedence (gap systems only, the default there): a DPLL-like search
//       that posts "a before b" decisions, derives forced orderings and dead
//       ends by propagation over the gap constraints, and performs a coupling
//       only when an exchange argument shows that doing it now loses no
//       solution;
//     - States (any system, the default for non-horizontal instances):
//       depth-first search over states with a memo of refuted states, safe
//       moves and stubborn-set partial-order reduction;
//  4. a YES order is replayed by the exact Simulator before it is returned;
//     if the simulator disagrees, solve_discrete throws std::logic_error
//     (a bug, never a silent wrong answer).
//
// Requirements: inst is a valid Instance (InstanceBuilder guarantees it).
// Complexity: set-up O(n + e log e) plus the constraint builder (near linear
// for gap systems; see build_pair_constraints for the general case), then
// per search node O(size of the constraint system) for the state search and
// O(C * r^2 + k^2 / 64 per derived ordering) for the precedence search
// (C constraints of at most r couplings each, k couplings). Memory: the memo
// holds k bits per refuted state; the precedence search keeps two k x k bit
// matrices per open decision.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "common/verdict.hpp"
#include "lattice/instance.hpp"
#include "lattice/prepared.hpp"
#include "lattice/simulate.hpp"

namespace gridlock {

struct PrecedenceHooks;  // solver/internal/search.hpp

// What a long solve reports through SolveOptions::on_progress. The library
// never draws: the command line turns these into its progress line
// (tools/progress_line.hpp).
struct SolveProgress {
  uint64_t states = 0;             // search nodes so far
  size_t depth = 0;                // depth of the current search path
  double seconds = 0;              // since the solve began
  const char* activity = nullptr;  // set when what runs counts no nodes (e.g. one call of Z3)
  bool finished = false;           // the last report: the solve is returning
};

struct SolveOptions {
  double seconds = 0;       // wall-clock limit; 0 = no limit
  uint64_t max_states = 0;  // limit on search nodes; 0 = none
  // Called at most twice a second while the search runs (from the thread
  // that searches), and once with finished = true before the solve returns
  // if it was called at all. Empty: no reports.
  std::function<void(const SolveProgress&)> on_progress;
  // Which search to run. Auto: Sat for horizontal-only instances, Pairs
  // otherwise (measured fastest, docs/performance.md). Precedence or Sat on a
  // non-horizontal instance throws std::invalid_argument; Pairs and States
  // take any instance. (Tests run every engine on the same instances.)
  enum class Engine { Auto, States, Precedence, Sat, Pairs } engine = Engine::Auto;
  // Passed to the precedence engine when it runs (NO certificates,
  // solver/no_certificate.hpp; tests). Not owned.
  const PrecedenceHooks* precedence_hooks = nullptr;
};

struct SolveStats {
  uint64_t states = 0;        // search nodes: states entered (moves) plus decisions
  uint64_t refuted = 0;       // dead ends proved (memo entries, conflicts)
  uint64_t propagations = 0;  // orderings derived (precedence) / safe moves made (states)
  double seconds = 0;         // wall-clock time of the whole call
  uint64_t decisions = 0;     // branches opened
  uint64_t safe_moves = 0;    // couplings performed without branching
  uint64_t memo_hits = 0;     // states search: revisits of a refuted state
  uint64_t constraints = 0;   // collision constraints built
  std::string engine;         // "cycle" (a coupling breaks a cycle), "states", "precedence", "sat", "pairs"
};

struct SolveResult {
  Verdict status = Verdict::Unknown;
  std::vector<CouplingId> order;  // Yes: every coupling once, accepted by the Simulator
  SolveStats stats;
  CouplingId cycle_breaker = kNone;  // No because this coupling breaks a cycle
  // No because this coupling alone moves two regions that collide during
  // its step, whatever ran before (found while building pair constraints;
  // no search runs): its coupling and "node (1,2) and node inserted by a".
  CouplingId lone_collider = kNone;
  std::string lone_pair;
};

// Decides Discrete Collision-free Schedule exactly, or returns Unknown when a
// limit of opt is reached (or a stop was requested: common/limits.hpp). The
// time limit covers the set-up too (cycle check, constraint building). See
// the contract above.
SolveResult solve_discrete(const Instance& inst, const SolveOptions& opt = {});

// The same on prepared tables (lattice/prepared.hpp): nothing is rebuilt.
// The YES replay runs on `replay` if it is given and simulates prep (its
// work arrays are then reused), else on a simulator of its own.
SolveResult solve_discrete(const PreparedInstance& prep, const SolveOptions& opt, Simulator* replay = nullptr);

}  // namespace gridlock
