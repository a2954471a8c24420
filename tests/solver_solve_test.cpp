// The exact discrete solver against the all-permutations reference (which
// runs every order through the Simulator), on seeded random instances of
// every kind, plus docs/model.md's worked cases and hand-made systems.
#include <gtest/gtest.h>

#include <sstream>

#include "common/random.hpp"
#include "lattice/grid_format.hpp"
#include "lattice/random_instance.hpp"
#include "lattice/simulate.hpp"
#include "solver/gaps.hpp"
#include "solver/internal/constraints.hpp"
#include "solver/internal/search.hpp"
#include "solver/planted.hpp"
#include "solver/solve.hpp"
#include "support/reference_solver.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

std::string write_instance_string(const Instance& inst) {
  std::ostringstream out;
  write_instance(out, inst);
  return out.str();
}

using Status = Verdict;

Instance load(const std::string& name) {
  Instance inst;
  auto err = read_instance_file(std::string(GRIDLOCK_SOURCE_DIR) + "/examples/instances/" + name, inst);
  EXPECT_FALSE(err) << err->str();
  return inst;
}

std::string names(const Instance& inst, const std::vector<CouplingId>& order) {
  std::string s;
  for (CouplingId q : order) s += " " + inst.couplings()[q].name;
  return s;
}

SolveResult solve_with(const Instance& inst, SolveOptions::Engine e) {
  SolveOptions o;
  o.engine = e;
  return solve_discrete(inst, o);
}

// --- docs/model.md worked cases ---------------------------------------------

TEST(SolveModelCases, Case1TwoGrowthsNo) {
  Instance inst = load("model-case1-two-growths.grid");
  SolveResult r = solve_discrete(inst);
  EXPECT_EQ(r.status, Status::No);
  EXPECT_EQ(solve_with(inst, SolveOptions::Engine::States).status, Status::No);
}

TEST(SolveModelCases, Case2OrderGadgetAThenB) {
  Instance inst = load("model-case2-order-gadget.grid");
  for (auto e : {SolveOptions::Engine::Auto, SolveOptions::Engine::States, SolveOptions::Engine::Precedence,
                 SolveOptions::Engine::Sat, SolveOptions::Engine::Pairs}) {
    SolveResult r = solve_with(inst, e);
    ASSERT_EQ(r.status, Status::Yes);
    EXPECT_EQ(names(inst, r.order), " a b");
  }
}

TEST(SolveModelCases, Case3CoupledBlockIsYes) {
  Instance inst = load("model-case3-block.grid");
  SolveResult r = solve_discrete(inst);
  ASSERT_EQ(r.status, Status::Yes);
  EXPECT_EQ(names(inst, r.order), " Q");
}

TEST(SolveModelCases, Case3SingleExpansionBreaksTheCycle) {
  Instance inst;
  std::istringstream in(
      "p grid 4 4 2 0\n"
      "n 0 0\nn 1 0\nn 0 1\nn 1 1\n"
      "e 0 0 1 0\ne 0 1 1 1\ne 0 0 0 1\ne 1 0 1 1\n"
      "o a expand 0 0 +x\no b expand 0 1 +x\n");
  auto err = read_instance(in, "block.grid", inst);
  ASSERT_FALSE(err) << err->str();
  SolveResult r = solve_discrete(inst);
  EXPECT_EQ(r.status, Status::No);
  EXPECT_EQ(r.stats.engine, "cycle");
  ASSERT_NE(r.cycle_breaker, kNone);
  EXPECT_FALSE(test::reference_solve(inst).has_value());
}

TEST(SolveLimits, ZeroBudgetIsUnknown) {
  Instance inst = load("model-case2-order-gadget.grid");
  SolveOptions o;
  o.max_states = 1;
  o.engine = SolveOptions::Engine::States;
  SolveResult r = solve_discrete(inst, o);
  EXPECT_EQ(r.status, Status::Unknown);
  EXPECT_TRUE(r.order.empty());
}

TEST(SolveLimits, PrecedenceOnVerticalInstanceThrows) {
  RandomInstanceParams p;
  p.nodes = 6;
  p.ops = 3;
  for (uint64_t seed = 1; seed < 50; ++seed) {
    Instance inst = random_instance(p, seed);
    if (inst.horizontal_only()) continue;
    SolveOptions o;
    o.engine = SolveOptions::Engine::Precedence;
    EXPECT_THROW(solve_discrete(inst, o), std::invalid_argument);
    o.engine = SolveOptions::Engine::Sat;
    EXPECT_THROW(solve_discrete(inst, o), std::invalid_argument);
    return;
  }
  FAIL() << "no random instance with a vertical operation among seeds 1..49: the test checked nothing";
}

// --- Random instances against the reference ----------------------------

struct Tally {
  int yes = 0, no = 0;
  int no_by_search = 0;  // NO not decided by the cycle test
  int big = 0;           // instances with at least 5 couplings
};

// The pairs engine with every multi-form constraint handled lazily (the
// path constraints of more than eight couplings take), on the instance's
// pair constraints (gap constraints when horizontal-only). A coupling that
// breaks a cycle is NO before any search, as in solve_discrete.
Status pairs_lazy(const Instance& inst) {
  const PreparedInstance prep(inst);
  for (CouplingId q = 0; q < inst.couplings().size(); ++q)
    if (prep.faces.coupling_breaks_cycle[q]) return Status::No;
  const ConstraintSystem sys = inst.horizontal_only() ? build_gap_constraints(prep) : build_pair_constraints(prep);
  SolveOptions o;
  SearchBudget budget(o);
  SolveStats st;
  const SearchOutcome out = search_pairs(sys, budget, st, 0);
  if (out.status == Status::Yes) {
    EXPECT_EQ(replay_order(sys, out.order).failed_step, out.order.size());
    EXPECT_FALSE(Simulator(inst).run_order(out.order).collision);
  }
  return out.status;
}

// One random instance: solve (every applicable engine) vs reference_solve.
void cross_check(const Instance& inst, uint64_t seed, const char* family, Tally& t) {
  auto ref = test::reference_solve(inst);
  std::vector<SolveOptions::Engine> engines = {SolveOptions::Engine::States, SolveOptions::Engine::Pairs};
  if (inst.horizontal_only()) {
    engines.push_back(SolveOptions::Engine::Precedence);
    engines.push_back(SolveOptions::Engine::Sat);
  }
  for (auto e : engines) {
    SolveResult r = solve_with(inst, e);
    ASSERT_EQ(r.status == Status::Yes, ref.has_value())
        << family << " seed " << seed << " engine " << r.stats.engine << ": solver says " << verdict_name(r.status)
        << ", reference says " << (ref ? "YES" + names(inst, *ref) : "NO") << "\n"
        << write_instance_string(inst);
    if (r.status == Status::Yes) {
      Simulator sim(inst);
      ASSERT_FALSE(sim.run_order(r.order).collision) << family << " seed " << seed;
    }
    // The prepared entry point (tables built once, the caller's simulator
    // replaying the YES order) gives the same answer and order.
    const PreparedInstance prep(inst);
    Simulator shared(prep);
    SolveOptions o;
    o.engine = e;
    SolveResult rp = solve_discrete(prep, o, &shared);
    EXPECT_EQ(rp.status, r.status) << family << " seed " << seed;
    EXPECT_EQ(rp.order, r.order) << family << " seed " << seed;
    EXPECT_EQ(rp.stats.states, r.stats.states) << family << " seed " << seed;
  }
  ASSERT_EQ(pairs_lazy(inst) == Status::Yes, ref.has_value()) << family << " seed " << seed << " (pairs, all lazy)";
  (ref ? t.yes : t.no) += 1;
  if (inst.couplings().size() >= 5) ++t.big;
  if (!ref && solve_discrete(inst).stats.engine != "cycle") ++t.no_by_search;
  if (ref && inst.horizontal_only()) {
    // Discrete YES implies continuous YES (run everything at once).
    EXPECT_TRUE(check_gaps(inst).collision_free) << family << " seed " << seed;
    EXPECT_TRUE(test::reference_all_at_once(inst)) << family << " seed " << seed;
  }
}

void run_family(const char* family, RandomInstanceParams p, int count, uint64_t seed0, bool vary) {
  Tally t;
  uint64_t base = test::base_seed(seed0);
  for (int i = 0; i < count; ++i) {
    uint64_t seed = base + static_cast<uint64_t>(i);
    RandomInstanceParams q = p;
    if (vary) {
      Rng rng(seed * 0x9E3779B97F4A7C15ULL + 1);
      q.nodes = 3 + static_cast<uint32_t>(rng.below(p.nodes));
      q.ops = p.ops / 2 + static_cast<uint32_t>(rng.below(p.ops - p.ops / 2 + 1));
      q.max_coupling = 1 + static_cast<uint32_t>(rng.below(p.max_coupling));
    }
    Instance inst = random_instance(q, seed);
    if (inst.couplings().size() > 7) continue;
    cross_check(inst, seed, family, t);
    if (::testing::Test::HasFatalFailure()) return;
  }
  // The families must exercise both answers, or the test proves little.
  EXPECT_GT(t.yes, 0) << family;
  EXPECT_GT(t.no_by_search, 0) << family;
  std::printf("[ %s ] %d instances (%d with >= 5 couplings): %d YES, %d NO (%d by search) (seed %llu)\n", family,
              t.yes + t.no, t.big, t.yes, t.no, t.no_by_search, static_cast<unsigned long long>(base));
}

TEST(SolveRandom, TreesAllKinds) {
  RandomInstanceParams p;
  p.nodes = 12;
  p.ops = 7;
  p.max_coupling = 3;
  run_family("trees", p, test::scaled(1500), 1000, true);
}

TEST(SolveRandom, CyclesAllKinds) {
  RandomInstanceParams p;
  p.nodes = 12;
  p.ops = 7;
  p.max_coupling = 3;
  p.extra_edge_percent = 40;
  run_family("cycles", p, test::scaled(1000), 50000, true);
}

TEST(SolveRandom, SparseShapes) {
  RandomInstanceParams p;
  p.nodes = 14;
  p.ops = 7;
  p.max_coupling = 2;
  p.spread = 3;
  run_family("sparse", p, test::scaled(600), 90000, true);
}

TEST(SolveRandom, HorizontalOnly) {
  RandomInstanceParams p;
  p.nodes = 14;
  p.ops = 7;
  p.max_coupling = 3;
  p.horizontal_only = true;
  run_family("horizontal", p, test::scaled(1500), 120000, true);
}

TEST(SolveRandom, HorizontalCycles) {
  RandomInstanceParams p;
  p.nodes = 14;
  p.ops = 7;
  p.max_coupling = 3;
  p.horizontal_only = true;
  p.extra_edge_percent = 35;
  run_family("horizontal-cycles", p, test::scaled(800), 160000, true);
}

TEST(SolveRandom, HorizontalPaths) {
  RandomInstanceParams p;
  p.nodes = 12;
  p.ops = 7;
  p.max_coupling = 2;
  p.horizontal_only = true;
  p.path_shape = true;
  run_family("horizontal-paths", p, test::scaled(600), 200000, true);
}

// Seven singleton couplings each: 5040 orders for the reference.
TEST(SolveRandom, SevenCouplings) {
  RandomInstanceParams p;
  p.nodes = 10;
  p.ops = 7;
  p.max_coupling = 1;
  run_family("seven", p, test::scaled(400), 300000, false);
}

TEST(SolveRandom, SevenCouplingsHorizontal) {
  RandomInstanceParams p;
  p.nodes = 12;
  p.ops = 7;
  p.max_coupling = 1;
  p.horizontal_only = true;
  run_family("seven-horizontal", p, test::scaled(400), 310000, false);
}

// Larger instances (8-16 couplings, beyond the all-permutations reference):
// the pairs engine (eager and all-lazy) against the states engine, every
// kind of operation, trees and cycles, half of them planted.
TEST(SolveRandomLarge, PairsAgreesWithStates) {
  const uint64_t base = test::base_seed(700000);
  const int count = test::scaled(2000);
  int yes = 0, no = 0, lazy_constraints = 0;
  for (int i = 0; i < count; ++i) {
    const uint64_t seed = base + static_cast<uint64_t>(i);
    Rng rng(seed * 0x9E3779B97F4A7C15ULL + 7);
    RandomInstanceParams p;
    p.nodes = 14 + static_cast<uint32_t>(rng.below(20));
    p.ops = 8 + static_cast<uint32_t>(rng.below(20));
    p.max_coupling = 1 + static_cast<uint32_t>(rng.below(3));
    p.extra_edge_percent = static_cast<uint32_t>(rng.below(3)) * 20;
    p.spread = static_cast<uint32_t>(rng.below(3));
    Instance inst = random_instance(p, seed);
    // Every other instance planted (a YES kept from a random order), so that
    // both answers are common.
    if (i % 2 == 1) inst = plant_schedule(inst, seed).instance;
    if (inst.couplings().size() < 8 || inst.couplings().size() > 16) continue;
    const SolveResult states = solve_with(inst, SolveOptions::Engine::States);
    const SolveResult pairs = solve_with(inst, SolveOptions::Engine::Pairs);
    ASSERT_EQ(pairs.status, states.status) << "seed " << seed << "\n" << write_instance_string(inst);
    ASSERT_EQ(pairs_lazy(inst), states.status) << "seed " << seed << " (all lazy)\n" << write_instance_string(inst);
    (states.status == Status::Yes ? yes : no) += 1;
    if (!inst.horizontal_only()) {
      const ConstraintSystem sys = build_pair_constraints(PreparedInstance(inst));
      for (const CollisionConstraint& c : sys.constraints)
        if (c.num_forms > 1 && c.rel.size() > kPairsEagerLimit) ++lazy_constraints;
    }
  }
  EXPECT_GT(yes, 0);
  EXPECT_GT(no, 0);
  std::printf("[ large ] %d instances: %d YES, %d NO; %d constraints above the eager limit (seed %llu)\n", yes + no,
              yes, no, lazy_constraints, static_cast<unsigned long long>(base));
}

// plant_schedule: the hidden order passes the simulator on the cut
// instance, and the solver agrees that it is YES; sizes as asked.
TEST(Planted, HiddenOrderIsCollisionFree) {
  const uint64_t base = test::base_seed(740000);
  for (int i = 0; i < test::scaled(100); ++i) {
    const uint64_t seed = base + static_cast<uint64_t>(i);
    RandomFamilyParams f;
    f.family = static_cast<ShapeFamily>(i % 5);
    f.couplings = 5 + static_cast<uint32_t>(i % 20);
    f.max_coupling = 1 + static_cast<uint32_t>(i % 3);
    const PlantedInstance p = planted_family_instance(f, seed);
    const Instance& inst = p.instance;
    ASSERT_EQ(p.hidden_order.size(), inst.couplings().size()) << "seed " << seed;
    EXPECT_LE(inst.couplings().size(), f.couplings) << "seed " << seed;
    std::vector<CouplingId> order;
    for (const std::string& n : p.hidden_order) order.push_back(inst.find_coupling(n));
    Simulator sim(inst);
    ASSERT_FALSE(sim.run_order(order).collision) << "seed " << seed << "\n" << write_instance_string(inst);
    EXPECT_EQ(solve_discrete(inst).status, Status::Yes) << "seed " << seed;
  }
  std::printf("[ planted ] %d instances (seed %llu)\n", test::scaled(100), static_cast<unsigned long long>(base));
}

}  // namespace
}  // namespace gridlock
