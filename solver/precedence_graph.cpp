#include "solver/internal/precedence_graph.hpp"

#include <algorithm>

#include "common/assert.hpp"
#include "common/internal/graph_order.hpp"

namespace gridlock {

void PrecedenceGraph::add(uint32_t a, uint32_t b, uint32_t tag) {
  GRIDLOCK_ASSERT(a != b && a < out_.size() && b < out_.size(), "an edge between two distinct nodes");
  out_[a].push_back({b, tag});
  in_[b].push_back({a, tag});
}

void PrecedenceGraph::pop(uint32_t a, uint32_t b) {
  GRIDLOCK_ASSERT(!out_[a].empty() && out_[a].back().node == b && in_[b].back().node == a,
                  "edges leave in reverse order of addition");
  out_[a].pop_back();
  in_[b].pop_back();
}

// Kahn's algorithm (common/internal/graph_order.hpp).
bool PrecedenceGraph::sort(std::vector<uint32_t>& order, std::vector<uint32_t>& cycle) const {
  std::vector<uint32_t> indeg(out_.size());
  for (size_t v = 0; v < out_.size(); ++v) indeg[v] = static_cast<uint32_t>(in_[v].size());
  const auto successors = [&](uint32_t v, auto&& f) {
    for (const Edge& e : out_[v]) f(e.node);
  };
  if (topological_order(indeg, successors, order)) return true;
  find_cycle(indeg, cycle);
  return false;
}

// The nodes Kahn's algorithm left (indeg > 0) each have a predecessor among
// them: walking back along such predecessors must repeat a node.
void PrecedenceGraph::find_cycle(const std::vector<uint32_t>& indeg, std::vector<uint32_t>& cycle) const {
  const size_t n = out_.size();
  std::vector<uint32_t> step(n, UINT32_MAX);  // index in the walk
  std::vector<Edge> walk;                     // (node, tag of the edge into the previous node)
  uint32_t v = 0;
  while (indeg[v] == 0) ++v;
  for (;;) {
    step[v] = static_cast<uint32_t>(walk.size());
    const auto pred = std::find_if(in_[v].begin(), in_[v].end(), [&](const Edge& e) { return indeg[e.node] > 0; });
    GRIDLOCK_ASSERT(pred != in_[v].end(), "a node left by Kahn's algorithm has a predecessor left");
    walk.push_back({v, pred->tag});
    v = pred->node;
    if (step[v] != UINT32_MAX) break;
  }
  // walk[step[v]..] runs backwards along the cycle through v.
  cycle.clear();
  for (size_t i = walk.size(); i-- > step[v];) cycle.push_back(walk[i].tag);
}

}  // namespace gridlock
