#include "support/reference_collide.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "lattice/simulate.hpp"

namespace gridlock::test {

namespace {

using Q = Rational;

// An affine function of the progress vector: c + sum a[q] p_q.
struct Aff {
  Q c;
  std::vector<Q> a;
};

Aff operator-(const Aff& x, const Aff& y) {
  Aff r{x.c - y.c, x.a};
  for (size_t i = 0; i < r.a.size(); ++i) r.a[i] = r.a[i] - y.a[i];
  return r;
}

Q eval(const Aff& f, const std::vector<Q>& p) {
  Q v = f.c;
  for (size_t i = 0; i < p.size(); ++i) v = v + f.a[i] * p[i];
  return v;
}

// Solves M x = b exactly (square); nullopt if singular.
std::optional<std::vector<Q>> solve(std::vector<std::vector<Q>> M, std::vector<Q> b) {
  size_t k = b.size();
  for (size_t col = 0; col < k; ++col) {
    size_t piv = col;
    while (piv < k && M[piv][col] == Q(0)) ++piv;
    if (piv == k) return std::nullopt;
    std::swap(M[piv], M[col]);
    std::swap(b[piv], b[col]);
    for (size_t r = 0; r < k; ++r) {
      if (r == col || M[r][col] == Q(0)) continue;
      Q f = M[r][col] / M[col][col];
      for (size_t c = col; c < k; ++c) M[r][c] = M[r][c] - f * M[col][c];
      b[r] = b[r] - f * b[col];
    }
  }
  std::vector<Q> x(k);
  for (size_t i = 0; i < k; ++i) x[i] = b[i] / M[i][i];
  return x;
}

// Is {p in [0,1]^k : g_i(p) > 0 for all i} non-empty? Returns a point.
std::optional<std::vector<Q>> strict_point(const std::vector<Aff>& g, size_t nq) {
  std::vector<size_t> vars;
  for (size_t q = 0; q < nq; ++q)
    for (const Aff& f : g)
      if (!(f.a[q] == Q(0))) {
        vars.push_back(q);
        break;
      }
  const size_t k = vars.size();
  // All constraints (closed) over the relevant variables: rows of (coefs, const) with row . p + c >= 0.
  std::vector<std::vector<Q>> A;
  std::vector<Q> C;
  for (const Aff& f : g) {
    std::vector<Q> row(k);
    for (size_t j = 0; j < k; ++j) row[j] = f.a[vars[j]];
    A.push_back(row), C.push_back(f.c);
  }
  for (size_t j = 0; j < k; ++j) {
    std::vector<Q> lo(k), hi(k);
    lo[j] = Q(1), hi[j] = Q(-1);
    A.push_back(lo), C.push_back(Q(0));
    A.push_back(hi), C.push_back(Q(1));
  }
  auto full = [&](const std::vector<Q>& x) {
    std::vector<Q> p(nq);
    for (size_t j = 0; j < k; ++j) p[vars[j]] = x[j];
    return p;
  };
  if (k == 0) {
    std::vector<Q> p(nq);
    for (const Aff& f : g)
      if (!(eval(f, p) > Q(0))) return std::nullopt;
    return p;
  }
  // Vertices: every k-subset of the constraints made tight.
  const size_t m = A.size();
  std::vector<std::vector<Q>> verts;
  std::vector<size_t> idx(k);
  std::iota(idx.begin(), idx.end(), 0);
  for (;;) {
    std::vector<std::vector<Q>> M;
    std::vector<Q> b;
    for (size_t i : idx) M.push_back(A[i]), b.push_back(Q(0) - C[i]);
    if (auto x = solve(M, b)) {
      bool ok = true;
      for (size_t i = 0; i < m && ok; ++i) {
        Q v = C[i];
        for (size_t j = 0; j < k; ++j) v = v + A[i][j] * (*x)[j];
        if (v < Q(0)) ok = false;
      }
      if (ok) verts.push_back(*x);
    }
    // next combination
    size_t i = k;
    while (i > 0 && idx[i - 1] == m - k + (i - 1)) --i;
    if (i == 0) break;
    ++idx[i - 1];
    for (size_t j = i; j < k; ++j) idx[j] = idx[j - 1] + 1;
  }
  if (verts.empty()) return std::nullopt;
  std::vector<Q> cen(k);
  for (const auto& v : verts)
    for (size_t j = 0; j < k; ++j) cen[j] = cen[j] + v[j];
  for (size_t j = 0; j < k; ++j) cen[j] = cen[j] / Q(static_cast<int64_t>(verts.size()));
  std::vector<Q> p = full(cen);
  for (const Aff& f : g)
    if (!(eval(f, p) > Q(0))) return std::nullopt;
  return p;
}

// The eight constraints of a pair as affine functions of p (nq couplings).
std::vector<Aff> pair_forms(const RegionForm& A, const RegionForm& B, const PathNets& nets, size_t nq) {
  auto face = [&](const RegionForm& R, int f, bool is_b) {
    Aff a{Q(R.base[f]), std::vector<Q>(nq)};
    if (R.own != kNone) a.a[R.own] = a.a[R.own] + Q(R.own_coef[f]);
    if (is_b)
      for (const auto& [q, w] : nets) a.a[q] = a.a[q] + Q(f < 2 ? w.x : w.y);
    return a;
  };
  Aff a[4], b[4];
  for (int f = 0; f < 4; ++f) a[f] = face(A, f, false), b[f] = face(B, f, true);
  return {a[1] - b[0], b[1] - a[0], a[3] - b[2], b[3] - a[2], a[1] - a[0], a[3] - a[2], b[1] - b[0], b[3] - b[2]};
}

}  // namespace

bool brute_pair_continuous(const RegionForm& A, const RegionForm& B, const PathNets& nets, size_t nq) {
  return strict_point(pair_forms(A, B, nets, nq), nq).has_value();
}

bool brute_pair_discrete(const RegionForm& A, const RegionForm& B, const PathNets& nets, size_t nq) {
  std::vector<Aff> g = pair_forms(A, B, nets, nq);
  for (uint32_t S = 0; S < (1u << nq); ++S)
    for (size_t q = 0; q < nq; ++q) {
      std::vector<Aff> h;
      for (const Aff& f : g) {
        Aff r{f.c, std::vector<Q>(1)};
        for (size_t j = 0; j < nq; ++j)
          if (j == q) r.a[0] = f.a[j];
          else if ((S >> j) & 1) r.c = r.c + f.a[j];
        h.push_back(r);
      }
      if (strict_point(h, 1)) return true;
    }
  return false;
}

Vec2 edge_vector(const Instance& inst, uint32_t e, NodeId from) {
  const Edge& ed = inst.edges()[e];
  if (ed.op == kNone) return {0, 0};
  NodeId to = ed.a == from ? ed.b : ed.a;
  Vec2 v = unit(*dir_between(inst.cells()[from], inst.cells()[to]));
  // The far side moves away from `from` (expansion) or toward it (contraction).
  return inst.ops()[ed.op].kind == OpKind::Contract ? Vec2{-v.x, -v.y} : v;
}

CouplingDisplacements coupling_displacements(const Instance& inst) {
  const size_t n = inst.num_nodes(), nq = inst.couplings().size();
  CouplingDisplacements cd;
  cd.disp.assign(n, std::vector<Vec2>(nq));
  cd.tree_edge.assign(inst.edges().size(), 0);
  std::vector<char> seen(n, 0);
  std::vector<NodeId> stack{0};
  seen[0] = 1;
  while (!stack.empty()) {
    NodeId w = stack.back();
    stack.pop_back();
    for (Dir d : kDirs) {
      NodeId x = inst.neighbour(w, d);
      if (x == kNone || seen[x]) continue;
      seen[x] = 1;
      uint32_t e = inst.edge_index(w, d);
      cd.tree_edge[e] = 1;
      cd.disp[x] = cd.disp[w];
      OpId k = inst.edges()[e].op;
      if (k != kNone) cd.disp[x][inst.ops()[k].coupling] += edge_vector(inst, e, w);
      stack.push_back(x);
    }
  }
  return cd;
}

BruteAnswer brute_discrete(const Instance& inst) {
  const size_t nq = inst.couplings().size();
  if (nq > 8) throw std::invalid_argument("brute_discrete: too many couplings");
  BruteAnswer ans;
  if (nq == 0) return ans;
  Simulator sim(inst);
  std::vector<CouplingId> order(nq);
  std::iota(order.begin(), order.end(), 0);
  do {
    if (sim.run_order(order).collision) {
      ans.collides = true;
      ans.schedule = schedule_from_order(order);
      return ans;
    }
  } while (std::next_permutation(order.begin(), order.end()));
  return ans;
}

BruteAnswer brute_continuous(const Instance& inst) {
  const size_t nq = inst.couplings().size();
  if (nq > 5) throw std::invalid_argument("brute_continuous: too many couplings");
  BruteAnswer ans = brute_discrete(inst);
  if (ans.collides || nq == 0) return ans;
  // (b) No order collides, so in particular no coupling breaks a cycle and
  // positions on any spanning tree are exact.
  const size_t n = inst.num_nodes();
  CouplingDisplacements cd = coupling_displacements(inst);
  std::vector<Aff> DX(n, Aff{Q(0), std::vector<Q>(nq)}), DY = DX;
  for (NodeId w = 0; w < n; ++w)
    for (size_t q = 0; q < nq; ++q) DX[w].a[q] = Q(cd.disp[w][q].x), DY[w].a[q] = Q(cd.disp[w][q].y);
  // Region rectangles as four affine functions, in the solver's numbering.
  struct RectF {
    Aff f[4];  // xlo, xhi, ylo, yhi
  };
  auto shift = [&](int64_t c, const Aff& D) { return Aff{D.c + Q(c), D.a}; };
  std::vector<RectF> regs;
  for (NodeId w = 0; w < n; ++w) {
    Vec2 c = inst.cells()[w];
    RectF r{{shift(c.x, DX[w]), shift(c.x + 1, DX[w]), shift(c.y, DY[w]), shift(c.y + 1, DY[w])}};
    OpId k = inst.op_of_node(w);
    if (k != kNone && inst.ops()[k].kind == OpKind::Contract && inst.ops()[k].v == w) {
      const Operation& op = inst.ops()[k];
      // The face of v toward u stays on u's face.
      NodeId u = op.u;
      Vec2 uc = inst.cells()[u];
      switch (op.dir) {
        case Dir::PosX: r.f[0] = shift(uc.x + 1, DX[u]); break;
        case Dir::NegX: r.f[1] = shift(uc.x, DX[u]); break;
        case Dir::PosY: r.f[2] = shift(uc.y + 1, DY[u]); break;
        case Dir::NegY: r.f[3] = shift(uc.y, DY[u]); break;
      }
    }
    regs.push_back(r);
  }
  for (OpId k = 0; k < inst.ops().size(); ++k) {
    const Operation& op = inst.ops()[k];
    if (op.kind == OpKind::Contract) continue;
    NodeId u = op.u;
    Vec2 uc = inst.cells()[u];
    // Starts as the segment on u's face toward dir, spans to v's face (or p).
    RectF r{{shift(uc.x, DX[u]), shift(uc.x + 1, DX[u]), shift(uc.y, DY[u]), shift(uc.y + 1, DY[u])}};
    int face = op.dir == Dir::PosX ? 1 : op.dir == Dir::NegX ? 0 : op.dir == Dir::PosY ? 3 : 2;
    int opp = face ^ 1;
    r.f[opp] = r.f[face];  // the near face sits on u's face
    Aff far = r.f[face];
    if (op.kind == OpKind::Expand) {
      NodeId v = op.v;
      Vec2 vc = inst.cells()[v];
      far = face == 1   ? shift(vc.x, DX[v])
            : face == 0 ? shift(vc.x + 1, DX[v])
            : face == 3 ? shift(vc.y, DY[v])
                        : shift(vc.y + 1, DY[v]);
    } else {
      int sg = (face == 1 || face == 3) ? 1 : -1;
      far.a[op.coupling] = far.a[op.coupling] + Q(sg);
    }
    r.f[face] = far;
    // far face is the one toward dir: xhi for +x (face 1), xlo for -x (face 0)
    regs.push_back(r);
  }
  for (size_t a = 0; a < regs.size(); ++a)
    for (size_t b = a + 1; b < regs.size(); ++b) {
      const RectF &A = regs[a], &B = regs[b];
      std::vector<Aff> g = {A.f[1] - B.f[0], B.f[1] - A.f[0], A.f[3] - B.f[2], B.f[3] - A.f[2],
                            A.f[1] - A.f[0], A.f[3] - A.f[2], B.f[1] - B.f[0], B.f[3] - B.f[2]};
      auto p = strict_point(g, nq);
      if (!p) continue;
      ans.collides = true;
      ans.from_pair_test = true;
      Schedule s;
      s.start.resize(nq);
      for (size_t q = 0; q < nq; ++q) s.start[q] = Q(1) - (*p)[q];
      if (!check_schedule_bounds(inst, s)) ans.schedule = s;
      return ans;
    }
  return ans;
}

}  // namespace gridlock::test
