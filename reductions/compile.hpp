// The gadget compiler: a CNF formula (clauses of 1 or more literals) to a
// lattice instance of Discrete Collision-free Schedule, after the paper's
// proof that the problem is NP-complete with horizontal expansions and
// couplings of size O(1). Correctness argument: docs/gadgets.md.
//
// Gadgets (gadgets/): one variable gadget per variable x_i (operations
// x_i.T, x_i.F, x_i.y, x_i.z), one clause gadget per clause C_h (one
// operation per literal occurrence, C_h.x_v or C_h.~x_v, and the release
// C_h.u), and one order gadget O_k per link of the chain
//   y_1 < ... < y_n < z_1 < ... < z_n < u_1 < ... < u_m.
// Couplings (every operation is in exactly one):
//   x_i:T = { x_i.T } + the clause operations of the literal ~x_i
//   x_i:F = { x_i.F } + the clause operations of the literal  x_i
//   y_i   = { x_i.y } + the order gadgets' operations for y_i   (likewise z_i, u_h)
// so running x_i:T sets x_i true and makes every occurrence of ~x_i false.
//
// Layout: the gadgets are stacked bottom to top (variables, clauses, order
// gadgets), one empty row between two gadgets, each at x >= 0. A spine, a
// column of nodes at x = -2 through every row, is joined to each gadget's
// attach node by an arm node at x = -1. No operation lies on the spine or an
// arm, and the leftmost node of each gadget row is rigidly joined to the
// gadget's attach node, so the gap between the spine and a gadget never
// changes and no two gadgets share a row: gadgets cannot interfere.
// (The continuous model's separation gadget lifts two of its nodes into the
// empty row above it, columns 2 and 3, where nothing else ever is.)
//
// Sizes for n >= 1 variables, m clauses, L literal occurrences, G = 3n + 2m - 1
// gadgets (2n + m - 1 of them order gadgets):
//   nodes      = 17n + (5L + m) + 6(2n + m - 1) + rows + G
//   rows       = 4n + 2m + 2(2n + m - 1) + (G - 1) = 11n + 6m - 4
//   so nodes   = 43n + 5L + 15m - 11   (3-CNF: 43n + 30m - 11); edges = nodes - 1
//   operations = 4n + (L + m) + 2(2n + m - 1) = 8n + L + 3m - 2
//   couplings  = 4n + m
// For LSAT and LSAT<=3 input every coupling has at most 3 operations (each
// literal occurs at most twice; each chain element is in at most two links).
//
// The continuous model (TimeModel::Continuous; the paper's theorem that
// continuous Collision-free Schedule is NP-hard): the same, except that the
// link y_n < z_1 is a separation gadget (gadgets/internal/separation_gadget.hpp,
// 8 nodes instead of 6, one vertical expansion): z_1 may start only once y_n
// has finished. That one separation is all the proof needs (docs/gadgets.md,
// "The continuous reduction"): at the moment y_n finishes every y_i is done
// and no z_i or u_h has started, and progress cannot pause, so every
// variable is then fully set one way. Sizes: nodes + 2 (n >= 1), the rest
// unchanged.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cnf/formula.hpp"
#include "gadgets/contract.hpp"
#include "gadgets/mutation.hpp"
#include "lattice/instance.hpp"
#include "lattice/schedule.hpp"
#include "lattice/time_model.hpp"

namespace gridlock {

// Which Collision-free Schedule problem the instance is for: TimeModel
// (lattice/time_model.hpp).

struct CompileStats {
  size_t nodes = 0, edges = 0, ops = 0, couplings = 0;
  size_t variable_gadgets = 0, clause_gadgets = 0, order_gadgets = 0, rows = 0;
  size_t separation_gadgets = 0;  // continuous model: 1 (n >= 1), else 0
  size_t vertical_ops = 0;        // one per separation gadget
  size_t literals = 0;            // L
  size_t max_coupling = 0;        // largest coupling (operations)
  std::string max_coupling_name;
  std::vector<std::string> oversize;  // one line per coupling above 3 operations, naming the literal
};

struct CompiledFormula {
  Instance instance;
  TimeModel model = TimeModel::Discrete;
  int num_vars = 0;
  size_t num_clauses = 0;
  // Coupling ids, indexed by variable - 1 / clause index.
  std::vector<CouplingId> set_true, set_false, y, z, release;
  // Each gadget with its contract, in drawing order (for tests and docs).
  std::vector<GadgetPlacement> gadgets;
  CompileStats stats;
};

// The node count of f's compiled instance, 43n + 5L + 15m - 11 (- 9 in the
// continuous model; 0 for n = 0), computed from the counts alone, before
// anything is drawn.
uint64_t compiled_node_count(const Formula& f, TimeModel model = TimeModel::Discrete);

// Why the reduction refuses clause h (0-based) of a formula: it is empty.
// The one wording, for compile_formula and for the command line's check
// right after reading (which adds the clause's line). O(1).
std::string empty_clause_message(size_t h);

// Compiles f. Requires validate(f) empty and every clause non-empty (throws
// std::invalid_argument with empty_clause_message of the first empty one), and
// compiled_node_count(f) <= kMaxNodes (checked first, before any allocation:
// std::invalid_argument "the compiled instance would have N nodes ..."). The mutation
// breaks one gadget kind (tests and the fuzzer's self-test only).
// Deterministic. Time and memory O(n + m + L).
CompiledFormula compile_formula(const Formula& f, Mutation mutation = Mutation::None,
                                TimeModel model = TimeModel::Discrete);

// Certificate, assignment -> schedule: for a satisfying assignment (indexed
// 1..num_vars), the order  [x_i:T or x_i:F by value, i = 1..n], y_1..y_n,
// z_1..z_n, u_1..u_m, [the other value of each x_i]. Collision-free iff value
// satisfies the formula (docs/gadgets.md); the caller checks it with the
// simulator. Requires value.size() > num_vars. O(couplings).
std::vector<CouplingId> schedule_from_assignment(const CompiledFormula& c, const std::vector<bool>& value);

// Certificate, schedule -> assignment: x_i is true iff x_i:T runs before
// x_i:F. For a collision-free order this is the assignment in force when y_n
// completes, which satisfies the formula (docs/gadgets.md); the caller checks
// it against the formula. Requires order to be a permutation of the
// couplings. Result indexed 1..num_vars. O(couplings).
std::vector<bool> assignment_from_schedule(const CompiledFormula& c, const std::vector<CouplingId>& order);

// Continuous certificate, assignment -> start times: the value of x_i by
// `value` at time 0, every y_i at 1, everything else (z_i, u_h, the other
// value of each x_i) at 2. Collision-free on the continuous instance iff
// value satisfies the formula (docs/gadgets.md); the caller checks it with
// the simulator. Requires value.size() > num_vars. O(couplings).
Schedule times_from_assignment(const CompiledFormula& c, const std::vector<bool>& value);

// Continuous certificate, start times -> assignment: x_i is true iff
// t(x_i:T) <= t(y_n), i.e. x_i:T has finished when y_n finishes. For a
// collision-free schedule of the continuous instance this is the
// assignment in force at that moment, which satisfies the formula
// (docs/gadgets.md); the caller checks it. Requires a start time per
// coupling. Result indexed 1..num_vars. O(n).
std::vector<bool> assignment_from_times(const CompiledFormula& c, const Schedule& s);

}  // namespace gridlock
