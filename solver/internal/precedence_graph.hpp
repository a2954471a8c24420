// The directed graph of the precedence literals set so far ("a before b" is
// the edge a -> b), growing and shrinking like a stack, with a topological
// sort that returns a cycle when there is none.
//
// The learning precedence search (solver/search_precedence.cpp) adds the
// edge of every literal it sets and removes them in reverse when it
// backtracks; adding and removing cost O(1). Cycles are looked for only
// when the search has nothing left to decide (lazily, as the SAT engine
// does between solver calls): keeping a topological order edge by edge
// (Pearce and Kelly) was measured to cost 90% of the search's time on the
// compiled formulas, whose long order chains make every reordering region
// large (docs/performance.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace gridlock {

class PrecedenceGraph {
 public:
  struct Edge {
    uint32_t node;  // the other end
    uint32_t tag;   // the caller's name for the edge (a literal)
  };

  // n nodes, no edges.
  explicit PrecedenceGraph(size_t n) : out_(n), in_(n) {}

  // Adds a -> b named tag. Requires a != b, both < n.
  void add(uint32_t a, uint32_t b, uint32_t tag);
  // Removes the edge a -> b. Requires it to be the most recent edge added
  // among those still present (edges leave in reverse order of addition).
  void pop(uint32_t a, uint32_t b);

  // Acyclic: order = all nodes, every edge forward; true. Otherwise cycle =
  // the tags of the edges of one cycle, in path order; false. O(n + edges).
  bool sort(std::vector<uint32_t>& order, std::vector<uint32_t>& cycle) const;

  const std::vector<Edge>& out(uint32_t v) const { return out_[v]; }
  const std::vector<Edge>& in(uint32_t v) const { return in_[v]; }

 private:
  void find_cycle(const std::vector<uint32_t>& indeg, std::vector<uint32_t>& cycle) const;
  std::vector<std::vector<Edge>> out_, in_;
};

}  // namespace gridlock
