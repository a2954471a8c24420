// Discrete and continuous Colliding Schedule agree on whole instances
// (docs/collide.md, "Colliding Schedule: the models agree"): if two
// regions overlap at some progress vector, some discrete schedule
// collides. The proof is a winding-number argument along the tree path,
// first for a unit node and a unit or inserted node, then for any pair
// through virtual nodes. This test holds the claim against both deciders
// on seeded random instances: a counterexample, or a wrong decider, shows
// up as a continuous YES with a discrete NO.
#include <gtest/gtest.h>

#include <iostream>
#include <string>

#include "collide/collide.hpp"
#include "common/random.hpp"
#include "lattice/random_instance.hpp"
#include "lattice/simulate.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

// A node region whose four faces all follow the node itself: a unit square
// at every progress (a contracting v's near face follows u instead).
bool unit_node(const Regions& regions, uint32_t r) {
  if (r == kNone || r >= regions.shapes.size()) return false;
  const RegionShape& s = regions.shapes[r];
  if (s.kind != RegionKind::Node) return false;
  for (NodeId f : s.ref)
    if (f != s.id) return false;
  return true;
}

struct ModelCounts {
  int continuous_yes = 0, unit_pairs = 0, other_pairs = 0, discrete_only_no = 0, witnesses_near = 0;
};

// The continuous decider, the discrete one on its own (Pairwise: subset
// sums on every pair) and Auto's discrete answer (the continuous decision,
// then the witness search from the nodes the continuous pair's faces follow) agree;
// that search never falls back to all pairs.
void check_instance(const Instance& inst, uint64_t seed, ModelCounts& n) {
  const CollideResult c = find_collision(inst, TimeModel::Continuous);
  const bool discrete = find_collision(inst, TimeModel::Discrete, CollideMethod::Pairwise).collides;
  EXPECT_EQ(discrete, c.collides) << "seed " << seed << ": continuous " << c.collides << ", discrete " << discrete;
  const CollideResult a = find_collision(inst, TimeModel::Discrete);  // a YES's order is simulated inside
  EXPECT_EQ(a.collides, discrete) << "seed " << seed << ": discrete Auto (" << a.algorithm << ") " << a.collides;
  EXPECT_EQ(a.stats.witness_fallbacks, 0u) << "seed " << seed;
  n.witnesses_near += a.algorithm.ends_with("+subset-sum");
  if (!c.collides) return;
  ++n.continuous_yes;
  if (c.region_a == kNone) return;  // a cycle: both models run that coupling alone
  const Simulator sim(inst);
  const Regions& rs = sim.regions();
  auto inserted = [&](uint32_t r) { return r < rs.shapes.size() && rs.shapes[r].kind == RegionKind::Inserted; };
  const bool unit = (unit_node(rs, c.region_a) && (unit_node(rs, c.region_b) || inserted(c.region_b))) ||
                    (unit_node(rs, c.region_b) && inserted(c.region_a));
  ++(unit ? n.unit_pairs : n.other_pairs);
  n.discrete_only_no += !discrete;
}

TEST(CollideModels, ModelsAgreeOnWholeInstances) {
  ModelCounts n;
  int instances = 0;
  for (int i = 0; i < test::scaled(3000); ++i) {
    const uint64_t seed = test::base_seed(76000) + static_cast<uint64_t>(i);
    SCOPED_TRACE("seed " + std::to_string(seed) + "; replay with GRIDLOCK_TEST_SEED");
    Rng rng(seed * 2741 + 13);
    RandomInstanceParams p;
    p.nodes = 4 + static_cast<uint32_t>(rng.below(50));
    p.ops = 2 + static_cast<uint32_t>(rng.below(p.nodes / 2 + 1));
    p.max_coupling = 1 + static_cast<uint32_t>(rng.below(8));
    p.couplings = rng.below(2) == 0 ? 2 + static_cast<uint32_t>(rng.below(3)) : 0;
    p.extra_edge_percent = rng.below(5) == 0 ? 20 : 0;
    p.path_shape = rng.below(2) == 0;
    p.spread = static_cast<uint32_t>(rng.below(6));
    p.allow_grow = rng.below(3) == 0;
    check_instance(random_instance(p, seed), seed, n);
    ++instances;
    if (::testing::Test::HasFailure()) return;
  }
  std::cout << "[collide] models: " << instances << " instances, " << n.continuous_yes << " continuous YES, "
            << n.unit_pairs << " on a unit node and a unit or inserted node, " << n.other_pairs
            << " on other regions; every one discrete YES (" << n.discrete_only_no << " discrete NO); "
            << n.witnesses_near << " discrete witnesses found near the continuous pair\n";
  EXPECT_GT(n.unit_pairs, test::scaled(300));
  EXPECT_GT(n.other_pairs, test::scaled(100));
  EXPECT_GT(n.witnesses_near, test::scaled(1000));
}

}  // namespace
}  // namespace gridlock
