// One coupling: the space-time cell sweep (collide/single_coupling.hpp)
// against its twins on seeded random instances with every operation in one
// coupling: the exact Simulator running the one schedule (independent
// code: its own broad phase and first-collision test), the all-pairs
// exact test, and, on tiny instances, the brute-force Colliding Schedule
// reference (tests/support/reference_collide). Failures print the seed
// (GRIDLOCK_TEST_SEED replays, GRIDLOCK_TEST_SCALE scales the count).
#include <gtest/gtest.h>

#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bench/bench_families.hpp"
#include "collide/adversarial.hpp"
#include "collide/collide.hpp"
#include "collide/single_coupling.hpp"
#include "common/random.hpp"
#include "lattice/random_instance.hpp"
#include "lattice/rational.hpp"
#include "lattice/schedule.hpp"
#include "lattice/simulate.hpp"
#include "support/instance_io.hpp"
#include "support/reference_collide.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

// The same shape and operations with every operation in one coupling "Q";
// with `transpose`, x and y swapped.
Instance one_coupling(const Instance& inst, bool transpose = false) { return test::rebuilt(inst, transpose, true); }

RandomInstanceParams single_params(Rng& rng) {
  RandomInstanceParams p;
  p.nodes = 2 + static_cast<uint32_t>(rng.below(rng.below(4) == 0 ? 60 : 14));
  p.ops = 1 + static_cast<uint32_t>(rng.below(p.nodes));
  p.extra_edge_percent = rng.below(4) == 0 ? 30 : 0;
  p.horizontal_only = rng.below(8) == 0;
  p.path_shape = rng.below(3) == 0;
  p.spread = static_cast<uint32_t>(rng.below(3));
  p.allow_contract = rng.below(3) != 0;
  p.allow_grow = rng.below(3) != 0;
  return p;
}

struct Tally {
  int cases = 0, yes = 0, no = 0, brute = 0, cycles = 0, by_packing = 0, multi_band = 0, first_named = 0, pruned = 0;
  int fixed_no = 0, fixed_yes = 0, fixed_y = 0;  // decided by single_coupling_fixed_axis (y: the kept axis is y)
  uint64_t fixed_sweeps = 0;                     // its sweeps on the YES (bisecting for the first moment)
  int fixed_named = 0;                           // its YES equal to the simulator's first collision, pair too
  int separated_no = 0, separated_yes = 0;       // of those, decided in several separated groups
  int classes_no = 0, classes_yes = 0;           // decided by motion classes, the whole set one class group
  int class_groups = 0;                          // with the cuts: some piece left to motion classes
  uint64_t classes_rounds = 0;                   // rounds of the classes' YES (bisecting for the first moment)
  int slabs_no = 0, slabs_yes = 0;               // decided by time slabs
  int slabs_split = 0;                           // of those, with some piece split in time
  int slabs8_no = 0, slabs8_yes = 0;             // decided by time slabs started from 8 slabs
  int slabs_named = 0;                           // their YES reported by find_collision, named as the simulator does
  uint64_t max_active = 0;
};

// A named YES: pair, first and during are set, first < during < 1, and
// the pair overlaps at `during` in the simulator's own configuration.
void expect_overlaps_during(const Instance& inst, const SingleCouplingAnswer& ans, const std::string& where) {
  ASSERT_TRUE(ans.pair && ans.first && ans.during) << where;
  ASSERT_LT(ans.pair->a, ans.pair->b) << where;
  ASSERT_LE(Rational(0), *ans.first) << where;
  ASSERT_LT(*ans.first, *ans.during) << where;
  ASSERT_LT(*ans.during, Rational(1)) << where;
  const std::vector<RectQ> at = configuration_at(inst, schedule_from_order({0}), *ans.during);
  const RectQ &A = at[ans.pair->a], &B = at[ans.pair->b];
  ASSERT_LT(std::max(A.xlo, B.xlo), std::min(A.xhi, B.xhi)) << where;
  ASSERT_LT(std::max(A.ylo, B.ylo), std::min(A.yhi, B.yhi)) << where;
}

// `ans` names the simulator's first collision `c` of the one schedule:
// the same moment and pair (the smallest on ties), and the pair overlaps
// at `during` in the simulator's own configuration.
void expect_names_first(const Instance& inst, const SingleCouplingAnswer& ans, const Collision& c,
                        const std::string& where) {
  expect_overlaps_during(inst, ans, where);
  if (::testing::Test::HasFatalFailure()) return;
  ASSERT_EQ(c.kind, Collision::Kind::Node) << where;
  ASSERT_EQ(*ans.first, c.time) << where;
  ASSERT_EQ(ans.pair->a, c.a) << where;
  ASSERT_EQ(ans.pair->b, c.b) << where;
}

// A faster method's answer `got` against the cell sweep's `swept`: the
// same verdict; a YES's pair overlaps at its `during`, and when the sweep
// names its first collision, got names the same moment and pair.
void expect_sweeps_answer(const Instance& inst, const SingleCouplingAnswer& got, const SingleCouplingAnswer& swept,
                          const std::string& how) {
  ASSERT_EQ(got.collides, swept.collides) << how;
  if (!swept.collides) return;
  expect_overlaps_during(inst, got, how);
  if (::testing::Test::HasFatalFailure() || !swept.pair) return;
  ASSERT_EQ(*got.first, *swept.first) << how;
  ASSERT_EQ(got.pair->a, swept.pair->a) << how;
  ASSERT_EQ(got.pair->b, swept.pair->b) << how;
}

// Sweep, all pairs and the simulator (all operations from t = 0) agree on
// whether a node collision happens, and the sweep names the simulator's
// first collision; find_collision agrees with the brute reference on tiny
// instances.
void check_instance(const Instance& inst, const std::string& where, Tally& tally) {
  Simulator sim(inst);
  SingleCouplingStats st;
  const SingleCouplingAnswer ans = single_coupling_sweep(inst, sim.tree(), sim.regions(), &st);
  const bool sweep = ans.collides;
  const auto pairs = single_coupling_pairwise(inst, sim.tree(), sim.regions());
  ASSERT_EQ(sweep, pairs.has_value()) << where;
  (sweep ? tally.yes : tally.no)++;
  ++tally.cases;
  // When one axis keeps its order: the same verdict as the pair tests, a
  // YES's pair overlaps at `during`, and its first moment is the sweep's.
  const std::optional<FixedAxisAnswer> fixed = single_coupling_fixed_axis(inst, sim.tree(), sim.regions());
  if (fixed) {
    ASSERT_EQ(fixed->answer.collides, sweep) << where << ": the fixed-axis sweep along axis " << fixed->axis;
    if (sweep) {
      expect_overlaps_during(inst, fixed->answer, where + ", the fixed-axis sweep");
      if (::testing::Test::HasFatalFailure()) return;
      if (ans.first) {
        ASSERT_EQ(*fixed->answer.first, *ans.first) << where << ", the fixed-axis sweep";
      }
      ++tally.fixed_yes;
      tally.fixed_sweeps += fixed->sweeps;
    } else {
      ASSERT_EQ(fixed->sweeps, 1u) << where;
      ++tally.fixed_no;
    }
    tally.fixed_y += fixed->axis == 1;
    if (fixed->groups > 1) (sweep ? tally.separated_yes : tally.separated_no)++;
  }
  // Motion classes: with the whole live set as one class group (every
  // class pair asked, whatever the cost), and with the cuts and kept-order
  // sweeps first. The same verdict; a YES's pair overlaps.
  for (bool whole : {true, false}) {
    const std::string how = where + (whole ? ", motion classes (one group)" : ", motion classes");
    const std::optional<MotionClassAnswer> mc = single_coupling_motion_classes(inst, sim.tree(), sim.regions(), nullptr,
                                                                               whole, true);
    if (!mc) continue;
    // The first collision, as the cell sweep names it (the simulator's:
    // checked against it below).
    expect_sweeps_answer(inst, mc->answer, ans, how);
    if (::testing::Test::HasFatalFailure()) return;
    if (sweep) {
      tally.classes_rounds += mc->sweeps;
    } else {
      ASSERT_EQ(mc->sweeps, 1u) << how;
    }
    if (whole) (sweep ? tally.classes_yes : tally.classes_no)++;
    if (!whole) tally.class_groups += mc->class_groups > 0;
  }
  // Time slabs: the same verdict; a YES names the cell sweep's first
  // collision (pair and moment). With Auto's budget (-1), whatever their
  // cost (the budget declines most small instances, whose motion is
  // small), and started from 4 and 8 slabs, so that every instance is cut
  // over slabs (the rescaled faces, the slabs' order, the first moment
  // mapped back).
  const std::optional<TimeSlabAnswer> slabs = single_coupling_time_slabs(inst, sim.tree(), sim.regions());
  for (int first_exp : {-1, 0, 2, 3}) {
    const std::optional<TimeSlabAnswer> ts = first_exp < 0 ? slabs
                                                           : single_coupling_time_slabs(inst, sim.tree(), sim.regions(),
                                                                                        nullptr, first_exp, true);
    if (!ts) continue;
    const std::string how = where + (first_exp < 0 ? std::string(", time slabs (Auto's budget)")
                                                   : ", time slabs from 2^" + std::to_string(first_exp));
    expect_sweeps_answer(inst, ts->answer, ans, how);
    if (::testing::Test::HasFatalFailure()) return;
    if (first_exp == 0) (sweep ? tally.slabs_yes : tally.slabs_no)++;
    if (first_exp == 0) tally.slabs_split += ts->finest > 0;
    if (first_exp == 3) (sweep ? tally.slabs8_yes : tally.slabs8_no)++;
  }
  tally.max_active = std::max<uint64_t>(tally.max_active, st.max_active);
  // Bounded memory: sweeping in column bands of a few items gives the
  // same answer, pair included, with the same items and tests.
  for (uint64_t band : {uint64_t{1}, uint64_t{3}, uint64_t{17}}) {
    SingleCouplingStats sb;
    const SingleCouplingAnswer banded = single_coupling_sweep(inst, sim.tree(), sim.regions(), &sb, nullptr, band);
    ASSERT_EQ(banded.collides, ans.collides) << where << ", band " << band;
    ASSERT_EQ(banded.pair.has_value(), ans.pair.has_value()) << where << ", band " << band;
    if (ans.pair) {
      ASSERT_EQ(banded.pair->a, ans.pair->a) << where << ", band " << band;
      ASSERT_EQ(banded.pair->b, ans.pair->b) << where << ", band " << band;
      ASSERT_EQ(banded.first, ans.first) << where << ", band " << band;
      ASSERT_EQ(banded.during, ans.during) << where << ", band " << band;
    }
    if (!ans.collides || ans.pair) {  // the same cells entered in the same order, whatever the bands
      ASSERT_EQ(sb.tests, st.tests) << where << ", band " << band;
      // Items that start after an overlap found in an earlier band are
      // not kept (the default here is one band: all of them are).
      if (ans.collides) {
        ASSERT_LE(sb.items, st.items) << where << ", band " << band;
        tally.pruned += sb.items < st.items;
      } else {
        ASSERT_EQ(sb.items, st.items) << where << ", band " << band;
      }
    }
    ASSERT_LE(sb.peak_items, st.peak_items) << where << ", band " << band;
    tally.multi_band += sb.bands > 1;
  }
  if (ans.pair) {
    expect_overlaps_during(inst, ans, where);
    if (::testing::Test::HasFatalFailure()) return;
  } else {
    tally.by_packing += sweep;
  }
  Schedule s;
  s.start.assign(inst.couplings().size(), Rational(0));
  if (sim.faces().faces.empty()) {
    const SimResult run = sim.run(s);
    ASSERT_EQ(sweep, run.collision.has_value()) << where;
    if (ans.pair) {
      expect_names_first(inst, ans, *run.collision, where);
      if (::testing::Test::HasFatalFailure()) return;
      ++tally.first_named;
      if (inst.couplings().size() == 1) {  // find_collision reports it, checked at one moment
        const CollideResult r = find_collision(inst, TimeModel::Continuous);
        // The simulator's first collision, its pair too.
        if (r.algorithm == "single-coupling-fixed-axis" || r.algorithm == "single-coupling-separated") {
          ASSERT_TRUE(fixed) << where;
          expect_names_first(inst, fixed->answer, *run.collision, where + ", the fixed-axis sweep");
          if (::testing::Test::HasFatalFailure()) return;
          ASSERT_EQ(r.checked_at, fixed->answer.during) << where;
          ASSERT_EQ(r.simulated->time, run.collision->time) << where;
          ASSERT_EQ(r.simulated->a, run.collision->a) << where;
          ASSERT_EQ(r.simulated->b, run.collision->b) << where;
          ++tally.fixed_named;
        }
        if (r.algorithm == "single-coupling-time-slabs") {
          ASSERT_TRUE(slabs) << where;
          expect_names_first(inst, slabs->answer, *run.collision, where + ", time slabs");
          if (::testing::Test::HasFatalFailure()) return;
          ASSERT_EQ(r.checked_at, slabs->answer.during) << where;
          ASSERT_EQ(r.simulated->time, run.collision->time) << where;
          ++tally.slabs_named;
        }
        if (r.algorithm == "single-coupling") {
          ASSERT_EQ(r.checked_at, ans.during) << where;
          ASSERT_EQ(r.simulated->time, run.collision->time) << where;
          ASSERT_EQ(r.simulated->a, run.collision->a) << where;
          ASSERT_EQ(r.simulated->b, run.collision->b) << where;
          ASSERT_EQ(r.simulated->moving, run.collision->moving) << where;
        }
      }
    }
  } else {
    ++tally.cycles;
  }
  if (inst.couplings().size() != 1) return;
  const CollideResult r = find_collision(inst, TimeModel::Continuous);  // throws if a YES witness fails
  ASSERT_EQ(r.collides, sweep || !sim.faces().faces.empty()) << where;
  if (inst.num_nodes() <= 10) {
    ASSERT_EQ(test::brute_continuous(inst).collides, r.collides) << where;
    ASSERT_EQ(find_collision(inst, TimeModel::Discrete).collides, r.collides) << where;
    ++tally.brute;
  }
}

TEST(SingleCouplingSweep, AgreesWithTwinsOnRandomInstances) {
  const uint64_t seed0 = test::base_seed(25000);
  const int cases = test::scaled(3000);
  Tally tally;
  for (int i = 0; i < cases; ++i) {
    const uint64_t seed = seed0 + static_cast<uint64_t>(i);
    Rng rng(seed * 104729 + 3);
    const RandomInstanceParams p = single_params(rng);
    const Instance inst = one_coupling(random_instance(p, seed));
    const std::string where = "seed " + std::to_string(seed) + " (nodes " + std::to_string(p.nodes) + ", ops " +
                              std::to_string(p.ops) + "); replay with GRIDLOCK_TEST_SEED=" + std::to_string(seed);
    check_instance(inst, where, tally);
    if (::testing::Test::HasFatalFailure()) return;
  }
  std::cout << "[ info ] " << tally.cases << " instances (" << tally.yes << " node collisions, " << tally.no
            << " none; " << tally.cycles << " with a cycle net; " << tally.brute << " against the brute reference; "
            << tally.by_packing << " decided by the packing bound; " << tally.first_named
            << " first collisions equal to the simulator's; most items present at an entry " << tally.max_active << "; "
            << tally.multi_band << " banded sweeps of several bands, " << tally.pruned
            << " of them keeping fewer items after an overlap; one axis keeping its order: " << tally.fixed_no
            << " NOs and " << tally.fixed_yes << " YES (" << tally.fixed_sweeps << " sweeps, " << tally.fixed_named
            << " named as the simulator does through find_collision), " << tally.fixed_y << " of them along y; "
            << tally.separated_no << " NOs and " << tally.separated_yes
            << " YES in several separated groups; motion classes on the whole set: " << tally.classes_no << " NOs and "
            << tally.classes_yes << " YES (" << tally.classes_rounds << " rounds), " << tally.class_groups
            << " instances with a piece left to them after the cuts; time slabs: " << tally.slabs_no << " NOs and "
            << tally.slabs_yes << " YES, " << tally.slabs_split << " of them split in time, " << tally.slabs_named
            << " YES named through find_collision; started from 8 slabs: " << tally.slabs8_no << " NOs and "
            << tally.slabs8_yes << " YES)\n";
  // Both answers occur often, or the comparison proves little.
  EXPECT_GT(tally.yes, cases / 10);
  EXPECT_GT(tally.multi_band, cases);  // most instances take several bands at band sizes 1, 3, 17
  EXPECT_GT(tally.first_named, cases / 10);
  EXPECT_GT(tally.pruned, cases / 20);
  EXPECT_GT(tally.no, cases / 10);
  EXPECT_GT(tally.fixed_no, cases / 10);
  EXPECT_GT(tally.fixed_yes, cases / 20);
  EXPECT_GT(tally.fixed_named, cases / 20);
  EXPECT_GT(tally.fixed_y, cases / 50);
  EXPECT_GT(tally.separated_no, cases / 300);
  EXPECT_GT(tally.separated_yes, cases / 100);
  EXPECT_GT(tally.classes_no + tally.classes_yes, cases * 9 / 10);  // whole-set classes seldom decline
  EXPECT_GT(tally.classes_no, cases / 10);
  EXPECT_GT(tally.classes_yes, cases / 10);
  EXPECT_GT(tally.class_groups, cases / 100);
  EXPECT_GT(tally.slabs_split, cases / 200);
  EXPECT_GT(tally.slabs_named, 0);
  EXPECT_GT(tally.slabs8_no, cases / 2);
  EXPECT_GT(tally.slabs8_yes, cases / 5);
}

// Time slabs on random stalactite combs: the same twins as on the random
// instances (the cell sweep, every pair, the simulator, the brute
// reference on the tiny ones), where most pieces must be split in time.
TEST(SingleCouplingTimeSlabs, AgreesWithTwinsOnRandomStalactiteCombs) {
  const uint64_t seed0 = test::base_seed(29000);
  const int cases = test::scaled(1500);
  Tally tally;
  for (int i = 0; i < cases; ++i) {
    const uint64_t seed = seed0 + static_cast<uint64_t>(i);
    const Instance inst = bench::random_stalactite_comb(seed);
    const std::string where = "random stalactite comb, seed " + std::to_string(seed) +
                              "; replay with GRIDLOCK_TEST_SEED=" + std::to_string(seed);
    check_instance(inst, where, tally);
    if (::testing::Test::HasFatalFailure()) return;
  }
  std::cout << "[ info ] " << tally.cases << " random stalactite combs (" << tally.yes << " node collisions, "
            << tally.no << " none; " << tally.first_named
            << " first collisions equal to the simulator's); time slabs: " << tally.slabs_no << " NOs and "
            << tally.slabs_yes << " YES, " << tally.slabs_split << " split in time, " << tally.slabs_named
            << " YES named through find_collision; from 8 slabs: " << tally.slabs8_no << " NOs and " << tally.slabs8_yes
            << " YES\n";
  EXPECT_GT(tally.yes, cases / 10);
  EXPECT_GT(tally.no, cases / 10);
  EXPECT_GT(tally.slabs_split, cases / 5);
  EXPECT_GT(tally.slabs_named, cases / 20);
}

// The question the classes' bisection asks, "some overlap before T?", on
// every class pair of the whole live set, against the exact test on every
// pair: at random fractions T and at the first moment of a YES (where
// nothing may start before it) and just after it, on instances with
// larger speeds (long paths) too. A failure prints the seed.
TEST(SingleCouplingMotionClasses, OverlapBeforeTAgreesWithEveryPair) {
  const uint64_t seed0 = test::base_seed(27000);
  const int cases = test::scaled(1500);
  int asked = 0, yes = 0, at_first = 0;
  for (int i = 0; i < cases; ++i) {
    const uint64_t seed = seed0 + static_cast<uint64_t>(i);
    Rng rng(seed * 104729 + 9);
    RandomInstanceParams p = single_params(rng);
    // A third tiny (a question then hinges on one or two pairs), a third
    // with long paths (larger speeds).
    const uint64_t kind = rng.below(3);
    if (kind == 0) p.nodes = 2 + static_cast<uint32_t>(rng.below(4)), p.ops = 1 + static_cast<uint32_t>(rng.below(2));
    if (kind == 1) p.nodes = 20 + static_cast<uint32_t>(rng.below(100)), p.path_shape = true;
    const Instance inst = one_coupling(random_instance(p, seed));
    const std::string where = "seed " + std::to_string(seed) +
                              "; replay with GRIDLOCK_TEST_SEED=" + std::to_string(seed);
    Simulator sim(inst);
    std::vector<Rational> ts;
    for (int64_t q = 1; q <= 7; ++q)  // every fraction of (0, 1] with a small denominator
      for (int64_t num = 1; num <= q; ++num)
        if (std::gcd(num, q) == 1) ts.emplace_back(num, q);
    for (int k = 0; k < 8; ++k) {  // random fractions, half with large denominators
      const int64_t q = 1 + static_cast<int64_t>(rng.below(k < 4 ? 40 : uint64_t{1} << 30));
      ts.emplace_back(1 + static_cast<int64_t>(rng.below(static_cast<uint64_t>(q))), q);
    }
    const SingleCouplingAnswer swept = single_coupling_sweep(inst, sim.tree(), sim.regions());
    if (swept.first && *swept.first > Rational(0)) {
      ts.push_back(*swept.first);
      ts.push_back(*swept.first + (Rational(1) - *swept.first) / Rational(1000));
    }
    for (const Rational& T : ts) {
      const auto classes = single_coupling_classes_before(inst, sim.tree(), sim.regions(), T);
      if (!classes) continue;
      const auto pairs = single_coupling_pairwise_before(inst, sim.tree(), sim.regions(), T);
      ASSERT_EQ(classes->has_value(), pairs.has_value()) << where << ", T = " << T.str();
      ++asked;
      yes += pairs.has_value();
      if (swept.first && T == *swept.first) {
        ASSERT_FALSE(classes->has_value()) << where << ": something before the first moment";
        ++at_first;
      }
    }
  }
  std::cout << "[ info ] " << asked << " questions (" << yes << " with an overlap before T), " << at_first
            << " at a first moment\n";
  EXPECT_GT(yes, asked / 10);
  EXPECT_LT(yes, asked - asked / 10);
  EXPECT_GT(at_first, cases / 150);  // most first moments are 0
}

// Larger shapes, long paths: more motion, more items per cell.
TEST(SingleCouplingSweep, AgreesWithTwinsOnLargerInstances) {
  const uint64_t seed0 = test::base_seed(26000);
  const int cases = test::scaled(200);
  Tally tally;
  for (int i = 0; i < cases; ++i) {
    const uint64_t seed = seed0 + static_cast<uint64_t>(i);
    Rng rng(seed * 104729 + 5);
    RandomInstanceParams p = single_params(rng);
    p.nodes = 100 + static_cast<uint32_t>(rng.below(300));
    p.ops = 1 + static_cast<uint32_t>(rng.below(p.nodes / 2));
    p.path_shape = rng.below(2) == 0;
    if (rng.below(2) == 0) p.allow_contract = p.allow_grow = false;  // expansions only: more NO
    const Instance inst = one_coupling(random_instance(p, seed));
    const std::string where = "seed " + std::to_string(seed) + " (nodes " + std::to_string(p.nodes) + ", ops " +
                              std::to_string(p.ops) + "); replay with GRIDLOCK_TEST_SEED=" + std::to_string(seed);
    check_instance(inst, where, tally);
    if (::testing::Test::HasFatalFailure()) return;
  }
  std::cout << "[ info ] " << tally.cases << " instances (" << tally.yes << " node collisions, " << tally.no
            << " none; " << tally.first_named
            << " first collisions equal to the simulator's; most items present at an entry " << tally.max_active
            << ")\n";
  EXPECT_GT(tally.no, cases / 10);
  EXPECT_GT(tally.yes, cases / 10);
}

// One axis (every operation along x, or every one along y): the row
// neighbours' test (single_coupling_one_axis) against the all-pairs exact
// test, the sweep and the simulator on the one schedule, on dense rows
// (spread 0, paths and shapes with extra edges) of every operation kind;
// and it declines instances that use both axes. (It may also decline when
// the coupling breaks a cycle: widths are then inconsistent; seed 103102
// at GRIDLOCK_TEST_SCALE=25, GRIDLOCK_TEST_SEED=91000, was such a case.)
TEST(SingleCouplingOneAxis, AgreesWithTwinsOnRandomInstances) {
  const uint64_t seed0 = test::base_seed(27000);
  const int cases = test::scaled(4000);
  int yes = 0, no = 0, vertical = 0, mixed = 0, declined = 0, first_checked = 0;
  uint64_t tests = 0, most_tests = 0;
  for (int i = 0; i < cases; ++i) {
    const uint64_t seed = seed0 + static_cast<uint64_t>(i);
    Rng rng(seed * 7727 + 11);
    RandomInstanceParams p = single_params(rng);
    p.nodes = 2 + static_cast<uint32_t>(rng.below(rng.below(3) == 0 ? 120 : 20));
    p.ops = 1 + static_cast<uint32_t>(rng.below(p.nodes));
    p.horizontal_only = rng.below(6) != 0;
    p.spread = static_cast<uint32_t>(rng.below(2));
    const bool transpose = rng.below(2) == 0;
    const Instance inst = one_coupling(random_instance(p, seed), transpose);
    const std::string where = "seed " + std::to_string(seed) + " (nodes " + std::to_string(p.nodes) + ", ops " +
                              std::to_string(p.ops) + (transpose ? ", transposed" : "") +
                              "); replay with GRIDLOCK_TEST_SEED=" + std::to_string(seed);
    Simulator sim(inst);
    uint64_t made = 0;
    const auto one = single_coupling_one_axis(inst, sim.tree(), sim.regions(), &made);
    bool x = false, y = false;
    for (const Operation& op : inst.ops()) (is_horizontal(op.dir) ? x : y) = true;
    if (x && y) {
      ASSERT_FALSE(one) << where;
      ++mixed;
      continue;
    }
    if (!one) {  // only when the coupling breaks a cycle (find_collision's first step)
      ASSERT_FALSE(sim.faces().faces.empty()) << where;
      ++declined;
      continue;
    }
    const auto pairs = single_coupling_pairwise(inst, sim.tree(), sim.regions());
    ASSERT_EQ(one->collides, pairs.has_value()) << where;
    ASSERT_EQ(one->collides, single_coupling_sweep(inst, sim.tree(), sim.regions()).collides) << where;
    if (one->collides) {
      ASSERT_TRUE(one->pair) << where;
      ASSERT_LT(one->pair->a, one->pair->b) << where;
    }
    if (one->collides) {
      expect_overlaps_during(inst, *one, where);
      if (::testing::Test::HasFatalFailure()) return;
    }
    if (sim.faces().faces.empty() && inst.couplings().size() == 1) {
      const SimResult run = sim.run_order({0});
      ASSERT_EQ(one->collides, run.collision.has_value()) << where;
      if (one->collides) {  // the first collision, as the simulator finds it
        expect_names_first(inst, *one, *run.collision, where);
        if (::testing::Test::HasFatalFailure()) return;
        const CollideResult res = find_collision(inst, TimeModel::Continuous);
        ASSERT_EQ(res.algorithm, "single-coupling-one-axis") << where;
        ASSERT_EQ(res.simulated->time, run.collision->time) << where;
        ASSERT_EQ(res.checked_at, one->during) << where;
        ASSERT_EQ(res.simulated->a, run.collision->a) << where;
        ASSERT_EQ(res.simulated->b, run.collision->b) << where;
        ASSERT_EQ(res.simulated->moving, run.collision->moving) << where;
        ++first_checked;
      }
    }
    // Linear in the regions: at most a few tests per region.
    ASSERT_LE(made, 4 * sim.regions().size()) << where;
    (one->collides ? yes : no)++;
    vertical += y;
    tests += made, most_tests = std::max(most_tests, made);
  }
  std::cout << "[ info ] one axis: " << yes + no << " instances (" << yes << " collide, " << no << " do not, "
            << vertical << " vertical), " << mixed << " on both axes and " << declined << " breaking a cycle declined; "
            << tests << " exact tests, at most " << most_tests << " in one instance; " << first_checked
            << " first collisions equal to the simulator's\n";
  EXPECT_GT(yes, cases / 10);
  EXPECT_GT(no, cases / 10);
  EXPECT_GT(vertical, cases / 5);
  EXPECT_GT(mixed, cases / 20);
}

// The adversarial diagonal sweep: NO by construction (collide/adversarial.hpp),
// for every method; the simulator meets many more candidate pairs than the
// sweep has items once K grows.
TEST(SingleCouplingSweep, DiagonalSweepIsNoForEveryMethod) {
  for (uint32_t K : {1u, 2u, 5u, 12u})
    for (uint32_t b : {3u, 4u, 7u}) {
      const Instance inst = diagonal_sweep_instance(K, b);
      const std::string where = "K " + std::to_string(K) + ", b " + std::to_string(b);
      ASSERT_EQ(inst.couplings().size(), 1u) << where;
      Simulator sim(inst);
      SingleCouplingStats st;
      EXPECT_FALSE(single_coupling_sweep(inst, sim.tree(), sim.regions(), &st).collides) << where;
      EXPECT_FALSE(single_coupling_pairwise(inst, sim.tree(), sim.regions())) << where;
      EXPECT_FALSE(sim.run_order({0}).collision) << where;
      EXPECT_FALSE(find_collision(inst, TimeModel::Continuous).collides) << where;
    }
  // Counts, not times: from K = 12 to 48 (b = K / 2) the simulator's
  // candidate pairs grow as K^4 (x 256), the sweep's items as K^3 (x 64).
  uint64_t items[2], pairs[2];
  for (int i = 0; i < 2; ++i) {
    const Instance inst = diagonal_sweep_instance(i == 0 ? 12 : 48, i == 0 ? 6 : 24);
    Simulator sim(inst);
    SingleCouplingStats st;
    EXPECT_FALSE(single_coupling_sweep(inst, sim.tree(), sim.regions(), &st).collides);
    const SimResult run = sim.run_order({0});
    EXPECT_FALSE(run.collision);
    items[i] = st.items, pairs[i] = run.stats.candidate_pairs;
  }
  EXPECT_GT(pairs[1], 150 * pairs[0]) << pairs[0] << " -> " << pairs[1];
  EXPECT_LT(items[1], 80 * items[0]) << items[0] << " -> " << items[1];
}

// The square serpentine keeps every order (no two faces of an axis swap),
// and the mixed comb keeps the order of its x faces (the spine pushes the
// teeth apart; the teeth's y faces pass each other): Auto answers their
// NO by one sweep along the kept axis; the cell sweep and the simulator
// agree. The diagonal and band sweeps' orders change on both axes.
TEST(SingleCouplingSweep, KeptOrderIsDecidedByOneSweep) {
  std::vector<std::pair<std::string, Instance>> cases;
  for (int64_t n : {64, 256, 1024})
    cases.emplace_back("serpentine of " + std::to_string(n),
                       serpentine_instance(square_serpentine(n, 1u << 30, SerpentineCouplings::Mixed), 1));
  for (int64_t n : {256, 1024})
    cases.emplace_back("mixed comb of " + std::to_string(n), bench::comb(n / 4, 3, n / 4, bench::CombOps::Mixed, 0, 7));
  for (const auto& [where, inst] : cases) {
    ASSERT_EQ(inst.couplings().size(), 1u) << where;
    const CollideResult r = find_collision(inst, TimeModel::Continuous);
    EXPECT_FALSE(r.collides) << where;
    EXPECT_EQ(r.algorithm, "single-coupling-fixed-axis") << where;
    Simulator sim(inst);
    const std::optional<FixedAxisAnswer> fixed = single_coupling_fixed_axis(inst, sim.tree(), sim.regions());
    ASSERT_TRUE(fixed) << where;
    EXPECT_EQ(fixed->axis, 0) << where;
    EXPECT_FALSE(fixed->answer.collides) << where;
    EXPECT_EQ(fixed->sweeps, 1u) << where;
    EXPECT_LE(fixed->tests, 2 * sim.regions().size()) << where;
    EXPECT_FALSE(single_coupling_sweep(inst, sim.tree(), sim.regions()).collides) << where;
    EXPECT_FALSE(sim.run_order({0}).collision) << where;
  }
  // The diagonal sweep and the band sweeps: a cut along x - y (slope 1)
  // or x - 2 y (slope 2, the direction across the commonest motion),
  // after one along y for the floor, separates what moves from the static
  // triangle or band; each side keeps an order.
  for (const auto& [where, inst] : {std::pair{std::string("diagonal sweep"), diagonal_sweep_instance(5, 4)},
                                    std::pair{std::string("band sweep of slope 1"), band_sweep_instance(40, 1)},
                                    std::pair{std::string("band sweep of slope 2"), band_sweep_instance(40, 2)}}) {
    const CollideResult r = find_collision(inst, TimeModel::Continuous);
    EXPECT_FALSE(r.collides) << where;
    EXPECT_EQ(r.algorithm, "single-coupling-separated") << where;
    Simulator sim(inst);
    EXPECT_FALSE(single_coupling_sweep(inst, sim.tree(), sim.regions()).collides) << where;
    EXPECT_FALSE(sim.run_order({0}).collision) << where;
  }
  // The arc sweep: cells move away from the anchor in many directions; no
  // cut over (0, 1), and too many members placed for the time slabs: the
  // cell sweep decides.
  const Instance arc = arc_sweep_instance(40, 13);
  Simulator sim(arc);
  EXPECT_FALSE(single_coupling_fixed_axis(arc, sim.tree(), sim.regions()));
  const CollideResult r = find_collision(arc, TimeModel::Continuous);
  EXPECT_FALSE(r.collides);
  EXPECT_EQ(r.algorithm, "single-coupling");
  EXPECT_FALSE(sim.run_order({0}).collision);
}

// The lidded comb (bench/bench_families.hpp): both axes change order (the
// teeth pass the lid's x faces and each other's y faces), but the lid's
// row lies above everything else at t = 0 and 1, and its column left of
// the comb: cut there, the comb keeps its x order and the lid is static.
// One sweep per group decides the NO that the cell sweep took n^2 for.
TEST(SingleCouplingSweep, LiddedCombIsCutIntoSeparatedGroups) {
  for (int64_t n : {256, 1024, 4096}) {
    const Instance inst = bench::comb(n / 4, 3, n / 4, bench::CombOps::Mixed, 0, 7, true);
    const std::string where = "lidded comb of " + std::to_string(n);
    ASSERT_EQ(inst.couplings().size(), 1u) << where;
    const CollideResult r = find_collision(inst, TimeModel::Continuous);
    EXPECT_FALSE(r.collides) << where;
    EXPECT_EQ(r.algorithm, "single-coupling-separated") << where;
    Simulator sim(inst);
    const std::optional<FixedAxisAnswer> fixed = single_coupling_fixed_axis(inst, sim.tree(), sim.regions());
    ASSERT_TRUE(fixed) << where;
    EXPECT_GE(fixed->groups, 3u) << where;
    EXPECT_EQ(fixed->axis, -1) << where;
    EXPECT_FALSE(fixed->answer.collides) << where;
    EXPECT_EQ(fixed->sweeps, 1u) << where;
    EXPECT_LE(fixed->tests, 2 * sim.regions().size()) << where;
    EXPECT_FALSE(single_coupling_sweep(inst, sim.tree(), sim.regions()).collides) << where;
    EXPECT_FALSE(sim.run_order({0}).collision) << where;
    // The certificate's pairs: every group's sweep pairs, as many as tested.
    const std::optional<KeptOrderPairs> pairs = single_coupling_kept_order_pairs(inst, sim.tree(), sim.regions());
    ASSERT_TRUE(pairs) << where;
    EXPECT_EQ(pairs->axis, 2) << where;
    EXPECT_EQ(pairs->pairs.size(), fixed->tests) << where;
  }
}

// The stalactite comb (bench/bench_families.hpp): the teeth pass under
// the stalactites, then rise past their tips. Both axes change order and
// no cut separates teeth from stalactites over (0, 1), so the fixed-axis
// sweep gives up. Over [0, 1/2] they lie apart along y, over [1/2, 1]
// along x: two time slabs, each cut (Auto). That piece also has six motion
// classes (the stalactites, teeth rising by 0, 1 and 2, the two inserted
// regions' kinds), which decide the same NO. The cell sweep, all pairs
// and the simulator agree.
// (The comb of 1 tooth is cut across its motion over (0, 1).)
TEST(SingleCouplingSweep, StalactiteCombIsDecidedByTimeSlabsAndMotionClasses) {
  for (int64_t L : {2, 5, 16, 40}) {
    const Instance inst = bench::stalactite_comb(L);
    const std::string where = "stalactite comb of " + std::to_string(L);
    ASSERT_EQ(inst.couplings().size(), 1u) << where;
    const CollideResult r = find_collision(inst, TimeModel::Continuous);
    EXPECT_FALSE(r.collides) << where;
    EXPECT_EQ(r.algorithm, "single-coupling-time-slabs") << where;
    Simulator sim(inst);
    EXPECT_FALSE(single_coupling_fixed_axis(inst, sim.tree(), sim.regions())) << where;
    const std::optional<TimeSlabAnswer> ts = single_coupling_time_slabs(inst, sim.tree(), sim.regions());
    ASSERT_TRUE(ts) << where;
    EXPECT_FALSE(ts->answer.collides) << where;
    if (L >= 5) {
      EXPECT_EQ(ts->finest, 1) << where;  // the halves of [0, 1] (smaller: a piece of at most 8, every pair)
    }
    EXPECT_LE(ts->work, 8 * sim.regions().size()) << where;  // [0, 1], its halves and their cuts
    const std::optional<MotionClassAnswer> mc = single_coupling_motion_classes(inst, sim.tree(), sim.regions());
    ASSERT_TRUE(mc) << where;
    EXPECT_FALSE(mc->answer.collides) << where;
    EXPECT_EQ(mc->class_groups, 1u) << where;
    EXPECT_LE(mc->classes, 6u) << where;
    EXPECT_FALSE(single_coupling_sweep(inst, sim.tree(), sim.regions()).collides) << where;
    EXPECT_FALSE(single_coupling_pairwise(inst, sim.tree(), sim.regions())) << where;
    EXPECT_FALSE(sim.run_order({0}).collision) << where;
  }
  // The middle stalactite reaching into the teeth's path: a YES found by
  // the classes, its first moment by bisection, named as the simulator
  // names it and as the cell sweep does.
  // L = 200: speeds up to 802, so starts 1 / (4 * 802^2) apart, past
  // what halving to 2^20 separates.
  for (int64_t L : {1, 2, 5, 16, 40, 200}) {
    const Instance inst = bench::stalactite_comb(L, false, true);
    const std::string where = "stalactite comb with a hit, " + std::to_string(L);
    Simulator sim(inst);
    const SimResult run = sim.run_order({0});
    ASSERT_TRUE(run.collision) << where;
    const std::optional<MotionClassAnswer> mc = single_coupling_motion_classes(inst, sim.tree(), sim.regions());
    ASSERT_TRUE(mc) << where;
    EXPECT_EQ(mc->class_groups, 1u) << where;
    expect_names_first(inst, mc->answer, *run.collision, where);
    if (::testing::Test::HasFatalFailure()) return;
    // The first moment floor(L / 2) / k: after 0 from L = 2 on, found by
    // bisecting, in O(log) rounds.
    if (L >= 2) {
      EXPECT_GT(mc->sweeps, 1u) << where;
      EXPECT_LE(mc->sweeps, 2u * 12u + 4u) << where;  // 2 log2(2 * 802) + 4
    }
    if (L <= 40) {
      const SingleCouplingAnswer swept = single_coupling_sweep(inst, sim.tree(), sim.regions());
      ASSERT_TRUE(swept.first) << where;
      EXPECT_EQ(*swept.first, *mc->answer.first) << where;
    }
    const std::optional<TimeSlabAnswer> ts = single_coupling_time_slabs(inst, sim.tree(), sim.regions());
    ASSERT_TRUE(ts) << where;
    expect_names_first(inst, ts->answer, *run.collision, where + ", time slabs");
    if (::testing::Test::HasFatalFailure()) return;
    if (L >= 5) {
      EXPECT_EQ(ts->finest, 1) << where;
    }
    const CollideResult r = find_collision(inst, TimeModel::Continuous);
    EXPECT_EQ(r.algorithm, "single-coupling-time-slabs") << where;
    ASSERT_TRUE(r.simulated) << where;
    EXPECT_EQ(r.simulated->time, run.collision->time) << where;
    EXPECT_EQ(r.checked_at, ts->answer.during) << where;
  }
  // Each pair of teeth at its own speed: many classes, the same NO, and
  // the same two time slabs (Auto).
  for (int64_t L : {2, 5, 16, 40}) {
    const Instance inst = bench::stalactite_comb(L, true);
    const std::string where = "own-speed stalactite comb of " + std::to_string(L);
    ASSERT_EQ(inst.couplings().size(), 1u) << where;
    const CollideResult r = find_collision(inst, TimeModel::Continuous);
    EXPECT_FALSE(r.collides) << where;
    EXPECT_EQ(r.algorithm, "single-coupling-time-slabs") << where;
    Simulator sim(inst);
    const std::optional<TimeSlabAnswer> ts = single_coupling_time_slabs(inst, sim.tree(), sim.regions());
    ASSERT_TRUE(ts) << where;
    EXPECT_FALSE(ts->answer.collides) << where;
    if (L >= 5) {
      EXPECT_EQ(ts->finest, 1) << where;
    }
    EXPECT_LE(ts->work, 8 * sim.regions().size()) << where;
    const std::optional<MotionClassAnswer> mc = single_coupling_motion_classes(inst, sim.tree(), sim.regions(), nullptr,
                                                                               false, true);
    ASSERT_TRUE(mc) << where;
    EXPECT_FALSE(mc->answer.collides) << where;
    if (L >= 16) {
      EXPECT_GT(mc->classes, static_cast<size_t>(L)) << where;
    }
    EXPECT_FALSE(single_coupling_pairwise(inst, sim.tree(), sim.regions())) << where;
    EXPECT_FALSE(sim.run_order({0}).collision) << where;
  }
}

// A limit reached stops the time slabs and the pairs the certificates
// list (the slabs' and the fixed-axis sweep's) with LimitReached, not
// with an answer: the own-speed comb, whose slabs place many pieces.
TEST(SingleCouplingTimeSlabs, StopAtAnExpiredDeadline) {
  const Instance comb = bench::stalactite_comb(40, true);
  const Instance lidded = bench::comb(64, 3, 64, bench::CombOps::Mixed, 0, 7, true);
  const Deadline expired(1e-9);
  while (!expired.expired()) {
  }
  Simulator sim(comb), lid(lidded);
  EXPECT_THROW(single_coupling_time_slabs(comb, sim.tree(), sim.regions(), &expired), LimitReached);
  EXPECT_THROW(single_coupling_slab_pairs(comb, sim.tree(), sim.regions(), &expired), LimitReached);
  EXPECT_THROW(single_coupling_kept_order_pairs(lidded, lid.tree(), lid.regions(), &expired), LimitReached);
  // Without a limit, the same calls answer.
  EXPECT_TRUE(single_coupling_slab_pairs(comb, sim.tree(), sim.regions()));
  EXPECT_TRUE(single_coupling_kept_order_pairs(lidded, lid.tree(), lid.regions()));
}

// The awning comb (bench/bench_families.hpp): the x faces keep their
// order, and the middle short tooth reaches its awning at t = 2/3. The
// fixed-axis sweep bisects for that moment and names that pair; the cell
// sweep and the simulator agree.
TEST(SingleCouplingSweep, AwningCombYesIsNamedByTheFixedAxisSweep) {
  for (int64_t L : {3, 4, 9, 40, 161}) {
    const Instance inst = bench::awning_comb(L, 11);
    const std::string where = "awning comb of " + std::to_string(L);
    ASSERT_EQ(inst.couplings().size(), 1u) << where;
    Simulator sim(inst);
    const std::optional<FixedAxisAnswer> fixed = single_coupling_fixed_axis(inst, sim.tree(), sim.regions());
    ASSERT_TRUE(fixed) << where;
    EXPECT_EQ(fixed->axis, 0) << where;
    ASSERT_TRUE(fixed->answer.collides) << where;
    expect_overlaps_during(inst, fixed->answer, where);
    if (::testing::Test::HasFatalFailure()) return;
    EXPECT_EQ(*fixed->answer.first, Rational(2, 3)) << where;
    const SimResult run = sim.run_order({0});
    ASSERT_TRUE(run.collision) << where;
    expect_names_first(inst, fixed->answer, *run.collision, where);  // one pair starts then: the simulator's
    if (::testing::Test::HasFatalFailure()) return;
    const SingleCouplingAnswer cells = single_coupling_sweep(inst, sim.tree(), sim.regions());
    ASSERT_TRUE(cells.collides && cells.first) << where;
    EXPECT_EQ(*cells.first, Rational(2, 3)) << where;
    const CollideResult r = find_collision(inst, TimeModel::Continuous);
    EXPECT_EQ(r.algorithm, "single-coupling-fixed-axis") << where;
    ASSERT_TRUE(r.collides && r.simulated) << where;
    EXPECT_EQ(r.simulated->time, Rational(2, 3)) << where;
    EXPECT_GE(fixed->sweeps, 2u) << where;
    EXPECT_LE(fixed->sweeps, 40u) << where;
  }
}

// The diagonal sweep with its post (collide/adversarial.hpp): YES, first
// at t = 1 - 1/K, after the motion that makes the simulator's broad phase
// quadratic. The sweep names that collision and find_collision reports it,
// checked at one moment, without simulating; the simulator agrees.
TEST(SingleCouplingSweep, DiagonalSweepWithThePostNamesItsFirstCollision) {
  int slabbed = 0;
  for (uint32_t K : {1u, 2u, 5u, 12u})
    for (uint32_t b : {3u, 4u, 7u}) {
      const Instance inst = diagonal_sweep_instance(K, b, true);
      const std::string where = "K " + std::to_string(K) + ", b " + std::to_string(b);
      Simulator sim(inst);
      const SingleCouplingAnswer ans = single_coupling_sweep(inst, sim.tree(), sim.regions());
      ASSERT_TRUE(ans.collides) << where;
      const SimResult run = sim.run_order({0});
      ASSERT_TRUE(run.collision) << where;
      EXPECT_EQ(run.collision->time, Rational(static_cast<int64_t>(K) - 1, K)) << where;
      expect_names_first(inst, ans, *run.collision, where);
      const CollideResult r = find_collision(inst, TimeModel::Continuous);
      ASSERT_TRUE(r.collides) << where;
      ASSERT_TRUE(r.simulated) << where;
      EXPECT_EQ(r.simulated->time, run.collision->time) << where;
      // K = 1: a move of one cell, after which no two x faces have swapped;
      // the fixed-axis sweep bisects for the same first collision. K > 1:
      // no cut over (0, 1); time slabs while they cut within their budget,
      // else motion classes when few enough, else the cell sweep; all name
      // the same first collision.
      if (K == 1) {
        EXPECT_EQ(r.algorithm, "single-coupling-fixed-axis") << where;
      } else {
        EXPECT_TRUE(r.algorithm == "single-coupling" || r.algorithm == "single-coupling-motion-classes" ||
                    r.algorithm == "single-coupling-time-slabs")
            << where << ": " << r.algorithm;
      }
      if (const std::optional<TimeSlabAnswer> ts = single_coupling_time_slabs(inst, sim.tree(), sim.regions(), nullptr,
                                                                              0, true)) {
        expect_names_first(inst, ts->answer, *run.collision, where + ", time slabs");
        ++slabbed;
      }
      EXPECT_EQ(r.checked_at, ans.during) << where;
      EXPECT_EQ(r.simulated->a, run.collision->a) << where;
      EXPECT_EQ(r.simulated->b, run.collision->b) << where;
      EXPECT_EQ(inst.num_nodes(), diagonal_sweep_instance(K, b).num_nodes() + b + 3) << where;
    }
  EXPECT_GE(slabbed, 6);
}

// The band sweeps (collide/adversarial.hpp) of slopes 1 to 3, with and
// without the hit, as built and mirrored in y (test::rebuilt): Auto, the cell sweep and
// the simulator agree; every YES names the simulator's first collision.
// From 12 periods on, each NO is cut across the motion (slope 1: along
// x - y, mirrored x + y; slope p: x - p y, mirrored x + p y) and decided
// without the cell sweep.
TEST(SingleCouplingSweep, BandSweepsAgreeWithTheSimulator) {
  int cut = 0;
  for (uint32_t p : {1u, 2u, 3u})
    for (uint32_t K : {1u, 2u, 5u, 12u, 30u})
      for (bool hits : {false, true})
        for (bool mirror : {false, true}) {
          const Instance built = band_sweep_instance(K, p, 3, hits);
          const Instance inst = mirror ? test::rebuilt(built, false, false, true) : built;
          const std::string where = "p " + std::to_string(p) + ", K " + std::to_string(K) + (hits ? ", hit" : "") +
                                    (mirror ? ", mirrored" : "");
          Simulator sim(inst);
          const SimResult run = sim.run_order({0});
          const SingleCouplingAnswer ans = single_coupling_sweep(inst, sim.tree(), sim.regions());
          ASSERT_EQ(ans.collides, run.collision.has_value()) << where;
          if (!hits) {
            EXPECT_FALSE(ans.collides) << where;
          }
          const CollideResult r = find_collision(inst, TimeModel::Continuous);
          ASSERT_EQ(r.collides, ans.collides) << where << ": " << r.algorithm;
          if (run.collision) {
            expect_names_first(inst, ans, *run.collision, where);
            ASSERT_TRUE(r.simulated) << where;
            EXPECT_EQ(r.simulated->time, run.collision->time) << where << ": " << r.algorithm;
            EXPECT_EQ(r.simulated->a, run.collision->a) << where;
            EXPECT_EQ(r.simulated->b, run.collision->b) << where;
          }
          if (!hits && K >= 12) {
            EXPECT_EQ(r.algorithm, "single-coupling-separated") << where;
            ++cut;
          }
        }
  EXPECT_EQ(cut, 12);
}

// Progress: the one-coupling step reports its column bands through
// find_collision's callback; the sweep reports each band before it runs.
TEST(SingleCouplingSweep, ReportsBandsAsProgress) {
  const Instance inst = arc_sweep_of_size(3200);  // J = 40
  std::vector<CollideProgress> seen;
  const CollideResult r = find_collision(inst, TimeModel::Continuous, CollideMethod::Auto, nullptr,
                                         [&](const CollideProgress& p) { seen.push_back(p); });
  ASSERT_FALSE(r.collides);
  ASSERT_EQ(r.algorithm, "single-coupling");
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.back().step, "single-coupling");
  EXPECT_EQ(seen.back().done, seen.back().total);
  Simulator sim(inst);
  std::vector<uint64_t> bands, totals;
  SingleCouplingStats st;
  EXPECT_FALSE(
      single_coupling_sweep(inst, sim.tree(), sim.regions(), &st, nullptr, 1000, [&](uint64_t done, uint64_t total) {
        bands.push_back(done);
        totals.push_back(total);
      }).collides);
  ASSERT_GT(st.bands, 1u);
  ASSERT_EQ(bands.size(), st.bands);
  for (uint64_t b = 0; b < bands.size(); ++b) {
    EXPECT_EQ(bands[b], b);
    EXPECT_EQ(totals[b], st.bands);
  }
}

// The U below: the sweep and the row neighbours' test name (0,0) and
// (0,1), and so does find_collision (one axis: the neighbours' test).
void check_u(const Instance& inst) {
  Simulator sim(inst);
  const SingleCouplingAnswer ans = single_coupling_sweep(inst, sim.tree(), sim.regions());
  ASSERT_TRUE(ans.collides);
  ASSERT_TRUE(ans.pair);
  EXPECT_EQ(ans.pair->a, 0u);
  EXPECT_EQ(ans.pair->b, 3u);
  const auto one = single_coupling_one_axis(inst, sim.tree(), sim.regions());
  ASSERT_TRUE(one && one->collides && one->pair);
  EXPECT_EQ(one->pair->a, 0u);
  EXPECT_EQ(one->pair->b, 3u);
  const CollideResult r = find_collision(inst, TimeModel::Continuous);
  EXPECT_TRUE(r.collides);
  EXPECT_EQ(r.algorithm, "single-coupling-one-axis");
  EXPECT_EQ(r.region_a, 0u);
  EXPECT_EQ(r.region_b, 3u);
}

// A U of four nodes, (0,0)-(1,0)-(1,1)-(0,1), with no edge between its
// ends: contracting (1,1) into (1,0) pulls (0,1) down onto (0,0).
// Also at the corner of the coordinate range (cells are keyed relative to
// the motion's lower left).
TEST(SingleCouplingSweep, NamesThePairOfACollision) {
  for (Vec2 o : {Vec2{0, 0}, Vec2{kMaxCoordinate - 1, -kMaxCoordinate}}) {
    InstanceBuilder b;
    for (Vec2 c : {Vec2{0, 0}, Vec2{1, 0}, Vec2{1, 1}, Vec2{0, 1}}) ASSERT_FALSE(b.add_node(o + c));
    ASSERT_FALSE(b.add_edge(o + Vec2{0, 0}, o + Vec2{1, 0}));
    ASSERT_FALSE(b.add_edge(o + Vec2{1, 0}, o + Vec2{1, 1}));
    ASSERT_FALSE(b.add_edge(o + Vec2{1, 1}, o + Vec2{0, 1}));
    ASSERT_FALSE(b.add_op("c", OpKind::Contract, o + Vec2{1, 0}, Dir::PosY));
    Instance inst;
    ASSERT_FALSE(b.finish(inst));
    check_u(inst);
  }
}

}  // namespace
}  // namespace gridlock
