// The adversarial serpentines (collide/adversarial.hpp) against the
// brute-force twins (tests/support/reference_collide) and the methods
// against each other; and the two properties the bench relies on: with
// expansions only the answer is NO, and the distance filter passes most
// pairs.
#include <gtest/gtest.h>

#include <iostream>
#include <numeric>
#include <string>

#include "collide/adversarial.hpp"
#include "collide/collide.hpp"
#include "collide/internal/collide_pairs.hpp"
#include "collide/internal/collide_tree.hpp"
#include "common/random.hpp"
#include "lattice/random_instance.hpp"
#include "lattice/simulate.hpp"
#include "support/reference_collide.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

std::string describe(uint64_t seed, const SerpentineParams& p) {
  return "seed " + std::to_string(seed) + " (columns " + std::to_string(p.columns) + ", height " +
         std::to_string(p.height) + ", coupling size " + std::to_string(p.coupling_size) + ", " +
         (p.couplings == SerpentineCouplings::Mixed ? "mixed" : "columns") + ", contract " +
         std::to_string(p.contract_percent) + "%); replay with GRIDLOCK_TEST_SEED";
}

SerpentineParams small_params(Rng& rng) {
  SerpentineParams p;
  p.columns = 1 + static_cast<uint32_t>(rng.below(4));
  p.height = 2 + static_cast<uint32_t>(rng.below(5));
  p.coupling_size = 1 + static_cast<uint32_t>(rng.below(4));
  p.couplings = rng.below(2) == 0 ? SerpentineCouplings::Mixed : SerpentineCouplings::Columns;
  p.contract_percent = static_cast<uint32_t>(rng.below(3)) * 30;
  return p;
}

// Auto and Pairwise (and the tree methods without couplings) must all say
// `expect`; find_collision itself checks every YES witness in the simulator.
void check_methods(const Instance& inst, TimeModel model, bool expect) {
  bool singletons = true;
  for (const auto& c : inst.couplings()) singletons = singletons && c.ops.size() == 1;
  std::vector<CollideMethod> methods{CollideMethod::Auto, CollideMethod::Pairwise};
  if (singletons) methods.push_back(CollideMethod::Tree), methods.push_back(CollideMethod::TreePairwise);
  for (CollideMethod m : methods) {
    CollideResult r = find_collision(inst, model, m);
    ASSERT_EQ(r.collides, expect) << "method " << static_cast<int>(m) << " (" << r.algorithm << "), "
                                  << (model == TimeModel::Continuous ? "continuous" : "discrete");
  }
}

// Small serpentines (expansions and contractions, both groupings) against
// every order (discrete) and every order + per-pair vertex enumeration
// (continuous).
TEST(CollideAdversarial, SmallSerpentinesAgainstBruteForce) {
  int compared_d = 0, compared_c = 0, yes_d = 0, yes_c = 0;
  for (int i = 0; i < test::scaled(1500); ++i) {
    uint64_t seed = test::base_seed(61000) + static_cast<uint64_t>(i);
    Rng rng(seed * 6151 + 3);
    SerpentineParams p = small_params(rng);
    Instance inst = serpentine_instance(p, seed);
    SCOPED_TRACE(describe(seed, p));
    if (inst.couplings().empty()) continue;
    if (inst.couplings().size() <= 5) {
      bool d = test::brute_discrete(inst).collides;
      check_methods(inst, TimeModel::Discrete, d);
      ++compared_d, yes_d += d;
    }
    if (inst.couplings().size() <= 4) {
      bool c = test::brute_continuous(inst).collides;
      check_methods(inst, TimeModel::Continuous, c);
      ++compared_c, yes_c += c;
    }
    if (::testing::Test::HasFatalFailure()) return;
  }
  std::cout << "[collide] serpentines vs brute force: discrete " << compared_d << " (" << yes_d << " YES), continuous "
            << compared_c << " (" << yes_c << " YES)\n";
  EXPECT_GT(compared_d, test::scaled(1500) / 2);
  EXPECT_GT(yes_d, 0);
  EXPECT_LT(yes_d, compared_d);
}

// Medium serpentines: the two models and the methods against each other
// (discrete YES implies continuous YES; Auto = Pairwise; without couplings
// the centroid algorithm and its twins agree), and with expansions only
// both models answer NO (the argument in collide/adversarial.hpp).
TEST(CollideAdversarial, MediumSerpentinesMethodsAgree) {
  int yes = 0, no = 0;
  for (int i = 0; i < test::scaled(150); ++i) {
    uint64_t seed = test::base_seed(62000) + static_cast<uint64_t>(i);
    Rng rng(seed * 7349 + 11);
    SerpentineParams p;
    p.columns = 2 + static_cast<uint32_t>(rng.below(6));
    p.height = 4 + static_cast<uint32_t>(rng.below(6));
    p.coupling_size = static_cast<uint32_t>(rng.below(5));  // 0: sqrt
    p.couplings = rng.below(2) == 0 ? SerpentineCouplings::Mixed : SerpentineCouplings::Columns;
    p.contract_percent = rng.below(2) == 0 ? 0 : 10 + static_cast<uint32_t>(rng.below(30));
    Instance inst = serpentine_instance(p, seed);
    SCOPED_TRACE(describe(seed, p));
    CollideResult c = find_collision(inst, TimeModel::Continuous, CollideMethod::Pairwise);
    CollideResult d = find_collision(inst, TimeModel::Discrete, CollideMethod::Pairwise);
    if (p.contract_percent == 0) {
      ASSERT_FALSE(c.collides);
      ASSERT_FALSE(d.collides);
    }
    if (d.collides) {
      ASSERT_TRUE(c.collides);
    }
    check_methods(inst, TimeModel::Continuous, c.collides);
    check_methods(inst, TimeModel::Discrete, d.collides);
    if (inst.couplings().size() <= 5) {
      ASSERT_EQ(d.collides, test::brute_discrete(inst).collides);
    }
    (d.collides ? yes : no)++;
  }
  std::cout << "[collide] medium serpentines: discrete " << yes << " YES, " << no << " NO\n";
}

// What makes the family adversarial: on a square serpentine the distance
// filter passes most pairs, and the paths carry many couplings.
TEST(CollideAdversarial, FilterPassesMostPairs) {
  for (SerpentineCouplings how : {SerpentineCouplings::Mixed, SerpentineCouplings::Columns}) {
    Instance inst = serpentine_instance(square_serpentine(256, 3, how), 1);
    ASSERT_EQ(inst.num_nodes(), 256u);
    CollideResult r = find_collision(inst, TimeModel::Continuous, CollideMethod::Pairwise);
    ASSERT_FALSE(r.collides);
    EXPECT_GT(r.stats.full_tests * 4, r.stats.pairs * 3) << r.stats.full_tests << " of " << r.stats.pairs;
  }
}

// The incremental support values (ZonotopeTest::Incremental) against the
// per-pair rebuild (PerPair): with Both, every pair that passes the filter
// is decided both ways and a disagreement throws; the first colliding pair
// found must be the same. Random instances with couplings and serpentines.
void incremental_twin(const Instance& inst, uint64_t& pairs_compared) {
  Simulator sim(inst);
  for (char b : sim.faces().coupling_breaks_cycle)
    if (b) return;  // the cycle step answers; no pairwise run
  PairwiseStats st;
  auto both = pairwise_collision(inst, sim.tree(), sim.regions(), TimeModel::Continuous, &st, nullptr,
                                 ZonotopeTest::Both);
  auto fast = pairwise_collision(inst, sim.tree(), sim.regions(), TimeModel::Continuous, nullptr, nullptr,
                                 ZonotopeTest::Incremental);
  auto slow = pairwise_collision(inst, sim.tree(), sim.regions(), TimeModel::Continuous, nullptr, nullptr,
                                 ZonotopeTest::PerPair);
  ASSERT_EQ(fast.has_value(), slow.has_value());
  ASSERT_EQ(both.has_value(), slow.has_value());
  if (fast) {
    EXPECT_EQ(fast->a, slow->a);
    EXPECT_EQ(fast->b, slow->b);
  }
  pairs_compared += st.full_tests;
}

// The fan serpentine (Fan couplings): NO for every method in both models
// with expansions only (brute force on the smallest), one coupling per
// direction of the largest fan that fits, the support table and the angle
// tree agree with the per-pair rebuild, the distance filter passes most
// pairs; with contractions, the methods agree with each other.
TEST(CollideAdversarial, FanSerpentinesMethodsAgree) {
  uint64_t pairs = 0;
  int yes = 0;
  for (int64_t n : {8, 12, 20, 32, 48, 80, 120})
    for (uint64_t seed = 1; seed <= 4; ++seed) {
      SerpentineParams p = fan_serpentine(n);
      p.contract_percent = seed == 4 ? 20 : 0;
      const Instance inst = serpentine_instance(p, seed);
      SCOPED_TRACE("n " + std::to_string(n) + ", seed " + std::to_string(seed));
      const uint32_t L = fan_size(p.columns - 1, p.columns);
      uint32_t grouped = 0;
      for (uint32_t s = 2; s <= L; ++s)
        for (uint32_t a = 0; a <= s; ++a) grouped += std::gcd(a, s - a) == 1;
      uint32_t couplings = 0;
      for (const auto& c : inst.couplings()) couplings += c.ops.size() > 1;
      ASSERT_EQ(couplings, grouped);
      const bool expect = find_collision(inst, TimeModel::Continuous, CollideMethod::Pairwise).collides;
      if (p.contract_percent == 0) {
        ASSERT_FALSE(expect);
      }
      yes += expect;
      check_methods(inst, TimeModel::Continuous, expect);
      if (inst.couplings().size() <= 6) {
        ASSERT_EQ(find_collision(inst, TimeModel::Discrete).collides, test::brute_discrete(inst).collides);
      }
      incremental_twin(inst, pairs);
      Simulator sim(inst);
      const bool tree = pairwise_collision(inst, sim.tree(), sim.regions(), TimeModel::Continuous, nullptr, nullptr,
                                           ZonotopeTest::AngleTree)
                            .has_value();
      ASSERT_EQ(tree, expect);
    }
  EXPECT_GT(pairs, 10000u);
  const Instance big = serpentine_instance(fan_serpentine(1000), 1);
  const CollideResult r = find_collision(big, TimeModel::Continuous, CollideMethod::Pairwise);
  ASSERT_FALSE(r.collides);
  EXPECT_GT(r.stats.full_tests * 4, r.stats.pairs * 3) << r.stats.full_tests << " of " << r.stats.pairs;
  std::cout << "[collide] fan serpentines: " << pairs << " pairs compared, " << yes << " YES with contractions; n "
            << big.num_nodes() << ": L " << fan_size(249, 250) << ", " << big.couplings().size() << " couplings\n";
}

// Progress: the pairwise step reports through find_collision's callback
// (growing counts of source nodes, the last with done == total on a NO),
// and a listener does not change the answer.
TEST(CollideAdversarial, PairwiseStepReportsProgress) {
  const Instance inst = serpentine_instance(square_serpentine(256, 3, SerpentineCouplings::Mixed), 1);
  std::vector<CollideProgress> seen;
  const CollideResult r = find_collision(inst, TimeModel::Continuous, CollideMethod::Auto, nullptr,
                                         [&](const CollideProgress& p) { seen.push_back(p); });
  ASSERT_FALSE(r.collides);
  ASSERT_GE(seen.size(), 2u);
  for (size_t i = 0; i < seen.size(); ++i) {
    EXPECT_EQ(seen[i].step, r.algorithm);
    EXPECT_EQ(seen[i].total, inst.num_nodes());
    EXPECT_LE(seen[i].done, seen[i].total);
    if (i > 0) {
      EXPECT_GE(seen[i].done, seen[i - 1].done);
      EXPECT_GE(seen[i].seconds, seen[i - 1].seconds);
    }
  }
  EXPECT_EQ(seen.back().done, seen.back().total);
  const CollideResult quiet = find_collision(inst, TimeModel::Continuous);
  EXPECT_EQ(quiet.collides, r.collides);
  EXPECT_EQ(quiet.stats.full_tests, r.stats.full_tests);
}

TEST(CollideAdversarial, IncrementalSupportsAgainstPerPair) {
  uint64_t pairs = 0;
  int instances = 0;
  for (int i = 0; i < test::scaled(2000); ++i) {
    uint64_t seed = test::base_seed(63000) + static_cast<uint64_t>(i);
    Rng rng(seed * 3571 + 5);
    RandomInstanceParams p;
    p.nodes = 4 + static_cast<uint32_t>(rng.below(60));
    p.ops = 2 + static_cast<uint32_t>(rng.below(p.nodes / 2 + 1));
    p.max_coupling = 2 + static_cast<uint32_t>(rng.below(6));
    p.extra_edge_percent = rng.below(4) == 0 ? 30 : 0;
    p.horizontal_only = rng.below(8) == 0;
    p.path_shape = rng.below(4) == 0;
    p.spread = static_cast<uint32_t>(rng.below(3));
    Instance inst = random_instance(p, seed);
    SCOPED_TRACE("random instance seed " + std::to_string(seed) + "; replay with GRIDLOCK_TEST_SEED");
    incremental_twin(inst, pairs);
    ++instances;
    if (::testing::Test::HasFatalFailure()) return;
  }
  for (int i = 0; i < test::scaled(500); ++i) {
    uint64_t seed = test::base_seed(64000) + static_cast<uint64_t>(i);
    Rng rng(seed * 1223 + 9);
    SerpentineParams p;
    p.columns = 2 + static_cast<uint32_t>(rng.below(8));
    p.height = 3 + static_cast<uint32_t>(rng.below(8));
    p.coupling_size = static_cast<uint32_t>(rng.below(6));
    p.couplings = rng.below(2) == 0 ? SerpentineCouplings::Mixed : SerpentineCouplings::Columns;
    p.contract_percent = rng.below(2) == 0 ? 0 : static_cast<uint32_t>(rng.below(20));
    Instance inst = serpentine_instance(p, seed);
    SCOPED_TRACE(describe(seed, p));
    incremental_twin(inst, pairs);
    ++instances;
    if (::testing::Test::HasFatalFailure()) return;
  }
  // Larger serpentines with big couplings: many lines come and go, so the
  // table drops its empty lines (the purge path) during the run.
  uint64_t purges = 0;
  for (uint64_t seed = test::base_seed(65000); seed < test::base_seed(65000) + 4; ++seed) {
    Instance inst = serpentine_instance(
        square_serpentine(144 + 16 * static_cast<int64_t>(seed % 4), 0, SerpentineCouplings::Mixed), seed);
    SCOPED_TRACE("square serpentine seed " + std::to_string(seed));
    Simulator sim(inst);
    PairwiseStats st;
    auto r = pairwise_collision(inst, sim.tree(), sim.regions(), TimeModel::Continuous, &st, nullptr,
                                ZonotopeTest::Both);
    ASSERT_FALSE(r.has_value());
    pairs += st.full_tests, purges += st.line_purges, ++instances;
  }
  EXPECT_GT(purges, 0u);
  std::cout << "[collide] incremental vs per-pair zonotope: " << instances << " instances, " << pairs
            << " pairs decided both ways, " << purges << " line purges\n";
  EXPECT_GT(pairs, 10000u);
}

TEST(CollideAdversarial, BadParametersThrow) {
  SerpentineParams p;
  p.columns = 0;
  EXPECT_THROW(serpentine_instance(p, 1), std::invalid_argument);
  p.columns = 2, p.height = 1;
  EXPECT_THROW(serpentine_instance(p, 1), std::invalid_argument);
  p.height = 4, p.contract_percent = 101;
  EXPECT_THROW(serpentine_instance(p, 1), std::invalid_argument);
}

}  // namespace
}  // namespace gridlock
