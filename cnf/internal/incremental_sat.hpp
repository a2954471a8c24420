// An incremental SAT solver (CaDiCaL behind a small interface) for engines
// that add clauses between solve calls: the solver keeps everything it has
// learned, so refining a formula and solving again is cheap. Only
// cnf/incremental_sat.cpp and cnf/sat_solver.cpp include cadical.hpp.
#pragma once

#include <cstdint>
#include <cstdio>
#include <functional>
#include <initializer_list>
#include <memory>
#include <vector>

#include "cnf/sat_solver.hpp"

namespace gridlock {

class IncrementalSat {
 public:
  IncrementalSat();
  ~IncrementalSat();
  IncrementalSat(const IncrementalSat&) = delete;
  IncrementalSat& operator=(const IncrementalSat&) = delete;

  // A fresh variable (1, 2, ...). O(1).
  int new_var();
  int num_vars() const { return vars_; }
  // Adds the clause (non-zero literals over variables from new_var). An
  // empty clause makes the formula unsatisfiable. O(size). Clauses are
  // buffered and handed to CaDiCaL, in the order added, at the next solve
  // or set_phase, right after one reserve() of every variable so far:
  // CaDiCaL always initializes variables in index order, so this is the
  // state one-by-one adding reaches, without its per-variable
  // initialization call as each new variable first appears.
  void add_clause(const std::vector<int>& lits);
  // The same for a clause written in place ({a, b, c}): no vector is built,
  // so the SAT engines' counters and order clauses (many thousands of short
  // clauses per formula) allocate nothing per clause.
  void add_clause(std::initializer_list<int> lits);
  // Solves the clauses added so far. `stop` is polled during the search
  // with the number of conflicts so far (over all calls); returning true
  // ends the call with Unknown. Sat: value() reads the model until the next
  // add_clause or solve.
  Verdict solve(const std::function<bool(uint64_t conflicts)>& stop);
  bool value(int var) const;
  // The value the search tries first for lit's variable (lit true). O(1).
  void set_phase(int lit);
  uint64_t conflicts() const;  // over all solve calls
  // Writes CaDiCaL's DRAT proof as text to `file` (which outlives this
  // object) from now on. Only before the first clause: it must see every
  // derivation. Also turns off the inprocessing that restores eliminated
  // clauses between incremental calls (variable elimination), so that
  // every added line is a RUP lemma (docs/certificates.md, kind pairs).
  void trace_proof(std::FILE* file);
  // Flushes the proof written so far.
  void flush_proof();
  // Sets a CaDiCaL option (its name and value as CaDiCaL documents them),
  // before the first clause. Throws std::invalid_argument on an unknown
  // name or a value out of range.
  void set_option(const char* name, int value);
  // Off: every clause goes to CaDiCaL at once, as before buffering (the
  // twin test's reference; tests/cnf_incremental_twin_test.cpp).
  void set_buffered(bool on);

 private:
  // The clause [first, last) (each literal checked), then its 0. O(size).
  void add_lits(const int* first, const int* last);
  // Hands the buffered clauses to CaDiCaL (see add_clause). O(their size).
  void flush();
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int vars_ = 0;
  bool buffered_ = true;
  std::vector<int> pending_;  // buffered clauses, each closed by its 0
};

}  // namespace gridlock
