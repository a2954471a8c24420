// Twin of the checker's row order (nodes_in_row_order, certify/geometry.cpp):
// the counting sort against std::sort by (y, x) on random sets of distinct
// cells, dense ones (the counting sort) and spread ones (its fallback).
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <utility>

#include "certify/internal/geometry.hpp"
#include "common/random.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

TEST(CertifyRowOrder, CountingSortAgreesWithSort) {
  const uint64_t seed = test::base_seed(24710);
  Rng rng(seed);
  int counted = 0;
  const int runs = test::scaled(3000);
  for (int t = 0; t < runs; ++t) {
    SCOPED_TRACE("seed " + std::to_string(seed) + ", case " + std::to_string(t) +
                 " (replay: GRIDLOCK_TEST_SEED=" + std::to_string(seed) + ")");
    const auto n = static_cast<size_t>(rng.between(0, 300));
    // Coordinate spans: mostly within the counting sort's limit (4n + 64),
    // sometimes far beyond it, up to the model's bound.
    const int64_t wx = rng.below(8) == 0 ? kMaxCoordinate : rng.between(1, 4 * static_cast<int64_t>(n) + 64);
    const int64_t wy = rng.below(8) == 0 ? kMaxCoordinate : rng.between(1, 4 * static_cast<int64_t>(n) + 64);
    const int64_t ox = rng.between(-kMaxCoordinate, kMaxCoordinate - wx),
                  oy = rng.between(-kMaxCoordinate, kMaxCoordinate - wy);
    std::set<std::pair<int64_t, int64_t>> seen;
    std::vector<Vec2> cells;
    for (size_t i = 0; i < n; ++i) {
      Vec2 c{ox + rng.between(0, wx), oy + rng.between(0, wy)};
      if (seen.insert({c.x, c.y}).second) cells.push_back(c);
    }
    std::vector<NodeId> expect(cells.size());
    for (NodeId w = 0; w < expect.size(); ++w) expect[w] = w;
    std::sort(expect.begin(), expect.end(), [&](NodeId p, NodeId q) {
      return cells[p].y != cells[q].y ? cells[p].y < cells[q].y : cells[p].x < cells[q].x;
    });
    ASSERT_EQ(nodes_in_row_order(cells), expect);
    counted += wx < 4 * static_cast<int64_t>(cells.size()) + 64 && wy < 4 * static_cast<int64_t>(cells.size()) + 64;
  }
  EXPECT_GT(counted, runs / 2);  // the counting sort itself, not only its fallback
}

}  // namespace
}  // namespace gridlock
