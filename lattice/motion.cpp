#include "lattice/motion.hpp"

#include <algorithm>

namespace gridlock {

SpanningTree SpanningTree::build(const Instance& inst, NodeId root) {
  SpanningTree t;
  size_t n = inst.num_nodes();
  t.root = root == kNone ? inst.anchor() : root;
  t.parent.assign(n, kNone);
  t.parent_dir.assign(n, Dir::PosX);
  t.parent_op.assign(n, kNone);
  t.tree_edge.assign(inst.edges().size(), 0);
  // Children lists as one array: a node's children are consecutive in the
  // BFS queue (pushed while the node is at its head), in direction order.
  std::vector<uint32_t> first_child(n, 0), num_children(n, 0);
  std::vector<char> seen(n, 0);
  std::vector<NodeId> queue;
  queue.reserve(n);
  queue.push_back(t.root);
  seen[t.root] = 1;
  for (size_t head = 0; head < queue.size(); ++head) {
    NodeId w = queue[head];
    first_child[w] = static_cast<uint32_t>(queue.size());
    for (Dir d : kDirs) {
      NodeId x = inst.neighbour(w, d);
      if (x == kNone || seen[x]) continue;
      seen[x] = 1;
      uint32_t e = inst.edge_index(w, d);
      t.tree_edge[e] = 1;
      t.parent[x] = w;
      t.parent_dir[x] = d;
      t.parent_op[x] = inst.edges()[e].op;
      ++num_children[w];
      queue.push_back(x);
    }
  }
  // Iterative Euler tour (deep trees must not overflow the call stack).
  t.tin.assign(n, 0);
  t.tout.assign(n, 0);
  t.subtree.assign(n, 1);
  t.order.reserve(n);
  std::vector<std::pair<NodeId, uint32_t>> stack;
  stack.reserve(n);
  stack.push_back({t.root, 0});
  t.tin[t.root] = 0;
  t.order.push_back(t.root);
  while (!stack.empty()) {
    auto& [w, i] = stack.back();
    if (i < num_children[w]) {
      NodeId c = queue[first_child[w] + i++];
      t.tin[c] = static_cast<uint32_t>(t.order.size());
      t.order.push_back(c);
      stack.push_back({c, 0});
    } else {
      t.tout[w] = static_cast<uint32_t>(t.order.size());
      t.subtree[w] = t.tout[w] - t.tin[w];
      stack.pop_back();
    }
  }
  return t;
}

Vec2 op_child_vector(const Instance& inst, const SpanningTree& t, NodeId child) {
  OpId k = t.parent_op[child];
  if (k == kNone) return {0, 0};
  Vec2 away = unit(t.parent_dir[child]);
  return inst.ops()[k].kind == OpKind::Contract ? Vec2{-away.x, -away.y} : away;
}

namespace {
// Face indices: 0 xlo, 1 xhi, 2 ylo, 3 yhi. The face of a cell toward d.
int face_toward(Dir d) {
  switch (d) {
    case Dir::PosX: return 1;
    case Dir::NegX: return 0;
    case Dir::PosY: return 3;
    case Dir::NegY: return 2;
  }
  return 0;
}
void set_box(RegionShape& s, Vec2 c, NodeId ref) {
  s.base[0] = c.x, s.base[1] = c.x + 1, s.base[2] = c.y, s.base[3] = c.y + 1;
  for (auto& r : s.ref) r = ref;
}
}  // namespace

Regions Regions::build(const Instance& inst) {
  Regions R;
  size_t n = inst.num_nodes();
  R.shapes.reserve(n + inst.ops().size());  // a region per node, at most one per operation
  R.shapes.resize(n);
  R.region_of_op.assign(inst.ops().size(), kNone);
  const auto& cells = inst.cells();
  for (NodeId w = 0; w < n; ++w) {
    R.shapes[w].kind = RegionKind::Node;
    R.shapes[w].id = w;
    set_box(R.shapes[w], cells[w], w);
  }
  for (OpId k = 0; k < inst.ops().size(); ++k) {
    const Operation& op = inst.ops()[k];
    int near = face_toward(opposite(op.dir));  // of the region beyond u: the face touching u
    int far = face_toward(op.dir);
    if (op.kind == OpKind::Contract) {
      // v spans from u's face to v's far face; its near face follows u.
      R.shapes[op.v].ref[near] = op.u;
      continue;
    }
    RegionShape s;
    s.kind = op.kind == OpKind::Expand ? RegionKind::Inserted : RegionKind::Grown;
    s.id = k;
    Vec2 c = cells[op.u] + unit(op.dir);  // the cell beyond u
    set_box(s, c, op.u);
    // Zero width at first: both faces on u's face toward dir.
    s.base[far] = s.base[near];
    if (op.kind == OpKind::Expand) {
      s.ref[far] = op.v;
    } else {
      s.grow_op = k;
      s.grow_face = far;
      s.grow_sign = is_positive(op.dir) ? 1 : -1;
    }
    R.region_of_op[k] = static_cast<uint32_t>(R.shapes.size());
    R.shapes.push_back(s);
  }
  return R;
}

std::string region_label(const Instance& inst, const Regions& regions, uint32_t r) {
  const RegionShape& s = regions.shapes[r];
  switch (s.kind) {
    case RegionKind::Node: return "node " + inst.node_label(s.id);
    case RegionKind::Inserted: return "node inserted by " + inst.ops()[s.id].name;
    case RegionKind::Grown: return "node grown by " + inst.ops()[s.id].name;
  }
  return "?";
}

FaceNets FaceNets::build(const Instance& inst) {
  FaceNets F;
  F.coupling_breaks_cycle.assign(inst.couplings().size(), 0);
  size_t n = inst.num_nodes();
  // Half-edge h = 4 * w + d, present iff w has a neighbour toward d.
  std::vector<char> used(4 * n, 0);
  // One walk and one list of steps, reused for every face: most faces
  // (the outer one above all, about 2n steps) have no non-zero net and are
  // dropped, so they are built in place and copied only when kept.
  Face face;
  // The steps of a walk summed per coupling in a dense table: the outer
  // face crosses every operation edge twice, so sorting its steps cost
  // O(e log e); only the couplings a walk touches are visited and reset.
  std::vector<Vec2> sum(inst.couplings().size(), Vec2{0, 0});
  std::vector<CouplingId> touched;
  for (NodeId w0 = 0; w0 < n; ++w0) {
    for (int d0 = 0; d0 < 4; ++d0) {
      if (used[4 * w0 + d0] || inst.neighbour(w0, static_cast<Dir>(d0)) == kNone) continue;
      face.walk.clear();
      face.nets.clear();
      touched.clear();
      NodeId w = w0;
      int d = d0;
      while (!used[4 * w + d]) {
        used[4 * w + d] = 1;
        face.walk.push_back(w);
        Dir dir = static_cast<Dir>(d);
        NodeId x = inst.neighbour(w, dir);
        OpId k = inst.edges()[inst.edge_index(w, dir)].op;
        if (k != kNone) {
          const Operation& op = inst.ops()[k];
          Vec2 step = unit(dir);  // relative motion of x w.r.t. w at full progress
          if (op.kind == OpKind::Contract) step = Vec2{-step.x, -step.y};
          Vec2& acc = sum[op.coupling];
          if (acc.is_zero()) touched.push_back(op.coupling);  // may repeat after a sum returns to zero
          acc += step;
        }
        // At x, turn: the first edge clockwise from the way back.
        int back = (d + 2) % 4, nd = back;
        for (int turn = 1; turn <= 4; ++turn) {
          int cand = (back + 4 - turn) % 4;
          if (inst.neighbour(x, static_cast<Dir>(cand)) != kNone) {
            nd = cand;
            break;
          }
        }
        w = x;
        d = nd;
      }
      // The non-zero sums, in increasing coupling order (a coupling can be
      // in touched twice: its sum is read and reset the first time).
      for (CouplingId q : touched) {
        if (!sum[q].is_zero()) face.nets.push_back({q, sum[q]}), F.coupling_breaks_cycle[q] = 1;
        sum[q] = Vec2{0, 0};
      }
      std::sort(face.nets.begin(), face.nets.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
      if (!face.nets.empty()) F.faces.push_back(face);
    }
  }
  return F;
}

}  // namespace gridlock
