// The exact simulator: docs/model.md's worked cases, each operation's geometry,
// anchor independence, and the fast simulator against the all-pairs twin.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <optional>
#include <sstream>

#include "common/random.hpp"
#include "lattice/grid_format.hpp"
#include "lattice/random_instance.hpp"
#include "lattice/simulate.hpp"
#include "support/instance_io.hpp"
#include "support/reference_simulator.hpp"
#include "support/same_collision.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

Instance parse(const std::string& text) { return test::parse_instance(text); }
Instance load(const std::string& name) { return test::load_example(name); }

std::optional<Collision> run_order(const Instance& inst, const std::vector<std::string>& names) {
  std::vector<CouplingId> order;
  auto err = parse_order(inst, names, "test", 0, order);
  EXPECT_FALSE(err);
  Simulator sim(inst);
  return sim.run_order(order).collision;
}

Schedule times(const Instance& inst, const std::vector<std::pair<std::string, Rational>>& t) {
  Schedule s;
  s.start.assign(inst.couplings().size(), Rational(0));
  for (auto& [name, v] : t) s.start[inst.find_coupling(name)] = v;
  return s;
}

// --- docs/model.md worked cases ---------------------------------------------

TEST(ModelCases, Case1TwoGrowthsAlwaysMeet) {
  Instance inst = load("model-case1-two-growths.grid");
  for (const auto& order : {std::vector<std::string>{"g1", "g2"}, std::vector<std::string>{"g2", "g1"}}) {
    auto c = run_order(inst, order);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->kind, Collision::Kind::Node);
    EXPECT_EQ(c->time, Rational(1));  // the second growth collides at once
  }
  // Continuous: any start times; both new nodes end in (1,0).
  Simulator sim(inst);
  for (auto [a, b] : {std::pair{0, 0}, std::pair{0, 5}, std::pair{3, 1}}) {
    auto c = sim.run(times(inst, {{"g1", Rational(a)}, {"g2", Rational(b, 2)}})).collision;
    ASSERT_TRUE(c);
  }
  // Each alone is fine: a single growth in its own instance.
  Instance one = parse(
      "p grid 5 4 1 0\nn 0 0\nn 2 0\nn 0 1\nn 1 1\nn 2 1\ne 0 0 0 1\ne 0 1 1 1\ne 1 1 2 1\ne 2 1 2 0\n"
      "o g1 grow 0 0 +x\n");
  EXPECT_FALSE(run_order(one, {"g1"}));
}

TEST(ModelCases, Case2OrderGadget) {
  Instance inst = load("model-case2-order-gadget.grid");
  EXPECT_FALSE(run_order(inst, {"a", "b"}));
  auto c = run_order(inst, {"b", "a"});
  ASSERT_TRUE(c);
  EXPECT_EQ(c->kind, Collision::Kind::Node);
  EXPECT_EQ(c->time, Rational(0));
  Simulator sim(inst);
  std::string pair = region_label(inst, sim.regions(), c->a) + " " + region_label(inst, sim.regions(), c->b);
  EXPECT_EQ(pair, "node (0,1) node (1,1)");
  // Continuous, both at once: collision-free. Also b a little after a.
  EXPECT_FALSE(sim.run(times(inst, {{"a", Rational(0)}, {"b", Rational(0)}})).collision);
  EXPECT_FALSE(sim.run(times(inst, {{"a", Rational(0)}, {"b", Rational(1, 3)}})).collision);
  // b before a, overlapping: (1,1) is pushed left faster than (0,1) moves.
  auto late = sim.run(times(inst, {{"a", Rational(1, 2)}, {"b", Rational(0)}})).collision;
  ASSERT_TRUE(late);
  EXPECT_EQ(late->time, Rational(0));
}

TEST(ModelCases, Case3BlockCycle) {
  const std::string block = "p grid 4 4 1 0\nn 0 0\nn 1 0\nn 0 1\nn 1 1\ne 0 0 1 0\ne 0 1 1 1\ne 0 0 0 1\ne 1 0 1 1\n";
  Instance alone = parse(block + "o a expand 0 0 +x\n");
  auto c = run_order(alone, {"a"});
  ASSERT_TRUE(c);
  EXPECT_EQ(c->kind, Collision::Kind::Cycle);
  EXPECT_EQ(c->time, Rational(0));
  Instance coupled = load("model-case3-block.grid");
  EXPECT_FALSE(run_order(coupled, {"Q"}));
  // The same two expansions uncoupled: whichever runs first breaks the cycle.
  Instance apart = parse(
      "p grid 4 4 2 0\nn 0 0\nn 1 0\nn 0 1\nn 1 1\ne 0 0 1 0\ne 0 1 1 1\ne 0 0 0 1\ne 1 0 1 1\n"
      "o a expand 0 0 +x\no b expand 0 1 +x\n");
  EXPECT_TRUE(run_order(apart, {"a", "b"}));
  // ... but in continuous time, started together, they move as one.
  Simulator sim(apart);
  EXPECT_FALSE(sim.run(times(apart, {{"a", Rational(0)}, {"b", Rational(0)}})).collision);
  auto off = sim.run(times(apart, {{"a", Rational(0)}, {"b", Rational(1, 4)}})).collision;
  ASSERT_TRUE(off);
  EXPECT_EQ(off->kind, Collision::Kind::Cycle);
  EXPECT_EQ(off->time, Rational(0));
}

// --- geometry of each operation kind, all four directions ------------------

struct Geo {
  Rational x0, x1, y0, y1;
};

// A node at (0,0) with the operation toward dir; a neighbour joined by an
// edge for expand/contract. Anchored at (0,0). Returns the rectangle of
// region r at progress p.
Geo at_progress(OpKind kind, Dir d, uint32_t region, Rational p) {
  InstanceBuilder b;
  Vec2 o{0, 0}, c = unit(d);
  b.add_node(o);
  if (kind != OpKind::Grow) {
    b.add_node(c);
    b.add_edge(o, c);
  }
  EXPECT_FALSE(b.add_op("k", kind, o, d));
  Instance inst;
  EXPECT_FALSE(b.finish(inst));
  Schedule s;
  s.start = {Rational(0)};
  auto r = configuration_at(inst, s, p)[region];
  return {r.xlo, r.xhi, r.ylo, r.yhi};
}

TEST(OperationGeometry, AllKindsAllDirectionsAtZeroHalfOne) {
  const Rational half(1, 2);
  for (Dir d : kDirs) {
    SCOPED_TRACE(dir_name(d));
    Vec2 u = unit(d);
    for (Rational p : {Rational(0), half, Rational(1)}) {
      SCOPED_TRACE("progress " + p.str());
      // Expansion: v moves p along d; the inserted node (region 2) spans the gap of width p.
      Geo v = at_progress(OpKind::Expand, d, 1, p);
      EXPECT_EQ(v.x0, Rational(u.x) + p * Rational(u.x));
      EXPECT_EQ(v.y0, Rational(u.y) + p * Rational(u.y));
      EXPECT_EQ(v.x1 - v.x0, Rational(1));
      Geo m = at_progress(OpKind::Expand, d, 2, p);
      Rational w = (m.x1 - m.x0) * (m.y1 - m.y0);
      EXPECT_EQ(w, p);  // width p times height 1
      // The inserted node touches u's face toward d.
      if (d == Dir::PosX) {
        EXPECT_EQ(m.x0, Rational(1));
      }
      if (d == Dir::NegX) {
        EXPECT_EQ(m.x1, Rational(0));
      }
      if (d == Dir::PosY) {
        EXPECT_EQ(m.y0, Rational(1));
      }
      if (d == Dir::NegY) {
        EXPECT_EQ(m.y1, Rational(0));
      }
      // Growth: grown node (region 1) from u's face, width p.
      Geo g = at_progress(OpKind::Grow, d, 1, p);
      EXPECT_EQ((g.x1 - g.x0) * (g.y1 - g.y0), p);
      if (d == Dir::PosX) {
        EXPECT_EQ(g.x0, Rational(1));
      }
      if (d == Dir::NegX) {
        EXPECT_EQ(g.x1, Rational(0));
      }
      // Contraction: v narrows to width 1-p on u's face.
      Geo cv = at_progress(OpKind::Contract, d, 1, p);
      EXPECT_EQ((cv.x1 - cv.x0) * (cv.y1 - cv.y0), Rational(1) - p);
      if (d == Dir::PosX) {
        EXPECT_EQ(cv.x0, Rational(1));
      }
      if (d == Dir::NegX) {
        EXPECT_EQ(cv.x1, Rational(0));
      }
      if (d == Dir::PosY) {
        EXPECT_EQ(cv.y0, Rational(1));
      }
      if (d == Dir::NegY) {
        EXPECT_EQ(cv.y1, Rational(0));
      }
      // u never moves (it is the anchor).
      Geo u0 = at_progress(OpKind::Contract, d, 0, p);
      EXPECT_EQ(u0.x0, Rational(0));
      EXPECT_EQ(u0.y0, Rational(0));
    }
  }
}

TEST(OperationGeometry, TouchingIsNoCollision) {
  // A growth into a cell whose node leaves in lock-step only touches it.
  Instance inst = parse(
      "p grid 4 3 2 1\nn 0 0\nn 0 1\nn 1 1\nn 1 0\ne 0 0 0 1\ne 0 1 1 1\ne 1 1 1 0\n"
      "o g grow 0 0 +x\no e expand 0 1 +x\nq Q g e\n");
  // (1,0) hangs from (1,1); e pushes (1,1) and (1,0) right while g grows into (1,0).
  EXPECT_FALSE(run_order(inst, {"Q"}));
  // The growth alone, into the occupied cell: collides at once.
  Instance alone = parse(
      "p grid 4 3 1 0\nn 0 0\nn 0 1\nn 1 1\nn 1 0\ne 0 0 0 1\ne 0 1 1 1\ne 1 1 1 0\n"
      "o g grow 0 0 +x\n");
  auto c = run_order(alone, {"g"});
  ASSERT_TRUE(c);
  EXPECT_EQ(c->time, Rational(0));
}

// --- anchor independence and the twin --------------------------------------

RandomInstanceParams small_params(uint64_t seed) {
  RandomInstanceParams p;
  Rng rng(seed);
  p.nodes = 2 + static_cast<uint32_t>(rng.below(9));
  p.ops = 1 + static_cast<uint32_t>(rng.below(5));
  p.max_coupling = 1 + static_cast<uint32_t>(rng.below(3));
  p.extra_edge_percent = rng.below(3) == 0 ? 40 : 0;
  p.horizontal_only = rng.below(4) == 0;
  p.spread = static_cast<uint32_t>(rng.below(3));
  return p;
}

// small_params(seed), or when `large` a shape of 40-199 nodes with 10-59
// operations in couplings of up to 4: many regions move at once (more than
// the 48 of the few-regions broad phase). Draws from rng only when large.
RandomInstanceParams twin_params(uint64_t seed, Rng& rng, bool large) {
  RandomInstanceParams p = small_params(seed);
  if (large) {
    p.nodes = 40 + static_cast<uint32_t>(rng.below(160));
    p.ops = 10 + static_cast<uint32_t>(rng.below(50));
    p.max_coupling = 1 + static_cast<uint32_t>(rng.below(4));
  }
  return p;
}

Schedule random_schedule(const Instance& inst, uint64_t seed, bool discrete) {
  Rng rng(seed ^ 0xabcdef);
  size_t k = inst.couplings().size();
  if (discrete) {
    std::vector<CouplingId> order(k);
    for (CouplingId q = 0; q < k; ++q) order[q] = q;
    rng.shuffle(order);
    return schedule_from_order(order);
  }
  Schedule sc;
  for (size_t q = 0; q < k; ++q) {
    // Small denominators so that starts and ends coincide often (the hard cases).
    int64_t den = 1 + static_cast<int64_t>(rng.below(3));
    sc.start.push_back(Rational(static_cast<int64_t>(rng.below(3 * static_cast<uint64_t>(den) + 1)), den));
  }
  return sc;
}

TEST(SimulatorTwin, FastAgreesWithAllPairsReference) {
  const int cases = test::scaled(3000);
  const uint64_t seed0 = test::base_seed(1);
  int collisions = 0, cycles = 0;
  for (int i = 0; i < cases; ++i) {
    uint64_t seed = seed0 + static_cast<uint64_t>(i);
    SCOPED_TRACE("seed " + std::to_string(seed) + " (replay: GRIDLOCK_TEST_SEED=" + std::to_string(seed) + ")");
    Instance inst = random_instance(small_params(seed), seed);
    Simulator sim(inst);
    for (bool discrete : {true, false}) {
      Schedule s = random_schedule(inst, seed, discrete);
      auto fast = sim.run(s).collision;
      NodeId root = static_cast<NodeId>(seed % inst.num_nodes());
      auto ref = test::reference_simulate(inst, s, root);
      ASSERT_EQ(fast.has_value(), ref.has_value()) << (discrete ? "discrete" : "continuous");
      if (!fast) continue;
      ++collisions;
      EXPECT_EQ(fast->kind == Collision::Kind::Cycle, ref->cycle);
      EXPECT_EQ(fast->time, ref->time);
      if (ref->cycle) {
        ++cycles;
      } else if (fast->kind == Collision::Kind::Node) {
        auto pr = std::pair{fast->a, fast->b};
        EXPECT_NE(std::find(ref->pairs.begin(), ref->pairs.end(), pr), ref->pairs.end())
            << "fast reports a pair the reference does not";
      }
    }
  }
  // The comparison is only worth something if both outcomes occur often.
  EXPECT_GT(collisions, cases / 5);
  EXPECT_LT(collisions, 2 * cases - cases / 5);
  EXPECT_GT(cycles, 0);
}

// Everything about one run, to compare runs exactly.
std::string run_summary(const SimResult& r) {
  std::ostringstream o;
  o << r.stats.intervals << "/" << r.stats.moved_regions << "/" << r.stats.candidate_pairs;
  if (!r.collision) return o.str() + " none";
  const Collision& c = *r.collision;
  o << (c.kind == Collision::Kind::Node ? " node " : " cycle ") << c.time.str() << " " << c.a << " " << c.b << " |";
  for (NodeId w : c.cycle) o << " " << w;
  o << " |";
  for (CouplingId q : c.moving) o << " " << q;
  return o.str();
}

// A simulator keeps its work arrays and cell table between runs, and may
// share a PreparedInstance, or be rebound from instance to instance: many
// runs on one simulator must give exactly what a fresh simulator gives for
// each schedule.
TEST(SimulatorTwin, ReusedSimulatorMatchesFreshOnes) {
  const int cases = test::scaled(600);
  const uint64_t seed0 = test::base_seed(5);
  int collisions = 0, clean = 0;
  std::optional<Simulator> roving;  // rebound to each instance in turn (as verify's Verifier does)
  for (int i = 0; i < cases; ++i) {
    uint64_t seed = seed0 + static_cast<uint64_t>(i);
    SCOPED_TRACE("seed " + std::to_string(seed) + " (replay: GRIDLOCK_TEST_SEED=" + std::to_string(seed) + ")");
    Instance inst = random_instance(small_params(seed), seed);
    const PreparedInstance prep(inst);
    Simulator reused(prep), owning(inst);
    if (roving) roving->rebind(prep);
    else roving.emplace(prep);
    for (uint64_t j = 0; j < 8; ++j) {
      Schedule s = random_schedule(inst, seed * 16 + j, j % 2 == 0);
      const std::string fresh = run_summary(Simulator(inst).run(s));
      ASSERT_EQ(run_summary(reused.run(s)), fresh) << "schedule " << j;
      ASSERT_EQ(run_summary(owning.run(s)), fresh) << "schedule " << j;
      ASSERT_EQ(run_summary(roving->run(s)), fresh) << "schedule " << j << " (rebound simulator)";
      (fresh.find("none") != std::string::npos ? clean : collisions)++;
    }
  }
  EXPECT_GT(collisions, cases);
  EXPECT_GT(clean, cases);
}

// The broad phase drops pairs of moving regions with the same face
// velocities that do not overlap now (Simulator::set_skip_rigid_pairs): the
// same runs with and without it, on shapes large enough that more than 48
// regions move (the sub-step broad phase) and on small ones, every coupling
// at once (whole gadgets move rigidly, as in verify's gap witness) and at
// random times.
TEST(SimulatorTwin, RigidPairSkipAgreesWithAllPairs) {
  const int cases = test::scaled(2000);
  const uint64_t seed0 = test::base_seed(11);
  int collisions = 0, clean = 0, skipped = 0;
  for (int i = 0; i < cases; ++i) {
    const uint64_t seed = seed0 + static_cast<uint64_t>(i);
    SCOPED_TRACE("seed " + std::to_string(seed) + " (replay: GRIDLOCK_TEST_SEED=" + std::to_string(seed) + ")");
    Rng rng(seed);
    const Instance inst = random_instance(twin_params(seed, rng, i % 2 == 0), seed);
    const PreparedInstance prep(inst);
    Simulator fast(prep), all(prep);
    all.set_skip_rigid_pairs(false);
    Schedule at_once;
    at_once.start.assign(inst.couplings().size(), Rational(0));
    for (const Schedule& s : {at_once, random_schedule(inst, seed, false), random_schedule(inst, seed, true)}) {
      const SimResult a = fast.run(s), b = all.run(s);
      ASSERT_EQ(a.collision.has_value(), b.collision.has_value());
      ASSERT_LE(a.stats.candidate_pairs, b.stats.candidate_pairs);
      skipped += a.stats.candidate_pairs < b.stats.candidate_pairs;
      if (!a.collision) {
        ++clean;
        continue;
      }
      ++collisions;
      test::expect_same_collision(*a.collision, *b.collision);
    }
  }
  // Both outcomes, and the skip itself, must occur often for the comparison to mean anything.
  EXPECT_GT(collisions, cases / 5);
  EXPECT_GT(clean, cases / 5);
  EXPECT_GT(skipped, cases / 5);
}

// The row sweep (Simulator::set_row_sweep): intervals of horizontal-only
// instances in which many regions move slowly take it as their broad phase
// instead of the cell grid. The same runs both ways (and against the
// all-pairs reference on every twentieth instance), on horizontal instances
// large enough that more than 48 regions move, every coupling at once
// (verify's gap witness) and at random times, in random orders. Random
// instances with this many operations nearly always collide: the
// collision-free runs (verify's case) are SimulatorTwin.RowSweepOnCompiledFormulas
// in tests/reductions_compile_test.cpp.
TEST(SimulatorTwin, RowSweepAgreesWithCellGrid) {
  const int cases = test::scaled(2000);
  const uint64_t seed0 = test::base_seed(13);
  int collisions = 0, clean = 0, swept_rows = 0;
  for (int i = 0; i < cases; ++i) {
    const uint64_t seed = seed0 + static_cast<uint64_t>(i);
    SCOPED_TRACE("seed " + std::to_string(seed) + " (replay: GRIDLOCK_TEST_SEED=" + std::to_string(seed) + ")");
    Rng rng(seed);
    RandomInstanceParams p = small_params(seed);
    p.horizontal_only = true;
    p.nodes = 40 + static_cast<uint32_t>(rng.below(160));
    p.ops = 10 + static_cast<uint32_t>(rng.below(p.nodes / 2));
    p.max_coupling = 1 + static_cast<uint32_t>(rng.below(6));
    const Instance inst = random_instance(p, seed);
    const PreparedInstance prep(inst);
    Simulator rows(prep), grid(prep);
    grid.set_row_sweep(false);
    Schedule at_once;
    at_once.start.assign(inst.couplings().size(), Rational(0));
    for (const Schedule& s : {at_once, random_schedule(inst, seed, false), random_schedule(inst, seed, true)}) {
      const SimResult a = rows.run(s), b = grid.run(s);
      ASSERT_EQ(b.stats.row_sweeps, 0u);
      swept_rows += a.stats.row_sweeps > 0;
      ASSERT_EQ(a.collision.has_value(), b.collision.has_value());
      EXPECT_EQ(a.stats.intervals, b.stats.intervals);
      EXPECT_EQ(a.stats.moved_regions, b.stats.moved_regions);
      std::optional<test::ReferenceCollision> ref;
      if (i % 20 == 0) {  // the all-pairs reference is slow on these sizes
        ref = test::reference_simulate(inst, s, static_cast<NodeId>(seed % inst.num_nodes()));
        ASSERT_EQ(a.collision.has_value(), ref.has_value());
      }
      if (!a.collision) {
        ++clean;
        continue;
      }
      ++collisions;
      test::expect_same_collision(*a.collision, *b.collision);
      if (ref) {
        EXPECT_EQ(a.collision->time, ref->time);
      }
    }
  }
  // Collisions, and the row sweep itself, must occur often for the comparison to mean anything.
  EXPECT_GT(collisions, cases / 5);
  EXPECT_GT(swept_rows, cases / 5);
  std::cout << "row sweeps in " << swept_rows << " of " << 3 * cases << " runs, " << collisions << " collisions, "
            << clean << " collision-free\n";
}

// Simulator::set_reuse_intervals: tight cell queries for the static regions,
// and the moving regions of an interval in which one coupling alone runs
// taken from the first such interval of that coupling. The same runs with
// and without it (results and stats), on one simulator per instance (so
// the second order reuses what the first recorded) and on one rebound from
// instance to instance (as verify's Verifier is): random orders, one of
// them twice, every coupling at once, random times with denominators 1 to 4.
TEST(SimulatorTwin, ReusedIntervalsAgreeWithFreshCuts) {
  const int cases = test::scaled(3000);
  const uint64_t seed0 = test::base_seed(17);
  int collisions = 0, clean = 0, reused = 0;
  std::optional<Simulator> roving;
  for (int i = 0; i < cases; ++i) {
    const uint64_t seed = seed0 + static_cast<uint64_t>(i);
    SCOPED_TRACE("seed " + std::to_string(seed) + " (replay: GRIDLOCK_TEST_SEED=" + std::to_string(seed) + ")");
    Rng rng(seed);
    const Instance inst = random_instance(twin_params(seed, rng, i % 3 == 0), seed);
    Schedule at_once;
    at_once.start.assign(inst.couplings().size(), Rational(0));
    const Schedule first = random_schedule(inst, seed, true);
    std::vector<Schedule> runs = {first, random_schedule(inst, seed + 1, true), at_once,
                                  random_schedule(inst, seed, false)};
    for (int64_t den : {2, 3, 4}) {  // every start a multiple of 1/den: faces stop between cells
      Schedule sc;
      for (size_t q = 0; q < inst.couplings().size(); ++q)
        sc.start.push_back(Rational(static_cast<int64_t>(rng.below(static_cast<uint64_t>(3 * den))), den));
      runs.push_back(sc);
    }
    runs.push_back(first);
    const PreparedInstance prep(inst);
    Simulator fast(prep), old(prep);
    old.set_reuse_intervals(false);
    if (roving) roving->rebind(prep);
    else roving.emplace(prep);
    for (const Schedule& s : runs) {
      const SimResult a = fast.run(s), b = old.run(s), c = roving->run(s);
      ASSERT_EQ(b.stats.reused_intervals, 0u);
      reused += a.stats.reused_intervals > 0;
      test::expect_same_run(a, b);
      test::expect_same_run(c, b);
      (b.collision ? collisions : clean)++;
    }
  }
  EXPECT_GT(collisions, cases / 2);
  EXPECT_GT(clean, cases / 2);
  EXPECT_GT(reused, cases);
  std::cout << "reuse in " << reused << " of " << 8 * cases << " runs, " << collisions << " collisions, " << clean
            << " collision-free\n";
}

// A sparse shape (an L of two long arms: its box has far more cells than
// regions) keeps its cells in the hash table instead of the dense box; moving
// far in one run (everything at once) also leaves the dense box of compact
// shapes. Both against the all-pairs reference.
TEST(SimulatorTwin, SparseShapesAndLongMovesAgreeWithReference) {
  for (int64_t arm : {40, 110}) {  // 110: a box of 114^2 cells > 16 per region + 4096
    SCOPED_TRACE("arm " + std::to_string(arm));
    InstanceBuilder b;
    for (int64_t x = 0; x < arm; ++x) ASSERT_FALSE(b.add_node({x, 0}));
    for (int64_t y = 1; y < arm; ++y) ASSERT_FALSE(b.add_node({0, y}));
    for (int64_t x = 0; x + 1 < arm; ++x) ASSERT_FALSE(b.add_edge({x, 0}, {x + 1, 0}));
    for (int64_t y = 0; y + 1 < arm; ++y) ASSERT_FALSE(b.add_edge({0, y}, {0, y + 1}));
    // Expansions along the horizontal arm (pushing its end outward) and a
    // contraction pair on the vertical one, plus a growth back into the arm.
    int id = 0;
    for (int64_t x = 2; x + 2 < arm; x += 5)
      ASSERT_FALSE(b.add_op("e" + std::to_string(id++), OpKind::Expand, {x, 0}, Dir::PosX));
    ASSERT_FALSE(b.add_op("c", OpKind::Contract, {0, 3}, Dir::PosY));
    ASSERT_FALSE(b.add_op("g", OpKind::Grow, {0, arm - 1}, Dir::PosX));
    Instance inst;
    if (auto e = b.finish(inst)) FAIL() << e->message;
    Simulator sim(inst);
    const size_t k = inst.couplings().size();
    std::vector<Schedule> schedules;
    Schedule all;
    all.start.assign(k, Rational(0));
    schedules.push_back(all);
    std::vector<CouplingId> order(k);
    for (CouplingId q = 0; q < k; ++q) order[q] = q;
    schedules.push_back(schedule_from_order(order));
    std::reverse(order.begin(), order.end());
    schedules.push_back(schedule_from_order(order));
    Schedule halves;
    for (CouplingId q = 0; q < k; ++q) halves.start.push_back(Rational(static_cast<int64_t>(q % 3), 2));
    schedules.push_back(halves);
    for (const Schedule& s : schedules) {
      auto fast = sim.run(s).collision;
      auto ref = test::reference_simulate(inst, s, 0);
      ASSERT_EQ(fast.has_value(), ref.has_value());
      if (fast) {
        EXPECT_EQ(fast->time, ref->time);
      }
      EXPECT_EQ(run_summary(sim.run(s)), run_summary(Simulator(inst).run(s)));
    }
  }
}

TEST(SimulatorTwin, VerdictIndependentOfAnchor) {
  const int cases = test::scaled(600);
  for (int i = 0; i < cases; ++i) {
    uint64_t seed = test::base_seed(77) + static_cast<uint64_t>(i);
    SCOPED_TRACE("seed " + std::to_string(seed));
    Instance inst = random_instance(small_params(seed), seed);
    Schedule s = random_schedule(inst, seed, i % 2 == 0);
    Simulator first(inst);
    auto base = first.run(s).collision;
    for (NodeId a = 0; a < inst.num_nodes(); ++a) {
      Instance moved = inst.with_anchor(a);
      Simulator sim(moved);
      auto c = sim.run(s).collision;
      ASSERT_EQ(c.has_value(), base.has_value()) << "anchor " << inst.node_label(a);
      if (c) {
        EXPECT_EQ(c->time, base->time);
        EXPECT_EQ(c->kind, base->kind);
      }
    }
  }
}

}  // namespace
}  // namespace gridlock
