#include "support/reference_simulator.hpp"

#include <algorithm>
#include <array>
#include <map>

namespace gridlock::test {

namespace {

using Q = Rational;
struct Box {
  Q x0, x1, y0, y1;
};

struct Ref {
  const Instance& inst;
  const Schedule& s;
  std::vector<NodeId> parent, order;
  std::vector<uint32_t> parent_edge;
  std::vector<char> in_tree;

  Ref(const Instance& i, const Schedule& sc, NodeId root) : inst(i), s(sc) {
    size_t n = inst.num_nodes();
    parent.assign(n, kNone);
    parent_edge.assign(n, kNone);
    in_tree.assign(inst.edges().size(), 0);
    // Depth-first this time (the fast one is breadth-first).
    std::vector<char> seen(n, 0);
    std::vector<NodeId> stack{root};
    seen[root] = 1;
    while (!stack.empty()) {
      NodeId w = stack.back();
      stack.pop_back();
      order.push_back(w);
      for (uint32_t e = 0; e < inst.edges().size(); ++e) {
        const Edge& ed = inst.edges()[e];
        NodeId x = ed.a == w ? ed.b : ed.b == w ? ed.a : kNone;
        if (x == kNone || seen[x]) continue;
        seen[x] = 1;
        parent[x] = w;
        parent_edge[x] = e;
        in_tree[e] = 1;
        stack.push_back(x);
      }
    }
  }

  Q progress(OpId k, const Q& t) const {
    Q p = t - s.start[inst.ops()[k].coupling];
    return p < Q(0) ? Q(0) : p > Q(1) ? Q(1) : p;
  }

  // How far b sits from a along unit(a->b) beyond the touching distance 1,
  // for an edge operation k between adjacent a and b: +p (expansion) or -p.
  Q stretch(OpId k, const Q& t) const {
    Q p = progress(k, t);
    return inst.ops()[k].kind == OpKind::Expand ? p : Q(0) - p;
  }

  // Lower-left corners of every node's unit square at time t.
  std::vector<std::pair<Q, Q>> corners(const Q& t) const {
    std::vector<std::pair<Q, Q>> pos(inst.num_nodes());
    const auto& c = inst.cells();
    for (NodeId w : order) {
      if (parent[w] == kNone) {
        pos[w] = {Q(c[w].x), Q(c[w].y)};
        continue;
      }
      NodeId p = parent[w];
      Q gx = Q(c[w].x - c[p].x), gy = Q(c[w].y - c[p].y);
      OpId k = inst.edges()[parent_edge[w]].op;
      Q extra = k == kNone ? Q(0) : stretch(k, t);
      pos[w] = {pos[p].first + gx + gx * extra, pos[p].second + gy + gy * extra};
    }
    return pos;
  }

  std::vector<Box> boxes(const Q& t) const {
    auto pos = corners(t);
    std::vector<Box> out;
    auto square = [&](NodeId w) { return Box{pos[w].first, pos[w].first + Q(1), pos[w].second, pos[w].second + Q(1)}; };
    for (NodeId w = 0; w < inst.num_nodes(); ++w) out.push_back(square(w));
    // A contracting v: between u's square and v's far side.
    for (const Operation& op : inst.ops()) {
      if (op.kind != OpKind::Contract) continue;
      Box u = square(op.u);
      Box& b = out[op.v];
      switch (op.dir) {
        case Dir::PosX: b.x0 = u.x1; break;
        case Dir::NegX: b.x1 = u.x0; break;
        case Dir::PosY: b.y0 = u.y1; break;
        case Dir::NegY: b.y1 = u.y0; break;
      }
    }
    // Inserted nodes fill the gap between u and v; grown ones stick out p from u.
    for (OpId k = 0; k < inst.ops().size(); ++k) {
      const Operation& op = inst.ops()[k];
      if (op.kind == OpKind::Contract) continue;
      Box u = square(op.u), b = u;
      Q far_x = op.kind == OpKind::Expand ? (op.dir == Dir::PosX ? square(op.v).x0 : square(op.v).x1) : Q(0);
      Q far_y = op.kind == OpKind::Expand ? (op.dir == Dir::PosY ? square(op.v).y0 : square(op.v).y1) : Q(0);
      Q p = progress(k, t);
      switch (op.dir) {
        case Dir::PosX: b.x0 = u.x1, b.x1 = op.kind == OpKind::Expand ? far_x : u.x1 + p; break;
        case Dir::NegX: b.x1 = u.x0, b.x0 = op.kind == OpKind::Expand ? far_x : u.x0 - p; break;
        case Dir::PosY: b.y0 = u.y1, b.y1 = op.kind == OpKind::Expand ? far_y : u.y1 + p; break;
        case Dir::NegY: b.y1 = u.y0, b.y0 = op.kind == OpKind::Expand ? far_y : u.y0 - p; break;
      }
      out.push_back(b);
    }
    return out;
  }

  // Mismatch around the fundamental cycle of non-tree edge e at time t.
  bool cycle_broken(const std::vector<std::pair<Q, Q>>& pos, uint32_t e, const Q& t) const {
    const Edge& ed = inst.edges()[e];
    const auto& c = inst.cells();
    Q gx = Q(c[ed.b].x - c[ed.a].x), gy = Q(c[ed.b].y - c[ed.a].y);
    Q extra = ed.op == kNone ? Q(0) : stretch(ed.op, t);
    Q wantx = gx + gx * extra, wanty = gy + gy * extra;
    return pos[ed.b].first - pos[ed.a].first != wantx || pos[ed.b].second - pos[ed.a].second != wanty;
  }
};

}  // namespace

std::optional<ReferenceCollision> reference_simulate(const Instance& inst, const Schedule& s, NodeId root) {
  Ref ref(inst, s, root);
  std::vector<Q> ev;
  for (const Q& t : s.start) ev.push_back(t), ev.push_back(t + Q(1));
  std::sort(ev.begin(), ev.end());
  ev.erase(std::unique(ev.begin(), ev.end()), ev.end());

  std::optional<ReferenceCollision> best;
  // Cycles: the first event point after which some fundamental cycle breaks.
  for (size_t j = 0; j + 1 < ev.size() && !best; ++j) {
    auto pos = ref.corners(ev[j + 1]);
    for (uint32_t e = 0; e < inst.edges().size(); ++e)
      if (!ref.in_tree[e] && ref.cycle_broken(pos, e, ev[j + 1])) {
        best = ReferenceCollision{true, ev[j], {}};
        break;
      }
  }
  // Nodes: in each interval, every pair; between consecutive roots of the
  // eight linear constraints each one has a fixed sign, so a midpoint decides.
  for (size_t j = 0; j + 1 < ev.size(); ++j) {
    if (best && best->time <= ev[j]) break;
    Q t0 = ev[j], t1 = ev[j + 1], span = t1 - t0;
    auto b0 = ref.boxes(t0), b1 = ref.boxes(t1);
    std::optional<Q> first;
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    for (uint32_t a = 0; a < b0.size(); ++a)
      for (uint32_t b = a + 1; b < b0.size(); ++b) {
        auto lin = [&](const Box& A, const Box& B) {
          return std::array<Q, 8>{A.x1 - B.x0, B.x1 - A.x0, A.y1 - B.y0, B.y1 - A.y0,
                                  A.x1 - A.x0, B.x1 - B.x0, A.y1 - A.y0, B.y1 - B.y0};
        };
        auto f0 = lin(b0[a], b0[b]), f1 = lin(b1[a], b1[b]);
        std::vector<Q> cuts{Q(0), Q(1)};  // in units of the interval
        for (int i = 0; i < 8; ++i) {
          Q d = f1[i] - f0[i];
          if (d == Q(0)) continue;
          Q r = (Q(0) - f0[i]) / d;
          if (r > Q(0) && r < Q(1)) cuts.push_back(r);
        }
        std::sort(cuts.begin(), cuts.end());
        cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
        for (size_t i = 0; i + 1 < cuts.size(); ++i) {
          Q mid = (cuts[i] + cuts[i + 1]) / Q(2);
          auto at = [&](int f) { return f0[f] + (f1[f] - f0[f]) * mid; };
          bool all = true;
          for (int f = 0; f < 8 && all; ++f) all = at(f) > Q(0);
          if (!all) continue;
          Q when = t0 + cuts[i] * span;
          if (!first || when < *first) first = when, pairs.clear();
          if (when == *first) pairs.push_back({a, b});
          break;
        }
      }
    if (first) {
      if (!best || *first < best->time) best = ReferenceCollision{false, *first, pairs};
      break;
    }
  }
  return best;
}

}  // namespace gridlock::test
