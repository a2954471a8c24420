// One axis, any couplings (collide/one_axis.cpp, listed_pairs_collision):
// the group pairs decide what every pair decides, the walk of the ends
// keeps the same nets as the traversal, and find_collision's Auto answer
// agrees with the all-pairs method and the brute-force simulations.
#include <gtest/gtest.h>

#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "collide/collide.hpp"
#include "collide/internal/collide_pairs.hpp"
#include "common/random.hpp"
#include "lattice/random_instance.hpp"
#include "lattice/simulate.hpp"
#include "support/instance_io.hpp"
#include "support/reference_collide.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

// Mostly horizontal-only shapes of 2 to 71 nodes, couplings of 1 to 5
// operations, some with cycles, some long paths.
RandomInstanceParams random_params(Rng& rng) {
  RandomInstanceParams p;
  p.nodes = 2 + static_cast<uint32_t>(rng.below(rng.below(3) == 0 ? 70 : 18));
  p.ops = 1 + static_cast<uint32_t>(rng.below(p.nodes));
  p.max_coupling = 1 + static_cast<uint32_t>(rng.below(5));
  p.extra_edge_percent = rng.below(4) == 0 ? 25 : 0;
  p.horizontal_only = rng.below(8) != 0;
  p.path_shape = rng.below(4) == 0;
  p.spread = static_cast<uint32_t>(rng.below(3));
  return p;
}

std::vector<std::pair<uint32_t, uint32_t>> every_pair(size_t regions) {
  std::vector<std::pair<uint32_t, uint32_t>> out;
  for (uint32_t a = 0; a < regions; ++a)
    for (uint32_t b = a + 1; b < regions; ++b) out.emplace_back(a, b);
  return out;
}

TEST(OneAxisGroups, AgreeWithEveryPairAndTheBruteForce) {
  const uint64_t seed0 = test::base_seed(29000);
  const int cases = test::scaled(3000);
  int decided = 0, yes = 0, vertical = 0, mixed = 0, cycles = 0, brute = 0, by_auto = 0;
  uint64_t group_pairs = 0, regions = 0, all_pairs = 0;
  for (int i = 0; i < cases; ++i) {
    const uint64_t seed = seed0 + static_cast<uint64_t>(i);
    Rng rng(seed * 4099 + 3);
    const RandomInstanceParams p = random_params(rng);
    const bool transpose = rng.below(2) == 0;
    const Instance made = random_instance(p, seed);
    const Instance inst = transpose ? test::rebuilt(made, true, false) : made;
    const std::string where = "seed " + std::to_string(seed) + " (nodes " + std::to_string(p.nodes) + ", ops " +
                              std::to_string(p.ops) + (transpose ? ", transposed" : "") +
                              "); replay with GRIDLOCK_TEST_SEED=" + std::to_string(seed);
    Simulator sim(inst);
    if (!sim.faces().faces.empty()) {  // a coupling breaks a cycle: find_collision's first step
      ++cycles;
      continue;
    }
    const auto groups = one_axis_group_pairs(inst, sim.regions());
    if (!p.horizontal_only) {
      bool x = false, y = false;
      for (const Operation& op : inst.ops()) (is_horizontal(op.dir) ? x : y) = true;
      if (x && y) {
        ASSERT_FALSE(groups) << where;
        ++mixed;
        continue;
      }
    }
    ASSERT_TRUE(groups) << where;
    const size_t R = sim.regions().size();
    // O(1) pairs per region: a group holds two units and the regions of
    // their two operations.
    ASSERT_LE(groups->size(), 3 * R) << where;
    const bool all = pairwise_collision(inst, sim.tree(), sim.regions(), TimeModel::Continuous).has_value();
    const auto listed = listed_pairs_collision(inst, sim.tree(), sim.regions(), TimeModel::Continuous, *groups);
    ASSERT_EQ(listed.has_value(), all) << where;
    // The walk of the ends, on every pair: the same nets as the traversal,
    // in both models.
    const auto everything = every_pair(R);
    ASSERT_EQ(listed_pairs_collision(inst, sim.tree(), sim.regions(), TimeModel::Continuous, everything).has_value(),
              all)
        << where;
    const bool all_discrete = pairwise_collision(inst, sim.tree(), sim.regions(), TimeModel::Discrete).has_value();
    ASSERT_EQ(all_discrete, all) << where << " (the models agree)";
    ASSERT_EQ(listed_pairs_collision(inst, sim.tree(), sim.regions(), TimeModel::Discrete, everything).has_value(),
              all_discrete)
        << where;
    // The whole answer, both models, against the all-pairs method.
    bool any_coupling = false;  // then Auto takes the group pairs (one coupling: the single-coupling step)
    for (const Coupling& cp : inst.couplings()) any_coupling |= cp.ops.size() > 1;
    if (!inst.ops().empty()) {
      for (TimeModel model : {TimeModel::Continuous, TimeModel::Discrete}) {
        const CollideResult a = find_collision(inst, model);
        if (any_coupling && inst.couplings().size() > 1) {
          ASSERT_EQ(a.algorithm.rfind("one-axis-groups", 0), 0u) << where << ": " << a.algorithm;
          ++by_auto;
        }
        const CollideResult b = find_collision(inst, model, CollideMethod::Pairwise);
        ASSERT_EQ(a.collides, all) << where;
        ASSERT_EQ(b.collides, all) << where;
        ASSERT_EQ(a.stats.witness_fallbacks, 0u) << where;
      }
    }
    if (inst.couplings().size() <= 6) {
      ASSERT_EQ(test::brute_discrete(inst).collides, all) << where << " (brute force: every order simulated)";
      ++brute;
    }
    ++decided, yes += all, vertical += transpose;
    group_pairs += groups->size(), regions += R, all_pairs += everything.size();
  }
  std::cout << "[ info ] one axis, any couplings: " << decided << " instances (" << yes << " collide, " << vertical
            << " vertical, " << brute << " against the brute force, " << by_auto << " answers of Auto by the groups), "
            << mixed << " on both axes, " << cycles << " breaking a cycle; " << group_pairs << " group pairs for "
            << regions << " regions (all pairs " << all_pairs << ")\n";
  EXPECT_GT(yes, cases / 10);
  EXPECT_GT(decided - yes, cases / 10);
  EXPECT_GT(vertical, cases / 5);
}

// Planted bugs the test above must catch, on the same seeds: fewer pairs
// (each group's two ends only) miss collisions.
TEST(OneAxisGroups, GroupEndsAloneAreNotEnough) {
  const uint64_t seed0 = test::base_seed(29000);
  int missed = 0;
  for (int i = 0; i < 3000 && missed == 0; ++i) {
    const uint64_t seed = seed0 + static_cast<uint64_t>(i);
    Rng rng(seed * 4099 + 3);
    RandomInstanceParams p = random_params(rng);
    p.horizontal_only = true;
    const Instance inst = random_instance(p, seed);
    Simulator sim(inst);
    if (!sim.faces().faces.empty()) continue;
    const auto groups = one_axis_group_pairs(inst, sim.regions());
    ASSERT_TRUE(groups);
    // Consecutive units only: drop every pair with a region that is not a unit node.
    std::vector<std::pair<uint32_t, uint32_t>> units;
    const std::vector<RegionForm> forms = region_forms(inst, sim.regions());
    for (const auto& [a, b] : *groups)
      if (forms[a].own == kNone && forms[b].own == kNone && a < inst.num_nodes() && b < inst.num_nodes())
        units.emplace_back(a, b);
    const bool all = pairwise_collision(inst, sim.tree(), sim.regions(), TimeModel::Continuous).has_value();
    missed += all && !listed_pairs_collision(inst, sim.tree(), sim.regions(), TimeModel::Continuous, units);
  }
  EXPECT_GT(missed, 0) << "the regions between two units matter: some instance needs them";
}

}  // namespace
}  // namespace gridlock
