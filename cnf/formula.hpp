// CNF formulas as DIMACS writes them: variables 1..num_vars, literal v is the
// variable v and -v its negation. Everything in cnf/ and reductions/ speaks
// this one type, so a formula read from a file, generated, or produced by a
// reduction can be handed to any checker or solver unchanged.
#pragma once

#include <climits>
#include <cstdint>
#include <string>
#include <vector>

#include "common/assert.hpp"

namespace gridlock {

struct Formula {
  int num_vars = 0;                       // variables are 1..num_vars
  std::vector<std::vector<int>> clauses;  // nonzero literals, |lit| <= num_vars
  std::vector<std::string> comments;      // provenance ("c" lines), one line each

  friend bool operator==(const Formula&, const Formula&) = default;
};

// The variable of a literal. Requires lit != 0 and lit != INT_MIN (the reader
// and every generator guarantee both; GRIDLOCK_ASSERT).
inline int var_of(int lit) {
  GRIDLOCK_ASSERT(lit != 0 && lit != INT_MIN, "var_of needs a non-zero literal other than INT_MIN");
  return lit < 0 ? -lit : lit;
}

// The value of a literal under value (indexed by variable, 1-based).
inline bool literal_value(int lit, const std::vector<bool>& value) {
  return lit > 0 ? value[static_cast<size_t>(lit)] : !value[static_cast<size_t>(-lit)];
}

// True iff every clause has a true literal under value. value is indexed
// 1..num_vars (value[0] unused), so value.size() must be at least num_vars+1;
// throws std::invalid_argument otherwise, or if a literal is 0 or out of
// range (a malformed formula is a bug, never silently "unsatisfied").
// An empty clause is never satisfied. O(total literals).
bool satisfies(const Formula& f, const std::vector<bool>& value);

// The first clause (0-based) that value falsifies, or -1 if none; same
// requirements as satisfies. For messages that name what went wrong.
long first_falsified_clause(const Formula& f, const std::vector<bool>& value);

// Empty string if every literal is nonzero and within 1..num_vars and
// num_vars >= 0; otherwise what is wrong (for assertions in tests and tools).
std::string validate(const Formula& f);

// Total number of literal occurrences. O(clauses).
size_t num_literals(const Formula& f);

// True iff the clause holds some literal and its negation.
bool is_tautology(const std::vector<int>& clause);

// "20 variables, 91 clauses, 273 literals" (for comments and messages).
std::string summary(const Formula& f);

// A model as DIMACS literals: for v in 1..num_vars, v if value[v] else -v.
std::vector<int> model_literals(const std::vector<bool>& value, int num_vars);

}  // namespace gridlock
