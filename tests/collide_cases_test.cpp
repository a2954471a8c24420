// Colliding Schedule on hand-made cases: docs/model.md's worked cases, growth
// into an occupied cell, touching is no collision, contraction widths,
// cycles; every applicable method, both models.
#include <gtest/gtest.h>

#include <algorithm>

#include "collide/collide.hpp"
#include "lattice/random_instance.hpp"
#include "support/instance_io.hpp"
#include "support/reference_collide.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

Instance parse(const std::string& text) { return test::parse_instance(text); }
Instance load(const std::string& name) { return test::load_example(name); }

void expect_answer(const Instance& inst, TimeModel model, bool expect) {
  bool singletons = true;
  for (const auto& c : inst.couplings()) singletons = singletons && c.ops.size() == 1;
  std::vector<CollideMethod> ms{CollideMethod::Auto, CollideMethod::Pairwise};
  if (singletons) ms.push_back(CollideMethod::Tree), ms.push_back(CollideMethod::TreePairwise);
  for (CollideMethod m : ms) {
    CollideResult r = find_collision(inst, model, m);
    EXPECT_EQ(r.collides, expect) << r.algorithm;
    if (r.collides) {
      EXPECT_TRUE(r.simulated.has_value());
    }
  }
  if (inst.couplings().size() <= 5) {
    bool b = model == TimeModel::Discrete ? test::brute_discrete(inst).collides : test::brute_continuous(inst).collides;
    EXPECT_EQ(b, expect) << "brute force";
  }
}

void expect_both_models(const Instance& inst, bool expect) {
  expect_answer(inst, TimeModel::Discrete, expect);
  expect_answer(inst, TimeModel::Continuous, expect);
}

TEST(CollideCases, ModelCase1TwoGrowths) {
  Instance inst = load("model-case1-two-growths.grid");
  expect_both_models(inst, true);
}

TEST(CollideCases, ModelCase2OrderGadget) {
  Instance inst = load("model-case2-order-gadget.grid");
  expect_answer(inst, TimeModel::Discrete, true);  // b then a
  expect_answer(inst, TimeModel::Continuous, true);
  CollideResult r = find_collision(inst, TimeModel::Discrete);
  EXPECT_EQ(inst.couplings()[r.witness.order[0]].name, "b");
}

TEST(CollideCases, ModelCase3Block) {
  Instance coupled = load("model-case3-block.grid");  // a and b coupled: no collision
  expect_both_models(coupled, false);
  EXPECT_EQ(find_collision(coupled, TimeModel::Continuous).algorithm, "single-coupling-one-axis");
  Instance single = parse(
      "p grid 4 4 1 0\nn 0 0\nn 1 0\nn 0 1\nn 1 1\ne 0 0 1 0\ne 0 1 1 1\ne 0 0 0 1\ne 1 0 1 1\no a expand 0 0 +x\n");
  CollideResult r = find_collision(single, TimeModel::Discrete);
  ASSERT_TRUE(r.collides);
  EXPECT_EQ(r.algorithm, "cycle");
  ASSERT_TRUE(r.simulated.has_value());
  EXPECT_EQ(r.simulated->kind, Collision::Kind::Cycle);
  expect_answer(single, TimeModel::Continuous, true);
}

// (0,0) grows into (1,0), where an unjoined node sits.
TEST(CollideCases, GrowthIntoOccupiedCell) {
  Instance inst = parse(
      "p grid 4 3 1 0\nn 0 0\nn 1 0\nn 0 1\nn 1 1\ne 0 0 0 1\ne 0 1 1 1\ne 1 1 1 0\no g grow 0 0 +x\n");
  expect_both_models(inst, true);
}

// An expansion pushes (2,0) and (2,1) right along (1,1): they only slide
// past each other's faces (touching), never overlap.
TEST(CollideCases, SlidingAlongIsNoCollision) {
  Instance inst = parse(
      "p grid 5 4 1 0\nn 0 0\nn 1 0\nn 2 0\nn 1 1\nn 2 1\ne 0 0 1 0\ne 1 0 2 0\ne 1 0 1 1\ne 2 0 2 1\n"
      "o a expand 1 0 +x\n");
  expect_both_models(inst, false);
}

// Contracting (1,0) into (0,0) pulls (2,0), (2,1) left: (2,1) runs into
// (1,1), which hangs off (0,0) through (0,1).
TEST(CollideCases, ContractionPullsIntoNeighbour) {
  Instance inst = parse(
      "p grid 6 5 1 0\nn 0 0\nn 1 0\nn 2 0\nn 2 1\nn 0 1\nn 1 1\ne 0 0 1 0\ne 1 0 2 0\ne 2 0 2 1\ne 0 0 0 1\n"
      "e 0 1 1 1\no c contract 0 0 +x\n");
  expect_both_models(inst, true);
}

// (1,0) contracts into (2,0), emptying its cell from the left, while (0,0)
// (unjoined to (1,0)) grows into that cell. Contraction first empties the
// cell (a width-0 region never collides); growth first (or both at once)
// meets the contracting node: Colliding is YES in both models.
TEST(CollideCases, GrowthIntoContractingCell) {
  Instance inst = parse(
      "p grid 6 5 2 0\nn 0 0\nn 1 0\nn 2 0\nn 0 1\nn 1 1\nn 2 1\ne 0 0 0 1\ne 0 1 1 1\ne 1 1 2 1\ne 2 1 2 0\n"
      "e 1 0 2 0\no g grow 0 0 +x\no c contract 2 0 -x\n");
  // g grows into (1,0) while (1,0) still occupies it (growth into an occupied cell).
  expect_both_models(inst, true);
}

}  // namespace
}  // namespace gridlock

namespace gridlock {
namespace {

// The cycle step relies on the face walks (FaceNets): a coupling can break
// some cycle iff it has a non-zero net around some face walk. The paper's
// lemma says elementary cycles (bounded faces of the biconnected blocks)
// suffice. Checked here against every fundamental cycle of a depth-first
// spanning tree (which together generate the whole cycle space), coupling
// by coupling, on random shapes with many cycles.
TEST(CollideCycles, FaceWalksDecideLikeAllFundamentalCycles) {
  int breaking = 0;
  for (int i = 0; i < test::scaled(2000); ++i) {
    uint64_t seed = test::base_seed(60000) + static_cast<uint64_t>(i);
    RandomInstanceParams p;
    p.nodes = 4 + static_cast<uint32_t>(seed % 30);
    p.ops = 1 + static_cast<uint32_t>(seed % 8);
    p.max_coupling = 1 + static_cast<uint32_t>(seed % 4);
    p.extra_edge_percent = 20 + static_cast<uint32_t>(seed % 60);
    Instance inst = random_instance(p, seed);
    const size_t nq = inst.couplings().size();
    test::CouplingDisplacements cd = test::coupling_displacements(inst);
    std::vector<char> breaks(nq, 0);
    for (uint32_t e = 0; e < inst.edges().size(); ++e) {
      if (cd.tree_edge[e]) continue;
      const Edge& ed = inst.edges()[e];
      Vec2 back = test::edge_vector(inst, e, ed.b);  // the edge walked b -> a
      for (CouplingId q = 0; q < nq; ++q) {
        Vec2 around = cd.disp[ed.b][q] - cd.disp[ed.a][q];  // tree path a -> b
        if (ed.op != kNone && inst.ops()[ed.op].coupling == q) around += back;
        if (!around.is_zero()) breaks[q] = 1;
      }
    }
    FaceNets f = FaceNets::build(inst);
    for (CouplingId q = 0; q < nq; ++q) {
      ASSERT_EQ(static_cast<bool>(f.coupling_breaks_cycle[q]), static_cast<bool>(breaks[q])) << "seed " << seed;
      breaking += breaks[q];
    }
    bool any = std::find(breaks.begin(), breaks.end(), 1) != breaks.end();
    if (any) {
      ASSERT_EQ(find_collision(inst, TimeModel::Discrete).algorithm, "cycle") << "seed " << seed;
    }
  }
  std::cout << "[collide] cycle-breaking couplings seen: " << breaking << "\n";
}

}  // namespace
}  // namespace gridlock
