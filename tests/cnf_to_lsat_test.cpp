// CNF -> LSAT<=3: on thousands of seeded random formulas (3-CNF, and messy
// CNF with empty, long, repeated and tautological clauses), SAT and UNSAT,
// the output is LSAT<=3, has exactly the documented size, has the input's
// answer (exhaustive search on the input, CaDiCaL and DPLL on the output),
// and the assignment maps work both ways. Then the 300 SATLIB formulas.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "cnf/brute_force.hpp"
#include "cnf/dimacs.hpp"
#include "cnf/generate.hpp"
#include "cnf/lsat.hpp"
#include "cnf/sat_solver.hpp"
#include "reductions/to_lsat.hpp"
#include "support/cnf_testing.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

// The size formulas of docs/formulas.md, computed from the definitions
// (independently of reductions/to_lsat.cpp).
struct Size {
  int64_t vars = 0, clauses = 0;
};

Size documented_size(const Formula& in, bool keep_duplicates = false) {
  std::vector<std::vector<int>> groups;  // per normalised clause: its input literals
  std::set<std::set<int>> kept;          // the literal sets of the clauses kept so far
  int64_t A = 0, e = 0, mprime = 0;
  for (const auto& c : in.clauses) {
    std::vector<int> s;
    for (int lit : c)
      if (std::find(s.begin(), s.end(), lit) == s.end()) s.push_back(lit);
    bool taut = false;
    for (int lit : s) taut = taut || std::find(s.begin(), s.end(), -lit) != s.end();
    if (taut) continue;
    if (s.empty()) {
      ++e;
      continue;
    }
    if (!keep_duplicates && !kept.insert(std::set<int>(s.begin(), s.end())).second) continue;
    if (s.size() <= 3) {
      groups.push_back(s);
      ++mprime;
      continue;
    }
    // (l1 l2 a1) (-a1 l3 a2) ... (-a l_{s-1} l_s): chain variables occur once per sign.
    A += static_cast<int64_t>(s.size()) - 3;
    mprime += static_cast<int64_t>(s.size()) - 2;
    groups.push_back({s[0], s[1]});
    for (size_t j = 2; j + 2 < s.size(); ++j) groups.push_back({s[j]});
    groups.push_back({s[s.size() - 2], s[s.size() - 1]});
  }
  std::map<int, int> p, q;
  for (const auto& g : groups)
    for (int lit : g) ++(lit > 0 ? p : q)[var_of(lit)];
  std::set<int> X;
  int64_t sum_k = 0;
  for (int x = 1; x <= in.num_vars; ++x)
    if (p[x] >= 2 || q[x] >= 2) {
      X.insert(x);
      sum_k += p[x] + q[x] - (p[x] > 0 && q[x] > 0 ? 1 : 0);
    }
  // Free ends: the first positive and the last negative occurrence of each
  // variable of X (in clause order) need no link.
  std::map<int, int> pos_seen, neg_seen;
  int64_t d = 0;
  for (const auto& g : groups) {
    int64_t r = 0;
    for (int lit : g) {
      const int x = var_of(lit);
      if (!X.count(x)) continue;
      const bool free_end = lit > 0 ? pos_seen[x]++ == 0 : ++neg_seen[x] == q[x];
      r += free_end ? 0 : 1;
    }
    d += std::max<int64_t>(0, r - 1);
  }
  const int64_t n = in.num_vars, cx = static_cast<int64_t>(X.size());
  return {n + A + (sum_k - cx) + d + e, mprime + (sum_k - cx) + d + 2 * e};
}

struct Tally {
  int sat = 0, unsat = 0;
};

// Everything the reduction promises, on one input. Returns the input's status.
Verdict check_reduction(const Formula& in, const ToLsatOptions& opt, bool with_dpll, bool all_models) {
  LsatReduction red = reduce_to_lsat(in, opt);
  const Formula& out = red.output();
  EXPECT_EQ(validate(out), "");
  LsatReport lr = check_lsat(out, LsatForm::AtMost3, 1);
  EXPECT_TRUE(lr.ok) << lr.violations.front().message;
  EXPECT_EQ(red.source_vars(), in.num_vars);
  EXPECT_EQ(red.stats().out_vars, out.num_vars);
  EXPECT_EQ(red.stats().out_clauses, out.clauses.size());
  if (red.stats().identity) {
    EXPECT_TRUE(opt.passthrough);
    EXPECT_TRUE(is_lsat(in, LsatForm::AtMost3));
    EXPECT_EQ(out.clauses, in.clauses);
    EXPECT_EQ(out.num_vars, in.num_vars);
  } else {
    Size s = documented_size(in, opt.keep_duplicates);
    EXPECT_EQ(out.num_vars, s.vars);
    EXPECT_EQ(static_cast<int64_t>(out.clauses.size()), s.clauses);
  }
  const SatResult ex = exhaustive_sat(in);
  const SatResult cd = solve_sat(out);
  EXPECT_EQ(cd.status, ex.status);
  if (with_dpll) {
    EXPECT_EQ(dpll_sat(out).status, ex.status);
  }
  if (ex.status == Verdict::Yes && cd.status == Verdict::Yes) {
    EXPECT_TRUE(satisfies(out, red.lift_to_target(ex.model)));
    EXPECT_TRUE(satisfies(in, red.lift_to_source(cd.model)));
    if (all_models) {
      // Every model of the input lifts to a model of the output ...
      for (uint64_t a = 0; a < (uint64_t{1} << in.num_vars); ++a) {
        std::vector<bool> v(static_cast<size_t>(in.num_vars) + 1);
        for (int x = 1; x <= in.num_vars; ++x) v[static_cast<size_t>(x)] = (a >> (x - 1)) & 1;
        if (satisfies(in, v)) {
          EXPECT_TRUE(satisfies(out, red.lift_to_target(v)));
        }
      }
      // ... and several different models of the output map back.
      Formula blocked = out;
      for (int k = 0; k < 8; ++k) {
        SatResult r = solve_sat(blocked);
        if (r.status != Verdict::Yes) break;
        EXPECT_TRUE(satisfies(in, red.lift_to_source(r.model)));
        std::vector<int> block;
        for (int v = 1; v <= out.num_vars; ++v) block.push_back(r.model[static_cast<size_t>(v)] ? -v : v);
        blocked.clauses.push_back(block);
      }
    }
  }
  return ex.status;
}

TEST(ToLsat, Random3CnfBothWays) {
  const int cases = test::scaled(4000);
  const uint64_t seed = test::base_seed(2024);
  Tally tally;
  for (int t = 0; t < cases; ++t) {
    SCOPED_TRACE("GRIDLOCK_TEST_SEED=" + std::to_string(seed) + " case " + std::to_string(t));
    Rng rng(seed * 1000 + static_cast<uint64_t>(t));
    const int n = static_cast<int>(rng.between(3, 14));
    // Ratios from 0 to 8 around the threshold 4.27: both answers common.
    const int m = static_cast<int>(rng.between(0, 8 * static_cast<int64_t>(n)));
    Formula in = test::random_cnf(rng, n, m, 3, 3, false);
    ToLsatOptions opt;
    opt.passthrough = t % 2 == 0;
    opt.keep_duplicates = t % 5 == 1;  // both ways (small n: many repeated clauses)
    auto st = check_reduction(in, opt, t % 4 == 0, t % 25 == 0 && n <= 8);
    (st == Verdict::Yes ? tally.sat : tally.unsat)++;
    if (::testing::Test::HasFailure()) break;  // one seed to replay, not a flood
    // The bounds for 3-CNF with three distinct literals per clause.
    LsatReduction red = reduce_to_lsat(in, opt);
    EXPECT_LE(red.output().num_vars, 5 * m + n);
    EXPECT_LE(static_cast<int>(red.output().clauses.size()), 6 * m + n);
  }
  EXPECT_GT(tally.sat, cases / 5);
  EXPECT_GT(tally.unsat, cases / 5);
}

TEST(ToLsat, MessyCnfBothWays) {
  // Clauses of 0 to 7 literals with repeats and tautologies.
  const int cases = test::scaled(1500);
  const uint64_t seed = test::base_seed(77);
  Tally tally;
  for (int t = 0; t < cases; ++t) {
    SCOPED_TRACE("GRIDLOCK_TEST_SEED=" + std::to_string(seed) + " case " + std::to_string(t));
    Rng rng(seed * 1000 + static_cast<uint64_t>(t));
    const int n = static_cast<int>(rng.between(1, 10));
    const int m = static_cast<int>(rng.between(0, 5 * static_cast<int64_t>(n)));
    Formula in = test::random_cnf(rng, n, m, t % 5 == 0 ? 0 : 1, 7, true);
    ToLsatOptions opt;
    opt.passthrough = t % 3 != 0;
    opt.keep_duplicates = t % 5 == 2;
    auto st = check_reduction(in, opt, t % 4 == 0, t % 25 == 0 && n <= 8);
    (st == Verdict::Yes ? tally.sat : tally.unsat)++;
    if (::testing::Test::HasFailure()) break;
  }
  EXPECT_GT(tally.sat, cases / 5);
  EXPECT_GT(tally.unsat, cases / 5);
}

TEST(ToLsat, LsatInputsPassThroughOrAreRebuilt) {
  const int cases = test::scaled(300);
  for (int t = 0; t < cases; ++t) {
    SCOPED_TRACE(t);
    Formula in = random_lsat(
        {static_cast<int>(6 + t % 10), static_cast<int>(4 + t % 6), 1, 3, static_cast<uint64_t>(t)});
    LsatReduction same = reduce_to_lsat(in);
    EXPECT_TRUE(same.stats().identity);
    std::vector<bool> v(static_cast<size_t>(in.num_vars) + 1, true);
    v[0] = false;  // index 0 is unused, and false in every lifted assignment
    EXPECT_EQ(same.lift_to_target(v), v);
    EXPECT_EQ(same.lift_to_source(v), v);
    ToLsatOptions rebuild;
    rebuild.passthrough = false;
    check_reduction(in, rebuild, true, t % 10 == 0);
    EXPECT_FALSE(reduce_to_lsat(in, rebuild).stats().identity);
  }
}

TEST(ToLsat, SmallCasesByHand) {
  // Only an empty clause: (u)(-u).
  Formula f;
  f.num_vars = 2;
  f.clauses = {{1, 2}, {}};
  LsatReduction red = reduce_to_lsat(f);
  EXPECT_EQ(red.output().clauses, (std::vector<std::vector<int>>{{1, 2}, {3}, {-3}}));
  // x in three clauses, positively: the path w1 = 4 -> w2 = 5 -> w3 = x (the
  // pivot); no links (one path variable per clause), each clause takes its
  // own path variable, the first one the free end w1.
  f.num_vars = 3;
  f.clauses = {{1, 2}, {1, -2}, {1, 3}};
  red = reduce_to_lsat(f);
  EXPECT_EQ(red.output().clauses, (std::vector<std::vector<int>>{{4, 2}, {5, -2}, {1, 3}, {-4, 5}, {-5, 1}}));
  EXPECT_EQ(red.lift_to_target({false, true, false, true}), (std::vector<bool>{false, true, false, true, true, true}));
  // Both signs and a link: x = 1 occurs +,+,- ; y = 2 occurs +,+. Path of x:
  // w1 = 3 (free), w2 = x (pivot: the second positive and the negative
  // occurrence, the negative one -w2 = -1 being the free end); path of y:
  // w1 = 4 (free), w2 = y. Clause 1 holds two free ends; clause 2 holds x's
  // w2 and y's w2, so y's occurrence becomes the link variable 5.
  {
    Formula g;
    g.num_vars = 2;
    g.clauses = {{1, 2}, {1, 2}, {-1}};
    ToLsatOptions keep;
    keep.keep_duplicates = true;  // by default the second {1, 2} is dropped (next case)
    LsatReduction r2 = reduce_to_lsat(g, keep);
    EXPECT_EQ(r2.output().clauses, (std::vector<std::vector<int>>{{3, 4}, {1, 5}, {-5, 2}, {-1}, {-3, 1}, {-4, 2}}));
    EXPECT_EQ(r2.stats().links, 1u);
  }
  // Clauses with the same literals as an earlier one are dropped (the input
  // is not LSAT<=3: literal 1 occurs three times).
  {
    Formula g;
    g.num_vars = 2;
    g.clauses = {{1, 2}, {2, 1}, {1, 2, 1}};
    LsatReduction r3 = reduce_to_lsat(g);
    EXPECT_EQ(r3.output().clauses, (std::vector<std::vector<int>>{{1, 2}}));
    EXPECT_EQ(r3.stats().duplicate_clauses, 2u);
    EXPECT_EQ(r3.stats().repeated_literals, 1u);
    EXPECT_FALSE(r3.stats().identity);
    check_reduction(g, ToLsatOptions{}, true, true);
  }
  // Tautologies vanish; a formula of tautologies becomes empty (when built:
  // as it stands it is LSAT<=3 and would pass through).
  f.clauses = {{1, -1}, {2, 3, -2}};
  EXPECT_TRUE(reduce_to_lsat(f).stats().identity);
  ToLsatOptions rebuild;
  rebuild.passthrough = false;
  red = reduce_to_lsat(f, rebuild);
  EXPECT_TRUE(red.output().clauses.empty());
  EXPECT_EQ(red.stats().tautologies, 2u);
  // Wrong-sized assignments are bugs.
  EXPECT_THROW(red.lift_to_target({true}), std::invalid_argument);
  EXPECT_THROW(red.lift_to_source({}), std::invalid_argument);
  Formula bad;
  bad.num_vars = 1;
  bad.clauses = {{-2}};
  EXPECT_THROW(reduce_to_lsat(bad), std::invalid_argument);
}

TEST(ToLsat, LongClausesAreSplit) {
  // 30 written literals, 20 distinct: one chain of 18 clauses, 17 chain variables.
  Formula f;
  f.num_vars = 20;
  std::vector<int> big;
  for (int v = 1; v <= 20; ++v) big.push_back(v % 3 ? v : -v);
  for (int v = 1; v <= 10; ++v) big.push_back(v % 3 ? v : -v);
  f.clauses.push_back(big);
  Rng rng(5);
  for (int i = 0; i < 60; ++i) f.clauses.push_back(test::random_cnf(rng, 20, 1, 2, 3, false).clauses[0]);
  ToLsatOptions opt;
  for (bool all_false_first : {false, true}) {
    // Also with every literal of the long clause forced false but the last,
    // so that a model of the input satisfies it only by its last literal and
    // lift_to_target must set every chain variable true.
    Formula g = f;
    if (all_false_first)
      for (size_t k = 0; k + 1 < 20; ++k) g.clauses.push_back({-big[k]});
    check_reduction(g, opt, true, false);
    LsatReduction red = reduce_to_lsat(g, opt);
    EXPECT_EQ(red.stats().split_clauses, 1u);
    EXPECT_EQ(red.stats().repeated_literals, 10u);
    EXPECT_EQ(red.stats().chain_vars, 17u);
  }
}

TEST(ToLsat, EverySatlibFormula) {
  auto files = test::satlib_files();
  ASSERT_EQ(files.size(), 300u);
  for (const auto& file : files) {
    SCOPED_TRACE(file.path);
    Formula in;
    auto e = read_dimacs_file(file.path, in);
    ASSERT_FALSE(e) << e->str();
    LsatReduction red = reduce_to_lsat(in);
    const Formula& out = red.output();
    ASSERT_TRUE(is_lsat(out, LsatForm::AtMost3));
    Size s = documented_size(in);
    EXPECT_EQ(out.num_vars, s.vars);
    EXPECT_EQ(static_cast<int64_t>(out.clauses.size()), s.clauses);
    SatResult r = solve_sat(out);
    ASSERT_EQ(r.status, file.sat ? Verdict::Yes : Verdict::No);
    if (file.sat) {
      EXPECT_TRUE(satisfies(in, red.lift_to_source(r.model)));
      SatResult src = solve_sat(in);
      ASSERT_EQ(src.status, Verdict::Yes);
      EXPECT_TRUE(satisfies(out, red.lift_to_target(src.model)));
    }
  }
}

}  // namespace
}  // namespace gridlock
