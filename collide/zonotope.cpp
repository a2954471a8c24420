// The continuous pair test (collide/internal/collide_pairs.hpp) and its zonotope
// geometry (collide/internal/zonotope.hpp).
#include "collide/internal/zonotope.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace gridlock {

namespace pairs {

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

namespace {

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

}  // namespace

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

bool projected_feasible(const PairSystem& S, const Normals& N) {
  std::vector<Lin> cons = projected_constraints(S, N);
  std::vector<Lin> one = S.nv == 2 ? eliminate_v1(cons) : cons;
  return !interval_of(one).empty();
}

namespace {

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

}  // namespace

OwnPolygon own_polygon(const PairSystem& S, int64_t* scale, std::vector<WidePoint>* pts) {
  Bound Ux, Lx, Uy, Ly;
  rect_bounds(S, Ux, Lx, Uy, Ly);
  std::vector<Lin> closed = own_constraints(S, Ux, Lx, Uy, Ly);
  // With at most one own progress v1 is pinned to 0 and interval_of reads v0 alone.
  if (interval_of(S.nv == 2 ? eliminate_v1(closed) : closed).empty()) return OwnPolygon::Empty;
  for (Lin& L : closed) L.strict = false;
  std::vector<std::array<i128, 3>> verts;
  if (S.nv == 1) {  // cl J is the segment between the closed interval's ends
    const LinearInterval<i128> iv = interval_of(closed);
    const Fraction lo = iv.lower().at, hi = iv.upper().at;
    const i128 glo = gcd128(lo.num, lo.den), ghi = gcd128(hi.num, hi.den);
    verts = {{lo.num / glo, 0, lo.den / glo}, {hi.num / ghi, 0, hi.den / ghi}};
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

}  // namespace pairs

using namespace pairs;

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

}  // namespace gridlock
