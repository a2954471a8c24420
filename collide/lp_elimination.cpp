// Exact linear programming in at most two variables (collide/internal/lp_elimination.hpp).
#include "collide/internal/lp_elimination.hpp"

#include <algorithm>

namespace gridlock::pairs {

LinearInterval<i128> interval_of(const std::vector<Lin>& cons) {
  LinearInterval<i128> iv;
  for (const Lin& L : cons) iv.add(L.c, L.a[0], L.strict);
  return iv;
}

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

i128 gcd128(i128 a, i128 b) {
  if (a < 0) a = -a;
  if (b < 0) b = -b;
  while (b != 0) a %= b, std::swap(a, b);
  return a;
}

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

}  // namespace gridlock::pairs
