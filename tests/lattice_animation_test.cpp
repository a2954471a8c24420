// The animation's keyframes (lattice/animation.hpp) against the independent
// configuration_at (lattice/simulate.hpp), exactly, on seeded random
// instances and schedules.
#include <gtest/gtest.h>

#include <algorithm>

#include "common/random.hpp"
#include "lattice/animation.hpp"
#include "lattice/random_instance.hpp"
#include "lattice/simulate.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

RandomInstanceParams params(uint64_t seed) {
  RandomInstanceParams p;
  Rng rng(seed * 7 + 3);
  p.nodes = 2 + static_cast<uint32_t>(rng.below(14));
  p.ops = 1 + static_cast<uint32_t>(rng.below(7));
  p.max_coupling = 1 + static_cast<uint32_t>(rng.below(3));
  p.extra_edge_percent = rng.below(3) == 0 ? 40 : 0;
  p.horizontal_only = rng.below(4) == 0;
  p.path_shape = rng.below(4) == 0;  // long paths: deep part trees
  p.spread = static_cast<uint32_t>(rng.below(3));
  return p;
}

Schedule schedule(const Instance& inst, uint64_t seed, bool discrete) {
  Rng rng(seed ^ 0x5eed);
  size_t k = inst.couplings().size();
  if (discrete) {
    std::vector<CouplingId> order(k);
    for (CouplingId q = 0; q < k; ++q) order[q] = q;
    rng.shuffle(order);
    return schedule_from_order(order);
  }
  Schedule sc;
  for (size_t q = 0; q < k; ++q) {
    int64_t den = 1 + static_cast<int64_t>(rng.below(4));
    sc.start.push_back(Rational(static_cast<int64_t>(rng.below(3 * static_cast<uint64_t>(den) + 1)) - den, den));
  }
  return sc;
}

TEST(AnimationTwin, KeyframesAgreeWithConfigurationAt) {
  const int cases = test::scaled(2000);
  const uint64_t seed0 = test::base_seed(1);
  size_t compared = 0;
  for (int i = 0; i < cases; ++i) {
    const uint64_t seed = seed0 + static_cast<uint64_t>(i);
    SCOPED_TRACE("seed " + std::to_string(seed) + " (replay: GRIDLOCK_TEST_SEED=" + std::to_string(seed) + ")");
    Instance inst = random_instance(params(seed), seed);
    Regions regions = Regions::build(inst);
    for (bool discrete : {true, false}) {
      Schedule s = schedule(inst, seed, discrete);
      Animation a = build_animation(inst, s);
      // Same collision as the simulator, and the stop moment after it.
      Simulator sim(inst);
      auto c = sim.run(s).collision;
      ASSERT_EQ(c.has_value(), a.collision.has_value());
      if (c) {
        EXPECT_EQ(c->time, a.collision->time);
        EXPECT_LT(a.collision->time, a.stop);
      } else {
        EXPECT_EQ(a.stop, Rational(a.events.back(), a.den));
      }
      // Times: every event, every midpoint, thirds, and outside the range.
      std::vector<Rational> times;
      for (size_t e = 0; e < a.events.size(); ++e) {
        Rational t(a.events[e], a.den);
        times.push_back(t);
        if (e + 1 < a.events.size()) {
          Rational u(a.events[e + 1], a.den);
          times.push_back((t + u) * Rational(1, 2));
          times.push_back(t + (u - t) * Rational(1, 3));
        }
      }
      times.push_back(Rational(a.events.front(), a.den) - Rational(1, 2));
      times.push_back(Rational(a.events.back(), a.den) + Rational(7, 3));
      for (const Rational& t : times) {
        std::vector<RectQ> ref = configuration_at(inst, s, t);
        for (uint32_t r = 0; r < regions.size(); ++r) {
          RectQ got = animation_rect(inst, regions, a, r, t);
          ASSERT_TRUE(got.xlo == ref[r].xlo && got.xhi == ref[r].xhi && got.ylo == ref[r].ylo && got.yhi == ref[r].yhi)
              << "region " << region_label(inst, regions, r) << " at t = " << t.str() << ": keyframes give ["
              << got.xlo.str() << "," << got.xhi.str() << "]x[" << got.ylo.str() << "," << got.yhi.str()
              << "], configuration_at [" << ref[r].xlo.str() << "," << ref[r].xhi.str() << "]x[" << ref[r].ylo.str()
              << "," << ref[r].yhi.str() << "]";
          ++compared;
        }
      }
    }
  }
  EXPECT_GT(compared, static_cast<size_t>(cases) * 20);
}

// Parts are the components of the tree cut at the edge operations; each
// part but the root has two keyframes, relative to its parent: 0 at its
// coupling's start, its cut edge's vector at its end.
TEST(AnimationParts, PartitionAndRelativeKeyframes) {
  const int cases = test::scaled(500);
  const uint64_t seed0 = test::base_seed(1);
  for (int i = 0; i < cases; ++i) {
    const uint64_t seed = seed0 + static_cast<uint64_t>(i);
    SCOPED_TRACE("seed " + std::to_string(seed));
    Instance inst = random_instance(params(seed), seed);
    Animation a = build_animation(inst, schedule(inst, seed, i % 2 == 0));
    size_t edge_ops = 0;
    for (const Operation& op : inst.ops()) edge_ops += op.is_edge_op();
    SpanningTree t = SpanningTree::build(inst);
    size_t cut = 0;
    for (NodeId w = 0; w < inst.num_nodes(); ++w) cut += t.parent_op[w] != kNone;
    EXPECT_EQ(a.parts.size(), cut + 1);
    EXPECT_LE(cut, edge_ops);
    for (NodeId w = 0; w < inst.num_nodes(); ++w) {
      ASSERT_LT(a.part_of_node[w], a.parts.size());
      if (w != t.root && t.parent_op[w] == kNone) {
        EXPECT_EQ(a.part_of_node[w], a.part_of_node[t.parent[w]]);
      }
    }
    EXPECT_LE(a.keyframes(), 2 * a.parts.size());
    for (size_t p = 1; p < a.parts.size(); ++p) {
      const auto& part = a.parts[p];
      EXPECT_LT(part.parent, p);
      ASSERT_EQ(part.key_event.size(), 2u);
      EXPECT_EQ(a.events[part.key_event[0]], a.start[part.coupling]);
      EXPECT_EQ(a.events[part.key_event[1]], a.start[part.coupling] + a.den);
      EXPECT_EQ(part.key_disp[0], (Vec2{0, 0}));
      EXPECT_EQ(part.key_disp[1], a.den * op_child_vector(inst, t, part.top));
    }
  }
}

}  // namespace
}  // namespace gridlock
