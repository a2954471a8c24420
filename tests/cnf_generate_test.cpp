// Generators: reproducible to the byte (same seed, same text; golden texts
// pin the output across machines and compilers), parameters recorded, and
// each generator's promise (distinct variables, LSAT shape, planted model).
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "cnf/dimacs.hpp"
#include "cnf/generate.hpp"
#include "cnf/lsat.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

TEST(Generate, BoundedDrawIsInRangeAndRoughlyUniform) {
  Rng rng(5);
  std::map<uint64_t, int> freq;
  const int draws = 60000;
  for (int i = 0; i < draws; ++i) ++freq[rng.below(6)];
  ASSERT_EQ(freq.size(), 6u);
  for (auto [value, count] : freq) {
    EXPECT_LT(value, 6u);
    EXPECT_NEAR(count, draws / 6.0, draws / 60.0) << value;  // 10% of the expected count: > 10 sigma
  }
  for (int i = 0; i < 100; ++i) EXPECT_EQ(rng.below(1), 0u);
  const uint64_t big = (uint64_t{1} << 63) + 1;  // half of all draws are rejected
  for (int i = 0; i < 100; ++i) EXPECT_LT(rng.below(big), big);
  for (int i = 0; i < 100; ++i) {
    int64_t v = rng.between(-3, 3);
    EXPECT_GE(v, -3);
    EXPECT_LE(v, 3);
  }
}

// Golden texts: produced once by this implementation (since the generators
// draw from the shared Rng, common/random.hpp) and pinned, so that a
// change of platform, compiler or standard library that changed the bytes
// (for example by using std::uniform_int_distribution) fails here.
TEST(Generate, GoldenOutputs) {
  EXPECT_EQ(to_dimacs(random_ksat({5, 4, 3, 42})),
            "c generator: random-ksat (uniform: k distinct variables per clause, uniform signs)\n"
            "c parameters: n=5 m=4 k=3 seed=42\n"
            "p cnf 5 4\n-4 -5 -3 0\n-4 -5 2 0\n1 -5 3 0\n-3 1 2 0\n");
  EXPECT_EQ(to_dimacs(random_lsat({10, 8, 3, 3, 3})),
            "c generator: random-lsat (exactly 3 literals per clause; clause pairs sharing one literal, all other "
            "literals used once)\n"
            "c parameters: n=10 m=8 min=3 max=3 seed=3\n"
            "p cnf 10 8\n3 6 -9 0\n-1 4 10 0\n-3 1 -5 0\n8 -2 9 0\n6 2 -7 0\n4 -10 5 0\n-4 9 -8 0\n-5 7 -6 0\n");
  EXPECT_EQ(to_dimacs(planted_ksat({6, 5, 3, 1})),
            "c generator: planted-ksat (random k-SAT clauses redrawn while the planted assignment falsifies them)\n"
            "c parameters: n=6 m=5 k=3 seed=1\n"
            "c planted: 1 2 3 -4 -5 6\n"
            "p cnf 6 5\n4 1 -5 0\n-5 6 3 0\n-5 -4 2 0\n-6 3 -1 0\n-3 6 5 0\n");
}

TEST(Generate, SameSeedSameBytesOtherSeedOtherBytes) {
  for (uint64_t seed : {0ULL, 1ULL, 77ULL, 18446744073709551615ULL}) {
    SCOPED_TRACE(seed);
    EXPECT_EQ(to_dimacs(random_ksat({40, 170, 3, seed})), to_dimacs(random_ksat({40, 170, 3, seed})));
    EXPECT_NE(to_dimacs(random_ksat({40, 170, 3, seed})), to_dimacs(random_ksat({40, 170, 3, seed + 1})));
    EXPECT_EQ(to_dimacs(random_lsat({60, 48, 1, 3, seed})), to_dimacs(random_lsat({60, 48, 1, 3, seed})));
    EXPECT_NE(to_dimacs(random_lsat({60, 48, 1, 3, seed})), to_dimacs(random_lsat({60, 48, 1, 3, seed + 1})));
    EXPECT_EQ(to_dimacs(planted_ksat({30, 120, 3, seed})), to_dimacs(planted_ksat({30, 120, 3, seed})));
  }
}

TEST(Generate, KSatClausesHaveKDistinctVariables) {
  for (int k : {1, 2, 3, 5}) {
    Formula f = random_ksat({8, 200, k, 9});
    EXPECT_EQ(f.num_vars, 8);
    ASSERT_EQ(f.clauses.size(), 200u);
    EXPECT_EQ(validate(f), "");
    std::set<int> used;
    for (const auto& c : f.clauses) {
      ASSERT_EQ(c.size(), static_cast<size_t>(k));
      std::set<int> vars;
      for (int lit : c) {
        vars.insert(var_of(lit));
        used.insert(lit);
      }
      EXPECT_EQ(vars.size(), c.size());
    }
    EXPECT_EQ(used.size(), 16u);  // every literal appears somewhere in 200 clauses
  }
  EXPECT_EQ(random_ksat({4, 10, 4, 1}).clauses[0].size(), 4u);  // k = n
}

TEST(Generate, ParametersAndSeedAreRecorded) {
  Formula f = random_ksat({20, 91, 3, 123});
  EXPECT_EQ(f.comments.at(1), "parameters: n=20 m=91 k=3 seed=123");
  f = random_lsat({9, 7, 2, 3, 5});
  EXPECT_EQ(f.comments.at(1), "parameters: n=9 m=7 min=2 max=3 seed=5");
  f = planted_ksat({4, 2, 2, 8});
  EXPECT_EQ(f.comments.at(1), "parameters: n=4 m=2 k=2 seed=8");
}

TEST(Generate, RatioRounds) {
  EXPECT_EQ(clauses_for_ratio(50, 4.26), 213);
  EXPECT_EQ(clauses_for_ratio(20, 4.55), 91);
  EXPECT_EQ(clauses_for_ratio(7, 0), 0);
  EXPECT_THROW(clauses_for_ratio(7, -1), std::invalid_argument);
  EXPECT_THROW(clauses_for_ratio(1 << 30, 1e9), std::invalid_argument);
}

TEST(Generate, LsatCapMatchesItsDefinition) {
  for (int L = 1; L <= 3; ++L)
    for (int n = 0; n <= 200; ++n) {
      int best = 0;
      for (int m = 0; m <= 5 * n + 2; ++m)
        if (static_cast<int64_t>(m) * L - m / 2 <= 2 * static_cast<int64_t>(n)) best = m;
      EXPECT_EQ(lsat_max_clauses(n, L), best) << "n=" << n << " L=" << L;
    }
  EXPECT_EQ(lsat_max_clauses(5, 3), 4);
  EXPECT_EQ(lsat_max_clauses(100, 3), 80);  // 4n/5
}

TEST(Generate, RandomLsatHasTheLsatShapeUpToTheCap) {
  const int cases = test::scaled(1500);
  const uint64_t seed = test::base_seed(3);
  for (int t = 0; t < cases; ++t) {
    SCOPED_TRACE("GRIDLOCK_TEST_SEED=" + std::to_string(seed) + " case " + std::to_string(t));
    Rng pick(seed * 31 + static_cast<uint64_t>(t));
    LsatParams p;
    p.min_len = static_cast<int>(pick.between(1, 3));
    p.max_len = static_cast<int>(pick.between(p.min_len, 3));
    p.n = static_cast<int>(pick.between(p.max_len, 50));
    const int cap = lsat_max_clauses(p.n, p.min_len);
    p.m = t % 3 == 0 ? cap : static_cast<int>(pick.between(0, cap));
    p.seed = pick.next();
    Formula f = random_lsat(p);
    ASSERT_EQ(f.clauses.size(), static_cast<size_t>(p.m));
    EXPECT_EQ(validate(f), "");
    LsatReport r = check_lsat(f, LsatForm::AtMost3, 1);
    ASSERT_TRUE(r.ok) << r.violations.front().message;
    if (p.min_len == 3) {
      EXPECT_TRUE(is_lsat(f, LsatForm::Exact3));
    }
    for (const auto& c : f.clauses) {
      EXPECT_GE(static_cast<int>(c.size()), p.min_len);
      EXPECT_LE(static_cast<int>(c.size()), p.max_len);
      EXPECT_FALSE(is_tautology(c));
    }
    EXPECT_TRUE(r.tautologies.empty());
  }
}

TEST(Generate, InvalidParametersAreExplained) {
  auto message = [](auto&& fn) {
    try {
      fn();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  EXPECT_EQ(message([] { random_ksat({0, 1, 3, 1}); }), "n must be at least 1 (got 0)");
  EXPECT_EQ(message([] { random_ksat({5, -1, 3, 1}); }), "m must be at least 0 (got -1)");
  EXPECT_EQ(message([] { random_ksat({2, 1, 3, 1}); }), "k must be between 1 and n = 2 (got 3)");
  EXPECT_EQ(message([] {
              random_lsat({10, 9, 3, 3, 1});
            }),
            "an LSAT formula with 10 variables and clauses of at least 3 literals has at most 8 clauses (got m=9)");
  EXPECT_EQ(message([] {
              random_lsat({10, 2, 2, 4, 1});
            }),
            "clause lengths must satisfy 1 <= min <= max <= 3 (got 2..4)");
  EXPECT_EQ(message([] { random_lsat({2, 1, 3, 3, 1}); }), "n must be at least the longest clause length 3 (got 2)");
  EXPECT_EQ(message([] { planted_ksat({3, 1, 0, 1}); }), "k must be between 1 and n = 3 (got 0)");
}

TEST(Generate, PlantedAssignmentSatisfies) {
  for (uint64_t seed = 0; seed < 50; ++seed) {
    std::vector<bool> planted;
    Formula f = planted_ksat({25, 150, 3, seed}, &planted);
    ASSERT_EQ(planted.size(), 26u);
    EXPECT_TRUE(satisfies(f, planted)) << seed;
    // The comment holds the same assignment.
    std::string lits;
    for (int lit : model_literals(planted, 25)) lits += " " + std::to_string(lit);
    EXPECT_EQ(f.comments.at(2), "planted:" + lits);
  }
}

}  // namespace
}  // namespace gridlock
