#include "collide/collide_pairs.hpp"

#include "collide/angle_tree.hpp"

#include <algorithm>
#include <array>
#include <climits>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>

#include "common/assert.hpp"
#include "common/int_math.hpp"

namespace gridlock {

namespace {

using i128 = __int128;

int axis_of_face(int f) { return f < 2 ? 0 : 1; }
int64_t comp(Vec2 v, int axis) { return axis == 0 ? v.x : v.y; }

// D_v - D_u at full progress of an edge operation (u, v): +dir for an
// expansion, -dir for a contraction.
Vec2 edge_op_delta(const Operation& op) {
  Vec2 d = unit(op.dir);
  return op.kind == OpKind::Contract ? Vec2{-d.x, -d.y} : d;
}

// Compares n1/d1 with n2/d2 (d1, d2 > 0) without overflow: -1, 0, 1.
int cmp_frac(i128 n1, i128 d1, i128 n2, i128 d2) {
  // Floors first; then compare the reciprocals of the fractional parts.
  int flip = 1;
  for (int guard = 0; guard < 400; ++guard) {
    i128 q1 = floor_div(n1, d1), q2 = floor_div(n2, d2);
    if (q1 != q2) return q1 < q2 ? -flip : flip;
    i128 r1 = n1 - q1 * d1, r2 = n2 - q2 * d2;  // 0 <= r < d
    if (r1 == 0 || r2 == 0) {
      if (r1 == 0 && r2 == 0) return 0;
      return (r1 == 0 ? -1 : 1) * flip;
    }
    // r1/d1 < r2/d2  <=>  d1/r1 > d2/r2: compare the reciprocals, flipped.
    n1 = d1, d1 = r1, n2 = d2, d2 = r2;
    flip = -flip;
  }
  throw std::logic_error("cmp_frac did not terminate");
}

// a0 v0 + a1 v1 + c  (> 0 if strict, >= 0 otherwise)
struct Lin {
  i128 a[2] = {0, 0};
  i128 c = 0;
  bool strict = true;
};

// Feasible set of one variable from constraints a v + c (>, >=) 0 (a[1] == 0):
// lower/upper bounds as fractions. Returns feasibility.
struct Interval {
  bool has_lo = false, has_hi = false;
  i128 lo_n = 0, lo_d = 1, hi_n = 0, hi_d = 1;
  bool lo_strict = false, hi_strict = false;
  bool empty = false;
};

Interval interval_of(const std::vector<Lin>& cons) {
  Interval iv;
  for (const Lin& L : cons) {
    i128 a = L.a[0], c = L.c;
    if (a == 0) {
      if (L.strict ? !(c > 0) : !(c >= 0)) iv.empty = true;
      continue;
    }
    if (a > 0) {  // v > -c/a
      i128 n = -c, d = a;
      int cmp = iv.has_lo ? cmp_frac(n, d, iv.lo_n, iv.lo_d) : 1;
      if (cmp > 0 || (cmp == 0 && L.strict)) iv.has_lo = true, iv.lo_n = n, iv.lo_d = d, iv.lo_strict = L.strict;
    } else {  // v < c/(-a)
      i128 n = c, d = -a;
      int cmp = iv.has_hi ? cmp_frac(n, d, iv.hi_n, iv.hi_d) : -1;
      if (cmp < 0 || (cmp == 0 && L.strict)) iv.has_hi = true, iv.hi_n = n, iv.hi_d = d, iv.hi_strict = L.strict;
    }
  }
  if (!iv.empty && iv.has_lo && iv.has_hi) {
    int cmp = cmp_frac(iv.lo_n, iv.lo_d, iv.hi_n, iv.hi_d);
    if (cmp > 0 || (cmp == 0 && (iv.lo_strict || iv.hi_strict))) iv.empty = true;
  }
  return iv;
}

// Fourier-Motzkin: eliminates v1, returns the constraints on v0 alone.
std::vector<Lin> eliminate_v1(const std::vector<Lin>& cons) {
  std::vector<Lin> out, pos, neg;
  for (const Lin& L : cons) {
    if (L.a[1] > 0) pos.push_back(L);
    else if (L.a[1] < 0) neg.push_back(L);
    else out.push_back(L);
  }
  for (const Lin& P : pos)
    for (const Lin& N : neg) {
      i128 fp = -N.a[1], fn = P.a[1];  // fp * P + fn * N cancels v1
      Lin L;
      L.a[0] = fp * P.a[0] + fn * N.a[0];
      L.c = fp * P.c + fn * N.c;
      L.strict = P.strict || N.strict;
      out.push_back(L);
    }
  return out;
}

constexpr int kScaleBits = 20;
constexpr int64_t kScale = int64_t{1} << kScaleBits;

// Picks an integer m in [0, kScale] with a*m + c (>, >=) 0 for all given
// (a, c, strict), preferring multiples of large powers of two (so that the
// values, as m / 2^20, have small denominators). nullopt if none.
std::optional<int64_t> pick_scaled(const std::vector<Lin>& cons) {
  i128 lo = 0, hi = kScale;
  for (const Lin& L : cons) {
    i128 a = L.a[0], c = L.c;
    if (a == 0) {
      if (L.strict ? !(c > 0) : !(c >= 0)) return std::nullopt;
    } else if (a > 0) {  // m > -c/a  or m >= -c/a
      i128 b = L.strict ? floor_div(-c, a) + 1 : ceil_div(-c, a);
      lo = std::max(lo, b);
    } else {  // m < c/(-a)  or m <= c/(-a)
      // strict: m < c/(-a)  <=>  m <= ceil(c/(-a)) - 1
      i128 b = L.strict ? ceil_div(c, -a) - 1 : floor_div(c, -a);
      hi = std::min(hi, b);
    }
  }
  if (lo > hi) return std::nullopt;
  for (int k = 0; k <= kScaleBits; ++k) {
    i128 step = i128{1} << (kScaleBits - k);
    i128 m = ceil_div(lo, step) * step;
    if (m <= hi) return static_cast<int64_t>(m);
  }
  return std::nullopt;
}

// The pair's constraints: c + e0 v0 + e1 v1 + sign * Delta'[axis] > 0, where
// v0, v1 are the progresses of the own couplings and Delta' is the sum over
// the other couplings' nets.
struct PairSystem {
  int nv = 0;
  CouplingId var[2] = {kNone, kNone};
  int64_t c[8] = {};
  int64_t e[8][2] = {};
  int axis[8] = {};  // -1: no Delta term
  int sign[8] = {};
  std::vector<std::pair<CouplingId, Vec2>> gens;
  std::vector<std::pair<CouplingId, Vec2>> var_nets;  // net of each own coupling on the path
};

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

// Rectangle bounds for Delta' as affine forms in (v0, v1): U_x from row 0,
// L_x from row 1 (as -row), U_y row 2, L_y row 3.
struct Bound {
  i128 c = 0, e[2] = {0, 0};
};

// The support function of the zonotope of gens on the normal set.
struct Normals {
  std::vector<Vec2> u;
  std::vector<i128> h;
};

// The line direction of w != 0: primitive, with x > 0 or (x == 0, y > 0).
Vec2 line_direction(Vec2 w) {
  int64_t gg = std::gcd(w.x < 0 ? -w.x : w.x, w.y < 0 ? -w.y : w.y);
  Vec2 d{w.x / gg, w.y / gg};
  if (d.x < 0 || (d.x == 0 && d.y < 0)) d = Vec2{-d.x, -d.y};
  return d;
}

Normals normals_of(const std::vector<std::pair<CouplingId, Vec2>>& gens) {
  Normals N;
  // Group by line direction; the zonotope's edge normals are the normals of
  // the distinct lines (plus the axes, for the rectangle).
  std::vector<Vec2> dirs;
  for (const auto& g : gens)
    if (!g.second.is_zero()) dirs.push_back(line_direction(g.second));
  std::sort(dirs.begin(), dirs.end(), [](Vec2 a, Vec2 b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
  dirs.erase(std::unique(dirs.begin(), dirs.end()), dirs.end());
  N.u = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  for (Vec2 d : dirs) {
    if (d.x == 0 || d.y == 0) continue;  // axis normals already in
    N.u.push_back({-d.y, d.x});
    N.u.push_back({d.y, -d.x});
  }
  N.h.assign(N.u.size(), 0);
  for (size_t k = 0; k < N.u.size(); ++k)
    for (const auto& g : gens) {
      i128 dot = static_cast<i128>(N.u[k].x) * g.second.x + static_cast<i128>(N.u[k].y) * g.second.y;
      if (dot > 0) N.h[k] += dot;
    }
  return N;
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

// inf over the rectangle of u . r, as an affine form.
Bound inf_rect(Vec2 u, const Bound& Ux, const Bound& Lx, const Bound& Uy, const Bound& Ly) {
  Bound r;
  auto add = [&](int64_t k, const Bound& b) {
    r.c += k * b.c;
    r.e[0] += k * b.e[0];
    r.e[1] += k * b.e[1];
  };
  if (u.x > 0) add(u.x, Lx);
  if (u.x < 0) add(u.x, Ux);
  if (u.y > 0) add(u.y, Ly);
  if (u.y < 0) add(u.y, Uy);
  return r;
}

// All constraints on (v0, v1) after eliminating Delta'.
std::vector<Lin> projected_constraints(const PairSystem& S, const Normals& N) {
  Bound Ux, Lx, Uy, Ly;
  rect_bounds(S, Ux, Lx, Uy, Ly);
  std::vector<Lin> cons;
  cons.reserve(N.u.size() + 10);
  for (size_t k = 0; k < N.u.size(); ++k) {
    Bound inf = inf_rect(N.u[k], Ux, Lx, Uy, Ly);
    Lin L;
    L.c = N.h[k] - inf.c;
    L.a[0] = -inf.e[0];
    L.a[1] = -inf.e[1];
    cons.push_back(L);
  }
  for (const auto& [U, Lo] : {std::pair{Ux, Lx}, std::pair{Uy, Ly}}) {  // non-empty rectangle
    Lin L;
    L.c = U.c - Lo.c;
    L.a[0] = U.e[0] - Lo.e[0];
    L.a[1] = U.e[1] - Lo.e[1];
    cons.push_back(L);
  }
  for (int i = 4; i < 8; ++i) {  // widths
    Lin L;
    L.c = S.c[i];
    L.a[0] = S.e[i][0];
    L.a[1] = S.e[i][1];
    cons.push_back(L);
  }
  for (int j = 0; j < S.nv; ++j) {  // 0 <= v_j <= 1
    Lin lo, hi;
    lo.a[j] = 1, lo.strict = false;
    hi.a[j] = -1, hi.c = 1, hi.strict = false;
    cons.push_back(lo), cons.push_back(hi);
  }
  return cons;
}

}  // namespace

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

namespace {

// Is the projected system on the own progresses feasible? N must hold the
// support of the zonotope of S.gens on a set of normals that contains the
// axis normals and both normals of every direction among S.gens (a larger
// set is harmless: the extra conditions hold whenever 0 lies in the open
// polygon Z' - R).
bool projected_feasible(const PairSystem& S, const Normals& N) {
  std::vector<Lin> cons = projected_constraints(S, N);
  std::vector<Lin> one = S.nv == 2 ? eliminate_v1(cons) : cons;
  return !interval_of(one).empty;
}

}  // namespace

bool continuous_pair_collides(const RegionForm& A, const RegionForm& B, const PathNets& nets, PairWitness* want) {
  PairSystem S = build_system(A, B, nets);
  Normals N = normals_of(S.gens);
  if (!projected_feasible(S, N)) return false;
  if (!want) return true;
  std::vector<Lin> cons = projected_constraints(S, N);
  std::vector<Lin> one = S.nv == 2 ? eliminate_v1(cons) : cons;

  // Witness: v0, then v1, then every other coupling in turn, each a multiple
  // of 2^-20 inside the (open) feasible interval given the earlier choices.
  int64_t m[2] = {0, 0};
  if (S.nv >= 1) {
    std::vector<Lin> c0;
    for (const Lin& L : one) {
      Lin t = L;
      t.c = L.c * kScale;
      c0.push_back(t);
    }
    auto v = pick_scaled(c0);
    if (!v) throw std::logic_error("collide: no witness value with denominator <= 2^20 for an own progress");
    m[0] = *v;
  }
  if (S.nv == 2) {
    std::vector<Lin> c1;
    for (const Lin& L : cons) {
      Lin t;
      t.a[0] = L.a[1];
      t.c = L.a[0] * m[0] + L.c * kScale;
      t.strict = L.strict;
      c1.push_back(t);
    }
    auto v = pick_scaled(c1);
    if (!v) throw std::logic_error("collide: no witness value with denominator <= 2^20 for an own progress");
    m[1] = *v;
  }
  for (int j = 0; j < S.nv; ++j) want->progress.push_back({S.var[j], Rational(m[j], kScale)});
  // The rectangle for Delta', scaled by 2^20.
  Bound Ux, Lx, Uy, Ly;
  rect_bounds(S, Ux, Lx, Uy, Ly);
  auto at = [&](const Bound& b) { return b.c * kScale + b.e[0] * m[0] + b.e[1] * m[1]; };
  i128 ux = at(Ux), lx = at(Lx), uy = at(Uy), ly = at(Ly);
  std::vector<i128> hrest = N.h;  // unscaled support of the couplings not yet fixed
  i128 Fx = 0, Fy = 0;            // scaled sum of the fixed ones
  for (const auto& [q, w] : S.gens) {
    std::vector<Lin> cq;
    for (size_t k = 0; k < N.u.size(); ++k) {
      Vec2 u = N.u[k];
      i128 dot = static_cast<i128>(u.x) * w.x + static_cast<i128>(u.y) * w.y;
      if (dot > 0) hrest[k] -= dot;
      i128 inf = (u.x > 0 ? u.x * lx : u.x * ux) + (u.y > 0 ? u.y * ly : u.y * uy);
      Lin L;
      L.a[0] = dot;
      L.c = hrest[k] * kScale + u.x * Fx + u.y * Fy - inf;
      cq.push_back(L);
    }
    auto v = pick_scaled(cq);
    if (!v) throw std::logic_error("collide: no witness value with denominator <= 2^20 for a coupling");
    Fx += static_cast<i128>(*v) * w.x;
    Fy += static_cast<i128>(*v) * w.y;
    want->progress.push_back({q, Rational(*v, kScale)});
  }
  return true;
}

namespace {

// Subset sums of vectors on a grid [x0, x0+W) x [y0, y0+H).
struct SumGrid {
  int64_t x0 = 0, y0 = 0, W = 1, H = 1;
  std::vector<uint8_t> cell;
  uint8_t& at(int64_t x, int64_t y) { return cell[static_cast<size_t>((x - x0) * H + (y - y0))]; }
  bool get(int64_t x, int64_t y) const {
    if (x < x0 || y < y0 || x >= x0 + W || y >= y0 + H) return false;
    return cell[static_cast<size_t>((x - x0) * H + (y - y0))] != 0;
  }
};

SumGrid subset_sums(const std::vector<Vec2>& vecs, std::vector<SumGrid>* layers) {
  SumGrid g;
  int64_t xmin = 0, xmax = 0, ymin = 0, ymax = 0;
  for (Vec2 w : vecs) {
    (w.x < 0 ? xmin : xmax) += w.x;
    (w.y < 0 ? ymin : ymax) += w.y;
  }
  g.x0 = xmin, g.y0 = ymin, g.W = xmax - xmin + 1, g.H = ymax - ymin + 1;
  g.cell.assign(static_cast<size_t>(g.W * g.H), 0);
  g.at(0, 0) = 1;
  for (Vec2 w : vecs) {
    if (layers) layers->push_back(g);
    // In place: visit targets before their sources.
    for (int64_t i = 0; i < g.W; ++i) {
      int64_t x = w.x > 0 ? g.x0 + g.W - 1 - i : g.x0 + i;
      int64_t tx = x + w.x;
      if (tx < g.x0 || tx >= g.x0 + g.W) continue;
      for (int64_t jj = 0; jj < g.H; ++jj) {
        int64_t y = w.y > 0 ? g.y0 + g.H - 1 - jj : g.y0 + jj;
        int64_t ty = y + w.y;
        if (ty < g.y0 || ty >= g.y0 + g.H) continue;
        if (g.at(x, y)) g.at(tx, ty) = 1;
      }
    }
  }
  return g;
}

// A choice of the coupling that runs last (is caught mid-way): an own
// coupling of the pair (var >= 0), or the path coupling S.gens[gen].
struct RunChoice {
  int var = -1;    // own coupling index, or -1
  size_t gen = 0;  // else: index into S.gens
};

// The choices worth trying: each own coupling, and one per distinct vector
// among the others (which copy of equal vectors runs last does not matter:
// the subset sums of the rest are the same).
std::vector<RunChoice> running_choices(const PairSystem& S) {
  std::vector<RunChoice> choices;
  choices.reserve(static_cast<size_t>(S.nv) + S.gens.size());
  for (int j = 0; j < S.nv; ++j) choices.push_back({j, 0});
  std::vector<Vec2> seen;
  for (size_t g = 0; g < S.gens.size(); ++g) {
    Vec2 w = S.gens[g].second;
    if (std::find(seen.begin(), seen.end(), w) != seen.end()) continue;
    seen.push_back(w);
    choices.push_back({-1, g});
  }
  return choices;
}

// Fills want with the witness of a meeting found at subset sum (x, y) of
// rest (the path vectors S.gens[rest_idx[i]] not running): a subset of rest
// with that sum (by backtracking through subset_sums' layers), the own
// couplings done (val[j] = 1), and the running coupling ch.
void recover_witness(const PairSystem& S, const RunChoice& ch, const std::vector<Vec2>& rest,
                     const std::vector<size_t>& rest_idx, const int64_t val[2], int64_t x, int64_t y,
                     PairWitness* want) {
  std::vector<SumGrid> layers;
  subset_sums(rest, &layers);
  std::vector<char> used(rest.size(), 0);
  int64_t cx = x, cy = y;
  for (size_t i = rest.size(); i-- > 0;) {
    if (layers[i].get(cx, cy)) continue;  // reachable without vector i
    used[i] = 1;
    cx -= rest[i].x, cy -= rest[i].y;
  }
  if (cx != 0 || cy != 0) throw std::logic_error("collide: subset-sum backtrack failed");
  for (size_t i = 0; i < rest.size(); ++i)
    if (used[i]) want->done.push_back(S.gens[rest_idx[i]].first);
  for (int j = 0; j < S.nv; ++j)
    if (j != ch.var && val[j]) want->done.push_back(S.var[j]);
  want->running = ch.var >= 0 ? S.var[ch.var] : S.gens[ch.gen].first;
}

}  // namespace

bool discrete_pair_collides_per_vector(const RegionForm& A, const RegionForm& B, const PathNets& nets,
                                       PairWitness* want) {
  PairSystem S = build_system(A, B, nets);
  const std::vector<RunChoice> choices = running_choices(S);
  if (choices.empty()) {  // nothing moves the pair: overlap now or never (never, in a valid instance)
    for (int i = 0; i < 8; ++i)
      if (S.c[i] <= 0) return false;
    return true;
  }
  for (const RunChoice& ch : choices) {
    std::vector<Vec2> rest;
    std::vector<size_t> rest_idx;
    for (size_t g = 0; g < S.gens.size(); ++g)
      if (ch.var >= 0 || g != ch.gen) rest.push_back(S.gens[g].second), rest_idx.push_back(g);
    SumGrid sums = subset_sums(rest, nullptr);
    // States of the own couplings that do not run: 0 or 1 each.
    int free_vars = S.nv - (ch.var >= 0 ? 1 : 0);
    for (int mask = 0; mask < (1 << free_vars); ++mask) {
      int64_t val[2] = {0, 0};
      {
        int bit = 0;
        for (int j = 0; j < S.nv; ++j) {
          if (j == ch.var) continue;
          val[j] = (mask >> bit++) & 1;
        }
      }
      // Per row: constant part (without z), the coefficient of s.
      i128 cst[8], ks[8];
      for (int i = 0; i < 8; ++i) {
        cst[i] = S.c[i];
        for (int j = 0; j < S.nv; ++j)
          if (j != ch.var) cst[i] += static_cast<i128>(S.e[i][j]) * val[j];
        if (ch.var >= 0) ks[i] = S.e[i][ch.var];
        else ks[i] = S.axis[i] >= 0 ? S.sign[i] * comp(S.gens[ch.gen].second, S.axis[i]) : 0;
      }
      for (int64_t x = sums.x0; x < sums.x0 + sums.W; ++x)
        for (int64_t y = sums.y0; y < sums.y0 + sums.H; ++y) {
          if (!sums.get(x, y)) continue;
          std::vector<Lin> cs;
          for (int i = 0; i < 8; ++i) {
            Lin L;
            L.a[0] = ks[i];
            L.c = cst[i] + (S.axis[i] < 0 ? 0 : S.sign[i] * (S.axis[i] == 0 ? x : y));
            cs.push_back(L);
          }
          Lin lo, hi;
          lo.a[0] = 1, lo.strict = false;
          hi.a[0] = -1, hi.c = 1, hi.strict = false;
          cs.push_back(lo), cs.push_back(hi);
          if (interval_of(cs).empty) continue;
          if (want) recover_witness(S, ch, rest, rest_idx, val, x, y, want);
          return true;
        }
    }
  }
  return false;
}

namespace {

// Subset sums of a multiset given as distinct vectors with multiplicities:
// one pass over the grid per distinct vector (O(c A) for c distinct
// vectors and grid area A, against O(K A) one vector at a time). A cell is
// reachable after vector w (m copies) iff one of the m + 1 cells
// p, p - w, ..., p - m w was reachable before: walked in an order where
// p - w comes before p, cnt[p] = steps since the last reachable cell on
// that chain.
SumGrid grouped_subset_sums(const std::vector<std::pair<Vec2, uint32_t>>& groups, std::vector<int32_t>& cnt) {
  SumGrid g;
  int64_t xmin = 0, xmax = 0, ymin = 0, ymax = 0;
  for (const auto& [w, m] : groups) {
    (w.x < 0 ? xmin : xmax) += w.x * m;
    (w.y < 0 ? ymin : ymax) += w.y * m;
  }
  g.x0 = xmin, g.y0 = ymin, g.W = xmax - xmin + 1, g.H = ymax - ymin + 1;
  g.cell.assign(static_cast<size_t>(g.W * g.H), 0);
  g.at(0, 0) = 1;
  constexpr int32_t kFar = INT32_MAX / 2;
  cnt.resize(g.cell.size());
  for (const auto& [w, m] : groups) {
    if (m == 0) continue;
    for (int64_t i = 0; i < g.W; ++i) {
      const int64_t x = w.x >= 0 ? g.x0 + i : g.x0 + g.W - 1 - i;
      for (int64_t j = 0; j < g.H; ++j) {
        const int64_t y = w.y >= 0 ? g.y0 + j : g.y0 + g.H - 1 - j;
        const auto at = static_cast<size_t>((x - g.x0) * g.H + (y - g.y0));
        int32_t c = 0;
        if (g.cell[at] == 0) {
          const int64_t px = x - w.x, py = y - w.y;
          const bool in = px >= g.x0 && py >= g.y0 && px < g.x0 + g.W && py < g.y0 + g.H;
          const int32_t prev = in ? cnt[static_cast<size_t>((px - g.x0) * g.H + (py - g.y0))] : kFar;
          c = prev >= kFar ? kFar : prev + 1;
        }
        cnt[at] = c;
        g.cell[at] = c <= static_cast<int32_t>(m) ? 1 : 0;
      }
    }
  }
  return g;
}

// Does some reachable Delta (a cell of sums) with the running progress s
// in [0,1] satisfy the eight rows c_i + k_i s + sign_i Delta[axis_i] > 0?
// Only the cells of the rows' bounding box over s in [0,1] can (Delta.x in
// (min(-c1, -c1 - k1), max(c0, c0 + k0)), and so for y): O(1 + |k|^2)
// cells, each an exact one-variable interval test. Returns the cell.
std::optional<std::pair<int64_t, int64_t>> meeting_cell(const PairSystem& S, const SumGrid& sums, const i128 cst[8],
                                                        const i128 ks[8], std::vector<Lin>& cs) {
  const i128 xlo = std::min(-cst[1], -cst[1] - ks[1]), xhi = std::max(cst[0], cst[0] + ks[0]);
  const i128 ylo = std::min(-cst[3], -cst[3] - ks[3]), yhi = std::max(cst[2], cst[2] + ks[2]);
  const int64_t x_from = static_cast<int64_t>(std::max<i128>(xlo, sums.x0));
  const int64_t x_to = static_cast<int64_t>(std::min<i128>(xhi, sums.x0 + sums.W - 1));
  const int64_t y_from = static_cast<int64_t>(std::max<i128>(ylo, sums.y0));
  const int64_t y_to = static_cast<int64_t>(std::min<i128>(yhi, sums.y0 + sums.H - 1));
  for (int64_t x = x_from; x <= x_to; ++x)
    for (int64_t y = y_from; y <= y_to; ++y) {
      if (!sums.get(x, y)) continue;
      cs.clear();
      for (int i = 0; i < 8; ++i) {
        Lin L;
        L.a[0] = ks[i];
        L.c = cst[i] + (S.axis[i] < 0 ? 0 : S.sign[i] * (S.axis[i] == 0 ? x : y));
        cs.push_back(L);
      }
      Lin lo, hi;
      lo.a[0] = 1, lo.strict = false;
      hi.a[0] = -1, hi.c = 1, hi.strict = false;
      cs.push_back(lo), cs.push_back(hi);
      if (!interval_of(cs).empty) return std::pair{x, y};
    }
  return std::nullopt;
}

}  // namespace

bool discrete_pair_collides(const RegionForm& A, const RegionForm& B, const PathNets& nets, PairWitness* want) {
  PairSystem S = build_system(A, B, nets);
  const std::vector<RunChoice> choices = running_choices(S);
  if (choices.empty()) {  // nothing moves the pair: overlap now or never (never, in a valid instance)
    for (int i = 0; i < 8; ++i)
      if (S.c[i] <= 0) return false;
    return true;
  }
  // The path's vectors as distinct vectors with multiplicities (c groups).
  std::vector<std::pair<Vec2, uint32_t>> groups;
  for (const auto& g : S.gens) {
    auto it = std::find_if(groups.begin(), groups.end(), [&](const auto& e) { return e.first == g.second; });
    if (it == groups.end()) groups.push_back({g.second, 1});
    else ++it->second;
  }
  std::vector<int32_t> cnt;
  std::vector<Lin> cs;
  cs.reserve(10);
  for (const RunChoice& ch : choices) {
    // The rest: every vector, minus one copy of the running one.
    auto rest_groups = groups;
    if (ch.var < 0)
      for (auto& e : rest_groups)
        if (e.first == S.gens[ch.gen].second) --e.second;
    const SumGrid sums = grouped_subset_sums(rest_groups, cnt);
    const int free_vars = S.nv - (ch.var >= 0 ? 1 : 0);
    for (int mask = 0; mask < (1 << free_vars); ++mask) {
      int64_t val[2] = {0, 0};
      for (int j = 0, bit = 0; j < S.nv; ++j)
        if (j != ch.var) val[j] = (mask >> bit++) & 1;
      i128 cst[8], ks[8];
      for (int i = 0; i < 8; ++i) {
        cst[i] = S.c[i];
        for (int j = 0; j < S.nv; ++j)
          if (j != ch.var) cst[i] += static_cast<i128>(S.e[i][j]) * val[j];
        if (ch.var >= 0) ks[i] = S.e[i][ch.var];
        else ks[i] = S.axis[i] >= 0 ? S.sign[i] * comp(S.gens[ch.gen].second, S.axis[i]) : 0;
      }
      const auto cell = meeting_cell(S, sums, cst, ks, cs);
      if (!cell) continue;
      if (want) {
        std::vector<Vec2> rest;
        std::vector<size_t> rest_idx;
        for (size_t g = 0; g < S.gens.size(); ++g)
          if (ch.var >= 0 || g != ch.gen) rest.push_back(S.gens[g].second), rest_idx.push_back(g);
        recover_witness(S, ch, rest, rest_idx, val, cell->first, cell->second, want);
      }
      return true;
    }
  }
  return false;
}

namespace {

// A spanning-tree arc with the vector (at full progress) from one end to the
// other and the coupling of the operation on it (kNone: rigid).
struct TreeArc {
  NodeId to;
  CouplingId q;
  Vec2 vec;
};

// Both directions of every spanning-tree edge, by node.
std::vector<std::vector<TreeArc>> tree_adjacency(const Instance& inst, const SpanningTree& tree) {
  const size_t n = inst.num_nodes();
  std::vector<std::vector<TreeArc>> adj(n);
  for (NodeId w = 0; w < n; ++w) {
    NodeId p = tree.parent[w];
    if (p == kNone) continue;
    OpId k = tree.parent_op[w];
    CouplingId q = k == kNone ? kNone : inst.ops()[k].coupling;
    Vec2 v = op_child_vector(inst, tree, w);
    adj[p].push_back({w, q, v});
    adj[w].push_back({p, q, Vec2{-v.x, -v.y}});
  }
  return adj;
}

// The support values of the zonotope of the path's non-zero nets, kept as
// the path changes: on the four axis normals, and on both normals of every
// line direction present among the nets (with how many nets have it).
struct SupportTable {
  struct Line {
    uint32_t count = 0;            // active nets on this line
    i128 h_plus = 0, h_minus = 0;  // support on (-d.y, d.x) and on (d.y, -d.x)
  };
  i128 h_axis[4] = {0, 0, 0, 0};                      // on (1,0), (-1,0), (0,1), (0,-1)
  std::map<std::pair<int64_t, int64_t>, Line> lines;  // by line direction, axis lines excluded
  size_t empty_lines = 0;                             // lines with count 0

  static i128 pos(i128 v) { return v > 0 ? v : 0; }
  static i128 dot_plus(Vec2 d, Vec2 w) { return static_cast<i128>(-d.y) * w.x + static_cast<i128>(d.x) * w.y; }
  // Adds (sign +1) or removes (-1) the contribution of a net w: O(lines).
  void contribute(Vec2 w, int sign) {
    h_axis[0] += sign * pos(w.x), h_axis[1] += sign * pos(-w.x);
    h_axis[2] += sign * pos(w.y), h_axis[3] += sign * pos(-w.y);
    for (auto& [key, line] : lines) {
      i128 t = dot_plus(Vec2{key.first, key.second}, w);
      line.h_plus += sign * pos(t), line.h_minus += sign * pos(-t);
    }
  }
  // The table as normals and supports (the order of normals_of's axes first).
  Normals normals() const {
    Normals N;
    N.u = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    N.h.assign(h_axis, h_axis + 4);
    for (const auto& [key, line] : lines) {
      if (line.count == 0) continue;
      N.u.push_back({-key.second, key.first}), N.h.push_back(line.h_plus);
      N.u.push_back({key.second, -key.first}), N.h.push_back(line.h_minus);
    }
    return N;
  }
};

bool on_axis(Vec2 w) { return w.x == 0 || w.y == 0; }

// The net vector of each coupling along a tree path that grows and shrinks
// one arc at a time: net[q]; active, the couplings with a non-zero net
// (pos[q] their place there, kNone if absent); reach_x / reach_y, the sums
// of |net| per axis. O(1) per apply(); with `supports` on, also the
// SupportTable: O(lines) per apply(), plus O(active) when a new line appears.
struct PathNetTracker {
  std::vector<Vec2> net;
  std::vector<uint32_t> pos;
  std::vector<CouplingId> active;
  int64_t reach_x = 0, reach_y = 0;
  bool supports = false;
  SupportTable table;
  uint64_t purges = 0;
  bool angles_on = false;
  AngleTree angles;                // the non-zero nets sorted by angle (ZonotopeTest::AngleTree)
  std::vector<WidePoint> polygon;  // scratch: the own progresses' polygon of the pair being tested

  explicit PathNetTracker(size_t nq) : net(nq), pos(nq, kNone) {}
  void apply(CouplingId q, Vec2 v) {
    Vec2& w = net[q];
    reach_x -= std::abs(w.x), reach_y -= std::abs(w.y);
    bool was = !w.is_zero();
    if (supports && was) forget_line(w);
    if (angles_on) angles.remove(w), angles.add(w + v);
    w += v;
    reach_x += std::abs(w.x), reach_y += std::abs(w.y);
    bool now = !w.is_zero();
    if (now && !was) pos[q] = static_cast<uint32_t>(active.size()), active.push_back(q);
    if (!now && was) {
      CouplingId last = active.back();
      active[pos[q]] = last;
      pos[last] = pos[q];
      active.pop_back();
      pos[q] = kNone;
    }
    if (supports && now) learn_line(q, w);
  }
  size_t live_lines() const { return table.lines.size() - table.empty_lines; }
  // Removes net w (about to change) from the table.
  void forget_line(Vec2 w) {
    table.contribute(w, -1);
    if (on_axis(w)) return;
    Vec2 d = line_direction(w);
    // Kept at count 0 (no O(K) rebuild when it returns) until the empty
    // lines outnumber twice the live ones; then all empty ones go at once
    // (amortised O(1) per forget), so steps and pairs cost O(live lines).
    if (--table.lines.find({d.x, d.y})->second.count == 0 && ++table.empty_lines > 2 * live_lines() + 8)
      std::erase_if(table.lines, [](const auto& kv) { return kv.second.count == 0; }), table.empty_lines = 0, ++purges;
  }
  // Adds q's new net w to the table; a new line gets its supports over the
  // other active nets first.
  void learn_line(CouplingId q, Vec2 w) {
    if (!on_axis(w)) {
      Vec2 d = line_direction(w);
      auto [it, fresh] = table.lines.try_emplace({d.x, d.y});
      if (!fresh && it->second.count == 0) --table.empty_lines;
      if (fresh)
        for (CouplingId r : active) {
          if (r == q) continue;
          i128 t = SupportTable::dot_plus(d, net[r]);
          it->second.h_plus += SupportTable::pos(t), it->second.h_minus += SupportTable::pos(-t);
        }
      ++it->second.count;
    }
    table.contribute(w, +1);
  }
  // The non-zero nets, as the pair tests take them.
  PathNets nets() const {
    PathNets out;
    out.reserve(active.size());
    for (CouplingId q : active) out.push_back({q, net[q]});
    return out;
  }
};

// The continuous test from the tracker's supports: only the own couplings'
// nets are taken out of the zonotope. Same answer as
// continuous_pair_collides(A, B, path.nets()).
bool continuous_pair_collides_supported(const RegionForm& A, const RegionForm& B, const PathNetTracker& path) {
  PathNets own;
  for (CouplingId q : {A.own, B.own})
    if (q != kNone && !path.net[q].is_zero() && (own.empty() || own.front().first != q))
      own.push_back({q, path.net[q]});
  PairSystem S = build_system(A, B, own);
  Normals N = path.table.normals();
  for (const auto& [q, w] : own)
    for (size_t k = 0; k < N.u.size(); ++k)
      N.h[k] -= SupportTable::pos(static_cast<i128>(N.u[k].x) * w.x + static_cast<i128>(N.u[k].y) * w.y);
  return projected_feasible(S, N);
}

// What the own progresses allow for Delta' (docs/collide.md, "The angle
// tree"): J = {v in [0,1]^nv : widths > 0, rectangle R(v) non-empty} (an
// unused variable is pinned to 0). J empty: no overlap. Otherwise the
// union U of the open boxes R(v) over J is open and convex with
// cl U = conv{cl R(v) : v a vertex of cl J} (box bounds are affine in v,
// so R at a convex combination is the Minkowski combination of the R's).
// Fills the corners of -cl R(v) at the vertices of cl J, scaled by *scale
// (the lcm of the vertices' denominators) to integers.
enum class OwnPolygon { Empty, Ready, TooFine };

std::vector<Lin> own_constraints(const PairSystem& S, const Bound& Ux, const Bound& Lx, const Bound& Uy,
                                 const Bound& Ly) {
  std::vector<Lin> cons;
  cons.reserve(10);
  for (const auto& [U, Lo] : {std::pair{Ux, Lx}, std::pair{Uy, Ly}}) {  // non-empty rectangle
    Lin L;
    L.c = U.c - Lo.c, L.a[0] = U.e[0] - Lo.e[0], L.a[1] = U.e[1] - Lo.e[1];
    cons.push_back(L);
  }
  for (int i = 4; i < 8; ++i) {  // widths
    Lin L;
    L.c = S.c[i], L.a[0] = S.e[i][0], L.a[1] = S.e[i][1];
    cons.push_back(L);
  }
  for (int j = 0; j < 2; ++j) {  // 0 <= v_j <= 1, or v_j = 0 when unused
    Lin lo, hi;
    lo.a[j] = 1, lo.strict = false;
    hi.a[j] = -1, hi.c = j < S.nv ? 1 : 0, hi.strict = false;
    cons.push_back(lo), cons.push_back(hi);
  }
  return cons;
}

i128 gcd128(i128 a, i128 b) {
  if (a < 0) a = -a;
  if (b < 0) b = -b;
  while (b != 0) a %= b, std::swap(a, b);
  return a;
}

// The vertices (n0/d, n1/d) of cl J: pairs of constraint lines that meet in
// a point satisfying every constraint (non-strict). O(c^3), c <= 10.
std::vector<std::array<i128, 3>> closure_vertices(const std::vector<Lin>& cons, int nv) {
  if (nv == 0) return {{0, 0, 1}};
  std::vector<std::array<i128, 3>> out;
  for (size_t i = 0; i < cons.size(); ++i)
    for (size_t k = i + 1; k < cons.size(); ++k) {
      const Lin &P = cons[i], &Q = cons[k];
      i128 det = P.a[0] * Q.a[1] - P.a[1] * Q.a[0];
      if (det == 0) continue;
      i128 n0 = -P.c * Q.a[1] + P.a[1] * Q.c, n1 = -P.a[0] * Q.c + P.c * Q.a[0];
      if (det < 0) det = -det, n0 = -n0, n1 = -n1;
      bool inside = std::ranges::all_of(cons, [&](const Lin& L) { return L.a[0] * n0 + L.a[1] * n1 + L.c * det >= 0; });
      if (!inside) continue;
      i128 g = gcd128(gcd128(n0, n1), det);
      out.push_back({n0 / g, n1 / g, det / g});
    }
  return out;
}

OwnPolygon own_polygon(const PairSystem& S, int64_t* scale, std::vector<WidePoint>* pts) {
  Bound Ux, Lx, Uy, Ly;
  rect_bounds(S, Ux, Lx, Uy, Ly);
  std::vector<Lin> closed = own_constraints(S, Ux, Lx, Uy, Ly);
  // With at most one own progress v1 is pinned to 0 and interval_of reads v0 alone.
  if (interval_of(S.nv == 2 ? eliminate_v1(closed) : closed).empty) return OwnPolygon::Empty;
  for (Lin& L : closed) L.strict = false;
  std::vector<std::array<i128, 3>> verts;
  if (S.nv == 1) {  // cl J is the segment between the closed interval's ends
    const Interval iv = interval_of(closed);
    const i128 glo = gcd128(iv.lo_n, iv.lo_d), ghi = gcd128(iv.hi_n, iv.hi_d);
    verts = {{iv.lo_n / glo, 0, iv.lo_d / glo}, {iv.hi_n / ghi, 0, iv.hi_d / ghi}};
  } else {
    verts = closure_vertices(closed, S.nv);
  }
  i128 lcm = 1;
  for (const auto& v : verts) {
    lcm = lcm / gcd128(lcm, v[2]) * v[2];
    if (lcm > (i128{1} << 20)) return OwnPolygon::TooFine;
  }
  *scale = static_cast<int64_t>(lcm);
  pts->clear();
  for (const auto& v : verts) {
    const i128 f = lcm / v[2];
    auto at = [&](const Bound& b) { return b.c * lcm + (b.e[0] * v[0] + b.e[1] * v[1]) * f; };
    const i128 ux = at(Ux), lx = at(Lx), uy = at(Uy), ly = at(Ly);
    pts->push_back({-ux, -uy}), pts->push_back({-lx, -uy}), pts->push_back({-lx, -ly}), pts->push_back({-ux, -ly});
  }
  return OwnPolygon::Ready;
}

// The continuous test from the angle tree: the own couplings' nets are
// taken out of the tree for the query (and put back), the own progresses
// become the polygon -cl U, and the pair can overlap iff 0 lies in the
// interior of Z' - cl U = Z' + (-cl U). nullopt: a vertex of cl J with a
// denominator too large to scale (never seen; the caller decides per pair).
std::optional<bool> continuous_pair_collides_angles(const RegionForm& A, const RegionForm& B, PathNetTracker& path) {
  PathNets own;
  for (CouplingId q : {A.own, B.own})
    if (q != kNone && !path.net[q].is_zero() && (own.empty() || own.front().first != q))
      own.push_back({q, path.net[q]});
  PairSystem S = build_system(A, B, own);
  int64_t scale = 1;
  std::vector<WidePoint>& pts = path.polygon;
  OwnPolygon poly = own_polygon(S, &scale, &pts);
  if (poly == OwnPolygon::Empty) return false;
  if (poly == OwnPolygon::TooFine) return std::nullopt;
  for (const auto& [q, w] : own) path.angles.remove(w);
  bool hit = path.angles.contains_origin(scale, pts);
  for (const auto& [q, w] : own) path.angles.add(w);
  return hit;
}

bool continuous_decision(const std::vector<RegionForm>& forms, uint32_t a, uint32_t b, PathNetTracker& path,
                         ZonotopeTest ztest, PairwiseStats& st) {
  if (ztest == ZonotopeTest::PerPair) return continuous_pair_collides(forms[a], forms[b], path.nets());
  if (ztest == ZonotopeTest::AngleTree || ztest == ZonotopeTest::AngleBoth) {
    std::optional<bool> tree = continuous_pair_collides_angles(forms[a], forms[b], path);
    if (!tree) ++st.angle_fallbacks;
    if (!tree || ztest == ZonotopeTest::AngleBoth) {
      bool slow = continuous_pair_collides(forms[a], forms[b], path.nets());
      if (tree && *tree != slow)
        throw std::logic_error("collide: angle-tree and per-pair zonotope tests disagree on regions " +
                               std::to_string(a) + ", " + std::to_string(b));
      return slow;
    }
    return *tree;
  }
  bool fast = continuous_pair_collides_supported(forms[a], forms[b], path);
  if (ztest == ZonotopeTest::Both && fast != continuous_pair_collides(forms[a], forms[b], path.nets()))
    throw std::logic_error("collide: incremental and per-pair zonotope tests disagree on regions " + std::to_string(a) +
                           ", " + std::to_string(b));
  return fast;
}

// Regions a and b with the path's nets between their reference nodes: the
// reach filter, then the exact test of the model, counted in st; on a
// meeting, the collision with its witness.
std::optional<PairCollision> test_pair(const std::vector<RegionForm>& forms, uint32_t a, uint32_t b,
                                       PathNetTracker& path, TimeModel model, ZonotopeTest ztest, PairwiseStats& st) {
  ++st.pairs;
  if (!pair_may_meet(forms[a], forms[b], path.reach_x, path.reach_y)) return std::nullopt;
  ++st.full_tests;
  bool hit = model == TimeModel::Continuous   ? continuous_decision(forms, a, b, path, ztest, st)
             : ztest == ZonotopeTest::PerPair ? discrete_pair_collides_per_vector(forms[a], forms[b], path.nets())
                                              : discrete_pair_collides(forms[a], forms[b], path.nets());
  if (!hit) return std::nullopt;
  PairCollision pc;
  pc.a = a, pc.b = b;
  PathNets nets = path.nets();
  bool again = model == TimeModel::Continuous ? continuous_pair_collides(forms[a], forms[b], nets, &pc.witness)
                                              : discrete_pair_collides(forms[a], forms[b], nets, &pc.witness);
  if (!again) throw std::logic_error("collide: the pair test gave no witness for a meeting it found");
  return pc;
}

}  // namespace

std::optional<PairCollision> pairwise_collision(const Instance& inst, const SpanningTree& tree, const Regions& regions,
                                                TimeModel model, PairwiseStats* stats, const Deadline* deadline,
                                                ZonotopeTest ztest) {
  const size_t n = inst.num_nodes(), nq = inst.couplings().size();
  std::vector<RegionForm> forms = region_forms(inst, regions);
  std::vector<std::vector<uint32_t>> regs_of(n);
  for (uint32_t r = 0; r < forms.size(); ++r) regs_of[forms[r].ref].push_back(r);
  const std::vector<std::vector<TreeArc>> adj = tree_adjacency(inst, tree);
  PathNetTracker path(nq);
  path.supports = model == TimeModel::Continuous && (ztest == ZonotopeTest::Incremental || ztest == ZonotopeTest::Both);
  path.angles_on = model == TimeModel::Continuous &&
                   (ztest == ZonotopeTest::AngleTree || ztest == ZonotopeTest::AngleBoth);
  PairwiseStats st;
  std::optional<PairCollision> found;
  auto test = [&](uint32_t a, uint32_t b) {
    found = test_pair(forms, a, b, path, model, ztest, st);
    return found.has_value();
  };
  struct Frame {
    NodeId w;
    NodeId from;
    size_t next;
    CouplingId q;
    Vec2 vec;
  };
  uint64_t steps = 0;
  for (NodeId s = 0; s < n && !found; ++s) {
    if (deadline) deadline->check();
    if (regs_of[s].empty()) continue;
    const auto& mine = regs_of[s];
    for (size_t i = 0; i < mine.size() && !found; ++i)
      for (size_t j = i + 1; j < mine.size(); ++j)
        if (test(mine[i], mine[j])) break;
    std::vector<Frame> stack{{s, kNone, 0, kNone, {0, 0}}};
    while (!stack.empty() && !found) {
      if (deadline && (++steps & 4095) == 0) deadline->check();
      Frame& f = stack.back();
      if (f.next < adj[f.w].size()) {
        const TreeArc& a = adj[f.w][f.next++];
        if (a.to == f.from) continue;
        if (a.q != kNone) path.apply(a.q, a.vec);
        stack.push_back({a.to, f.w, 0, a.q, a.vec});
        NodeId w = a.to;
        if (w > s)
          for (uint32_t ra : mine) {
            for (uint32_t rb : regs_of[w])
              if (test(ra, rb)) break;
            if (found) break;
          }
      } else {
        if (f.q != kNone) path.apply(f.q, Vec2{-f.vec.x, -f.vec.y});
        stack.pop_back();
      }
    }
    // Unwind what is left (after an early stop) so the state stays clean.
    while (!stack.empty()) {
      Frame& f = stack.back();
      if (f.q != kNone) path.apply(f.q, Vec2{-f.vec.x, -f.vec.y});
      stack.pop_back();
    }
  }
  st.line_purges = path.purges;
  if (stats) *stats = st;
  return found;
}

}  // namespace gridlock
