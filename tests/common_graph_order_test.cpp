// topological_order and strong_components (common/internal/graph_order.hpp) against
// a naive reference: the transitive closure (Floyd–Warshall on booleans).
// A graph is acyclic iff no node reaches itself; u, v share a component iff
// each reaches the other; Kahn's order leaves out exactly the nodes some
// cycle reaches. Thousands of seeded random graphs (GRIDLOCK_TEST_SEED
// replays), self loops and parallel edges included.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "common/internal/graph_order.hpp"
#include "common/random.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

using Edges = std::vector<std::pair<uint32_t, uint32_t>>;

// reach[u][v]: a path of at least one edge from u to v.
std::vector<std::vector<char>> closure(size_t n, const Edges& edges) {
  std::vector<std::vector<char>> reach(n, std::vector<char>(n, 0));
  for (auto [a, b] : edges) reach[a][b] = 1;
  for (size_t k = 0; k < n; ++k)
    for (size_t i = 0; i < n; ++i)
      for (size_t j = 0; j < n; ++j)
        if (reach[i][k] && reach[k][j]) reach[i][j] = 1;
  return reach;
}

Edges random_edges(Rng& rng, size_t n) {
  Edges edges(rng.below(3 * n + 1));
  const bool dag = rng.coin();  // half the graphs acyclic: edges from lower to higher
  for (auto& [a, b] : edges) {
    a = static_cast<uint32_t>(rng.below(n));
    b = static_cast<uint32_t>(rng.below(n));
    if (dag && a >= b) {
      if (a == b) b = static_cast<uint32_t>((a + 1) % n);
      if (a > b) std::swap(a, b);
    }
  }
  if (dag)
    edges.erase(std::remove_if(edges.begin(), edges.end(), [](auto e) { return e.first == e.second; }), edges.end());
  return edges;
}

void check_topological(size_t n, const Edges& edges, const std::vector<std::vector<char>>& reach, uint64_t seed) {
  std::vector<uint32_t> order;
  const Digraph g = Digraph::from_edges(n, edges);
  bool cyclic = false;
  std::vector<char> after_cycle(n, 0);  // some node on a cycle reaches v, or v is on one
  for (size_t u = 0; u < n; ++u)
    if (reach[u][u]) {
      cyclic = true;
      after_cycle[u] = 1;
      for (size_t v = 0; v < n; ++v)
        if (reach[u][v]) after_cycle[v] = 1;
    }
  ASSERT_EQ(topological_order(g, order), !cyclic) << "seed " << seed;
  std::vector<size_t> place(n, SIZE_MAX);
  for (size_t i = 0; i < order.size(); ++i) {
    ASSERT_EQ(place[order[i]], SIZE_MAX) << "seed " << seed << ": node twice";
    place[order[i]] = i;
  }
  for (size_t v = 0; v < n; ++v) EXPECT_EQ(place[v] != SIZE_MAX, !after_cycle[v]) << "seed " << seed << " node " << v;
  for (auto [a, b] : edges) {
    if (place[a] != SIZE_MAX && place[b] != SIZE_MAX) {
      EXPECT_LT(place[a], place[b]) << "seed " << seed;
    }
  }
  // The residual in-degrees mark exactly the nodes left.
  std::vector<uint32_t> indeg(n, 0);
  for (auto e : edges) ++indeg[e.second];
  const auto succ = [&](uint32_t v, auto&& f) {
    for (uint32_t e = g.first[v]; e < g.first[v + 1]; ++e) f(g.target[e]);
  };
  topological_order(indeg, succ, order);
  for (size_t v = 0; v < n; ++v) EXPECT_EQ(indeg[v] > 0, after_cycle[v] != 0) << "seed " << seed << " node " << v;
}

void check_components(size_t n, const Edges& edges, const std::vector<std::vector<char>>& reach, uint64_t seed) {
  const StrongComponents sc = strong_components(Digraph::from_edges(n, edges));
  ASSERT_EQ(sc.component.size(), n);
  ASSERT_EQ(sc.nodes.size(), n);
  for (size_t u = 0; u < n; ++u)
    for (size_t v = 0; v < n; ++v) {
      const bool same = u == v || (reach[u][v] && reach[v][u]);
      ASSERT_EQ(sc.component[u] == sc.component[v], same) << "seed " << seed << ": " << u << ", " << v;
    }
  for (auto [a, b] : edges)  // sinks first: edges run to lower numbers
    EXPECT_GE(sc.component[a], sc.component[b]) << "seed " << seed;
  for (size_t c = 0; c < sc.count(); ++c) {
    ASSERT_GT(sc.size_of(c), 0U);
    for (uint32_t i = sc.start[c]; i < sc.start[c + 1]; ++i) EXPECT_EQ(sc.component[sc.nodes[i]], c);
  }
}

TEST(GraphOrder, MatchesTheTransitiveClosureOnRandomGraphs) {
  const uint64_t base = test::base_seed(2201);
  for (int i = 0; i < test::scaled(5000); ++i) {
    const uint64_t seed = derive_seed(base, static_cast<uint64_t>(i));
    Rng rng(seed);
    const size_t n = 1 + rng.below(9);
    const Edges edges = random_edges(rng, n);
    const auto reach = closure(n, edges);
    check_topological(n, edges, reach, seed);
    check_components(n, edges, reach, seed);
    if (HasFailure()) return;
  }
}

TEST(GraphOrder, LongPathNeedsNoRecursion) {
  // 10^6 nodes in one path and one big cycle: the iterative Tarjan does not
  // overflow the call stack.
  const uint32_t n = 1000000;
  Edges path;
  for (uint32_t v = 0; v + 1 < n; ++v) path.push_back({v, v + 1});
  std::vector<uint32_t> order;
  EXPECT_TRUE(topological_order(Digraph::from_edges(n, path), order));
  EXPECT_EQ(strong_components(Digraph::from_edges(n, path)).count(), n);
  path.push_back({n - 1, 0});
  EXPECT_EQ(strong_components(Digraph::from_edges(n, path)).count(), 1U);
  EXPECT_FALSE(topological_order(Digraph::from_edges(n, path), order));
  EXPECT_TRUE(order.empty());
}

}  // namespace
}  // namespace gridlock
