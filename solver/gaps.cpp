#include "solver/gaps.hpp"

#include <algorithm>
#include <stdexcept>

#include "common/assert.hpp"
#include "lattice/motion.hpp"
#include "lattice/prepared.hpp"
#include "lattice/row_order.hpp"
#include "solver/internal/op_tree.hpp"

namespace gridlock {

namespace {

// The node whose displacement a node's left (right) face follows: itself,
// except for a contracting v, whose face toward u follows u (docs/model.md).
NodeId face_ref(const Instance& inst, NodeId w, bool right_face) {
  OpId k = inst.op_of_node(w);
  if (k == kNone) return w;
  const Operation& op = inst.ops()[k];
  if (op.kind != OpKind::Contract || op.v != w) return w;
  // dir points from u to v: with +x, u is on v's left.
  bool u_on_left = op.dir == Dir::PosX;
  return (u_on_left != right_face) ? op.u : w;
}

// +1 if w grows into the side given (its node then extends by one cell).
int64_t grows_toward(const Instance& inst, NodeId w, Dir d) {
  OpId k = inst.op_of_node(w);
  if (k == kNone) return 0;
  const Operation& op = inst.ops()[k];
  return (op.kind == OpKind::Grow && op.u == w && op.dir == d) ? 1 : 0;
}

// The breadth-first tree from the anchor (the same tree SpanningTree builds,
// without its Euler tour: this is the hot loop of the checker) and every
// node's final displacement along it (x only: nothing moves vertically).
struct BfsTree {
  std::vector<int64_t> D;       // final x displacement, by node
  std::vector<NodeId> parent;   // kNone at the anchor
  std::vector<char> tree_edge;  // by edge index
};

BfsTree final_displacements(const Instance& inst) {
  const size_t n = inst.num_nodes();
  const auto& ops = inst.ops();
  const auto& edges = inst.edges();
  BfsTree t{std::vector<int64_t>(n, 0), std::vector<NodeId>(n, kNone), std::vector<char>(edges.size(), 0)};
  std::vector<int64_t>& D = t.D;
  std::vector<NodeId>& parent = t.parent;
  std::vector<NodeId> queue;
  queue.reserve(n);
  const NodeId root = inst.anchor();
  queue.push_back(root);
  parent[root] = root;
  for (size_t head = 0; head < queue.size(); ++head) {
    NodeId w = queue[head];
    for (Dir d : kDirs) {
      NodeId x = inst.neighbour(w, d);
      if (x == kNone || parent[x] != kNone) continue;
      uint32_t e = inst.edge_index(w, d);
      t.tree_edge[e] = 1;
      parent[x] = w;
      int64_t step = 0;
      if (OpId k = edges[e].op; k != kNone) {
        step = unit(d).x;                                   // x moves away from w by one unit along d ...
        if (ops[k].kind == OpKind::Contract) step = -step;  // ... or toward it
      }
      D[x] = D[w] + step;
      queue.push_back(x);
    }
  }
  parent[root] = kNone;
  return t;
}

// The tree path from a to b (through their lowest common ancestor); the
// edge b-a closes it into a cycle.
std::vector<NodeId> tree_path(const std::vector<NodeId>& parent, NodeId a, NodeId b) {
  auto depth = [&](NodeId w) {
    uint32_t dep = 0;
    for (; parent[w] != kNone; w = parent[w]) ++dep;
    return dep;
  };
  std::vector<NodeId> up_a, up_b;
  NodeId x = a, y = b;
  uint32_t dx = depth(x), dy = depth(y);
  while (x != y) {
    if (dx >= dy) up_a.push_back(x), x = parent[x], --dx;
    else up_b.push_back(y), y = parent[y], --dy;
  }
  std::vector<NodeId> path = up_a;
  path.push_back(x);
  path.insert(path.end(), up_b.rbegin(), up_b.rend());
  return path;
}

// Cycles: each non-tree edge closes one fundamental cycle; with everything
// running at once its mismatch grows linearly, so only the end matters.
// Counts them into v and reports the first open one (if v has no reason yet).
void check_cycles(const Instance& inst, const BfsTree& t, GapVerdict& v) {
  const auto& ops = inst.ops();
  const auto& edges = inst.edges();
  for (uint32_t e = 0; e < edges.size(); ++e) {
    if (t.tree_edge[e]) continue;
    ++v.cycles_checked;
    const Edge& ed = edges[e];
    int64_t expected = 0;  // displacement of b relative to a that the edge itself makes
    if (ed.op != kNone) {
      const Operation& op = ops[ed.op];
      int64_t s = unit(op.dir).x * (op.kind == OpKind::Contract ? -1 : 1);  // v relative to u
      expected = ed.a == op.u ? s : -s;
    }
    int64_t mis = (t.D[ed.b] - t.D[ed.a]) - expected;
    if (mis == 0) continue;
    ++v.open_cycles;
    if (v.reason != GapVerdict::Reason::None) continue;
    v.collision_free = false;
    v.reason = GapVerdict::Reason::Cycle;
    v.mismatch = mis;
    v.cycle = tree_path(t.parent, ed.a, ed.b);
  }
}

// Gaps: consecutive nodes of each row, from the radix order, at their final
// displacements D. Counts them into v and reports the first negative one
// (if v has no reason yet).
// order and runs: nodes_by_row(inst) and its row_runs.
void check_row_gaps(const Instance& inst, const std::vector<NodeId>& order, const std::vector<RowRun>& runs,
                    const std::vector<int64_t>& D, GapVerdict& v) {
  const auto& cells = inst.cells();
  bool first_gap = v.reason == GapVerdict::Reason::None;
  for (const RowRun& run : runs)
    for (uint32_t i = run.begin; i + 1 < run.end; ++i) {
      NodeId a = order[i], b = order[i + 1];
      ++v.gaps_checked;
      int64_t right_a = cells[a].x + 1 + D[face_ref(inst, a, true)] + grows_toward(inst, a, Dir::PosX);
      int64_t left_b = cells[b].x + D[face_ref(inst, b, false)] - grows_toward(inst, b, Dir::NegX);
      int64_t final_size = left_b - right_a;
      if (final_size >= 0) continue;
      ++v.negative_gaps;
      if (!first_gap) continue;
      first_gap = false;
      v.collision_free = false;
      v.reason = GapVerdict::Reason::Gap;
      v.row = cells[a].y;
      v.left = a, v.right = b;
      v.initial_size = cells[b].x - cells[a].x - 1;
      v.final_size = final_size;
    }
}

// The operations that change the reported gap (v.left, v.right) into
// v.changes: O(n), once.
// tree: SpanningTree::build(inst), rooted at the anchor.
void list_gap_changes(const Instance& inst, const SpanningTree& tree, GapVerdict& v) {
  const OpTree ot(inst, tree);
  // Each operation appears once on the path, and a growth is never on it.
  ot.for_each_op_on_path(face_ref(inst, v.left, true), face_ref(inst, v.right, false), [&](OpId k, int sign) {
    int64_t dx = sign * ot.child_vector(k).x;
    if (dx != 0) v.changes.push_back({k, dx});
  });
  for (NodeId w : {v.left, v.right})
    if (grows_toward(inst, w, w == v.left ? Dir::PosX : Dir::NegX)) v.changes.push_back({inst.op_of_node(w), -1});
}

// The checks up to the reported gap's operations (which need the tree).
GapVerdict gap_verdict(const Instance& inst, const std::vector<NodeId>& order, const std::vector<RowRun>& runs) {
  GRIDLOCK_REQUIRE(inst.horizontal_only(), "check_gaps needs a horizontal-only instance");
  GapVerdict v;
  const BfsTree t = final_displacements(inst);
  check_cycles(inst, t, v);
  check_row_gaps(inst, order, runs, t.D, v);
  return v;
}

}  // namespace

GapVerdict check_gaps(const Instance& inst) {
  const std::vector<NodeId> order = nodes_by_row(inst);
  GapVerdict v = gap_verdict(inst, order, row_runs(inst, order));
  if (v.reason == GapVerdict::Reason::Gap) list_gap_changes(inst, SpanningTree::build(inst), v);
  return v;
}

GapVerdict check_gaps(const PreparedInstance& prep) {
  GapVerdict v = gap_verdict(prep.inst, prep.rows, prep.runs);
  if (v.reason == GapVerdict::Reason::Gap) list_gap_changes(prep.inst, prep.tree, v);
  return v;
}

std::string describe_gap_verdict(const Instance& inst, const GapVerdict& v) {
  switch (v.reason) {
    case GapVerdict::Reason::None:
      return "every gap stays >= 0 and every cycle closes when all couplings start at time 0";
    case GapVerdict::Reason::Cycle: {
      std::string s = "cycle through";
      size_t shown = std::min<size_t>(v.cycle.size(), 12);
      for (size_t i = 0; i < shown; ++i) s += " " + inst.node_label(v.cycle[i]);
      if (shown < v.cycle.size()) s += " ... (" + std::to_string(v.cycle.size()) + " nodes)";
      return s + " does not close at the end: net horizontal displacement " + std::to_string(v.mismatch);
    }
    case GapVerdict::Reason::Gap: {
      std::string s = "gap in row " + std::to_string(v.row) + " between " + inst.node_label(v.left) + " and " +
                      inst.node_label(v.right) + ": initial size " + std::to_string(v.initial_size) + ", final size " +
                      std::to_string(v.final_size);
      std::string widen, narrow;
      for (const GapChange& c : v.changes) {
        std::string item = " " + inst.ops()[c.op].name + " (" + (c.delta > 0 ? "+" : "") + std::to_string(c.delta) +
                           ")";
        (c.delta > 0 ? widen : narrow) += item;
      }
      s += "; widened by" + (widen.empty() ? std::string(" none") : widen);
      s += "; narrowed by" + (narrow.empty() ? std::string(" none") : narrow);
      return s;
    }
  }
  return "";
}

}  // namespace gridlock
