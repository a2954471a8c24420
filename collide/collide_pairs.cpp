// The pair's inequalities (collide/internal/collide_pairs.hpp): region forms, the
// quick filter, the exact check of a witness, and the system the pair tests
// eliminate (collide/internal/pair_system.hpp). The tests themselves:
// collide/zonotope.cpp (continuous), collide/subset_sums.cpp (discrete),
// collide/pair_traversal.cpp (every pair of an instance);
// collide/lp_elimination.cpp their exact linear programming.
#include "collide/internal/collide_pairs.hpp"

#include <algorithm>
#include <stdexcept>

#include "collide/internal/pair_system.hpp"
#include "common/assert.hpp"

namespace gridlock {

namespace {

int axis_of_face(int f) { return f < 2 ? 0 : 1; }

// D_v - D_u at full progress of an edge operation (u, v): +dir for an
// expansion, -dir for a contraction.
Vec2 edge_op_delta(const Operation& op) {
  Vec2 d = unit(op.dir);
  return op.kind == OpKind::Contract ? Vec2{-d.x, -d.y} : d;
}

}  // namespace

namespace pairs {

PairSystem build_system(const RegionForm& A, const RegionForm& B, const PathNets& nets) {
  PairSystem S;
  auto var_index = [&](CouplingId q) -> int {
    if (q == kNone) return -1;
    for (int j = 0; j < S.nv; ++j)
      if (S.var[j] == q) return j;
    S.var[S.nv] = q;
    return S.nv++;
  };
  int ja = var_index(A.own), jb = var_index(B.own);
  // (constant, A face coefs, B face coefs, axis, sign)
  struct Row {
    int64_t c;
    int af_hi, af_lo, bf_hi, bf_lo;  // faces: + A[af_hi] - A[af_lo] + B[bf_hi] - B[bf_lo] (-1: none)
    int axis, sign;
  };
  const Row rows[8] = {
      {A.base[1] - B.base[0], 1, -1, -1, 0, 0, -1}, {B.base[1] - A.base[0], -1, 0, 1, -1, 0, +1},
      {A.base[3] - B.base[2], 3, -1, -1, 2, 1, -1}, {B.base[3] - A.base[2], -1, 2, 3, -1, 1, +1},
      {A.base[1] - A.base[0], 1, 0, -1, -1, -1, 0}, {A.base[3] - A.base[2], 3, 2, -1, -1, -1, 0},
      {B.base[1] - B.base[0], -1, -1, 1, 0, -1, 0}, {B.base[3] - B.base[2], -1, -1, 3, 2, -1, 0},
  };
  for (int i = 0; i < 8; ++i) {
    const Row& r = rows[i];
    S.c[i] = r.c;
    S.axis[i] = r.axis;
    S.sign[i] = r.sign;
    if (ja >= 0) {
      if (r.af_hi >= 0) S.e[i][ja] += A.own_coef[r.af_hi];
      if (r.af_lo >= 0) S.e[i][ja] -= A.own_coef[r.af_lo];
    }
    if (jb >= 0) {
      if (r.bf_hi >= 0) S.e[i][jb] += B.own_coef[r.bf_hi];
      if (r.bf_lo >= 0) S.e[i][jb] -= B.own_coef[r.bf_lo];
    }
  }
  for (const auto& [q, w] : nets) {
    int j = -1;
    for (int t = 0; t < S.nv; ++t)
      if (S.var[t] == q) j = t;
    if (j < 0) {
      S.gens.push_back({q, w});
      continue;
    }
    S.var_nets.push_back({q, w});
    for (int i = 0; i < 8; ++i)
      if (S.axis[i] >= 0) S.e[i][j] += S.sign[i] * comp(w, S.axis[i]);
  }
  return S;
}

void rect_bounds(const PairSystem& S, Bound& Ux, Bound& Lx, Bound& Uy, Bound& Ly) {
  auto row = [&](int i, bool negate) {
    Bound b;
    i128 s = negate ? -1 : 1;
    b.c = s * S.c[i];
    b.e[0] = s * S.e[i][0];
    b.e[1] = s * S.e[i][1];
    return b;
  };
  Ux = row(0, false), Lx = row(1, true), Uy = row(2, false), Ly = row(3, true);
}

}  // namespace pairs

using pairs::comp;

std::vector<RegionForm> region_forms(const Instance& inst, const Regions& regions) {
  GRIDLOCK_ASSERT(std::ranges::none_of(FaceNets::build(inst).coupling_breaks_cycle, [](char b) { return b != 0; }),
                  "region_forms needs no coupling that breaks a cycle");
  std::vector<RegionForm> forms(regions.size());
  for (size_t r = 0; r < regions.size(); ++r) {
    const RegionShape& s = regions.shapes[r];
    RegionForm& F = forms[r];
    OpId k = kNone;
    if (s.kind == RegionKind::Node) {
      F.ref = s.id;
      k = inst.op_of_node(s.id);
    } else {
      k = s.id;
      F.ref = inst.ops()[k].u;
    }
    for (int f = 0; f < 4; ++f) F.base[f] = s.base[f];
    if (k == kNone) continue;
    const Operation& op = inst.ops()[k];
    bool varies = false;
    for (int f = 0; f < 4; ++f) {
      if (s.ref[f] == F.ref) continue;
      // D_{ref[f]} - D_ref = +-p * delta, over the operation's own edge.
      Vec2 d = edge_op_delta(op);
      int sgn = (F.ref == op.u && s.ref[f] == op.v) ? 1 : (F.ref == op.v && s.ref[f] == op.u) ? -1 : 0;
      if (sgn == 0) throw std::logic_error("region_forms: unexpected face reference");
      F.own_coef[f] = sgn * static_cast<int>(comp(d, axis_of_face(f)));
      varies = true;
    }
    if (s.grow_op != kNone) {
      F.own_coef[s.grow_face] += s.grow_sign;
      varies = true;
    }
    if (varies) F.own = op.coupling;
  }
  return forms;
}

bool pair_may_meet(const RegionForm& A, const RegionForm& B, int64_t reach_x, int64_t reach_y) {
  auto lo = [](const RegionForm& R, int f) { return R.base[f] + std::min(0, R.own_coef[f]); };
  auto hi = [](const RegionForm& R, int f) { return R.base[f] + std::max(0, R.own_coef[f]); };
  // Delta.x must lie in (A.xlo - B.xhi, A.xhi - B.xlo), and |Delta.x| <= reach_x.
  if (lo(A, 0) - hi(B, 1) >= reach_x || hi(A, 1) - lo(B, 0) <= -reach_x) return false;
  if (lo(A, 2) - hi(B, 3) >= reach_y || hi(A, 3) - lo(B, 2) <= -reach_y) return false;
  return true;
}

bool pair_overlaps_at(const RegionForm& A, const RegionForm& B, const PathNets& nets, const std::vector<Rational>& p) {
  Rational dx, dy;
  for (const auto& [q, w] : nets) dx = dx + p[q] * Rational(w.x), dy = dy + p[q] * Rational(w.y);
  auto face = [&](const RegionForm& R, int f, bool is_b) {
    Rational v = Rational(R.base[f]);
    if (R.own != kNone) v = v + p[R.own] * Rational(R.own_coef[f]);
    if (is_b) v = v + (f < 2 ? dx : dy);
    return v;
  };
  Rational a[4], b[4];
  for (int f = 0; f < 4; ++f) a[f] = face(A, f, false), b[f] = face(B, f, true);
  return a[1] > b[0] && b[1] > a[0] && a[3] > b[2] && b[3] > a[2] && a[1] > a[0] && a[3] > a[2] && b[1] > b[0] &&
         b[3] > b[2];
}

}  // namespace gridlock
