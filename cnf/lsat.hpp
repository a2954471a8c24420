// LSAT (Linear SAT) recognition, after Arkin et al. (Discrete Applied
// Mathematics 2018) and the paper's proof of its NP-hardness theorem:
//
//   a CNF formula is LSAT if each clause, viewed as a set of literals,
//   intersects at most one other clause, and two clauses that intersect have
//   exactly one literal in common.
//
// Literals, not variables: x in one clause and -x in another is no
// intersection. Two forms:
//   LsatForm::Exact3   the paper's: every clause has exactly 3 literals;
//   LsatForm::AtMost3  "LSAT<=3": clauses of 1 to 3 literals, same rules.
//
// Decisions (docs/formulas.md, "LSAT"):
//   - a clause that writes a literal twice ("1 1 2") is rejected in both
//     forms (rule RepeatedLiteral): as a set it would be a shorter clause than
//     written, and the paper's clause gadget has one operation per literal
//     occurrence, so the formula's meaning would depend on the reading;
//   - a tautology ("1 -1 2") is allowed: the definition only constrains shared
//     literals, and such a clause is simply always true. check_lsat lists them.
//   - the empty clause breaks the length rule of both forms.
//
// Note (proved in docs/formulas.md): every Exact3 LSAT formula is satisfiable
// (Hall's theorem gives each clause its own variable); hall_assignment builds
// such an assignment. The NP-hard form is AtMost3, which is what
// reductions/to_lsat.hpp produces.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "cnf/formula.hpp"

namespace gridlock {

enum class LsatForm { Exact3, AtMost3 };

enum class LsatRule {
  ClauseLength,          // not exactly 3 literals (Exact3) / not 1 to 3 (AtMost3)
  RepeatedLiteral,       // a literal written twice in one clause
  SharesTwoLiterals,     // two clauses with 2 or more literals in common
  IntersectsTwoClauses,  // a clause sharing literals with 2 or more other clauses
};

// "clause-length", "repeated-literal", "shares-two-literals",
// "intersects-two-clauses" (stable names for --json and tests).
const char* rule_name(LsatRule rule);

struct LsatViolation {
  LsatRule rule;
  std::vector<size_t> clauses;  // 0-based; the offending clause first, then the others involved
  std::vector<int> literals;    // the literals concerned (repeated / shared ones)
  std::string message;          // names clauses 1-based with their literals, and the rule
};

struct LsatReport {
  bool ok = true;                         // the formula is LSAT in the form asked for
  std::vector<LsatViolation> violations;  // the first ones in clause order (at most max_violations)
  std::vector<size_t> tautologies;        // 0-based clauses holding x and -x (allowed)
};

// Checks f against the form. Clauses are visited in order and each clause
// reports the first rule it breaks, in the order of LsatRule (a pair of
// clauses sharing two literals is reported once, at the first of the two);
// the first max_violations are kept (0 = just the verdict). Requires
// validate(f) empty (GRIDLOCK_ASSERT). Time O(L log L) for L literal occurrences, memory O(L),
// independent of num_vars.
LsatReport check_lsat(const Formula& f, LsatForm form, size_t max_violations = 1);

// check_lsat(f, form, 0).ok
bool is_lsat(const Formula& f, LsatForm form);

// A satisfying assignment in which every clause is satisfied by a variable of
// its own (a system of distinct representatives, found by augmenting paths),
// or nullopt if no such system exists (Hall's condition fails). It exists for
// every Exact3 LSAT formula. Empty clauses have no representative. Result
// indexed 1..num_vars; variables no clause needs are false.
// Time O(m * L) worst case, memory O(num_vars + L).
std::optional<std::vector<bool>> hall_assignment(const Formula& f);

}  // namespace gridlock
