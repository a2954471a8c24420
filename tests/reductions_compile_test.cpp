// The gadget compiler: sizes, coupling bounds, non-interference of gadgets,
// certificates both ways, and the answer of the reduction on every small
// formula of a sweep.
#include <gtest/gtest.h>

#include <functional>
#include <iostream>
#include <optional>
#include <utility>

#include "cnf/brute_force.hpp"
#include "cnf/dimacs.hpp"
#include "cnf/generate.hpp"
#include "cnf/lsat.hpp"
#include "cnf/sat_solver.hpp"
#include "lattice/simulate.hpp"
#include "reductions/compile.hpp"
#include "reductions/to_lsat.hpp"
#include "solver/gaps.hpp"
#include "solver/solve.hpp"
#include "support/cnf_testing.hpp"
#include "support/contract_search.hpp"
#include "support/same_collision.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

bool order_collides(const CompiledFormula& c, const std::vector<CouplingId>& order) {
  Simulator sim(c.instance);
  return sim.run_order(order).collision.has_value();
}

TEST(Compile, SizesFollowTheFormulas) {
  Rng rng(test::base_seed(11));
  for (int t = 0; t < test::scaled(200); ++t) {
    int n = static_cast<int>(rng.between(1, 12)), m = static_cast<int>(rng.between(0, 15));
    Formula f = test::random_cnf(rng, n, m, 1, 3, false);
    CompiledFormula c = compile_formula(f);
    const auto L = static_cast<int64_t>(num_literals(f));
    SCOPED_TRACE(to_dimacs(f));
    EXPECT_EQ(c.stats.nodes,
              static_cast<size_t>((43 * static_cast<int64_t>(n)) + (5 * L) + (15 * static_cast<int64_t>(m)) - 11));
    EXPECT_EQ(c.stats.edges, c.stats.nodes - 1);  // a tree
    EXPECT_EQ(c.stats.ops, static_cast<size_t>((8 * static_cast<int64_t>(n)) + L + (3 * static_cast<int64_t>(m)) - 2));
    EXPECT_EQ(c.stats.couplings, static_cast<size_t>(4 * n + m));
    EXPECT_EQ(c.stats.rows, static_cast<size_t>(11 * n + 6 * m - 4));
    EXPECT_TRUE(c.instance.horizontal_only());
  }
}

TEST(Compile, EmptyFormulasAndEmptyClauses) {
  CompiledFormula c = compile_formula(test::make_formula(0, {}));
  EXPECT_EQ(c.instance.num_nodes(), 1u);
  EXPECT_EQ(c.instance.couplings().size(), 0u);
  EXPECT_THROW(compile_formula(test::make_formula(2, {{1, 2}, {}})), std::invalid_argument);
  try {
    compile_formula(test::make_formula(2, {{1, 2}, {}}));
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "clause 2 is empty; the reduction needs at least one literal per clause");
  }
}

TEST(Compile, CouplingsOfLsatInputHaveAtMostThreeOperations) {
  for (uint64_t seed = 1; seed <= static_cast<uint64_t>(test::scaled(100)); ++seed) {
    LsatParams p;
    p.n = 12;
    p.min_len = 1;
    p.max_len = 3;
    p.m = lsat_max_clauses(p.n, 1) / 2;
    p.seed = test::base_seed(0) + seed;
    Formula f = random_lsat(p);
    ASSERT_TRUE(is_lsat(f, LsatForm::AtMost3));
    CompiledFormula c = compile_formula(f);
    EXPECT_LE(c.stats.max_coupling, 3u) << "seed " << p.seed;
    EXPECT_TRUE(c.stats.oversize.empty());
  }
  // A literal occurring three times breaks the bound, and is named.
  CompiledFormula c = compile_formula(test::make_formula(2, {{1, 2}, {1, -2}, {1}}));
  EXPECT_EQ(c.stats.max_coupling, 4u);
  ASSERT_EQ(c.stats.oversize.size(), 1u);
  EXPECT_EQ(c.stats.oversize[0], "literal x1 occurs 3 times: coupling x1:F has 4 operations");
}

// Non-interference: on random orders of compiled small formulas, the
// simulator collides exactly when some gadget's contract is broken.
TEST(Compile, GadgetsDoNotInterfere) {
  const uint64_t seed = test::base_seed(2024);
  Rng rng(seed);
  Rng order_rng(seed);
  int colliding = 0, total = 0;
  for (int t = 0; t < test::scaled(300); ++t) {
    int n = static_cast<int>(rng.between(1, 4)), m = static_cast<int>(rng.between(1, 5));
    Formula f = test::random_cnf(rng, n, m, 1, 3, true);
    bool empty = false;
    for (auto& cl : f.clauses) empty = empty || cl.empty();
    if (empty) continue;
    CompiledFormula c = compile_formula(f);
    std::vector<CouplingId> order(c.instance.couplings().size());
    for (CouplingId q = 0; q < order.size(); ++q) order[q] = q;
    for (int r = 0; r < 10; ++r) {
      order_rng.shuffle(order);
      bool got = order_collides(c, order), want = test::order_breaks_contracts(c, order);
      ASSERT_EQ(got, want) << "seed " << seed << " formula\n" << to_dimacs(f);
      colliding += got;
      ++total;
    }
  }
  EXPECT_GT(colliding, 0);
  EXPECT_LT(colliding, total);
}

// Certificates: every assignment's schedule is collision-free iff the
// assignment satisfies the formula, and lifting it back gives the assignment.
TEST(Compile, AssignmentScheduleCertificates) {
  const uint64_t seed = test::base_seed(7);
  Rng rng(seed);
  for (int t = 0; t < test::scaled(150); ++t) {
    int n = static_cast<int>(rng.between(1, 5)), m = static_cast<int>(rng.between(1, 8));
    Formula f = test::random_cnf(rng, n, m, 1, 3, false);
    CompiledFormula c = compile_formula(f);
    for (uint32_t mask = 0; mask < (1u << n); ++mask) {
      std::vector<bool> value(static_cast<size_t>(n) + 1);
      for (int v = 1; v <= n; ++v) value[static_cast<size_t>(v)] = mask >> (v - 1) & 1;
      auto order = schedule_from_assignment(c, value);
      ASSERT_EQ(order_collides(c, order), !satisfies(f, value)) << "seed " << seed << "\n" << to_dimacs(f);
      EXPECT_EQ(assignment_from_schedule(c, order), value);
    }
  }
}

// The reduction's answer on every formula over 3 variables with 1 to 4
// distinct clauses (17 901 formulas; repeating a clause changes nothing):
// a collision-free schedule exists (contract-level search, whose agreement
// with the simulator the tests above establish) iff the formula is
// satisfiable (brute force); every schedule found is collision-free in the
// simulator and lifts to a satisfying assignment; and the exact solver on the
// lattice says NO on every unsatisfiable one and YES (checked) on a spread of
// the satisfiable ones.
TEST(Compile, SmallFormulaSweep) {
  std::vector<std::vector<int>> clauses;  // the 26 non-empty, non-tautological clauses over 3 variables
  for (int mask = 1; mask < 27; ++mask) {
    std::vector<int> cl;
    for (int v = 1, x = mask; v <= 3; ++v, x /= 3)
      if (x % 3) cl.push_back(x % 3 == 1 ? v : -v);
    clauses.push_back(cl);
  }
  ASSERT_EQ(clauses.size(), 26u);
  std::vector<Formula> sweep;
  std::vector<size_t> pick;
  std::function<void(size_t)> grow = [&](size_t from) {
    if (!pick.empty()) {
      Formula f = test::make_formula(3, {});
      for (size_t i : pick) f.clauses.push_back(clauses[i]);
      sweep.push_back(f);
    }
    if (pick.size() == 4) return;
    for (size_t i = from; i < clauses.size(); ++i) {
      pick.push_back(i);
      grow(i + 1);
      pick.pop_back();
    }
  };
  grow(0);
  ASSERT_EQ(sweep.size(), 26u + 325 + 2600 + 14950);
  // Under the sanitizers every k-th formula (all of them at scale 1).
  const size_t step = static_cast<size_t>(std::max(1, 1000 / test::scaled(1000)));
  int sat = 0, unsat = 0, solved = 0;
  for (size_t i = 0; i < sweep.size(); i += step) {
    const Formula& f = sweep[i];
    CompiledFormula c = compile_formula(f);
    std::vector<CouplingId> witness;
    bool yes = test::contract_schedule_exists(c, &witness);
    bool is_sat = exhaustive_sat(f).status == Verdict::Yes;
    ASSERT_EQ(yes, is_sat) << to_dimacs(f);
    if (yes) {
      ++sat;
      ASSERT_FALSE(order_collides(c, witness)) << to_dimacs(f);
      EXPECT_TRUE(satisfies(f, assignment_from_schedule(c, witness))) << to_dimacs(f);
    } else {
      ++unsat;
    }
    if (!is_sat || i % 16 == 0) {
      SolveResult r = solve_discrete(c.instance);
      ASSERT_EQ(r.status, is_sat ? Verdict::Yes : Verdict::No) << to_dimacs(f);
      if (is_sat) {
        EXPECT_TRUE(satisfies(f, assignment_from_schedule(c, r.order))) << to_dimacs(f);
      }
      ++solved;
    }
  }
  EXPECT_GT(unsat, 10);
  EXPECT_GT(sat, 100);
  std::cout << "sweep: " << sat + unsat << " formulas (" << sat << " SAT, " << unsat << " UNSAT), " << solved
            << " solved on the lattice\n";
}

// A few hundred seeded random LSAT<=3 formulas (the reduction's real input):
// the exact solver agrees with CaDiCaL, its schedules lift to satisfying
// assignments, and CaDiCaL's models lift to collision-free schedules.
TEST(Compile, RandomLsatFormulasEndToEnd) {
  const uint64_t seed = test::base_seed(31);
  int sat = 0, unsat = 0;
  for (int t = 0; t < test::scaled(300); ++t) {
    LsatParams p;
    p.n = 3 + t % 8;
    p.min_len = 1;
    p.max_len = 3;
    p.m = std::max(1, lsat_max_clauses(p.n, 1) * (30 + t % 50) / 100);  // sparse to full: SAT and UNSAT
    p.seed = seed + static_cast<uint64_t>(t);
    Formula f = random_lsat(p);
    CompiledFormula c = compile_formula(f);
    SatResult s = solve_sat(f);
    SolveResult r = solve_discrete(c.instance);
    ASSERT_NE(r.status, Verdict::Unknown);
    ASSERT_EQ(r.status == Verdict::Yes, s.status == Verdict::Yes) << "seed " << p.seed << "\n" << to_dimacs(f);
    if (s.status == Verdict::Yes) {
      ++sat;
      EXPECT_TRUE(satisfies(f, assignment_from_schedule(c, r.order))) << "seed " << p.seed;
      EXPECT_FALSE(order_collides(c, schedule_from_assignment(c, s.model))) << "seed " << p.seed;
    } else {
      ++unsat;
    }
  }
  EXPECT_GT(sat, 0);
  EXPECT_GT(unsat, 0);
  std::cout << "random LSAT<=3: " << sat << " SAT, " << unsat << " UNSAT\n";
}

// The continuous model always says YES on a compiled instance (the paper's
// point: continuous time is easy), whatever the formula.
TEST(Compile, ContinuousAlwaysCollisionFree) {
  Rng rng(test::base_seed(5));
  for (int t = 0; t < test::scaled(100); ++t) {
    Formula f = test::random_cnf(rng, static_cast<int>(rng.between(1, 8)), static_cast<int>(rng.between(1, 30)), 1, 3,
                                 false);
    CompiledFormula c = compile_formula(f);
    EXPECT_TRUE(check_gaps(c.instance).collision_free);
    Schedule s;
    s.start.assign(c.instance.couplings().size(), Rational(0));
    EXPECT_FALSE(Simulator(c.instance).run(s).collision.has_value());
  }
}

// A random CNF formula of 1-6 variables and 1-20 clauses, compiled, a third
// of them with a random gadget mutation (the simulator twins' inputs).
struct TwinFormula {
  Formula f;
  Mutation m;
  CompiledFormula c;
};
TwinFormula twin_formula(Rng& rng) {
  Formula f = test::random_cnf(rng, static_cast<int>(rng.between(1, 6)), static_cast<int>(rng.between(1, 20)), 1, 3,
                               false);
  const std::vector<Mutation> mutations = all_mutations();
  const Mutation m = rng.below(3) == 0 ? mutations[rng.below(mutations.size())] : Mutation::None;
  CompiledFormula c = compile_formula(f, m);
  return TwinFormula{std::move(f), m, std::move(c)};
}

// The simulator's row sweep (Simulator::set_row_sweep) on what verify runs:
// compiled formulas (also mutated ones), every coupling at once (the gap
// witness: about half the regions move, collision-free unless a mutation
// breaks it), CaDiCaL's order or a random one, random start times. The same
// runs with the row sweep and with the cell grid.
TEST(SimulatorTwin, RowSweepOnCompiledFormulas) {
  const uint64_t seed0 = test::base_seed(41);
  int clean = 0, collisions = 0, swept_rows = 0;
  const int cases = test::scaled(2000);
  for (int t = 0; t < cases; ++t) {
    const uint64_t seed = seed0 + static_cast<uint64_t>(t);
    SCOPED_TRACE("seed " + std::to_string(seed) + " (replay: GRIDLOCK_TEST_SEED=" + std::to_string(seed) + ")");
    Rng rng(seed);
    const TwinFormula tf = twin_formula(rng);
    const Formula& f = tf.f;
    const Mutation m = tf.m;
    const CompiledFormula& c = tf.c;
    const Instance& inst = c.instance;
    const size_t k = inst.couplings().size();
    std::vector<Schedule> runs(1);
    runs[0].start.assign(k, Rational(0));
    const SatResult sat = solve_sat(f);
    std::vector<CouplingId> order(k);
    for (CouplingId q = 0; q < k; ++q) order[q] = q;
    rng.shuffle(order);
    runs.push_back(schedule_from_order(order));
    if (sat.status == Verdict::Yes) runs.push_back(schedule_from_order(schedule_from_assignment(c, sat.model)));
    Schedule times;
    for (size_t q = 0; q < k; ++q) times.start.push_back(Rational(static_cast<int64_t>(rng.below(7)), 2));
    runs.push_back(times);
    const PreparedInstance prep(inst);
    Simulator rows(prep), grid(prep);
    grid.set_row_sweep(false);
    for (const Schedule& s : runs) {
      const SimResult a = rows.run(s), b = grid.run(s);
      swept_rows += a.stats.row_sweeps > 0;
      ASSERT_EQ(a.collision.has_value(), b.collision.has_value()) << mutation_name(m);
      EXPECT_EQ(a.stats.intervals, b.stats.intervals);
      if (!a.collision) {
        ++clean;
        continue;
      }
      ++collisions;
      test::expect_same_collision(*a.collision, *b.collision);
    }
  }
  EXPECT_GT(clean, cases / 2);
  EXPECT_GT(collisions, cases / 2);
  EXPECT_GT(swept_rows, cases / 2);
  std::cout << "compiled: row sweeps in " << swept_rows << " runs, " << clean << " collision-free, " << collisions
            << " collisions\n";
}

// Simulator::set_reuse_intervals on what verify runs: compiled formulas
// (a third with a random gadget mutation), on one pair of simulators
// rebound from formula to formula (verify's Verifier): the gap witness,
// CaDiCaL's order, two random orders and the first of them again, random
// half-integer times. Results and stats with and without the reuse.
TEST(SimulatorTwin, ReusedIntervalsOnCompiledFormulas) {
  const uint64_t seed0 = test::base_seed(43);
  int clean = 0, collisions = 0, reused = 0;
  const int cases = test::scaled(2000);
  std::optional<Simulator> fast, old;
  for (int t = 0; t < cases; ++t) {
    const uint64_t seed = seed0 + static_cast<uint64_t>(t);
    SCOPED_TRACE("seed " + std::to_string(seed) + " (replay: GRIDLOCK_TEST_SEED=" + std::to_string(seed) + ")");
    Rng rng(seed);
    const TwinFormula tf = twin_formula(rng);
    const size_t k = tf.c.instance.couplings().size();
    std::vector<Schedule> runs(1);
    runs[0].start.assign(k, Rational(0));
    const SatResult sat = solve_sat(tf.f);
    if (sat.status == Verdict::Yes) runs.push_back(schedule_from_order(schedule_from_assignment(tf.c, sat.model)));
    std::vector<CouplingId> order(k);
    for (CouplingId q = 0; q < k; ++q) order[q] = q;
    for (int j = 0; j < 2; ++j) {
      rng.shuffle(order);
      runs.push_back(schedule_from_order(order));
    }
    runs.push_back(runs[runs.size() - 2]);
    Schedule times;
    for (size_t q = 0; q < k; ++q) times.start.push_back(Rational(static_cast<int64_t>(rng.below(7)), 2));
    runs.push_back(times);
    const PreparedInstance prep(tf.c.instance);
    if (!fast) fast.emplace(prep), old.emplace(prep), old->set_reuse_intervals(false);
    fast->rebind(prep), old->rebind(prep);
    for (const Schedule& s : runs) {
      const SimResult a = fast->run(s), b = old->run(s);
      reused += a.stats.reused_intervals > 0;
      ASSERT_EQ(b.stats.reused_intervals, 0u);
      test::expect_same_run(a, b);
      (b.collision ? collisions : clean)++;
    }
  }
  EXPECT_GT(clean, cases / 2);
  EXPECT_GT(collisions, cases / 2);
  EXPECT_GT(reused, cases);
  std::cout << "compiled: reuse in " << reused << " runs, " << clean << " collision-free, " << collisions
            << " collisions\n";
}

// Every mutation of a gadget changes the reduction's answer on some small
// formula: the end-to-end comparison (contract search vs SAT) catches it,
// and on the lattice itself the simulator confirms the wrong answer.
TEST(Compile, EveryMutationIsCaughtEndToEnd) {
  std::vector<Formula> probes = {
      test::make_formula(1, {{1}, {-1}}),                           // UNSAT
      test::make_formula(2, {{1, 2}, {1, -2}, {-1, 2}, {-1, -2}}),  // UNSAT
      test::make_formula(2, {{1, 2}, {-1}, {-2, 1}}),               // UNSAT
      test::make_formula(3, {{1, 2, 3}, {-1}, {-2}}),               // SAT, first clause has one true literal
      test::make_formula(2, {{1, 2}}),                              // SAT
  };
  for (Mutation m : all_mutations()) {
    if (m == Mutation::SeparationLoose)
      continue;  // no separation gadget in the discrete reduction: see
                 // reductions_continuous_test
    SCOPED_TRACE(mutation_name(m));
    bool caught = false;
    for (const Formula& f : probes) {
      CompiledFormula c = compile_formula(f, m);
      std::vector<CouplingId> witness;
      bool yes = test::contract_schedule_exists(c, &witness);
      bool is_sat = exhaustive_sat(f).status == Verdict::Yes;
      if (yes == is_sat) continue;
      caught = true;
      // The simulator agrees with the broken contracts: the wrong answer is real.
      if (yes) {
        EXPECT_FALSE(order_collides(c, witness));
      }
    }
    EXPECT_TRUE(caught);
  }
}

TEST(Compile, SatlibThroughToLsatLiftsToCollisionFreeSchedules) {
  auto files = test::satlib_files();
  int checked = 0;
  for (const auto& file : files) {
    if (!file.sat || file.path.find("uf20-") == std::string::npos) continue;
    if (checked >= test::scaled(100)) break;
    Formula f;
    ASSERT_FALSE(read_dimacs_file(file.path, f));
    LsatReduction red = reduce_to_lsat(f);
    CompiledFormula c = compile_formula(red.output());
    EXPECT_LE(c.stats.max_coupling, 3u);
    SatResult r = solve_sat(f);
    ASSERT_EQ(r.status, Verdict::Yes);
    auto order = schedule_from_assignment(c, red.lift_to_target(r.model));
    ASSERT_FALSE(order_collides(c, order)) << file.path;
    auto back = red.lift_to_source(assignment_from_schedule(c, order));
    EXPECT_TRUE(satisfies(f, back)) << file.path;
    ++checked;
  }
  EXPECT_GT(checked, 0);
}

}  // namespace
}  // namespace gridlock
