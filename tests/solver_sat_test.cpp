// The SAT engine (solver/search_sat.cpp, the default for horizontal-only
// instances) against its twins: every permutation on random gap systems with
// weights (the weighted counter), the precedence engine on the same systems,
// and CaDiCaL on the source formula for every SATLIB sample compiled through
// to-lsat. The random lattice instances run it in solver_solve_test.cpp
// (SolveRandom.*, against the all-permutations Simulator reference).
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "cnf/dimacs.hpp"
#include "cnf/generate.hpp"
#include "cnf/sat_solver.hpp"
#include "reductions/compile.hpp"
#include "reductions/to_lsat.hpp"
#include "solver/internal/order_sat.hpp"
#include "solver/internal/search.hpp"
#include "solver/solve.hpp"
#include "support/cnf_testing.hpp"
#include "support/random_gap_system.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

using Status = Verdict;

// A random gap system: k couplings, some gaps over 2..k of them with
// coefficients in [-3, 3] \ {0} and bases in [-4, 0].
ConstraintSystem random_gap_system(Rng& rng, size_t k) { return test::random_gap_system(rng, k, {}); }

bool brute_force(const ConstraintSystem& s) {
  std::vector<CouplingId> order(s.num_couplings);
  std::iota(order.begin(), order.end(), 0);
  do {
    if (replay_order(s, order).failed_step == order.size()) return true;
  } while (std::next_permutation(order.begin(), order.end()));
  return false;
}

SearchOutcome run(const ConstraintSystem& s, bool sat) {
  SolveOptions o;
  SearchBudget budget(o);
  SolveStats st;
  return sat ? search_sat(s, budget, st) : search_precedence(s, budget, st);
}

TEST(SatEngine, RandomGapSystemsAgreeWithAllPermutations) {
  const uint64_t seed = test::base_seed(7100);
  Rng rng(seed);
  const int count = test::scaled(4000);
  int yes = 0, no = 0;
  for (int i = 0; i < count; ++i) {
    const auto k = static_cast<size_t>(rng.between(2, 7));
    const ConstraintSystem s = random_gap_system(rng, k);
    const bool ref = brute_force(s);
    const SearchOutcome sat = run(s, true);
    const SearchOutcome prec = run(s, false);
    ASSERT_EQ(sat.status == Status::Yes, ref) << "seed " << seed << " case " << i;
    ASSERT_EQ(prec.status == Status::Yes, ref) << "seed " << seed << " case " << i;
    if (ref) {
      ASSERT_EQ(sat.order.size(), k);
      EXPECT_EQ(replay_order(s, sat.order).failed_step, k) << "seed " << seed << " case " << i;
    }
    (ref ? yes : no) += 1;
  }
  // Both answers must be exercised, or the test proves little.
  EXPECT_GT(yes, count / 10);
  EXPECT_GT(no, count / 10);
  std::printf("[ sat-gap-systems ] %d systems: %d YES, %d NO (seed %llu)\n", count, yes, no,
              static_cast<unsigned long long>(seed));
}

// OrderSat::at_most against arithmetic: a random weighted constraint over n
// order literals of disjoint pairs (no cycles possible), each of the 2^n
// assignments fixed by unit clauses, must be satisfiable exactly when the
// true literals weigh at most the bound. Both encodings must occur: the one
// clause "not all of them" (only all together weigh too much) and the
// weighted counter.
TEST(SatEngine, AtMostAgreesWithArithmetic) {
  const uint64_t seed = test::base_seed(7300);
  Rng rng(seed);
  const int count = test::scaled(3000);
  int one_clause = 0, counter = 0;
  for (int i = 0; i < count; ++i) {
    const auto n = static_cast<size_t>(rng.between(1, 5));
    std::vector<int64_t> w(n);
    int64_t total = 0;
    for (auto& x : w) x = rng.between(1, 4), total += x;
    const int64_t bound = rng.between(-1, total);
    const std::vector<bool> negate = [&] {
      std::vector<bool> v(n);
      for (size_t j = 0; j < n; ++j) v[j] = rng.coin();
      return v;
    }();
    int64_t kept = 0, kept_lightest = INT64_MAX;  // the literals the counter keeps (weight <= bound)
    for (int64_t x : w)
      if (x <= bound) kept += x, kept_lightest = std::min(kept_lightest, x);
    if (bound >= 0 && kept > bound) (kept - kept_lightest <= bound ? one_clause : counter) += 1;
    for (uint32_t mask = 0; mask < (1u << n); ++mask) {
      SolveOptions o;
      SearchBudget budget(o);
      SolveStats st;
      OrderSat os(2 * n, budget, st);
      std::vector<std::pair<int, int64_t>> lits;
      int64_t weight = 0;
      for (size_t j = 0; j < n; ++j) {
        const auto a = static_cast<CouplingId>(2 * j), b = static_cast<CouplingId>(2 * j + 1);
        const int lit = negate[j] ? os.before(b, a) : os.before(a, b);
        lits.push_back({lit, w[j]});
        const bool on = (mask >> j) & 1;
        os.add_clause({on ? lit : -lit});
        if (on) weight += w[j];
      }
      const bool encoded = os.at_most(lits, bound);
      const bool expect = weight <= bound;
      if (!encoded) {
        ASSERT_LT(bound, 0) << "seed " << seed << " case " << i;
        continue;
      }
      ASSERT_TRUE(os.add_order_clauses({}));
      const SearchOutcome out = os.solve([](const std::vector<CouplingId>&) { return true; });
      ASSERT_EQ(out.status == Verdict::Yes, expect) << "seed " << seed << " case " << i << " mask " << mask;
    }
  }
  EXPECT_GT(one_clause, count / 20);
  EXPECT_GT(counter, count / 20);
  std::printf("[ at-most ] %d constraints: %d as one clause, %d as a counter (seed %llu)\n", count, one_clause, counter,
              static_cast<unsigned long long>(seed));
}

// Long cycles: a chain a_0 < a_1 < ... < a_{n-1} of two-coupling gaps plus
// one gap that asks for a_{n-1} before a_0 is NO only through a cycle of n
// order literals (found by the forced closure); without the last gap it is
// YES in exactly one order.
TEST(SatEngine, ChainAndClosingGap) {
  for (size_t n : {2u, 3u, 10u, 200u}) {
    ConstraintSystem s;
    s.kind = ConstraintKind::Gaps;
    s.num_couplings = n;
    auto before = [&](CouplingId a, CouplingId b) {  // b narrows what a widens
      CollisionConstraint c;
      c.num_forms = 1;
      c.base = {0};
      c.rel = {std::min(a, b), std::max(a, b)};
      c.set_coef(a < b ? std::vector<int64_t>{-1, 1} : std::vector<int64_t>{1, -1});
      s.constraints.push_back(c);
    };
    for (CouplingId i = 0; i + 1 < n; ++i) before(i, i + 1);
    s.index();
    SearchOutcome yes = run(s, true);
    ASSERT_EQ(yes.status, Status::Yes) << n;
    std::vector<CouplingId> expect(n);
    std::iota(expect.begin(), expect.end(), 0);
    EXPECT_EQ(yes.order, expect);
    before(static_cast<CouplingId>(n - 1), 0);
    s.index();
    EXPECT_EQ(run(s, true).status, Status::No) << n;
  }
}

TEST(SatEngine, LimitsGiveUnknown) {
  Formula f;
  ASSERT_FALSE(read_dimacs_file(GRIDLOCK_DATA_DIR "/satlib/uuf50-218/uuf50-01.cnf", f));
  const Instance inst = compile_formula(reduce_to_lsat(f).output()).instance;
  SolveOptions o;
  o.engine = SolveOptions::Engine::Sat;
  o.max_states = 1;
  SolveResult r = solve_discrete(inst, o);
  EXPECT_EQ(r.status, Status::Unknown);
  EXPECT_TRUE(r.order.empty());
  o.max_states = 0;
  // 2 ms: the whole solve of this formula takes 20-70 ms on the 2-core
  // hosts (50 ms was once a limit it reached; a faster host answered NO).
  o.seconds = 0.002;
  r = solve_discrete(inst, o);
  EXPECT_EQ(r.status, Status::Unknown);
  EXPECT_LT(r.stats.seconds, 0.002 * 1.1 + 0.05);  // set-up and search both watch the clock
}

// Every SATLIB sample through to-lsat and compile: the default engine (SAT)
// agrees with CaDiCaL on the source formula and with the label; a YES order
// passed the simulator inside solve_discrete and gives, read back, an
// assignment that satisfies the source. A spread subset under a scale < 1.
TEST(SatEngine, SatlibAgreesWithCadical) {
  auto files = test::satlib_files();
  ASSERT_EQ(files.size(), 300u);
  const auto want = static_cast<size_t>(test::scaled(300));
  size_t checked = 0, yes = 0;
  for (size_t i = 0; i < files.size(); ++i) {
    if (want < files.size() && (i * want) % files.size() >= want) continue;
    Formula f;
    ASSERT_FALSE(read_dimacs_file(files[i].path, f)) << files[i].path;
    const bool sat = solve_sat(f).status == Verdict::Yes;
    ASSERT_EQ(sat, files[i].sat) << files[i].path;
    const LsatReduction red = reduce_to_lsat(f);
    const CompiledFormula comp = compile_formula(red.output());
    SolveResult r = solve_discrete(comp.instance);
    ASSERT_EQ(r.stats.engine, "sat");
    ASSERT_NE(r.status, Status::Unknown) << files[i].path;
    ASSERT_EQ(r.status == Status::Yes, sat) << files[i].path;
    if (r.status == Status::Yes) {
      std::vector<bool> a = red.lift_to_source(assignment_from_schedule(comp, r.order));
      EXPECT_EQ(first_falsified_clause(f, a), -1) << files[i].path;
      ++yes;
    }
    ++checked;
  }
  std::printf("[ sat-satlib ] %zu samples (%zu YES) agree with CaDiCaL\n", checked, yes);
}

// The SAT engine and the precedence engine agree on compiled uf20-91
// samples (the precedence engine is too slow for all of uf50 in a test).
TEST(SatEngine, AgreesWithPrecedenceOnUf20) {
  auto files = test::satlib_files();
  const auto want = static_cast<size_t>(test::scaled(10));
  size_t checked = 0;
  for (const auto& file : files) {
    if (checked >= want) break;
    if (file.path.find("/uf20-91/") == std::string::npos) continue;
    Formula f;
    ASSERT_FALSE(read_dimacs_file(file.path, f));
    const Instance inst = compile_formula(reduce_to_lsat(f).output()).instance;
    SolveOptions o;
    o.engine = SolveOptions::Engine::Precedence;
    const Status prec = solve_discrete(inst, o).status;
    o.engine = SolveOptions::Engine::Sat;
    EXPECT_EQ(solve_discrete(inst, o).status, prec) << file.path;
    ++checked;
  }
}

}  // namespace
}  // namespace gridlock
