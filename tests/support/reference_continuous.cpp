#include "support/reference_continuous.hpp"

#include <deque>
#include <string>
#include <vector>

#include <z3++.h>

namespace gridlock::test {

namespace {

struct Pos {
  z3::expr x, y;
};

struct Rect {
  z3::expr xlo, xhi, ylo, yhi;
};

}  // namespace

std::optional<bool> reference_continuous(const Instance& inst, Schedule* witness, unsigned timeout_ms) {
  z3::context ctx;
  const size_t k = inst.couplings().size(), n = inst.num_nodes();
  const auto& cells = inst.cells();
  const auto& ops = inst.ops();
  auto rv = [&](int64_t v) { return ctx.real_val(v); };

  std::vector<z3::expr> start;
  z3::expr_vector starts(ctx);
  for (size_t q = 0; q < k; ++q) {
    start.push_back(ctx.real_const(("s" + std::to_string(q)).c_str()));
    starts.push_back(start.back());
  }
  z3::expr t = ctx.real_const("time");
  std::vector<z3::expr> p;
  for (size_t q = 0; q < k; ++q)
    p.push_back(z3::ite(t <= start[q], rv(0), z3::ite(t >= start[q] + 1, rv(1), t - start[q])));
  auto prog = [&](OpId op) { return p[ops[op].coupling]; };

  // The signed move of b's side relative to a's along the edge {a, b}: the
  // side across an expansion moves away, across a contraction toward.
  auto edge_move = [&](const Edge& e, NodeId a, NodeId b) -> Pos {
    if (e.op == kNone) return {rv(0), rv(0)};
    Vec2 d = cells[b] - cells[a];
    int64_t s = ops[e.op].kind == OpKind::Expand ? 1 : -1;
    return {rv(s * d.x) * prog(e.op), rv(s * d.y) * prog(e.op)};
  };

  // Breadth-first tree from the last node: displacement of every node.
  std::vector<std::optional<Pos>> disp(n);
  std::vector<char> tree_edge(inst.edges().size(), 0);
  std::vector<std::vector<uint32_t>> inc(n);
  for (uint32_t i = 0; i < inst.edges().size(); ++i) {
    inc[inst.edges()[i].a].push_back(i);
    inc[inst.edges()[i].b].push_back(i);
  }
  NodeId root = static_cast<NodeId>(n - 1);
  disp[root] = Pos{rv(0), rv(0)};
  std::deque<NodeId> queue{root};
  while (!queue.empty()) {
    NodeId a = queue.front();
    queue.pop_front();
    for (uint32_t i : inc[a]) {
      const Edge& e = inst.edges()[i];
      NodeId b = e.a == a ? e.b : e.a;
      if (disp[b]) continue;
      tree_edge[i] = 1;
      Pos m = edge_move(e, a, b);
      disp[b] = Pos{disp[a]->x + m.x, disp[a]->y + m.y};
      queue.push_back(b);
    }
  }

  // Faces of node w's cell: lo/hi along x and y, displaced.
  auto node_rect = [&](NodeId w) {
    return Rect{rv(cells[w].x) + disp[w]->x, rv(cells[w].x + 1) + disp[w]->x, rv(cells[w].y) + disp[w]->y,
                rv(cells[w].y + 1) + disp[w]->y};
  };
  std::vector<Rect> regions;
  for (NodeId w = 0; w < n; ++w) {
    OpId k2 = inst.op_of_node(w);
    if (k2 != kNone && ops[k2].kind == OpKind::Contract && ops[k2].v == w) {
      // v narrows: its face toward u stays on u's face, its far face is its own.
      const Operation& op = ops[k2];
      Rect rv_ = node_rect(w), ru = node_rect(op.u);
      switch (op.dir) {
        case Dir::PosX: rv_.xlo = ru.xhi; break;
        case Dir::NegX: rv_.xhi = ru.xlo; break;
        case Dir::PosY: rv_.ylo = ru.yhi; break;
        case Dir::NegY: rv_.yhi = ru.ylo; break;
      }
      regions.push_back(rv_);
    } else {
      regions.push_back(node_rect(w));
    }
  }
  for (OpId o = 0; o < ops.size(); ++o) {
    const Operation& op = ops[o];
    if (op.kind == OpKind::Contract) continue;
    Rect ru = node_rect(op.u);
    Rect r = ru;
    if (op.kind == OpKind::Expand) {
      // Between u's face and v's facing face.
      Rect rvv = node_rect(op.v);
      switch (op.dir) {
        case Dir::PosX: r.xlo = ru.xhi, r.xhi = rvv.xlo; break;
        case Dir::NegX: r.xhi = ru.xlo, r.xlo = rvv.xhi; break;
        case Dir::PosY: r.ylo = ru.yhi, r.yhi = rvv.ylo; break;
        case Dir::NegY: r.yhi = ru.ylo, r.ylo = rvv.yhi; break;
      }
    } else {
      // From u's face, p deep along the direction.
      switch (op.dir) {
        case Dir::PosX: r.xlo = ru.xhi, r.xhi = ru.xhi + prog(o); break;
        case Dir::NegX: r.xhi = ru.xlo, r.xlo = ru.xlo - prog(o); break;
        case Dir::PosY: r.ylo = ru.yhi, r.yhi = ru.yhi + prog(o); break;
        case Dir::NegY: r.yhi = ru.ylo, r.ylo = ru.ylo - prog(o); break;
      }
    }
    regions.push_back(r);
  }

  z3::expr_vector safe(ctx);
  for (size_t a = 0; a < regions.size(); ++a) {
    const Rect& A = regions[a];
    for (size_t b = a + 1; b < regions.size(); ++b) {
      const Rect& B = regions[b];
      z3::expr overlap = A.xlo < B.xhi && B.xlo < A.xhi && A.ylo < B.yhi && B.ylo < A.yhi && A.xlo < A.xhi &&
                         A.ylo < A.yhi && B.xlo < B.xhi && B.ylo < B.yhi;
      safe.push_back(!overlap);
    }
  }
  for (uint32_t i = 0; i < inst.edges().size(); ++i) {
    if (tree_edge[i]) continue;
    const Edge& e = inst.edges()[i];
    Pos m = edge_move(e, e.a, e.b);
    safe.push_back(disp[e.b]->x - disp[e.a]->x == m.x && disp[e.b]->y - disp[e.a]->y == m.y);
  }
  z3::expr bounds = ctx.bool_val(true);
  for (size_t q = 0; q < k; ++q) bounds = bounds && start[q] >= 0 && start[q] <= rv(static_cast<int64_t>(k));
  z3::expr formula = bounds && z3::forall(t, z3::mk_and(safe));

  z3::solver s = z3::tactic(ctx, "qsat").mk_solver();
  if (timeout_ms > 0) {
    z3::params prm(ctx);
    prm.set("timeout", timeout_ms);
    s.set(prm);
  }
  s.add(formula);
  z3::check_result r = s.check();
  if (r == z3::unknown) return std::nullopt;
  if (r == z3::unsat) return false;
  if (witness) {
    z3::model m = s.get_model();
    witness->order.clear();
    witness->start.clear();
    for (size_t q = 0; q < k; ++q) {
      z3::expr v = m.eval(start[q], true);
      auto val = Rational::parse(Z3_get_numeral_string(ctx, v));
      if (!val) return std::nullopt;
      witness->start.push_back(*val);
    }
  }
  return true;
}

}  // namespace gridlock::test
