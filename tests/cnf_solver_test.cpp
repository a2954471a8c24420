// The three SAT oracles against each other (CaDiCaL, exhaustive search,
// DPLL) on random formulas of every shape, model counts against the
// exhaustive search, and CaDiCaL's limits.
#include <gtest/gtest.h>

#include <chrono>

#include "cnf/brute_force.hpp"
#include "cnf/generate.hpp"
#include "cnf/sat_solver.hpp"
#include "support/cnf_testing.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

// Pigeonhole: p pigeons in p-1 holes. Unsatisfiable, and hard for
// resolution, so CaDiCaL needs many conflicts for p around 10.
Formula pigeonhole(int p) {
  const int h = p - 1;
  Formula f;
  f.num_vars = p * h;
  auto x = [&](int i, int j) { return i * h + j + 1; };
  for (int i = 0; i < p; ++i) {
    std::vector<int> c;
    c.reserve(static_cast<size_t>(h));
    for (int j = 0; j < h; ++j) c.push_back(x(i, j));
    f.clauses.push_back(c);
  }
  for (int j = 0; j < h; ++j)
    for (int a = 0; a < p; ++a)
      for (int b = a + 1; b < p; ++b) f.clauses.push_back({-x(a, j), -x(b, j)});
  return f;
}

TEST(Solver, OraclesAgreeOnRandomFormulas) {
  const int cases = test::scaled(3000);
  const uint64_t seed = test::base_seed(99);
  int sat = 0;
  for (int t = 0; t < cases; ++t) {
    SCOPED_TRACE("GRIDLOCK_TEST_SEED=" + std::to_string(seed) + " case " + std::to_string(t));
    Rng rng(seed * 7777 + static_cast<uint64_t>(t));
    const int n = static_cast<int>(rng.between(1, 12));
    const int m = static_cast<int>(rng.between(0, 6 * static_cast<int64_t>(n)));
    // Every third formula is messy: empty clauses, repeats, tautologies.
    Formula f = test::random_cnf(rng, n, m, t % 3 == 0 ? 0 : 1, t % 4 == 0 ? 5 : 3, t % 3 == 0);
    SatResult ex = exhaustive_sat(f);
    SatResult cd = solve_sat(f);
    SatResult dp = dpll_sat(f);
    ASSERT_NE(ex.status, Verdict::Unknown);
    ASSERT_EQ(cd.status, ex.status);
    ASSERT_EQ(dp.status, ex.status);
    const uint64_t models = t % 4 == 0 ? count_models(f) : (ex.status == Verdict::Yes ? 1 : 0);
    EXPECT_EQ(models > 0, ex.status == Verdict::Yes);
    if (ex.status == Verdict::Yes) {
      ++sat;
      EXPECT_TRUE(satisfies(f, ex.model));
      EXPECT_TRUE(satisfies(f, cd.model));
      EXPECT_TRUE(satisfies(f, dp.model));
      EXPECT_EQ(cd.model.size(), static_cast<size_t>(n) + 1);
    }
  }
  EXPECT_GT(sat, cases / 5);
  EXPECT_LT(sat, cases - cases / 5);
}

TEST(Solver, CountModelsSmallCases) {
  Formula f;
  f.num_vars = 3;
  EXPECT_EQ(count_models(f), 8u);  // no clauses: every assignment
  f.clauses = {{1, 2}};
  EXPECT_EQ(count_models(f), 6u);
  f.clauses.push_back({-1});
  EXPECT_EQ(count_models(f), 2u);
  f.clauses.push_back({});
  EXPECT_EQ(count_models(f), 0u);
}

TEST(Solver, EdgeCases) {
  Formula none;
  SatResult r = solve_sat(none);
  EXPECT_EQ(r.status, Verdict::Yes);
  EXPECT_EQ(r.model.size(), 1u);
  Formula empty_clause;
  empty_clause.num_vars = 2;
  empty_clause.clauses = {{1}, {}};
  EXPECT_EQ(solve_sat(empty_clause).status, Verdict::No);
  EXPECT_EQ(dpll_sat(empty_clause).status, Verdict::No);
  EXPECT_EQ(exhaustive_sat(empty_clause).status, Verdict::No);
  // Declared but unused variables still get a value.
  Formula unused;
  unused.num_vars = 1000;
  unused.clauses = {{-7}};
  r = solve_sat(unused);
  ASSERT_EQ(r.status, Verdict::Yes);
  EXPECT_EQ(r.model.size(), 1001u);
  EXPECT_FALSE(r.model[7]);
  // Malformed formulas are bugs, not answers.
  Formula bad;
  bad.num_vars = 1;
  bad.clauses = {{2}};
  EXPECT_THROW(solve_sat(bad), std::invalid_argument);
  EXPECT_THROW(dpll_sat(bad), std::invalid_argument);
  EXPECT_THROW(exhaustive_sat(bad), std::invalid_argument);
  Formula big;
  big.num_vars = kExhaustiveMaxVars + 1;
  EXPECT_THROW(exhaustive_sat(big), std::invalid_argument);
  EXPECT_THROW(satisfies(unused, std::vector<bool>(10)), std::invalid_argument);
}

TEST(Solver, LimitsGiveUnknown) {
  const Formula php = pigeonhole(10);
  SatLimits few;
  few.conflicts = 20;
  EXPECT_EQ(solve_sat(php, few).status, Verdict::Unknown);
  SatLimits quick;
  quick.seconds = 0.05;
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(solve_sat(pigeonhole(13), quick).status, Verdict::Unknown);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
  // Small enough to finish: the limits do not change answers.
  SatLimits generous;
  generous.conflicts = 1000000;
  generous.seconds = 60;
  EXPECT_EQ(solve_sat(pigeonhole(6), generous).status, Verdict::No);
  EXPECT_EQ(solve_sat(pigeonhole(6)).status, Verdict::No);
  EXPECT_EQ(dpll_sat(pigeonhole(6)).status, Verdict::No);
  EXPECT_EQ(dpll_sat(pigeonhole(8), 10).status, Verdict::Unknown);
}

TEST(Solver, PlantedFormulasAreSatisfiable) {
  for (uint64_t seed = 0; seed < static_cast<uint64_t>(test::scaled(40)); ++seed) {
    Formula f = planted_ksat({60, 250, 3, seed});
    SatResult r = solve_sat(f);
    ASSERT_EQ(r.status, Verdict::Yes) << seed;
    EXPECT_TRUE(satisfies(f, r.model));
  }
}

}  // namespace
}  // namespace gridlock
