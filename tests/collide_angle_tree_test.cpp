// The paper's angle-sorted augmented tree (collide/internal/angle_tree.hpp) against
// brute force, and the pairwise method with it (ZonotopeTest::AngleTree)
// against the per-pair rebuild (the twin) on random instances and the
// adversarial serpentines.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "collide/adversarial.hpp"
#include "collide/internal/angle_tree.hpp"
#include "collide/internal/collide_pairs.hpp"
#include "common/random.hpp"
#include "lattice/random_instance.hpp"
#include "lattice/simulate.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

using i128 = __int128;

i128 cross(WidePoint o, WidePoint a, WidePoint b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

// The origin strictly inside the hull of `all`: no line through it has
// every point on one closed side (for each candidate direction, through the
// origin and a point, all points weakly on one side means outside or on the
// boundary). O(P^2).
bool origin_interior(const std::vector<WidePoint>& all) {
  const WidePoint o{0, 0};
  bool any_nonzero = false;
  for (const WidePoint& a : all) {
    if (a.x == 0 && a.y == 0) continue;
    any_nonzero = true;
    bool left = true, right = true;
    for (const WidePoint& b : all) {
      i128 c = cross(o, a, b);
      if (c > 0) right = false;
      if (c < 0) left = false;
    }
    if (left || right) return false;
  }
  return any_nonzero;
}

// Brute force: every subset sum of the vectors (scaled) plus every point.
bool brute_contains_origin(const std::vector<Vec2>& vecs, int64_t scale, const std::vector<WidePoint>& pts) {
  std::vector<WidePoint> all;
  for (uint32_t mask = 0; mask < (1u << vecs.size()); ++mask) {
    i128 x = 0, y = 0;
    for (size_t i = 0; i < vecs.size(); ++i)
      if (mask >> i & 1) x += vecs[i].x, y += vecs[i].y;
    for (const WidePoint& p : pts) all.push_back({scale * x + p.x, scale * y + p.y});
  }
  return origin_interior(all);
}

// A tree and the multiset of vectors it holds, changed together.
struct KeptTree {
  AngleTree tree;
  std::vector<Vec2> kept;
  void add(Vec2 v) { tree.add(v), kept.push_back(v); }
  void remove_at(size_t k) {
    tree.remove(kept[k]);
    kept.erase(kept.begin() + static_cast<std::ptrdiff_t>(k));
  }
};

// A vector with both coordinates uniform in [-span, span].
Vec2 random_vector(Rng& rng, int64_t span) {
  return Vec2{static_cast<int64_t>(rng.below(2 * static_cast<uint64_t>(span) + 1)) - span,
              static_cast<int64_t>(rng.below(2 * static_cast<uint64_t>(span) + 1)) - span};
}

TEST(AngleTree, ContainsOriginAgainstBruteForce) {
  const uint64_t seed0 = test::base_seed(71000);
  int inside = 0, cases = 0;
  for (int i = 0; i < test::scaled(4000); ++i) {
    const uint64_t seed = seed0 + static_cast<uint64_t>(i);
    SCOPED_TRACE("seed " + std::to_string(seed) + "; replay with GRIDLOCK_TEST_SEED");
    Rng rng(seed * 7919 + 3);
    KeptTree t;
    const int steps = 1 + static_cast<int>(rng.below(12));
    for (int s = 0; s < steps; ++s) {
      if (!t.kept.empty() && rng.below(3) == 0) {
        t.remove_at(rng.below(t.kept.size()));
      } else if (t.kept.size() < 7) {
        const int64_t span = rng.below(2) == 0 ? 2 : 5;
        t.add(random_vector(rng, span));
      }
    }
    const int64_t scale = 1 + static_cast<int64_t>(rng.below(3));
    std::vector<WidePoint> pts;
    const int np = 3 + static_cast<int>(rng.below(6));
    pts.reserve(static_cast<size_t>(np));
    for (int k = 0; k < np; ++k)
      pts.push_back({static_cast<i128>(rng.below(25)) - 12, static_cast<i128>(rng.below(25)) - 12});
    bool full = false;  // the polygon needs an interior
    for (size_t a = 1; a < pts.size() && !full; ++a)
      for (size_t b = a + 1; b < pts.size() && !full; ++b) full = cross(pts[0], pts[a], pts[b]) != 0;
    if (!full) continue;
    const bool fast = t.tree.contains_origin(scale, pts);
    ASSERT_EQ(fast, brute_contains_origin(t.kept, scale, pts));
    inside += fast, ++cases;
  }
  std::cout << "[collide] angle tree vs brute force: " << cases << " cases, " << inside << " inside\n";
  EXPECT_GT(inside, cases / 10);
  EXPECT_LT(inside, cases - cases / 10);
}

TEST(AngleTree, RemovingAbsentVectorThrows) {
  AngleTree tree;
  tree.add({1, 2});
  EXPECT_THROW(tree.remove({2, 1}), std::logic_error);
  std::vector<WidePoint> flat{{0, 0}, {1, 1}, {2, 2}};
  EXPECT_THROW(tree.contains_origin(1, flat), std::logic_error);
}

// The zonotope's vertices the naive way (every generator flipped into the
// upper half-plane, sorted by angle with std::sort, the walk N + prefix
// sums and back), each plus every point of pts: the origin is interior to
// the hull of these iff it is interior to scale * Z + Q. O(m log m + m r).
std::vector<WidePoint> sum_vertices(const std::vector<Vec2>& vecs, int64_t scale, const std::vector<WidePoint>& pts) {
  std::vector<Vec2> up;
  Vec2 base;
  for (Vec2 v : vecs) {
    if (v.is_zero()) continue;
    const bool upper = v.y > 0 || (v.y == 0 && v.x > 0);
    if (!upper) base += v;
    up.push_back(upper ? v : Vec2{-v.x, -v.y});
  }
  std::sort(up.begin(), up.end(), [](Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x > 0; });
  std::vector<Vec2> walk{base};
  for (Vec2 g : up) walk.push_back(walk.back() + g);
  for (Vec2 g : up) walk.push_back(walk.back() - g);
  std::vector<WidePoint> all;
  for (Vec2 w : walk)
    for (const WidePoint& p : pts)
      all.push_back({static_cast<i128>(scale) * w.x + p.x, static_cast<i128>(scale) * w.y + p.y});
  return all;
}

// Many directions with heavy churn (adds and removes in angle order, the
// order that unbalances a plain search tree, and at random): the height
// stays within the AVL bound 1.44 log2(m + 2), and every query agrees with
// the naive zonotope walk. Catches a rotation or a removal that loses a
// subtree's size or sum.
TEST(AngleTree, BalancedUnderChurnAndAgreesWithNaiveWalk) {
  const uint64_t seed0 = test::base_seed(71500);
  int queries = 0, inside = 0;
  uint32_t tallest = 0;
  for (int i = 0; i < test::scaled(300); ++i) {
    const uint64_t seed = seed0 + static_cast<uint64_t>(i);
    SCOPED_TRACE("seed " + std::to_string(seed) + "; replay with GRIDLOCK_TEST_SEED");
    Rng rng(seed * 6151 + 11);
    KeptTree t;
    const int64_t span = 3 + static_cast<int64_t>(rng.below(40));
    // Ascending angle: (span, 0), (span, 1), ..., then leftwards.
    for (int64_t k = 0; k <= span; ++k) t.add({span, k});
    for (int step = 0; step < 400; ++step) {
      if (!t.kept.empty() && rng.below(2) == 0)
        t.remove_at(rng.below(2) == 0 ? 0 : rng.below(t.kept.size()));  // often the first added
      else t.add(random_vector(rng, span));
      const double m = static_cast<double>(t.tree.directions());
      ASSERT_LE(static_cast<double>(t.tree.height()), 1.4405 * std::log2(m + 2) + 1e-9) << "m " << m;
      tallest = std::max(tallest, t.tree.height());
      if (step % 20 != 19) continue;
      std::vector<WidePoint> pts;
      pts.reserve(4);
      for (int k = 0; k < 4; ++k)
        pts.push_back({static_cast<i128>(rng.below(2001)) - 1000, static_cast<i128>(rng.below(2001)) - 1000});
      if (cross(pts[0], pts[1], pts[2]) == 0) continue;
      // Shift the polygon so the origin lands near the sum's boundary as
      // often as inside or outside it.
      const std::vector<WidePoint> near = sum_vertices(t.kept, 1, pts);
      const WidePoint pick = near[rng.below(near.size())];
      for (WidePoint& p : pts) p.x -= pick.x + static_cast<i128>(rng.below(3)) - 1, p.y -= pick.y;
      std::vector<WidePoint> copy = pts;
      const bool fast = t.tree.contains_origin(1, copy);
      ASSERT_EQ(fast, origin_interior(sum_vertices(t.kept, 1, pts)));
      inside += fast, ++queries;
    }
  }
  std::cout << "[collide] angle tree under churn: " << queries << " queries (" << inside << " inside), tallest tree "
            << tallest << "\n";
  EXPECT_GT(inside, queries / 20);
  EXPECT_LT(inside, queries - queries / 20);
}

// AngleBoth decides every filtered pair with the angle tree and the
// per-pair rebuild and throws on a disagreement; AngleTree alone must find
// the same first pair as PerPair.
void angle_twin(const Instance& inst, uint64_t& pairs_compared, uint64_t& yes) {
  Simulator sim(inst);
  for (char b : sim.faces().coupling_breaks_cycle)
    if (b) return;  // the cycle step answers; no pairwise run
  PairwiseStats st;
  auto both = pairwise_collision(inst, sim.tree(), sim.regions(), TimeModel::Continuous, &st, nullptr,
                                 ZonotopeTest::AngleBoth);
  PairwiseStats fst;
  auto fast = pairwise_collision(inst, sim.tree(), sim.regions(), TimeModel::Continuous, &fst, nullptr,
                                 ZonotopeTest::AngleTree);
  auto slow = pairwise_collision(inst, sim.tree(), sim.regions(), TimeModel::Continuous, nullptr, nullptr,
                                 ZonotopeTest::PerPair);
  ASSERT_EQ(fast.has_value(), slow.has_value());
  ASSERT_EQ(both.has_value(), slow.has_value());
  EXPECT_EQ(fst.angle_fallbacks, 0u);
  if (fast) {
    EXPECT_EQ(fast->a, slow->a);
    EXPECT_EQ(fast->b, slow->b);
    ++yes;
  }
  pairs_compared += st.full_tests;
}

TEST(CollideAngleTree, AgainstPerPairOnRandomAndSerpentines) {
  uint64_t pairs = 0, yes = 0;
  int instances = 0;
  for (int i = 0; i < test::scaled(2000); ++i) {
    const uint64_t seed = test::base_seed(72000) + static_cast<uint64_t>(i);
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
    angle_twin(inst, pairs, yes);
    ++instances;
    if (::testing::Test::HasFatalFailure()) return;
  }
  for (int i = 0; i < test::scaled(500); ++i) {
    const uint64_t seed = test::base_seed(73000) + static_cast<uint64_t>(i);
    Rng rng(seed * 1223 + 9);
    SerpentineParams p;
    p.columns = 2 + static_cast<uint32_t>(rng.below(8));
    p.height = 3 + static_cast<uint32_t>(rng.below(8));
    p.coupling_size = static_cast<uint32_t>(rng.below(6));
    p.couplings = rng.below(2) == 0 ? SerpentineCouplings::Mixed : SerpentineCouplings::Columns;
    p.contract_percent = rng.below(2) == 0 ? 0 : static_cast<uint32_t>(rng.below(20));
    Instance inst = serpentine_instance(p, seed);
    SCOPED_TRACE("serpentine seed " + std::to_string(seed) + "; replay with GRIDLOCK_TEST_SEED");
    angle_twin(inst, pairs, yes);
    ++instances;
    if (::testing::Test::HasFatalFailure()) return;
  }
  // Larger square serpentines with big couplings (many directions on a
  // path), expansions only (NO: every pair decided both ways) and with
  // some contractions.
  for (uint64_t k = 0; k < 6; ++k) {
    const uint64_t seed = test::base_seed(75000) + k;
    SerpentineParams p = square_serpentine(144 + 52 * static_cast<int64_t>(k % 3), k % 2 == 0 ? 0 : 6,
                                           SerpentineCouplings::Mixed);
    p.contract_percent = k < 3 ? 0 : 3;
    Instance inst = serpentine_instance(p, seed);
    SCOPED_TRACE("square serpentine seed " + std::to_string(seed) + "; replay with GRIDLOCK_TEST_SEED");
    angle_twin(inst, pairs, yes);
    ++instances;
    if (::testing::Test::HasFatalFailure()) return;
  }
  std::cout << "[collide] angle tree vs per-pair zonotope: " << instances << " instances (" << yes << " YES), " << pairs
            << " pairs decided both ways\n";
  EXPECT_GT(pairs, 10000u);
  EXPECT_GT(yes, 50u);
}

}  // namespace
}  // namespace gridlock
