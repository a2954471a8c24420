// The per-pair exact tests of collide/collide_pairs against vertex
// enumeration, on random region forms and random path nets (every kind of
// width change, couplings shared between the path and the own operations).
#include <gtest/gtest.h>

#include <iostream>

#include "collide/internal/collide_pairs.hpp"
#include "common/random.hpp"
#include "lattice/random_instance.hpp"
#include "support/reference_collide.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

RegionForm random_form(Rng& rng, size_t nq) {
  RegionForm F;
  F.ref = 0;
  int64_t x = static_cast<int64_t>(rng.below(7)) - 3, y = static_cast<int64_t>(rng.below(7)) - 3;
  F.base[0] = x, F.base[1] = x + 1, F.base[2] = y, F.base[3] = y + 1;
  uint64_t kind = rng.below(4);  // 0 node, 1 inserted/grown (width p), 2 contracting (width 1-p)
  if (kind == 0 || kind == 3) return F;
  F.own = static_cast<CouplingId>(rng.below(nq));
  int face = static_cast<int>(rng.below(4));
  int opp = face ^ 1;
  bool hi_face = face % 2 == 1;
  if (kind == 1) {  // zero width at p = 0: face moves away from its opposite
    F.base[face] = F.base[opp];
    F.own_coef[face] = hi_face ? 1 : -1;
  } else {  // width 1 - p: face moves toward its opposite
    F.own_coef[face] = hi_face ? -1 : 1;
  }
  return F;
}

TEST(CollidePairs, AgainstVertexEnumeration) {
  int yes_c = 0, yes_d = 0, only_c = 0;
  const int cases = test::scaled(10000);
  for (int i = 0; i < cases; ++i) {
    uint64_t seed = test::base_seed(4242) + static_cast<uint64_t>(i);
    Rng rng(seed * 104729 + 7);
    size_t nq = 1 + rng.below(4);
    RegionForm A = random_form(rng, nq), B = random_form(rng, nq);
    PathNets nets;
    for (size_t q = 0; q < nq; ++q) {
      if (rng.below(4) == 0) continue;
      Vec2 w{static_cast<int64_t>(rng.below(5)) - 2, static_cast<int64_t>(rng.below(5)) - 2};
      if (rng.below(3) == 0) w.y = 0;
      if (!w.is_zero()) nets.push_back({static_cast<CouplingId>(q), w});
    }
    std::string info = "seed " + std::to_string(seed) + "; replay with GRIDLOCK_TEST_SEED; A own " +
                       std::to_string(static_cast<int>(A.own)) + " B own " + std::to_string(static_cast<int>(B.own));
    for (int f = 0; f < 4; ++f)
      info += " A" + std::to_string(f) + "=" + std::to_string(A.base[f]) + "+" + std::to_string(A.own_coef[f]) + "p";
    for (int f = 0; f < 4; ++f)
      info += " B" + std::to_string(f) + "=" + std::to_string(B.base[f]) + "+" + std::to_string(B.own_coef[f]) + "p";
    for (auto& [q, w] : nets)
      info += " net" + std::to_string(q) + "=(" + std::to_string(w.x) + "," + std::to_string(w.y) + ")";
    SCOPED_TRACE(info);
    bool c = continuous_pair_collides(A, B, nets);
    ASSERT_EQ(c, test::brute_pair_continuous(A, B, nets, nq));
    bool d = discrete_pair_collides(A, B, nets);
    ASSERT_EQ(d, test::brute_pair_discrete(A, B, nets, nq));
    if (d) {
      ASSERT_TRUE(c);
    }
    if (c) {
      PairWitness w;
      ASSERT_TRUE(continuous_pair_collides(A, B, nets, &w));
      std::vector<Rational> p(nq);
      for (auto& [q, v] : w.progress) p[q] = v;
      ASSERT_TRUE(pair_overlaps_at(A, B, nets, p));
    }
    if (d) {
      // Some moment of the witness's running coupling overlaps.
      PairWitness w;
      ASSERT_TRUE(discrete_pair_collides(A, B, nets, &w));
      std::vector<Rational> p(nq);
      for (CouplingId q : w.done) p[q] = Rational(1);
      bool hit = false;
      for (int k = 0; k <= 64 && !hit; ++k) {
        if (w.running != kNone) p[w.running] = Rational(k, 64);
        hit = pair_overlaps_at(A, B, nets, p);
      }
      ASSERT_TRUE(hit);
    }
    yes_c += c, yes_d += d, only_c += c && !d;
  }
  std::cout << "[collide] pairs: " << cases << " compared, continuous YES " << yes_c << ", discrete YES " << yes_d
            << ", continuous only " << only_c << "\n";
}

// The distinct-vector refinement (grouped subset sums, only the cells the
// running coupling can reach) against the per-vector twin, on paths with
// many equal vectors (up to 14 nets drawn from a few vectors), and its
// witnesses checked at the moment they name.
TEST(CollidePairs, GroupedDiscreteAgainstPerVector) {
  int yes = 0;
  const int cases = test::scaled(6000);
  for (int i = 0; i < cases; ++i) {
    uint64_t seed = test::base_seed(74000) + static_cast<uint64_t>(i);
    SCOPED_TRACE("seed " + std::to_string(seed) + "; replay with GRIDLOCK_TEST_SEED");
    Rng rng(seed * 7727 + 1);
    size_t nq = 2 + rng.below(14);
    RegionForm A = random_form(rng, nq), B = random_form(rng, nq);
    std::vector<Vec2> palette;
    for (size_t k = 0, m = 1 + rng.below(3); k < m; ++k)
      palette.push_back({static_cast<int64_t>(rng.below(5)) - 2, static_cast<int64_t>(rng.below(5)) - 2});
    PathNets nets;
    for (size_t q = 0; q < nq; ++q) {
      Vec2 w = palette[rng.below(palette.size())];
      if (!w.is_zero()) nets.push_back({static_cast<CouplingId>(q), w});
    }
    // Shift B so the pair is often within reach.
    int64_t dx = static_cast<int64_t>(rng.below(7)) - 3, dy = static_cast<int64_t>(rng.below(7)) - 3;
    B.base[0] += dx, B.base[1] += dx, B.base[2] += dy, B.base[3] += dy;
    const bool fast = discrete_pair_collides(A, B, nets);
    ASSERT_EQ(fast, discrete_pair_collides_per_vector(A, B, nets));
    if (!fast) continue;
    ++yes;
    PairWitness w;
    ASSERT_TRUE(discrete_pair_collides(A, B, nets, &w));
    std::vector<Rational> p(nq);
    for (CouplingId q : w.done) p[q] = Rational(1);
    bool hit = false;
    for (int k = 0; k <= 64 && !hit; ++k) {
      if (w.running != kNone) p[w.running] = Rational(k, 64);
      hit = pair_overlaps_at(A, B, nets, p);
    }
    ASSERT_TRUE(hit);
  }
  std::cout << "[collide] grouped vs per-vector discrete: " << cases << " pairs, " << yes << " YES\n";
  EXPECT_GT(yes, cases / 20);
  EXPECT_LT(yes, cases - cases / 20);
}

// Node (1,1) pushed by (-2,0) and by (0,-2): only the diagonal, both at
// once, passes over node (0,0); each corner path only touches it.
TEST(CollidePairs, DiagonalIsContinuousOnly) {
  RegionForm A, B;
  A.base[0] = 0, A.base[1] = 1, A.base[2] = 0, A.base[3] = 1;
  B.base[0] = 1, B.base[1] = 2, B.base[2] = 1, B.base[3] = 2;
  PathNets nets{{0, {-2, 0}}, {1, {0, -2}}};
  EXPECT_TRUE(continuous_pair_collides(A, B, nets));
  EXPECT_FALSE(discrete_pair_collides(A, B, nets));
  // Sliding along: touching is no collision.
  PathNets slide{{0, {-3, 0}}};
  B.base[2] = 1, B.base[3] = 2;
  EXPECT_FALSE(continuous_pair_collides(A, B, slide));
}

}  // namespace
}  // namespace gridlock
