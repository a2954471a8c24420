// The continuous reduction (compile_formula with TimeModel::Continuous):
// sizes, non-interference of the gadgets in continuous time (the simulator
// collides iff some gadget's continuous contract breaks), certificates both
// ways, and the broken separation gadget changing the answer for real.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "cnf/brute_force.hpp"
#include "cnf/dimacs.hpp"
#include "cnf/formula.hpp"
#include "cnf/generate.hpp"
#include "lattice/simulate.hpp"
#include "reductions/compile.hpp"
#include "solver/continuous.hpp"
#include "support/cnf_testing.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

constexpr TimeModel kCont = TimeModel::Continuous;

bool collides(const CompiledFormula& c, const Schedule& s) {
  return Simulator(c.instance).run(s).collision.has_value();
}

// Some gadget's continuous contract breaks under s.
bool breaks_contracts(const CompiledFormula& c, const Schedule& s) {
  std::map<std::string, Rational> start;
  for (const Operation& op : c.instance.ops()) start[op.name] = s.start[op.coupling];
  for (const GadgetPlacement& g : c.gadgets)
    if (g.contract.collides_continuous(start)) return true;
  return false;
}

std::vector<bool> assignment_of(int n, uint32_t mask) {
  std::vector<bool> v(static_cast<size_t>(n) + 1, false);
  for (int i = 1; i <= n; ++i) v[static_cast<size_t>(i)] = (mask >> (i - 1)) & 1;
  return v;
}

TEST(CompileContinuous, SizesFollowTheFormulas) {
  const uint64_t seed = test::base_seed(21);
  Rng rng(seed);
  for (int t = 0; t < test::scaled(200); ++t) {
    int n = static_cast<int>(rng.between(1, 12)), m = static_cast<int>(rng.between(0, 15));
    Formula f = test::random_cnf(rng, n, m, 1, 3, false);
    CompiledFormula c = compile_formula(f, Mutation::None, kCont);
    const auto L = static_cast<int64_t>(num_literals(f));
    SCOPED_TRACE("seed " + std::to_string(seed) + "\n" + to_dimacs(f));
    EXPECT_EQ(c.model, kCont);
    EXPECT_EQ(c.stats.nodes,
              static_cast<size_t>((43 * static_cast<int64_t>(n)) + (5 * L) + (15 * static_cast<int64_t>(m)) - 9));
    EXPECT_EQ(c.stats.edges, c.stats.nodes - 1);  // a tree
    EXPECT_EQ(c.stats.ops, static_cast<size_t>((8 * static_cast<int64_t>(n)) + L + (3 * static_cast<int64_t>(m)) - 2));
    EXPECT_EQ(c.stats.couplings, static_cast<size_t>(4 * n + m));
    EXPECT_EQ(c.stats.rows, static_cast<size_t>(11 * n + 6 * m - 4));
    EXPECT_EQ(c.stats.separation_gadgets, 1u);
    EXPECT_EQ(c.stats.order_gadgets, static_cast<size_t>(2 * n + m - 2));
    EXPECT_EQ(c.stats.vertical_ops, 1u);
    EXPECT_FALSE(c.instance.horizontal_only());
    // The discrete compile is unchanged by the new model.
    CompiledFormula d = compile_formula(f);
    EXPECT_EQ(d.stats.nodes, c.stats.nodes - 2);
    EXPECT_EQ(d.stats.vertical_ops, 0u);
    EXPECT_TRUE(d.instance.horizontal_only());
  }
  CompiledFormula empty = compile_formula(test::make_formula(0, {}), Mutation::None, kCont);
  EXPECT_EQ(empty.instance.num_nodes(), 1u);
  EXPECT_EQ(empty.stats.separation_gadgets, 0u);
}

// The point of the separation: running everything at once no longer works
// (it does in the discrete reduction's instance, for every formula).
TEST(CompileContinuous, EverythingAtOnceCollides) {
  Rng rng(test::base_seed(22));
  for (int t = 0; t < test::scaled(50); ++t) {
    Formula f = test::random_cnf(rng, static_cast<int>(rng.between(1, 6)), static_cast<int>(rng.between(0, 10)), 1, 3,
                                 false);
    Schedule s;
    s.start.assign(4 * static_cast<size_t>(f.num_vars) + f.clauses.size(), Rational(0));
    EXPECT_TRUE(collides(compile_formula(f, Mutation::None, kCont), s));
    EXPECT_FALSE(collides(compile_formula(f), s));
  }
}

// Non-interference in continuous time: on random start times (the canonical
// schedule of a random assignment, each start moved by a random multiple of
// 1/4 in [-1, 1], or fully random multiples of 1/2 in [0, 4]) the simulator
// collides iff some gadget's continuous contract breaks.
TEST(CompileContinuous, GadgetsDoNotInterfere) {
  const uint64_t seed = test::base_seed(23);
  Rng rng(seed);
  int colliding = 0, free = 0;
  for (int t = 0; t < test::scaled(3000); ++t) {
    int n = static_cast<int>(rng.between(1, 4));
    Formula f = test::random_cnf(rng, n, static_cast<int>(rng.between(1, 5)), 1, 3, false);
    CompiledFormula c = compile_formula(f, Mutation::None, kCont);
    Schedule s;
    if (rng.coin()) {
      s = times_from_assignment(c, assignment_of(n, static_cast<uint32_t>(rng.below(1u << n))));
      const int moved = static_cast<int>(rng.between(0, 3));
      for (int k = 0; k < moved; ++k) {
        auto q = static_cast<size_t>(rng.below(s.start.size()));
        s.start[q] = s.start[q] + Rational(rng.between(-4, 4), 4);
      }
    } else {
      s.start.resize(c.instance.couplings().size());
      for (auto& x : s.start) x = Rational(rng.between(0, 8), 2);
    }
    const bool got = collides(c, s);
    ASSERT_EQ(got, breaks_contracts(c, s)) << "seed " << seed << " case " << t << "\n" << to_dimacs(f);
    (got ? colliding : free)++;
  }
  EXPECT_GT(colliding, 0);
  EXPECT_GT(free, 0);
}

// Assignment -> start times, for every assignment of random small formulas:
// collision-free iff the assignment satisfies the formula, and the times lift
// back to the assignment.
TEST(CompileContinuous, EveryAssignmentsScheduleAndBack) {
  const uint64_t seed = test::base_seed(24);
  Rng rng(seed);
  for (int t = 0; t < test::scaled(150); ++t) {
    int n = static_cast<int>(rng.between(1, 5));
    Formula f = test::random_cnf(rng, n, static_cast<int>(rng.between(1, 8)), 1, 3, false);
    CompiledFormula c = compile_formula(f, Mutation::None, kCont);
    Simulator sim(c.instance);
    for (uint32_t mask = 0; mask < (1u << n); ++mask) {
      std::vector<bool> v = assignment_of(n, mask);
      Schedule s = times_from_assignment(c, v);
      const bool free = !sim.run(s).collision;
      ASSERT_EQ(free, satisfies(f, v)) << "seed " << seed << " mask " << mask << "\n" << to_dimacs(f);
      EXPECT_EQ(assignment_from_times(c, s), v);
    }
  }
}

// Start times -> assignment on collision-free schedules that are not the
// canonical ones: jittered canonical schedules that the simulator accepts
// lift to satisfying assignments (the half-setting argument at work).
TEST(CompileContinuous, CollisionFreeTimesLiftToSatisfyingAssignments) {
  const uint64_t seed = test::base_seed(25);
  Rng rng(seed);
  int lifted = 0;
  for (int t = 0; t < test::scaled(2000); ++t) {
    int n = static_cast<int>(rng.between(1, 4));
    Formula f = test::random_cnf(rng, n, static_cast<int>(rng.between(1, 5)), 1, 3, false);
    CompiledFormula c = compile_formula(f, Mutation::None, kCont);
    Schedule s = times_from_assignment(c, assignment_of(n, static_cast<uint32_t>(rng.below(1u << n))));
    for (auto& x : s.start) x = x * Rational(2) + Rational(rng.between(-3, 3), 3);
    if (collides(c, s)) continue;
    ++lifted;
    EXPECT_TRUE(satisfies(f, assignment_from_times(c, s))) << "seed " << seed << " case " << t << "\n" << to_dimacs(f);
  }
  EXPECT_GT(lifted, 0);
}

// The broken separation gadget lets an unsatisfiable formula through:
// "everything at time 0" is collision-free on the simulator.
TEST(CompileContinuous, LooseSeparationChangesTheAnswer) {
  Formula f = test::make_formula(1, {{1}, {-1}});
  ASSERT_EQ(exhaustive_sat(f).status, Verdict::No);
  CompiledFormula bad = compile_formula(f, Mutation::SeparationLoose, kCont);
  Schedule s;
  s.start.assign(bad.instance.couplings().size(), Rational(0));
  EXPECT_FALSE(collides(bad, s));
  EXPECT_TRUE(collides(compile_formula(f, Mutation::None, kCont), s));
}

}  // namespace
}  // namespace gridlock

namespace gridlock {
namespace {

// The exact continuous solver on compiled formulas: every formula over one
// variable, and every formula over two variables with 1 to 4 distinct
// clauses (162; every 5th under the sanitizers). The answer is the
// formula's, a YES's start times pass the simulator and lift to a satisfying
// assignment. (The three-variable sweep runs through `gridlock verify
// --model continuous`, docs/verify.md.)
TEST(CompileContinuous, ExactContinuousSolverOnEveryTwoVariableFormula) {
  std::vector<std::vector<int>> clauses;  // the 8 non-empty, non-tautological clauses over 2 variables
  for (int mask = 1; mask < 9; ++mask) {
    std::vector<int> cl;
    for (int v = 1, x = mask; v <= 2; ++v, x /= 3)
      if (x % 3) cl.push_back(x % 3 == 1 ? v : -v);
    clauses.push_back(cl);
  }
  std::vector<Formula> sweep = {test::make_formula(1, {{1}}), test::make_formula(1, {{-1}}),
                                test::make_formula(1, {{1}, {-1}})};
  std::vector<Formula> two;
  for (uint32_t set = 1; set < 256; ++set) {
    if (__builtin_popcount(set) > 4) continue;
    Formula f = test::make_formula(2, {});
    for (size_t i = 0; i < 8; ++i)
      if (set >> i & 1) f.clauses.push_back(clauses[i]);
    two.push_back(f);
  }
  ASSERT_EQ(two.size(), 162u);
  const size_t step = static_cast<size_t>(std::max(1, 1000 / test::scaled(1000)));
  for (size_t i = 0; i < two.size(); i += step) sweep.push_back(two[i]);
  int yes = 0, no = 0;
  for (const Formula& f : sweep) {
    SCOPED_TRACE(to_dimacs(f));
    CompiledFormula c = compile_formula(f, Mutation::None, kCont);
    const bool is_sat = exhaustive_sat(f).status == Verdict::Yes;
    ContinuousResult r = solve_continuous(c.instance);
    ASSERT_NE(r.status, Verdict::Unknown);
    ASSERT_EQ(r.status == Verdict::Yes, is_sat);
    if (is_sat) {
      ++yes;
      EXPECT_FALSE(collides(c, r.schedule));
      EXPECT_TRUE(satisfies(f, assignment_from_times(c, r.schedule)));
    } else {
      ++no;
    }
  }
  EXPECT_GT(yes, 0);
  EXPECT_GT(no, 0);
}

}  // namespace
}  // namespace gridlock
