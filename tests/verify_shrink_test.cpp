// The shrinker: what it returns still fails, and is 1-minimal.
#include <gtest/gtest.h>

#include "cnf/brute_force.hpp"
#include "cnf/generate.hpp"
#include "support/test_scale.hpp"
#include "verify/shrink.hpp"

namespace gridlock {
namespace {

bool unsat(const Formula& f) { return exhaustive_sat(f).status == Verdict::No; }

TEST(Shrink, UnsatFormulasShrinkToMinimalUnsatisfiableCores) {
  const int cases = test::scaled(150);
  int shrunk = 0;
  for (int i = 0; i < cases; ++i) {
    uint64_t seed = test::base_seed(5) + static_cast<uint64_t>(i);
    SCOPED_TRACE("seed " + std::to_string(seed));
    KSatParams p;
    p.n = 6;
    p.m = 40;  // well above the threshold: nearly always unsatisfiable
    p.seed = seed;
    Formula f = random_ksat(p);
    if (!unsat(f)) continue;
    ShrinkStats st;
    Formula g = shrink_formula(f, unsat, &st);
    ASSERT_TRUE(unsat(g));
    EXPECT_LE(g.clauses.size(), f.clauses.size());
    // 1-minimal: dropping any clause, or any literal, makes it satisfiable.
    for (size_t c = 0; c < g.clauses.size(); ++c) {
      Formula h = g;
      h.clauses.erase(h.clauses.begin() + static_cast<long>(c));
      if (!h.clauses.empty()) {
        EXPECT_FALSE(unsat(h)) << "clause " << c << " was removable";
      }
      for (size_t l = 0; l < g.clauses[c].size() && g.clauses[c].size() > 1; ++l) {
        Formula k = g;
        k.clauses[c].erase(k.clauses[c].begin() + static_cast<long>(l));
        EXPECT_FALSE(unsat(k)) << "literal " << l << " of clause " << c << " was removable";
      }
    }
    // Variables are numbered 1..k with no gaps.
    std::vector<char> seen(static_cast<size_t>(g.num_vars) + 1, 0);
    for (auto& c : g.clauses)
      for (int lit : c) seen[static_cast<size_t>(var_of(lit))] = 1;
    for (int v = 1; v <= g.num_vars; ++v) EXPECT_TRUE(seen[static_cast<size_t>(v)]);
    if (g.clauses.size() < f.clauses.size()) ++shrunk;
  }
  EXPECT_GT(shrunk, cases / 2);
}

TEST(Shrink, CompactVariablesKeepsStructure) {
  Formula f;
  f.num_vars = 9;
  f.clauses = {{9, -4}, {4, 7}};
  Formula g = compact_variables(f);
  EXPECT_EQ(g.num_vars, 3);
  EXPECT_EQ(g.clauses, (std::vector<std::vector<int>>{{1, -2}, {2, 3}}));
}

}  // namespace
}  // namespace gridlock
