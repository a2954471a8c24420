#include "cnf/formula.hpp"

#include <algorithm>
#include <climits>
#include <stdexcept>

namespace gridlock {

namespace {

void require_assignment(const Formula& f, const std::vector<bool>& value) {
  if (f.num_vars < 0 || value.size() < static_cast<size_t>(f.num_vars) + 1)
    throw std::invalid_argument("assignment has " + std::to_string(value.size()) + " entries, formula needs " +
                                std::to_string(f.num_vars) + "+1");
}

bool clause_true(const std::vector<int>& clause, const std::vector<bool>& value, int num_vars) {
  for (int lit : clause) {
    if (lit == 0 || lit == INT_MIN || var_of(lit) > num_vars)
      throw std::invalid_argument("literal " + std::to_string(lit) + " out of range 1.." + std::to_string(num_vars));
    if (literal_value(lit, value)) return true;
  }
  return false;
}

}  // namespace

bool satisfies(const Formula& f, const std::vector<bool>& value) { return first_falsified_clause(f, value) < 0; }

long first_falsified_clause(const Formula& f, const std::vector<bool>& value) {
  require_assignment(f, value);
  for (size_t i = 0; i < f.clauses.size(); ++i)
    if (!clause_true(f.clauses[i], value, f.num_vars)) return static_cast<long>(i);
  return -1;
}

std::string validate(const Formula& f) {
  if (f.num_vars < 0) return "negative variable count " + std::to_string(f.num_vars);
  for (size_t i = 0; i < f.clauses.size(); ++i)
    for (int lit : f.clauses[i])
      if (lit == 0 || lit == INT_MIN || var_of(lit) > f.num_vars)
        return "clause " + std::to_string(i + 1) + ": literal " + std::to_string(lit) + " out of range 1.." +
               std::to_string(f.num_vars);
  return "";
}

size_t num_literals(const Formula& f) {
  size_t n = 0;
  for (const auto& c : f.clauses) n += c.size();
  return n;
}

bool is_tautology(const std::vector<int>& clause) {
  // Clauses are short (LSAT: at most 3), so a quadratic scan beats sorting a copy.
  if (clause.size() <= 8) {
    for (size_t i = 0; i < clause.size(); ++i)
      for (size_t j = i + 1; j < clause.size(); ++j)
        if (clause[i] == -clause[j]) return true;
    return false;
  }
  std::vector<int> s(clause);
  std::sort(s.begin(), s.end(),
            [](int a, int b) { return var_of(a) < var_of(b) || (var_of(a) == var_of(b) && a < b); });
  for (size_t i = 0; i + 1 < s.size(); ++i)
    if (s[i] == -s[i + 1]) return true;
  return false;
}

std::string summary(const Formula& f) {
  return std::to_string(f.num_vars) + " variables, " + std::to_string(f.clauses.size()) + " clauses, " +
         std::to_string(num_literals(f)) + " literals";
}

std::vector<int> model_literals(const std::vector<bool>& value, int num_vars) {
  std::vector<int> lits;
  lits.reserve(static_cast<size_t>(std::max(num_vars, 0)));
  for (int v = 1; v <= num_vars; ++v) lits.push_back(value.at(static_cast<size_t>(v)) ? v : -v);
  return lits;
}

}  // namespace gridlock
