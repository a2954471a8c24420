// The LSAT check: formulas built to break each rule (exact messages), the
// literal-not-variable reading, tautologies, a naive twin of the definition
// on random formulas, and the theorem that exactly-3 LSAT formulas are all
// satisfiable (hall_assignment, confirmed by CaDiCaL).
#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <set>

#include "cnf/generate.hpp"
#include "cnf/lsat.hpp"
#include "cnf/sat_solver.hpp"
#include "support/cnf_testing.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

std::string first_message(const Formula& f, LsatForm form) {
  LsatReport r = check_lsat(f, form, 5);
  return r.ok ? "OK" : r.violations.front().message;
}

TEST(Lsat, PaperStyleFormulaIsLsat) {
  // examples/formulas/lsat-sat.cnf: clauses 1 and 2 share literal 3; the
  // others meet only through negations, which do not count.
  Formula f = test::make_formula(6, {{1, 2, 3}, {3, 4, 5}, {-1, -4, 6}, {-2, -5, -6}});
  EXPECT_TRUE(is_lsat(f, LsatForm::Exact3));
  EXPECT_TRUE(is_lsat(f, LsatForm::AtMost3));
}

TEST(Lsat, LiteralsNotVariables) {
  // Every variable in all three clauses, but no literal twice: no intersection.
  Formula f = test::make_formula(3, {{1, 2, 3}, {-1, -2, -3}, {-1, 2, -3}});
  EXPECT_FALSE(is_lsat(f, LsatForm::Exact3));  // -1 and -3 shared by clauses 2 and 3
  EXPECT_EQ(first_message(f, LsatForm::Exact3),
            "clauses 2 (-1 -2 -3) and 3 (-1 2 -3) share 2 literals (-3 -1), not exactly 1");
  EXPECT_TRUE(is_lsat(test::make_formula(3, {{1, 2, 3}, {-1, -2, -3}}), LsatForm::Exact3));
}

TEST(Lsat, EachRuleWithItsMessage) {
  // Length.
  EXPECT_EQ(first_message(test::make_formula(5, {{1, 2, 3}, {4, 5}}), LsatForm::Exact3),
            "clause 2 (4 5) has 2 literals, not 3");
  EXPECT_EQ(first_message(test::make_formula(3, {{1, 2}}), LsatForm::AtMost3), "OK");
  EXPECT_EQ(first_message(test::make_formula(4, {{1, 2, 3, 4}}), LsatForm::AtMost3),
            "clause 1 (1 2 3 4) has 4 literals, not 1 to 3");
  EXPECT_EQ(first_message(test::make_formula(1, {{}}), LsatForm::AtMost3), "clause 1 () has 0 literals, not 1 to 3");
  EXPECT_EQ(first_message(test::make_formula(8, {{1, 2, 3, 4, 5, 6, 7, 8}}), LsatForm::Exact3),
            "clause 1 (1 2 3 4 5 6 ... 8 literals) has 8 literals, not 3");
  // Repeated literal.
  EXPECT_EQ(first_message(test::make_formula(2, {{1, 1, 2}}), LsatForm::Exact3), "clause 1 (1 1 2) repeats literal 1");
  EXPECT_EQ(first_message(test::make_formula(2, {{-2, 1, -2}}), LsatForm::AtMost3),
            "clause 1 (-2 1 -2) repeats literal -2");
  // Two clauses sharing two literals.
  EXPECT_EQ(first_message(test::make_formula(4, {{1, 2, 3}, {4, 2, 1}}), LsatForm::Exact3),
            "clauses 1 (1 2 3) and 2 (4 2 1) share 2 literals (1 2), not exactly 1");
  EXPECT_EQ(first_message(test::make_formula(2, {{1, 2}, {2, 1}}), LsatForm::AtMost3),
            "clauses 1 (1 2) and 2 (2 1) share 2 literals (1 2), not exactly 1");
  // A clause meeting two others.
  EXPECT_EQ(first_message(test::make_formula(7, {{1, 2, 3}, {1, 4, 5}, {2, 6, 7}}), LsatForm::Exact3),
            "clause 1 (1 2 3) intersects clauses 2 (in literal 1) and 3 (in literal 2), not at most one");
  // A literal three times: the first clause meets the two others.
  EXPECT_EQ(first_message(test::make_formula(7, {{-1, 2, 3}, {4, -1, 5}, {6, 7, -1}}), LsatForm::AtMost3),
            "clause 1 (-1 2 3) intersects clauses 2 (in literal -1) and 3 (in literal -1), not at most one");
}

TEST(Lsat, ViolationsInClauseOrderAndRules) {
  Formula f = test::make_formula(9, {{1, 2, 3}, {4, 5}, {6, 6, 7}, {1, 8, -9}, {1, 2, 9}});
  LsatReport r = check_lsat(f, LsatForm::Exact3, 10);
  ASSERT_FALSE(r.ok);
  std::vector<std::string> got;
  for (const auto& v : r.violations) got.push_back(std::string(rule_name(v.rule)));
  // clause 1 meets 4 (via 1) and 5 (via 1, 2): it shares two literals with 5;
  // clause 2 is short; clause 3 repeats; clause 4 meets 1 and 5 (-9 is not
  // 9); clause 5's pair with 1 was reported already, so nothing more.
  EXPECT_EQ(got, (std::vector<std::string>{"shares-two-literals", "clause-length", "repeated-literal",
                                           "intersects-two-clauses"}));
  EXPECT_EQ(r.violations[0].clauses, (std::vector<size_t>{0, 4}));
  EXPECT_EQ(r.violations[3].clauses, (std::vector<size_t>{3, 0, 4}));
  // max_violations bounds the list, not the verdict.
  LsatReport one = check_lsat(f, LsatForm::Exact3, 1);
  EXPECT_FALSE(one.ok);
  EXPECT_EQ(one.violations.size(), 1u);
  LsatReport none = check_lsat(f, LsatForm::Exact3, 0);
  EXPECT_FALSE(none.ok);
  EXPECT_TRUE(none.violations.empty());
}

TEST(Lsat, TautologiesAllowedAndListed) {
  Formula f = test::make_formula(4, {{1, -1, 2}, {3, 4, -4}});
  LsatReport r = check_lsat(f, LsatForm::Exact3, 3);
  EXPECT_TRUE(r.ok);
  EXPECT_EQ(r.tautologies, (std::vector<size_t>{0, 1}));
}

TEST(Lsat, MemoryIndependentOfDeclaredVariables) {
  Formula f = test::make_formula(INT_MAX, {{INT_MAX, -INT_MAX + 1, 5}, {INT_MAX, 6, 7}});
  EXPECT_TRUE(is_lsat(f, LsatForm::Exact3));
  // The matching works on the variables that occur; only the answer has one
  // bit per declared variable (found by the fuzzer: "p cnf 666666666 0").
  Formula g = test::make_formula(100000000, {{100000000, -5, 6}, {100000000, 7, 8}});
  auto a = hall_assignment(g);
  ASSERT_TRUE(a);
  EXPECT_EQ(a->size(), 100000001u);
  EXPECT_TRUE(satisfies(g, *a));
}

TEST(Lsat, LongRunsOfOneLiteralStayFast) {
  // Literal 1 in 200000 clauses: the check must not scan its run once per
  // occurrence (quadratic: 4e10 steps).
  Formula f;
  f.num_vars = 200001;
  for (int k = 2; k <= 200001; ++k) f.clauses.push_back({1, k});
  f.clauses.push_back({3, 3});
  LsatReport r = check_lsat(f, LsatForm::AtMost3, 1000000);
  ASSERT_FALSE(r.ok);
  EXPECT_EQ(r.violations.size(), 200001u);  // every clause meets two others, and the last repeats 3
  EXPECT_EQ(r.violations.back().rule, LsatRule::RepeatedLiteral);
  EXPECT_EQ(r.violations.front().message,
            "clause 1 (1 2) intersects clauses 2 (in literal 1) and 3 (in literal 1), not at most one");
}

// The definition, read literally: all pairs of clauses, as sets.
bool naive_lsat(const Formula& f, LsatForm form) {
  std::vector<std::set<int>> sets;
  for (const auto& c : f.clauses) {
    std::set<int> s(c.begin(), c.end());
    if (s.size() != c.size()) return false;  // repeated literal (our documented decision)
    if (form == LsatForm::Exact3 ? s.size() != 3 : (s.empty() || s.size() > 3)) return false;
    sets.push_back(s);
  }
  for (size_t i = 0; i < sets.size(); ++i) {
    int meets = 0;
    for (size_t j = 0; j < sets.size(); ++j) {
      if (i == j) continue;
      size_t common = 0;
      for (int lit : sets[i]) common += sets[j].count(lit);
      if (common > 1) return false;
      meets += common == 1;
    }
    if (meets > 1) return false;
  }
  return true;
}

TEST(Lsat, AgreesWithNaiveDefinitionOnRandomFormulas) {
  const int cases = test::scaled(4000);
  const uint64_t seed = test::base_seed(7);
  int yes = 0;
  for (int t = 0; t < cases; ++t) {
    SCOPED_TRACE("GRIDLOCK_TEST_SEED=" + std::to_string(seed) + " case " + std::to_string(t));
    Rng rng(seed * 1000003 + static_cast<uint64_t>(t));
    // Many variables and few clauses make LSAT formulas common; few
    // variables make every kind of violation common.
    int n = static_cast<int>(rng.between(3, 24));
    int m = static_cast<int>(rng.between(1, 8));
    Formula f = test::random_cnf(rng, n, m, t % 3 == 0 ? 0 : 1, t % 3 == 0 ? 4 : 3, t % 2 == 0);
    for (LsatForm form : {LsatForm::Exact3, LsatForm::AtMost3}) {
      LsatReport r = check_lsat(f, form, 3);
      ASSERT_EQ(r.ok, naive_lsat(f, form));
      EXPECT_EQ(r.ok, r.violations.empty());
      yes += r.ok;
    }
  }
  EXPECT_GT(yes, cases / 10);  // both verdicts well represented
  EXPECT_LT(yes, 2 * cases - cases / 10);
}

TEST(Lsat, HallAssignmentFailsWhenNoDistinctRepresentatives) {
  EXPECT_FALSE(hall_assignment(test::make_formula(1, {{1}, {-1}})));
  EXPECT_FALSE(hall_assignment(test::make_formula(1, {{}})));
  auto a = hall_assignment(test::make_formula(2, {{1, 2}, {-1}}));
  ASSERT_TRUE(a);
  EXPECT_TRUE(satisfies(test::make_formula(2, {{1, 2}, {-1}}), *a));
}

// Theorem (docs/formulas.md): every exactly-3 LSAT formula is satisfiable,
// and the matching gives a model. Checked at the density cap, where it is
// tightest, and below it.
TEST(Lsat, EveryExact3LsatFormulaIsSatisfiable) {
  const int cases = test::scaled(1500);
  const uint64_t seed = test::base_seed(11);
  for (int t = 0; t < cases; ++t) {
    SCOPED_TRACE("GRIDLOCK_TEST_SEED=" + std::to_string(seed) + " case " + std::to_string(t));
    Rng pick(seed + static_cast<uint64_t>(t) * 7919);
    LsatParams p;
    p.n = static_cast<int>(pick.between(3, t % 10 == 0 ? 400 : 40));
    const int cap = lsat_max_clauses(p.n, 3);
    p.m = t % 2 == 0 ? cap : static_cast<int>(pick.between(0, cap));
    p.seed = pick.next();
    Formula f = random_lsat(p);
    ASSERT_TRUE(is_lsat(f, LsatForm::Exact3));
    auto a = hall_assignment(f);
    ASSERT_TRUE(a);
    EXPECT_TRUE(satisfies(f, *a));
    if (t % 5 == 0) {
      EXPECT_EQ(solve_sat(f).status, Verdict::Yes);
    }
  }
}

}  // namespace
}  // namespace gridlock
