// Orders of directed graphs on nodes 0..n-1: a topological order (Kahn) and
// the strongly connected components (Tarjan, iterative), the one
// implementation of each (solver/order_sat.cpp: the cycles
// of a SAT model's orientation and of the forced relations;
// solver/precedence_graph.cpp: the precedence search's set literals; and
// certify/order_proof.cpp: the NO-certificate checker's cycle tests).
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace gridlock {

// A directed graph in compressed rows: the edges out of v go to
// target[first[v]] .. target[first[v + 1] - 1].
struct Digraph {
  std::vector<uint32_t> first{0};  // n + 1 offsets
  std::vector<uint32_t> target;    // one entry per edge

  size_t size() const { return first.size() - 1; }

  // The graph of n nodes with the given edges (a, b) = a -> b, each < n;
  // parallel edges are kept. O(n + edges).
  static Digraph from_edges(size_t n, const std::vector<std::pair<uint32_t, uint32_t>>& edges) {
    Digraph g;
    g.first.assign(n + 1, 0);
    for (const auto& e : edges) ++g.first[e.first + 1];
    for (size_t i = 0; i < n; ++i) g.first[i + 1] += g.first[i];
    g.target.resize(edges.size());
    std::vector<uint32_t> fill(g.first.begin(), g.first.end() - 1);
    for (const auto& e : edges) g.target[fill[e.first]++] = e.second;
    return g;
  }
};

// Kahn's algorithm on nodes 0..indeg.size() - 1. indeg[v]: the number of
// edges into v (consumed: left at what the algorithm did not remove);
// for_each_successor(v, f) calls f(w) once per edge v -> w.
// Acyclic: returns true, order = every node, each edge from an earlier to a
// later one. Otherwise returns false, order = the nodes no cycle reaches,
// and indeg[v] > 0 exactly for the others, each of which has a predecessor
// among them (walking back along such predecessors finds a cycle).
// O(n + edges).
template <class ForEachSuccessor>
bool topological_order(std::vector<uint32_t>& indeg, ForEachSuccessor&& for_each_successor,
                       std::vector<uint32_t>& order) {
  const size_t n = indeg.size();
  order.clear();
  for (size_t v = 0; v < n; ++v)
    if (indeg[v] == 0) order.push_back(static_cast<uint32_t>(v));
  for (size_t h = 0; h < order.size(); ++h)
    for_each_successor(order[h], [&](uint32_t w) {
      if (--indeg[w] == 0) order.push_back(w);
    });
  return order.size() == n;
}

// The same on a Digraph. O(n + edges).
inline bool topological_order(const Digraph& g, std::vector<uint32_t>& order) {
  std::vector<uint32_t> indeg(g.size(), 0);
  for (uint32_t w : g.target) ++indeg[w];
  return topological_order(
      indeg,
      [&](uint32_t v, auto&& f) {
        for (uint32_t e = g.first[v]; e < g.first[v + 1]; ++e) f(g.target[e]);
      },
      order);
}

// The strongly connected components of a graph: component[v] numbers v's
// component; components are numbered sinks first (an edge between two
// components goes from a higher number to a lower one), so `nodes`, which
// lists the nodes component by component in that numbering (component c is
// nodes[start[c]] .. nodes[start[c + 1] - 1]), read backwards is a
// topological order when every component is a single node.
struct StrongComponents {
  std::vector<uint32_t> component;  // per node
  std::vector<uint32_t> nodes;      // grouped by component, sinks first
  std::vector<uint32_t> start{0};   // count() + 1 offsets into nodes
  size_t count() const { return start.size() - 1; }
  size_t size_of(size_t c) const { return start[c + 1] - start[c]; }
};

// Tarjan's algorithm, iteratively (no recursion, so no stack overflow on
// long paths). O(n + edges).
inline StrongComponents strong_components(const Digraph& g) {
  constexpr uint32_t kUnseen = UINT32_MAX;
  const size_t n = g.size();
  StrongComponents sc;
  sc.component.assign(n, kUnseen);
  std::vector<uint32_t> index(n, kUnseen), low(n, 0), stack;
  std::vector<std::pair<uint32_t, uint32_t>> call;  // (node, next edge)
  std::vector<char> on_stack(n, 0);
  uint32_t next_index = 0;
  auto visit = [&](uint32_t v) {
    index[v] = low[v] = next_index++;
    stack.push_back(v);
    on_stack[v] = 1;
    call.push_back({v, g.first[v]});
  };
  for (uint32_t s = 0; s < n; ++s) {
    if (index[s] != kUnseen) continue;
    visit(s);
    while (!call.empty()) {
      auto& [v, e] = call.back();
      if (e < g.first[v + 1]) {
        const uint32_t w = g.target[e++];
        if (index[w] == kUnseen) visit(w);
        else if (on_stack[w]) low[v] = std::min(low[v], index[w]);
        continue;
      }
      const uint32_t done = v;
      call.pop_back();
      if (!call.empty()) low[call.back().first] = std::min(low[call.back().first], low[done]);
      if (low[done] != index[done]) continue;
      const auto c = static_cast<uint32_t>(sc.count());
      uint32_t x;
      do {
        x = stack.back();
        stack.pop_back();
        on_stack[x] = 0;
        sc.component[x] = c;
        sc.nodes.push_back(x);
      } while (x != done);
      sc.start.push_back(static_cast<uint32_t>(sc.nodes.size()));
    }
  }
  return sc;
}

}  // namespace gridlock
