// The exact continuous solver (solver/continuous.hpp) against its twin (one
// quantified Z3 formula built straight from region geometry,
// tests/support/reference_continuous.hpp) on seeded random instances of
// every kind, against the discrete solver (a discrete YES is a continuous
// YES) and the gap checker (horizontal-only instances), plus docs/model.md's
// worked cases and hand-made ones.
#include <gtest/gtest.h>

#include <sstream>

#include "bench/bench_families.hpp"
#include "lattice/grid_format.hpp"
#include "lattice/random_instance.hpp"
#include "lattice/simulate.hpp"
#include "solver/continuous.hpp"
#include "solver/gaps.hpp"
#include "solver/internal/constraints.hpp"
#include "solver/internal/continuous_pairs.hpp"
#include "solver/solve.hpp"
#include "support/instance_io.hpp"
#include "support/reference_continuous.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

using Status = Verdict;
using test::load_example;
using test::parse_instance;

std::string text_of(const Instance& inst) {
  std::ostringstream out;
  write_instance(out, inst);
  return out.str();
}

// A YES must come with start times the simulator accepts (solve_continuous
// checks this itself; the test checks it again on its own).
void expect_witness(const Instance& inst, const ContinuousResult& r) {
  ASSERT_EQ(r.schedule.start.size(), inst.couplings().size());
  EXPECT_FALSE(check_schedule_bounds(inst, r.schedule));
  Simulator sim(inst);
  EXPECT_FALSE(sim.run(r.schedule).collision);
}

// --- docs/model.md worked cases ---------------------------------------------

TEST(ContinuousModelCases, Case1TwoGrowthsNoInBothPaths) {
  Instance inst = load_example("model-case1-two-growths.grid");
  EXPECT_EQ(solve_continuous(inst).status, Status::No);
  ContinuousResult g = solve_continuous_general(inst);
  EXPECT_EQ(g.status, Status::No);
  EXPECT_EQ(g.stats.engine, "dl");
  ContinuousResult z = solve_continuous_general(inst, {}, PairEncoding::Auto, ContinuousEngine::Z3);
  EXPECT_EQ(z.status, Status::No);
  EXPECT_EQ(z.stats.engine, "z3");
  EXPECT_EQ(test::reference_continuous(inst), std::optional<bool>(false));
}

TEST(ContinuousModelCases, Case2OrderGadgetBothAtOnce) {
  Instance inst = load_example("model-case2-order-gadget.grid");
  for (const ContinuousResult& r : {solve_continuous(inst), solve_continuous_general(inst)}) {
    ASSERT_EQ(r.status, Status::Yes);
    expect_witness(inst, r);
  }
  // "b then a" collides in discrete time, but both at once do not.
  Schedule both;
  both.start = {Rational(0), Rational(0)};
  EXPECT_FALSE(Simulator(inst).run(both).collision);
  EXPECT_EQ(test::reference_continuous(inst), std::optional<bool>(true));
}

TEST(ContinuousModelCases, Case3CoupledBlockYes) {
  Instance inst = load_example("model-case3-block.grid");
  ContinuousResult r = solve_continuous(inst);
  ASSERT_EQ(r.status, Status::Yes);
  expect_witness(inst, r);
}

const char* kBlockTwoCouplings =
    "p grid 4 4 2 0\n"
    "n 0 0\nn 1 0\nn 0 1\nn 1 1\n"
    "e 0 0 1 0\ne 0 1 1 1\ne 0 0 0 1\ne 1 0 1 1\n"
    "o a expand 0 0 +x\no b expand 0 1 +x\n";

// Continuous YES, discrete NO: the two expansions of the block are separate
// couplings; each alone breaks the cycle, so no order works, but started at
// the same moment they move as one.
TEST(ContinuousModelCases, BlockWithTwoCouplingsIsContinuousYesDiscreteNo) {
  Instance inst = parse_instance(kBlockTwoCouplings);
  EXPECT_EQ(solve_discrete(inst).status, Status::No);
  ContinuousResult r = solve_continuous(inst);
  ASSERT_EQ(r.status, Status::Yes);
  expect_witness(inst, r);
  EXPECT_EQ(r.schedule.start[0], r.schedule.start[1]);
  EXPECT_EQ(test::reference_continuous(inst), std::optional<bool>(true));
}

TEST(ContinuousModelCases, SingleExpansionInBlockIsNo) {
  Instance inst = parse_instance(
      "p grid 4 4 1 0\nn 0 0\nn 1 0\nn 0 1\nn 1 1\n"
      "e 0 0 1 0\ne 0 1 1 1\ne 0 0 0 1\ne 1 0 1 1\no a expand 0 0 +x\n");
  EXPECT_EQ(solve_continuous(inst).status, Status::No);
  EXPECT_EQ(test::reference_continuous(inst), std::optional<bool>(false));
}

// A vertical separation: b's growth into the cell that a's contraction
// empties. b collides iff it starts before a has finished... (checked by the
// twin and the simulator rather than by hand-written times).
TEST(ContinuousModelCases, VerticalSeparationNeedsOrder) {
  // Column (0,0),(0,1) joined; a contracts (0,1) into (0,0) (-y from (0,0)'s
  // view: v = (0,1)); b grows (1,1) into (0,1)... from the right, along -x.
  Instance inst = parse_instance(
      "p grid 4 3 2 0\nn 0 0\nn 0 1\nn 1 0\nn 1 1\n"
      "e 0 0 0 1\ne 0 0 1 0\ne 1 0 1 1\n"
      "o a contract 0 0 +y\no b grow 1 1 -x\n");
  ContinuousResult r = solve_continuous(inst);
  ASSERT_EQ(r.status, Status::Yes);
  expect_witness(inst, r);
  // b starts no earlier than a ends: the simulator confirms that earlier collides.
  EXPECT_GE(r.schedule.start[1] - r.schedule.start[0], Rational(1));
  Schedule early = r.schedule;
  early.start[1] = early.start[0] + Rational(99, 100);
  EXPECT_TRUE(Simulator(inst).run(early).collision);
  EXPECT_EQ(test::reference_continuous(inst), std::optional<bool>(true));
}

// The separation chain (the continuous reduction's t_b >= t_a + 1 in a row):
// the layered candidate settles it without Z3, at times 0, 1, 2, ...; Z3
// with the segment cover agrees, and so does the twin on a short chain.
TEST(ContinuousModelCases, SeparationChainLayered) {
  for (bool rows : {false, true}) {
    Instance inst = bench::separation_chain(40, rows);
    ContinuousResult r = solve_continuous(inst);
    ASSERT_EQ(r.status, Status::Yes);
    expect_witness(inst, r);
    EXPECT_EQ(r.stats.states, 0u);  // no component needed Z3
    for (CouplingId q = 0; q < inst.couplings().size(); ++q)
      EXPECT_EQ(r.schedule.start[q], Rational(static_cast<int64_t>(q)));
  }
  Instance small = bench::separation_chain(6, true);
  ContinuousResult z = solve_continuous_general(small, {}, PairEncoding::Segments);
  EXPECT_EQ(z.status, Status::Yes);
  EXPECT_GT(z.stats.states, 0u);
  EXPECT_EQ(test::reference_continuous(bench::separation_chain(3, false)), std::optional<bool>(true));
}

// Two separation gadgets whose couplings wait for each other (NO, by Z3).
const char* kMutualWait =
    "p grid 9 8 4 2\nn 0 0\nn 0 1\nn 1 0\nn 1 1\nn 2 0\nn 3 0\nn 3 1\nn 4 0\nn 4 1\n"
    "e 0 0 1 0\ne 1 0 2 0\ne 2 0 3 0\ne 3 0 4 0\ne 0 0 0 1\ne 1 0 1 1\ne 3 0 3 1\ne 4 0 4 1\n"
    "o a0 contract 0 0 +y\no b0 grow 1 1 -x\no a1 contract 3 0 +y\no b1 grow 4 1 -x\n"
    "q P a0 b1\nq Q a1 b0\n";

TEST(ContinuousLimits, TimeoutGivesUnknownNeverAWrongAnswer) {
  Instance inst = parse_instance(kMutualWait);
  ContinuousResult full = solve_continuous(inst);
  EXPECT_EQ(full.status, Status::No);
  EXPECT_EQ(full.stats.engine, "dl");
  EXPECT_EQ(solve_continuous(inst, {}, ContinuousEngine::Z3).status, Status::No);
  EXPECT_EQ(solve_continuous_general(inst, {}, PairEncoding::Segments).status, Status::No);
  EXPECT_EQ(test::reference_continuous(inst), std::optional<bool>(false));
  SolveOptions o;
  o.seconds = 1e-9;  // passed before Z3 is asked
  ContinuousResult r = solve_continuous(inst, o);
  EXPECT_EQ(r.status, Status::Unknown);
  EXPECT_TRUE(r.schedule.start.empty());
}

// --max-states bounds Z3's conflicts: a run that needs more stops with
// Unknown; otherwise the answer is the unlimited one.
TEST(ContinuousLimits, MaxStatesBoundsZ3Conflicts) {
  const uint64_t seed0 = test::base_seed(1000);
  int limited = 0;
  for (int i = 0; i < 60; ++i) {  // not scaled: the seeds that need Z3 conflicts are few
    uint64_t seed = seed0 + static_cast<uint64_t>(i);
    RandomInstanceParams p;
    p.nodes = 40, p.ops = 10, p.spread = 2;
    Instance inst = random_instance(p, seed);
    ContinuousResult full = solve_continuous(inst);
    SolveOptions o;
    o.max_states = 1;
    ContinuousResult lim = solve_continuous(inst, o);
    if (lim.status != Status::Unknown) {
      EXPECT_EQ(lim.status, full.status) << "seed " << seed;
      EXPECT_LE(lim.stats.refuted, 1u) << "seed " << seed;
    } else {
      ++limited;
      EXPECT_TRUE(lim.schedule.start.empty());
    }
  }
  EXPECT_GE(limited, 1);
}

// --- Random instances against the twin ----------------------------------

struct Family {
  const char* name;
  RandomInstanceParams p;
};

std::vector<Family> families() {
  std::vector<Family> f;
  RandomInstanceParams p;
  p.nodes = 6, p.ops = 3, p.max_coupling = 1;
  f.push_back({"small-singletons", p});
  p.nodes = 7, p.ops = 4, p.max_coupling = 2;
  f.push_back({"couplings", p});
  p.nodes = 7, p.ops = 4, p.max_coupling = 2, p.extra_edge_percent = 40;
  f.push_back({"cycles", p});
  p = {};
  p.nodes = 8, p.ops = 5, p.max_coupling = 1, p.extra_edge_percent = 15;
  f.push_back({"five-couplings", p});
  p = {};
  p.nodes = 6, p.ops = 4, p.max_coupling = 1, p.allow_grow = false;
  f.push_back({"edge-ops", p});
  p = {};
  p.nodes = 6, p.ops = 4, p.max_coupling = 2, p.allow_contract = false, p.spread = 2;
  f.push_back({"growths-spread", p});
  p = {};
  p.nodes = 7, p.ops = 4, p.max_coupling = 1, p.path_shape = true;
  f.push_back({"paths", p});
  p = {};
  p.nodes = 7, p.ops = 5, p.max_coupling = 2, p.horizontal_only = true, p.extra_edge_percent = 30;
  f.push_back({"horizontal", p});
  return f;
}

TEST(ContinuousRandom, AgreesWithQuantifiedTwin) {
  const uint64_t seed0 = test::base_seed(20261123);
  const int per_family = test::scaled(300);
  int yes = 0, no = 0, skipped = 0;
  for (const Family& fam : families()) {
    for (int i = 0; i < per_family; ++i) {
      uint64_t seed = seed0 + static_cast<uint64_t>(i);
      Instance inst = random_instance(fam.p, seed);
      if (inst.couplings().size() > 5) continue;
      ContinuousResult r = solve_continuous_general(inst);
      std::optional<bool> ref = test::reference_continuous(inst, nullptr, 20000);
      if (!ref) {
        ++skipped;
        continue;
      }
      ASSERT_NE(r.status, Status::Unknown) << fam.name << " seed " << seed;
      ASSERT_EQ(r.status == Status::Yes, *ref) << fam.name << " seed " << seed << " (GRIDLOCK_TEST_SEED replays)\n"
                                               << text_of(inst);
      if (r.status == Status::Yes) {
        expect_witness(inst, r);
        ++yes;
      } else {
        ++no;
      }
      if (inst.horizontal_only()) {
        ASSERT_EQ(solve_continuous(inst).status, r.status) << fam.name << " seed " << seed;
      }
    }
  }
  // Both answers occur, or the comparison would be weak.
  EXPECT_GT(yes, per_family / 4);
  EXPECT_GT(no, per_family / 4);
  EXPECT_LE(skipped, per_family / 50 + 1);
  std::printf("twin agreement: %d YES, %d NO, %d skipped (twin timeout)\n", yes, no, skipped);
}

// The twin's own witnesses go through the simulator too, so that the twin
// cannot agree with the solver by being wrong in the same way on YES.
TEST(ContinuousRandom, TwinWitnessesAreCollisionFree) {
  const uint64_t seed0 = test::base_seed(77);
  RandomInstanceParams p;
  p.nodes = 7, p.ops = 4, p.max_coupling = 2, p.extra_edge_percent = 25;
  int checked = 0;
  for (int i = 0; i < test::scaled(200); ++i) {
    uint64_t seed = seed0 + static_cast<uint64_t>(i);
    Instance inst = random_instance(p, seed);
    Schedule w;
    std::optional<bool> ref = test::reference_continuous(inst, &w, 20000);
    if (!ref || !*ref) continue;
    ++checked;
    Rational lo = w.start.empty() ? Rational(0) : *std::min_element(w.start.begin(), w.start.end());
    for (auto& x : w.start) x = x - lo;
    if (check_schedule_bounds(inst, w)) continue;
    EXPECT_FALSE(Simulator(inst).run(w).collision) << "seed " << seed << "\n" << text_of(inst);
  }
  EXPECT_GT(checked, test::scaled(200) / 10);
}

// A discrete YES gives a continuous YES: start each coupling at its position
// in the order (checked by the simulator), and the solver must say YES too.
TEST(ContinuousRandom, DiscreteYesImpliesContinuousYes) {
  const uint64_t seed0 = test::base_seed(4242);
  int discrete_yes = 0;
  for (const Family& fam : families()) {
    RandomInstanceParams p = fam.p;
    p.nodes += 4, p.ops += 3;  // larger: no twin needed here
    for (int i = 0; i < test::scaled(150); ++i) {
      uint64_t seed = seed0 + static_cast<uint64_t>(i);
      Instance inst = random_instance(p, seed);
      SolveResult d = solve_discrete(inst);
      if (d.status != Status::Yes) continue;
      ++discrete_yes;
      EXPECT_FALSE(Simulator(inst).run(schedule_from_order(d.order)).collision);
      ContinuousResult r = solve_continuous_general(inst);
      ASSERT_EQ(r.status, Status::Yes) << fam.name << " seed " << seed << "\n" << text_of(inst);
      expect_witness(inst, r);
    }
  }
  EXPECT_GT(discrete_yes, test::scaled(150));
}

// The two pair encodings (difference bounds from free_offsets vs the segment
// cover for every pair) agree, on instances larger than the twin's.
TEST(ContinuousRandom, PairEncodingsAgree) {
  const uint64_t seed0 = test::base_seed(31337);
  int yes = 0, no = 0;
  for (const Family& fam : families()) {
    RandomInstanceParams p = fam.p;
    p.nodes += 3, p.ops += 2;
    for (int i = 0; i < test::scaled(100); ++i) {
      uint64_t seed = seed0 + static_cast<uint64_t>(i);
      Instance inst = random_instance(p, seed);
      ContinuousResult a = solve_continuous_general(inst, {}, PairEncoding::Auto);
      ContinuousResult b = solve_continuous_general(inst, {}, PairEncoding::Segments);
      ASSERT_EQ(a.status, b.status) << fam.name << " seed " << seed << "\n" << text_of(inst);
      (a.status == Status::Yes ? yes : no)++;
    }
  }
  EXPECT_GT(yes, test::scaled(100));
  EXPECT_GT(no, test::scaled(100));
}

// free_offsets against the simulator: two couplings, no cycle, coupling 1
// started at offset d (small denominators, and next to every interval end):
// the schedule is collision-free iff d lies in the free offsets of every pair.
TEST(ContinuousPairs, FreeOffsetsMatchTheSimulator) {
  const uint64_t seed0 = test::base_seed(555);
  RandomInstanceParams p;
  p.nodes = 7, p.ops = 3, p.max_coupling = 2;
  int tested = 0, both = 0;
  for (int i = 0; i < test::scaled(400); ++i) {
    uint64_t seed = seed0 + static_cast<uint64_t>(i);
    Instance inst = random_instance(p, seed);
    if (inst.couplings().size() != 2 || !FaceNets::build(inst).faces.empty()) continue;
    SpanningTree tree = SpanningTree::build(inst);
    ConstraintSystem sys = build_pair_constraints(inst, tree);
    std::vector<std::vector<OffsetInterval>> iv;
    std::vector<Rational> probes;
    for (int num = -30; num <= 30; ++num) probes.push_back(Rational(num, 10)), probes.push_back(Rational(num, 7));
    for (auto& c : sys.constraints) {
      if (c.rel.size() != 2) {
        iv.push_back({});  // one coupling: free at every offset or at none
        if (pair_free_at_offset(c, Rational(0))) iv.back().push_back({});
        continue;
      }
      ASSERT_EQ(c.rel[0], 0u);
      iv.push_back(free_offsets(c));
      for (auto& x : iv.back())
        for (auto& e : {x.lo, x.hi})
          if (e)
            probes.push_back(*e), probes.push_back(*e + Rational(1, 1000)), probes.push_back(*e - Rational(1, 1000));
    }
    Simulator sim(inst);
    for (const Rational& d : probes) {
      Schedule s;
      s.start = {Rational(0), d};
      if (d < Rational(0)) s.start = {Rational(0) - d, Rational(0)};
      bool free = true;
      for (auto& ivs : iv) free = free && std::any_of(ivs.begin(), ivs.end(), [&](auto& x) { return x.contains(d); });
      bool sim_free = !sim.run(s).collision;
      ASSERT_EQ(sim_free, free) << "seed " << seed << " offset " << d.str() << "\n" << text_of(inst);
      ++tested;
      both += free;
    }
  }
  EXPECT_GT(tested, test::scaled(400) * 5);
  EXPECT_GT(both, tested / 10);
  EXPECT_LT(both, tested - tested / 10);
}

// Horizontal-only: the general path equals the linear gap checker, also on
// instances far beyond the twin's reach.
TEST(ContinuousRandom, HorizontalEqualsGaps) {
  const uint64_t seed0 = test::base_seed(9001);
  int yes = 0, no = 0;
  for (int i = 0; i < test::scaled(600); ++i) {
    uint64_t seed = seed0 + static_cast<uint64_t>(i);
    RandomInstanceParams p;
    p.horizontal_only = true;
    p.nodes = 6 + static_cast<uint32_t>(i % 20);
    p.ops = 2 + static_cast<uint32_t>(i % 9);
    p.max_coupling = 1 + static_cast<uint32_t>(i % 3);
    p.extra_edge_percent = (i % 4) * 15;
    p.spread = static_cast<uint32_t>(i % 3);
    Instance inst = random_instance(p, seed);
    GapVerdict g = check_gaps(inst);
    ContinuousResult r = solve_continuous_general(inst);
    ASSERT_EQ(r.status, g.collision_free ? Status::Yes : Status::No) << "seed " << seed << "\n" << text_of(inst);
    (g.collision_free ? yes : no)++;
    if (r.status == Status::Yes) expect_witness(inst, r);
  }
  EXPECT_GT(yes, test::scaled(600) / 20);
  EXPECT_GT(no, test::scaled(600) / 20);
}

}  // namespace
}  // namespace gridlock
