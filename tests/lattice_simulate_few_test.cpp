// The simulator's pairing of few moving regions by rigid-velocity class and
// its rebinding (Simulator::set_reuse_intervals, Simulator::rebind), against
// the previous path and against fresh simulators.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "common/random.hpp"
#include "lattice/instance.hpp"
#include "lattice/prepared.hpp"
#include "lattice/random_instance.hpp"
#include "lattice/simulate.hpp"
#include "support/compiled_runs.hpp"
#include "support/same_collision.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

// A random order of every coupling.
Schedule random_order(size_t k, Rng& rng) {
  std::vector<CouplingId> order(k);
  for (CouplingId q = 0; q < k; ++q) order[q] = q;
  rng.shuffle(order);
  return schedule_from_order(order);
}

// Two simulators kept across instances, `fast` (reuse on) and `old`
// (reuse off, the previous path) rebound to each instance, as verify's
// Verifier does, and a fresh one per run (reuse on). Every run: the
// same result and statistics (expect_same_run). Every fourth instance also
// runs with the rigid skip off on both paths (every class kNone).
struct Triplets {
  std::optional<Simulator> fast, old;
  int collisions = 0, clean = 0, tested = 0;
  void run(const PreparedInstance& prep, const std::vector<Schedule>& runs, bool skip_rigid) {
    if (!fast) fast.emplace(prep), old.emplace(prep), old->set_reuse_intervals(false);
    fast->rebind(prep), old->rebind(prep);
    fast->set_skip_rigid_pairs(skip_rigid), old->set_skip_rigid_pairs(skip_rigid);
    for (size_t j = 0; j < runs.size(); ++j) {
      SCOPED_TRACE("run " + std::to_string(j) + (skip_rigid ? "" : " (rigid skip off)"));
      Simulator fresh(prep);
      fresh.set_skip_rigid_pairs(skip_rigid);
      const SimResult a = fast->run(runs[j]), b = old->run(runs[j]), c = fresh.run(runs[j]);
      test::expect_same_run(a, b);
      test::expect_same_run(a, c);
      tested += a.stats.candidate_pairs > 0;
      (b.collision ? collisions : clean)++;
    }
  }
};

// Random instances of every kind (sparse ones, without the dense cell box,
// a quarter of the time), run in several random orders (one coupling at a
// time: few moving regions), at half-integer times, every coupling at once,
// and in orders again (D back to 1 after D = 2).
TEST(SimulatorTwin, FewMovingPairsAgreeWithThePreviousPath) {
  const int cases = test::scaled(3000);
  const uint64_t seed0 = test::base_seed(101);
  Triplets t;
  for (int i = 0; i < cases; ++i) {
    const uint64_t seed = seed0 + static_cast<uint64_t>(i);
    SCOPED_TRACE("seed " + std::to_string(seed) + " (replay: GRIDLOCK_TEST_SEED=" + std::to_string(seed) + ")");
    Rng rng(seed);
    RandomInstanceParams p;
    p.nodes = 2 + static_cast<uint32_t>(rng.below(rng.below(4) == 0 ? 200 : 50));
    p.ops = 1 + static_cast<uint32_t>(rng.below(p.nodes / 3 + 2));
    p.max_coupling = 1 + static_cast<uint32_t>(rng.below(4));
    p.extra_edge_percent = rng.below(3) == 0 ? 30 : 0;
    p.horizontal_only = rng.below(2) == 0;
    p.spread = rng.below(4) == 0 ? 6 : static_cast<uint32_t>(rng.below(3));
    p.path_shape = rng.below(6) == 0;
    const Instance inst = random_instance(p, seed);
    const size_t k = inst.couplings().size();
    Schedule at_once, halves;
    at_once.start.assign(k, Rational(0));
    for (size_t q = 0; q < k; ++q) halves.start.push_back(Rational(static_cast<int64_t>(rng.below(2 * k + 1)), 2));
    const std::vector<Schedule> runs = {
        random_order(k, rng), random_order(k, rng), halves, random_order(k, rng), at_once, random_order(k, rng)};
    const PreparedInstance prep(inst);
    t.run(prep, runs, i % 4 != 3);
  }
  EXPECT_GT(t.collisions, cases);
  EXPECT_GT(t.clean, cases / 2);
  EXPECT_GT(t.tested, cases);
  std::cout << "random: " << t.tested << " runs with exact tests, " << t.clean << " collision-free, " << t.collisions
            << " collisions\n";
}

// The same on compiled formulas (a third mutated): CaDiCaL's order when
// satisfiable (collision-free: every interval tested), random orders, every
// coupling at once, the SAT order again.
TEST(SimulatorTwin, FewMovingPairsOnCompiledFormulas) {
  const int cases = test::scaled(1500);
  const uint64_t seed0 = test::base_seed(103);
  Triplets t;
  for (int i = 0; i < cases; ++i) {
    const uint64_t seed = seed0 + static_cast<uint64_t>(i);
    SCOPED_TRACE("seed " + std::to_string(seed) + " (replay: GRIDLOCK_TEST_SEED=" + std::to_string(seed) + ")");
    Rng rng(seed);
    const test::CompiledRuns c = test::compiled_runs(rng, 16);
    const PreparedInstance prep(c.compiled.instance);
    t.run(prep, c.runs, i % 4 != 3);
  }
  EXPECT_GT(t.collisions, cases / 2);
  EXPECT_GT(t.clean, cases);
  EXPECT_GT(t.tested, cases);
  std::cout << "compiled: " << t.tested << " runs with exact tests, " << t.clean << " collision-free, " << t.collisions
            << " collisions\n";
}

// Two wide rows joined by an arm with expansions that push the upper row up
// into fresh rows (thousands of new hashed cells: the shape is too sparse
// for the dense box), so reset_positions builds the cell table again
// between runs; a hook over the upper row, on a pillar that the last
// operation lifts, meets the row only when the lift comes last. One
// simulator kept across such orders (the hook lifted in one run, hit in the
// next), at-once and half-integer schedules, rebound between two shapes:
// every run as a fresh simulator's and as the previous path's.
Instance hooked_arms(int64_t top, int64_t height, int64_t pushes) {
  InstanceBuilder b;
  const auto row = [&](int64_t y, int64_t x0, int64_t x1) {
    for (int64_t x = x0; x <= x1; ++x) EXPECT_FALSE(b.add_node({x, y}));
    for (int64_t x = x0; x < x1; ++x) EXPECT_FALSE(b.add_edge({x, y}, {x + 1, y}));
  };
  const auto column = [&](int64_t x, int64_t y0, int64_t y1) {  // nodes y0 + 1 .. y1 - 1 between two rows
    for (int64_t y = y0 + 1; y < y1; ++y) EXPECT_FALSE(b.add_node({x, y}));
    for (int64_t y = y0; y < y1; ++y) EXPECT_FALSE(b.add_edge({x, y}, {x, y + 1}));
  };
  const int64_t pillar = top + 50, hook = height + pushes;
  row(0, 0, pillar + 50);
  row(height, 0, top - 1);
  row(hook, top / 2, pillar);
  column(0, 0, height);
  column(pillar, 0, hook);
  for (int64_t i = 0; i < pushes; ++i)
    EXPECT_FALSE(b.add_op("e" + std::to_string(i), OpKind::Expand, {0, 2 + 3 * i}, Dir::PosY));
  EXPECT_FALSE(b.add_op("lift", OpKind::Expand, {pillar, 5}, Dir::PosY));
  Instance inst;
  if (auto e = b.finish(inst)) ADD_FAILURE() << e->message;
  return inst;
}

TEST(SimulatorTwin, RebuiltCellTableAgreesWithFreshSimulators) {
  const Instance first = hooked_arms(200, 100, 12), second = hooked_arms(150, 80, 9);
  const PreparedInstance a(first), b(second);
  Triplets t;
  Rng rng(test::base_seed(107));
  for (int round = 0; round < 4; ++round) {
    for (const PreparedInstance* prep : {&a, &b}) {
      SCOPED_TRACE("round " + std::to_string(round));
      const size_t k = prep->inst.couplings().size();
      std::vector<CouplingId> lift_last(k);
      for (CouplingId q = 0; q < k; ++q) lift_last[q] = q;
      std::vector<CouplingId> lift_first = lift_last;
      std::rotate(lift_first.begin(), lift_first.end() - 1, lift_first.end());
      Schedule at_once, halves;
      at_once.start.assign(k, Rational(0));
      for (size_t q = 0; q < k; ++q) halves.start.push_back(Rational(static_cast<int64_t>(rng.below(2 * k)), 2));
      t.run(*prep,
            {schedule_from_order(lift_first), schedule_from_order(lift_last), random_order(k, rng), at_once, halves,
             schedule_from_order(lift_first), schedule_from_order(lift_last)},
            round != 3);
    }
  }
  EXPECT_GT(t.clean, 16);
  EXPECT_GT(t.collisions, 16);
}
}  // namespace
}  // namespace gridlock
