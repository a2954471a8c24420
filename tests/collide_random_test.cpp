// Colliding Schedule: every algorithm against the brute-force twins
// (tests/support/reference_collide) on seeded random instances, and the
// algorithms that apply to an instance against each other.
#include <gtest/gtest.h>

#include "collide/collide.hpp"
#include "collide/internal/collide_pairs.hpp"
#include "collide/internal/collide_tree.hpp"
#include "common/random.hpp"
#include "lattice/random_instance.hpp"
#include "support/reference_collide.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

RandomInstanceParams tiny_params(Rng& rng, uint32_t max_coupling, uint32_t max_ops = 5) {
  RandomInstanceParams p;
  p.nodes = 2 + static_cast<uint32_t>(rng.below(8 + max_ops - 5));
  p.ops = 1 + static_cast<uint32_t>(rng.below(max_ops));
  p.max_coupling = max_coupling;
  p.extra_edge_percent = rng.below(3) == 0 ? 40 : 0;
  p.horizontal_only = rng.below(6) == 0;
  p.path_shape = rng.below(5) == 0;
  p.spread = static_cast<uint32_t>(rng.below(3));
  return p;
}

std::string describe_seed(uint64_t seed, const RandomInstanceParams& p) {
  return "seed " + std::to_string(seed) + " (nodes " + std::to_string(p.nodes) + ", ops " + std::to_string(p.ops) +
         ", max_coupling " + std::to_string(p.max_coupling) + ", extra edges " + std::to_string(p.extra_edge_percent) +
         "%); replay with GRIDLOCK_TEST_SEED";
}

// Every method that applies, in one model; all must agree with `expect`.
void check_all_methods(const Instance& inst, TimeModel model, bool expect, const std::string& where) {
  bool singletons = true;
  for (const auto& c : inst.couplings()) singletons = singletons && c.ops.size() == 1;
  std::vector<CollideMethod> methods{CollideMethod::Auto, CollideMethod::Pairwise};
  if (singletons) methods.push_back(CollideMethod::Tree), methods.push_back(CollideMethod::TreePairwise);
  for (CollideMethod m : methods) {
    CollideResult r = find_collision(inst, model, m);  // throws if a witness fails the simulator
    ASSERT_EQ(r.collides, expect) << where << ": method " << static_cast<int>(m) << " (" << r.algorithm << "), "
                                  << (model == TimeModel::Continuous ? "continuous" : "discrete");
    if (r.collides && model == TimeModel::Discrete) {
      ASSERT_EQ(r.witness.order.size(), inst.couplings().size()) << where;
    }
  }
}

int g_compared_discrete = 0, g_compared_continuous = 0;
struct Tally {
  int yes = 0, no = 0, cycle = 0, continuous_only = 0, pairwise_used = 0;
};
Tally g_tally;

void run_against_brute(uint64_t seed0, int cases, uint32_t max_coupling, size_t max_couplings_cont,
                       uint32_t max_ops = 5) {
  for (int i = 0; i < cases; ++i) {
    uint64_t seed = seed0 + static_cast<uint64_t>(i);
    Rng rng(seed * 7919 + 17);
    RandomInstanceParams p = tiny_params(rng, max_coupling, max_ops);
    Instance inst = random_instance(p, seed);
    std::string where = describe_seed(seed, p);
    SCOPED_TRACE(where);
    if (inst.couplings().size() <= 6) {
      bool d = test::brute_discrete(inst).collides;
      check_all_methods(inst, TimeModel::Discrete, d, where);
      CollideResult r = find_collision(inst, TimeModel::Discrete);
      (d ? g_tally.yes : g_tally.no)++;
      g_tally.cycle += r.algorithm == "cycle";
      g_tally.pairwise_used += r.algorithm.rfind("pairwise", 0) == 0;
      ++g_compared_discrete;
    }
    if (inst.couplings().size() <= max_couplings_cont) {
      test::BruteAnswer c = test::brute_continuous(inst);
      check_all_methods(inst, TimeModel::Continuous, c.collides, where);
      g_tally.continuous_only += c.from_pair_test;
      ++g_compared_continuous;
    }
    if (::testing::Test::HasFatalFailure()) return;
  }
}

TEST(CollideRandom, NoCouplingsAgainstBruteForce) {
  run_against_brute(test::base_seed(1000), test::scaled(1500), 1, 4);
  std::cout << "[collide] compared so far: " << g_compared_discrete << " discrete, " << g_compared_continuous
            << " continuous\n";
}

TEST(CollideRandom, CouplingsAgainstBruteForce) {
  run_against_brute(test::base_seed(50000), test::scaled(1500), 3, 4);
  std::cout << "[collide] compared so far: " << g_compared_discrete << " discrete, " << g_compared_continuous
            << " continuous\n";
}

TEST(CollideRandom, LargeCouplingsAgainstBruteForce) {
  run_against_brute(test::base_seed(90000), test::scaled(600), 5, 4);
  // More operations per coupling, fewer couplings: where continuous-only
  // collisions (overlapping start times) show up.
  run_against_brute(test::base_seed(120000), test::scaled(1500), 4, 4, 10);
  std::cout << "[collide] compared in all: " << g_compared_discrete << " discrete, " << g_compared_continuous
            << " continuous; discrete YES " << g_tally.yes << " / NO " << g_tally.no << ", cycle " << g_tally.cycle
            << ", per-pair method " << g_tally.pairwise_used << ", continuous-only YES " << g_tally.continuous_only
            << "\n";
}

// Without couplings the discrete and the continuous answers are the same
// (paper: the reachable boxes are the same in both models).
TEST(CollideRandom, NoCouplingsModelsAgree) {
  for (int i = 0; i < test::scaled(400); ++i) {
    uint64_t seed = test::base_seed(7000) + static_cast<uint64_t>(i);
    RandomInstanceParams p;
    p.nodes = 10 + static_cast<uint32_t>(seed % 40);
    p.ops = 2 + static_cast<uint32_t>(seed % 9);
    p.extra_edge_percent = seed % 4 == 0 ? 20 : 0;
    Instance inst = random_instance(p, seed);
    SCOPED_TRACE(describe_seed(seed, p));
    CollideResult c = find_collision(inst, TimeModel::Continuous);
    CollideResult d = find_collision(inst, TimeModel::Discrete);
    ASSERT_EQ(c.collides, d.collides);
    if (inst.couplings().size() <= 6) {
      ASSERT_EQ(d.collides, test::brute_discrete(inst).collides);
    }
  }
}

// Larger trees without couplings: the centroid algorithm, its all-pairs
// twin, and the general per-pair method agree (few operations, so that NO
// answers are common too).
TEST(CollideRandom, CentroidAgainstPairwiseOnLargerTrees) {
  int yes = 0, no = 0;
  for (int i = 0; i < test::scaled(300); ++i) {
    uint64_t seed = test::base_seed(20000) + static_cast<uint64_t>(i);
    RandomInstanceParams p;
    p.nodes = 20 + static_cast<uint32_t>(seed % 180);
    p.ops = 1 + static_cast<uint32_t>(seed % 12);
    p.spread = static_cast<uint32_t>(seed % 5);
    p.path_shape = seed % 7 == 0;
    p.allow_grow = seed % 3 != 0;
    Instance inst = random_instance(p, seed);
    SCOPED_TRACE(describe_seed(seed, p));
    Simulator sim(inst);
    bool cyc = false;
    for (char b : sim.faces().coupling_breaks_cycle) cyc = cyc || b;
    ASSERT_FALSE(cyc);
    auto a = tree_collision(inst, sim.tree(), sim.regions());
    auto b = tree_collision_pairwise(inst, sim.tree(), sim.regions());
    auto c = pairwise_collision(inst, sim.tree(), sim.regions(), TimeModel::Continuous);
    auto d = pairwise_collision(inst, sim.tree(), sim.regions(), TimeModel::Discrete);
    ASSERT_EQ(a.has_value(), b.has_value());
    ASSERT_EQ(a.has_value(), c.has_value());
    ASSERT_EQ(a.has_value(), d.has_value());
    (a ? yes : no)++;
    find_collision(inst, TimeModel::Continuous);  // witness check
  }
  std::cout << "[collide] larger trees: " << yes << " YES, " << no << " NO\n";
}

// Couplings on medium instances: continuous and discrete per-pair methods
// against the discrete brute force where it can run; discrete YES implies
// continuous YES (every order is a continuous schedule). The discrete side
// is the subset-sum decider on its own (Auto's discrete answer is the
// continuous decision, checked against it in the same way).
TEST(CollideRandom, CouplingsMediumInstances) {
  for (int i = 0; i < test::scaled(200); ++i) {
    uint64_t seed = test::base_seed(30000) + static_cast<uint64_t>(i);
    RandomInstanceParams p;
    p.nodes = 12 + static_cast<uint32_t>(seed % 30);
    p.ops = 4 + static_cast<uint32_t>(seed % 10);
    p.max_coupling = 2 + static_cast<uint32_t>(seed % 4);
    p.extra_edge_percent = seed % 5 == 0 ? 30 : 0;
    p.horizontal_only = seed % 6 == 0;
    Instance inst = random_instance(p, seed);
    SCOPED_TRACE(describe_seed(seed, p));
    CollideResult c = find_collision(inst, TimeModel::Continuous);
    CollideResult d = find_collision(inst, TimeModel::Discrete, CollideMethod::Pairwise);
    if (d.collides) {
      ASSERT_TRUE(c.collides);
    }
    ASSERT_EQ(find_collision(inst, TimeModel::Discrete).collides, d.collides);
    if (inst.couplings().size() <= 6) {
      ASSERT_EQ(d.collides, test::brute_discrete(inst).collides);
    }
  }
}

}  // namespace
}  // namespace gridlock
