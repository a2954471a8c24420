// The simulator's row order from the prepared instance and its skipped last
// advance (Simulator::set_reuse_intervals), against the previous paths.
#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <cstdint>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "common/random.hpp"
#include "lattice/instance.hpp"
#include "lattice/prepared.hpp"
#include "lattice/random_instance.hpp"
#include "lattice/row_order.hpp"
#include "lattice/simulate.hpp"
#include "support/compiled_runs.hpp"
#include "support/same_collision.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

// Random instances of every kind (horizontal-only ones, whose row sweep
// uses the order, half of the time), small to a few hundred nodes.
Instance rows_instance(uint64_t seed, Rng& rng) {
  RandomInstanceParams p;
  p.nodes = 1 + static_cast<uint32_t>(rng.below(rng.below(4) == 0 ? 300 : 40));
  p.ops = static_cast<uint32_t>(rng.below(p.nodes / 2 + 2));
  p.max_coupling = 1 + static_cast<uint32_t>(rng.below(5));
  p.extra_edge_percent = rng.below(3) == 0 ? 40 : 0;
  p.horizontal_only = rng.below(2) == 0;
  p.spread = static_cast<uint32_t>(rng.below(4));
  p.path_shape = rng.below(8) == 0;
  return random_instance(p, seed);
}

// One to three long rows (joined at x = 0) with one to four expansions at
// random cells: extras whose corners lie further apart than 4 m + 64 cells
// (regions_by_row's comparison sort) most of the time.
Instance spread_extras_instance(Rng& rng) {
  InstanceBuilder b;
  const auto width = static_cast<int64_t>(150 + rng.below(250)), rows = static_cast<int64_t>(1 + rng.below(3));
  for (int64_t y = 0; y < rows; ++y) {
    for (int64_t x = 0; x < width; ++x) EXPECT_FALSE(b.add_node({x, y}));
    for (int64_t x = 0; x + 1 < width; ++x) EXPECT_FALSE(b.add_edge({x, y}, {x + 1, y}));
    if (y > 0) {
      EXPECT_FALSE(b.add_edge({0, y - 1}, {0, y}));
    }
  }
  for (uint64_t k = 0, ops = 1 + rng.below(4); k < ops; ++k) {  // cells 3 apart: one operation per node
    const Vec2 u{3 * static_cast<int64_t>(rng.below(static_cast<uint64_t>((width - 1) / 3))),
                 static_cast<int64_t>(rng.below(static_cast<uint64_t>(rows)))};
    (void)b.add_op("e" + std::to_string(k), OpKind::Expand, u, Dir::PosX);  // a cell drawn twice: refused
  }
  Instance inst;
  if (auto e = b.finish(inst)) ADD_FAILURE() << e->message;
  return inst;
}

// Two simulators, set_reuse_intervals on and off, kept across instances
// (rebound to each, as verify's Verifier does): every run gives the same
// results and statistics.
struct Twins {
  std::optional<Simulator> fast, old;
  int collisions = 0, clean = 0, row_sweeps = 0;
  void run(const PreparedInstance& prep, const std::vector<Schedule>& runs) {
    if (!fast) fast.emplace(prep), old.emplace(prep), old->set_reuse_intervals(false);
    fast->rebind(prep), old->rebind(prep);
    for (const Schedule& s : runs) {
      const SimResult a = fast->run(s), b = old->run(s);
      row_sweeps += a.stats.row_sweeps > 0;
      test::expect_same_run(a, b);
      (b.collision ? collisions : clean)++;
    }
  }
};

// The merged order (its extras counting-sorted or, when spread out,
// sorted by comparison) is a permutation strictly ordered by (row, x, id),
// with the previous path's (row, x); it equals the previous path's order
// wherever that counting-sorts (a box of corners at most 4 r + 64 wide and
// high).
TEST(PreparedRowOrder, RegionsByRowTwin) {
  const int cases = test::scaled(4000);
  const uint64_t seed0 = test::base_seed(91);
  int counted = 0, with_extras = 0, extras_counted = 0, extras_sorted = 0;
  for (int i = 0; i < cases; ++i) {
    const uint64_t seed = seed0 + static_cast<uint64_t>(i);
    SCOPED_TRACE("seed " + std::to_string(seed) + " (replay: GRIDLOCK_TEST_SEED=" + std::to_string(seed) + ")");
    Rng rng(seed);
    const Instance inst = i % 8 == 7 ? spread_extras_instance(rng) : rows_instance(seed, rng);
    const PreparedInstance prep(inst);
    const std::vector<uint32_t> merged = regions_by_row(prep.regions, prep.rows);
    const std::vector<uint32_t> old = regions_by_row(prep.regions);
    ASSERT_EQ(merged.size(), prep.regions.size());
    with_extras += prep.regions.size() > inst.num_nodes();
    const auto& sh = prep.regions.shapes;
    int64_t xlo = INT64_MAX, xhi = INT64_MIN, ylo = INT64_MAX, yhi = INT64_MIN;
    for (const RegionShape& s : sh) {
      xlo = std::min(xlo, s.base[0]), xhi = std::max(xhi, s.base[0]);
      ylo = std::min(ylo, s.base[2]), yhi = std::max(yhi, s.base[2]);
    }
    const int64_t limit = 4 * static_cast<int64_t>(sh.size()) + 64;
    if (xhi - xlo < limit && yhi - ylo < limit) {
      ++counted;
      ASSERT_EQ(merged, old);
    }
    // Which way regions_by_row sorted the extras (both must occur).
    int64_t ex_lo = INT64_MAX, ex_hi = INT64_MIN, ey_lo = INT64_MAX, ey_hi = INT64_MIN;
    for (size_t r = inst.num_nodes(); r < sh.size(); ++r) {
      ex_lo = std::min(ex_lo, sh[r].base[0]), ex_hi = std::max(ex_hi, sh[r].base[0]);
      ey_lo = std::min(ey_lo, sh[r].base[2]), ey_hi = std::max(ey_hi, sh[r].base[2]);
    }
    const auto extras = static_cast<int64_t>(sh.size() - inst.num_nodes());
    if (extras > 0)
      (ex_hi - ex_lo < 4 * extras + 64 && ey_hi - ey_lo < 4 * extras + 64 ? extras_counted : extras_sorted)++;
    std::vector<char> seen(merged.size(), 0);
    for (size_t j = 0; j < merged.size(); ++j) {
      ASSERT_LT(merged[j], merged.size());
      ASSERT_FALSE(seen[merged[j]]);
      seen[merged[j]] = 1;
      const int64_t* b = sh[merged[j]].base;
      ASSERT_EQ(b[2], sh[old[j]].base[2]);
      ASSERT_EQ(b[0], sh[old[j]].base[0]);
      if (j > 0) {
        const int64_t* a = sh[merged[j - 1]].base;
        ASSERT_TRUE(a[2] < b[2] || (a[2] == b[2] && (a[0] < b[0] || (a[0] == b[0] && merged[j - 1] < merged[j]))));
      }
    }
  }
  EXPECT_GT(counted, cases / 2);
  EXPECT_GT(with_extras, cases / 2);
  EXPECT_GT(extras_counted, cases / 4);
  EXPECT_GT(extras_sorted, cases / 100);
  std::cout << "extras counting-sorted in " << extras_counted << " instances, sorted by comparison in " << extras_sorted
            << "\n";
}

// Runs with set_reuse_intervals on (the merged row order, no advance after
// the last interval) and off, on simulators kept across runs and rebound
// from instance to instance: every coupling at once (the row sweep on
// horizontal instances), orders, the at-once schedule again after an order
// (its regions must be back at their bases), random times.
TEST(PreparedRowOrder, RunsAgreeWithThePreviousPath) {
  const int cases = test::scaled(3000);
  const uint64_t seed0 = test::base_seed(93);
  Twins twins;
  for (int i = 0; i < cases; ++i) {
    const uint64_t seed = seed0 + static_cast<uint64_t>(i);
    SCOPED_TRACE("seed " + std::to_string(seed) + " (replay: GRIDLOCK_TEST_SEED=" + std::to_string(seed) + ")");
    Rng rng(seed);
    RandomInstanceParams p;
    p.horizontal_only = rng.below(4) != 0;
    p.nodes = 20 + static_cast<uint32_t>(rng.below(180));
    p.ops = 5 + static_cast<uint32_t>(rng.below(p.nodes / 3));
    p.max_coupling = 1 + static_cast<uint32_t>(rng.below(6));
    p.spread = static_cast<uint32_t>(rng.below(3));
    const Instance inst = random_instance(p, seed);
    const size_t k = inst.couplings().size();
    Schedule at_once;
    at_once.start.assign(k, Rational(0));
    std::vector<CouplingId> order(k);
    for (CouplingId q = 0; q < k; ++q) order[q] = q;
    rng.shuffle(order);
    Schedule times;
    for (size_t q = 0; q < k; ++q) times.start.push_back(Rational(static_cast<int64_t>(rng.below(7)), 2));
    const std::vector<Schedule> runs = {at_once, schedule_from_order(order), at_once, times, at_once};
    const PreparedInstance prep(inst);
    twins.run(prep, runs);
  }
  EXPECT_GT(twins.collisions, cases);
  EXPECT_GT(twins.clean, cases / 8);  // random shapes with this many operations mostly collide
  EXPECT_GT(twins.row_sweeps, cases / 2);
  std::cout << "random: row sweeps in " << twins.row_sweeps << " runs, " << twins.clean << " collision-free, "
            << twins.collisions << " collisions\n";
}

// The same on what verify runs: compiled random formulas (a third mutated),
// CaDiCaL's order when satisfiable, a random order, every coupling at once
// (verify's gap witness, last), then the SAT order again.
TEST(PreparedRowOrder, CompiledFormulasAgreeWithThePreviousPath) {
  const int cases = test::scaled(2000);
  const uint64_t seed0 = test::base_seed(95);
  Twins twins;
  for (int i = 0; i < cases; ++i) {
    const uint64_t seed = seed0 + static_cast<uint64_t>(i);
    SCOPED_TRACE("seed " + std::to_string(seed) + " (replay: GRIDLOCK_TEST_SEED=" + std::to_string(seed) + ")");
    Rng rng(seed);
    const test::CompiledRuns c = test::compiled_runs(rng, 20);
    const PreparedInstance prep(c.compiled.instance);
    twins.run(prep, c.runs);
  }
  EXPECT_GT(twins.collisions, cases / 2);
  EXPECT_GT(twins.clean, cases);
  EXPECT_GT(twins.row_sweeps, cases / 2);
  std::cout << "compiled: row sweeps in " << twins.row_sweeps << " runs, " << twins.clean << " collision-free, "
            << twins.collisions << " collisions\n";
}

}  // namespace
}  // namespace gridlock
