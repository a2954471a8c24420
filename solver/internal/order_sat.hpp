// Order literals for CaDiCaL: the machinery shared by the SAT engines
// (solver/search_sat.cpp on gap systems, solver/search_pairs.cpp on any
// system). Why it is exact: docs/solver.md, "Engine sat".
//
// A variable B(a, b) = "a before b" exists for each pair of couplings an
// engine asks about (B(b, a) is its negation, so antisymmetry and totality
// on these pairs are built in). An engine adds its clauses over these
// literals (each must hold in every collision-free total order), then
// solve() runs CaDiCaL incrementally: a model orients the pairs; a cyclic
// orientation gets one clause "not all of these B's" per shortest cycle
// found (true in every total order) and the solver runs again; an acyclic
// one gives a topological order, which the engine's `accept` either takes
// or refutes by adding clauses (lazy constraints).
#pragma once

#include <cstdint>
#include <cstdio>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "cnf/internal/incremental_sat.hpp"
#include "common/internal/graph_order.hpp"
#include "lattice/flat_map.hpp"
#include "solver/internal/gap_inequalities.hpp"
#include "solver/internal/search.hpp"

namespace gridlock {

class OrderSat {
 public:
  // k couplings 0..k-1. budget and st outlive this object.
  OrderSat(size_t k, SearchBudget& budget, SolveStats& st) : budget_(budget), st_(st), k_(k) {}

  // The literal "a before b" (a != b), creating its variable. O(1) expected.
  int before(CouplingId a, CouplingId b);
  // True iff the variable of the pair {a, b} exists already.
  bool has_pair(CouplingId a, CouplingId b) const;
  void add_clause(const std::vector<int>& lits) { sat_.add_clause(lits); }

  // sum w_i [l_i] <= bound, weights > 0, as a weighted sequential counter
  // (Hoelldobler, Manthey, Steinke): O(n * bound) clauses and variables;
  // one clause "not all of them" when only all of them together weigh more
  // than bound (no variables: the usual gap of a compiled formula).
  // False if the bound is negative (unsatisfiable). lits is not kept.
  bool at_most(const std::vector<std::pair<int, int64_t>>& lits, int64_t bound);

  // Clauses true in every total order, added once after every pair variable
  // an engine needs exists: the transitive closure R of `forced` (relations
  // (a, b) = "a before b" true in every solution; bit matrix, skipped above
  // kClosureLimit couplings) as units on the pairs it decides and, for a
  // coupling x and partners c1 R c2, "x before c1 -> x before c2"; and
  // transitivity on every triangle of pairs. False iff `forced` is cyclic
  // (then no order exists). O(k^2 / 64 * |forced| + sum_x deg(x)^2).
  bool add_order_clauses(const std::vector<std::pair<CouplingId, CouplingId>>& forced);

  // Solves until an acyclic model's topological order is accepted
  // (Verdict::Yes with it) or the clauses are unsatisfiable (Verdict::No).
  // accept(order) returns true to take the order; otherwise it must add at
  // least one clause the current model violates (else the loop would not
  // end). Throws LimitReached when the budget runs out (conflicts count as
  // nodes). Statistics: decisions = solve calls, refuted = conflicts,
  // propagations = cycle clauses, states = both.
  SearchOutcome solve(const std::function<bool(const std::vector<CouplingId>&)>& accept);

  size_t num_pairs() const { return pair_vars_.size(); }
  // Reference mode (the twin tests': tests/solver_order_sat_twin_test.cpp):
  // every unit is sent again when it repeats (see add_unit) and the forced
  // closure tries every pair of partners, as before these shortcuts.
  void set_reference(bool on) { reference_ = on; }
  // Repeated units not sent to CaDiCaL so far (add_unit).
  size_t skipped_units() const { return skipped_units_; }
  // A CaDiCaL option (IncrementalSat::set_option), before the first clause.
  void set_solver_option(const char* name, int value) { sat_.set_option(name, value); }

  // Proof mode (NO certificates, docs/certificates.md kind pairs), set
  // before the first clause: CaDiCaL writes its DRAT proof to `drat` and
  // every lazy cycle clause is appended to `cycles` (its literals, as
  // edges, are a directed cycle). The triangle and forced-closure clauses
  // are not logged: the checker derives them itself. Engines must then use
  // no at_most (its counter variables have no order meaning).
  void prove_to(std::FILE* drat, std::vector<std::vector<int>>* cycles);
  // The pair of variable var as "lo before hi" (var > 0 a pair variable).
  std::pair<CouplingId, CouplingId> pair_of(int var) const;
  void flush_proof() { sat_.flush_proof(); }

  // Above this many couplings the forced closure (k^2 / 8 bytes) is skipped.
  static constexpr size_t kClosureLimit = 40000;

 private:
  struct PairVar {
    int var;
    CouplingId lo, hi;  // var true: lo before hi
  };
  static uint64_t key(CouplingId a, CouplingId b) { return (uint64_t{a} << 32) | b; }

  // The pairs of each coupling x: list[first[x] .. first[x + 1]) holds
  // (other, literal "x before other"), in pair creation order.
  struct Partners {
    std::vector<uint32_t> first;
    std::vector<std::pair<CouplingId, int>> list;
    std::span<const std::pair<CouplingId, int>> of(CouplingId x) const {
      return {list.data() + first[x], list.data() + first[x + 1]};
    }
  };
  // The unit clause {lit}, unless it went in before (not in reference mode).
  void add_unit(int lit);
  bool add_closure_clauses(const std::vector<std::pair<CouplingId, CouplingId>>& forced, const Partners& partners);
  void add_triangle_clauses(const Partners& partners);
  bool order_of_model(std::vector<CouplingId>& out);
  // The orientation of the pairs in the model (common/internal/graph_order.hpp).
  Digraph model_orientation() const;
  void add_cycle_clauses(const Digraph& g, const StrongComponents& cc);

  SearchBudget& budget_;
  SolveStats& st_;
  size_t k_;
  IncrementalSat sat_;
  FlatMap64 var_of_pair_;  // pair key -> its variable (no allocation per pair)
  std::vector<PairVar> pair_vars_;
  uint64_t counted_conflicts_ = 0;
  // at_most's work vectors, kept between calls (one call per narrower of
  // every gap: thousands per formula).
  std::vector<std::pair<int, int64_t>> kept_;
  std::vector<int> prev_, cur_, clause_;
  // encode_gap_constraint's work vectors, kept likewise (one call per gap).
  friend bool encode_gap_constraint(const CollisionConstraint& c, OrderSat& os);
  std::vector<PrecedenceTerm> terms_;
  std::vector<std::pair<int, int64_t>> lits_;
  std::vector<uint8_t> units_;  // variable -> 1: unit {var} added, 2: unit {-var}, 3: both
  size_t skipped_units_ = 0;
  bool reference_ = false;
  std::vector<std::vector<int>>* cycle_log_ = nullptr;  // proof mode
  std::vector<uint32_t> pair_index_;                    // proof mode: variable -> pair_vars_ index + 1
  void add_cycle_clause(const std::vector<int>& c) {
    if (cycle_log_) cycle_log_->push_back(c);
    sat_.add_clause(c);
  }
};

// A one-form constraint (a gap, or a pair of regions with one changing
// form) as clauses: one weighted at-most counter per narrower (the
// inequalities of solver/internal/gap_inequalities.hpp). Requires c.num_forms == 1 and
// c.base[0] <= 0. False iff some bound is negative (no order exists).
bool encode_gap_constraint(const CollisionConstraint& c, OrderSat& os);

}  // namespace gridlock
