// Strip pairs (collide/internal/strip_pairs.hpp): one sweep, one segment
// tree of maxima.
#include <algorithm>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "collide/internal/strip_pairs.hpp"

namespace gridlock {

namespace {

// The two largest values of distinct ids in a range (id kNoId: none).
constexpr uint32_t kNoId = UINT32_MAX;
struct Top2 {
  __int128 v1 = 0, v2 = 0;
  uint32_t id1 = kNoId, id2 = kNoId;
  void add(__int128 v, uint32_t id) {
    if (id1 == kNoId || v > v1) {
      v2 = v1, id2 = id1;
      v1 = v, id1 = id;
    } else if (id2 == kNoId || v > v2) {
      v2 = v, id2 = id;
    }
  }
  // Ids are distinct across ranges (each point is entered once), so the
  // two largest of four are two largest of distinct ids.
  void merge(const Top2& o) {
    if (o.id1 != kNoId) add(o.v1, o.id1);
    if (o.id2 != kNoId) add(o.v2, o.id2);
  }
};

}  // namespace

std::optional<std::pair<uint32_t, uint32_t>> strip_pair(const std::vector<StripPoint>& A,
                                                        const std::vector<StripPoint>& B, int64_t x_lo, int64_t x_hi,
                                                        __int128 u_min, __int128 v_max) {
  if (A.empty() || B.empty() || x_lo > x_hi) return std::nullopt;
  std::vector<int64_t> xs;
  xs.reserve(B.size());
  for (const StripPoint& b : B) xs.push_back(b.x);
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  size_t size = 1;
  while (size < xs.size()) size *= 2;
  std::vector<Top2> tree(2 * size);
  std::vector<uint32_t> a_order(A.size()), b_order(B.size());
  for (uint32_t i = 0; i < A.size(); ++i) a_order[i] = i;
  for (uint32_t i = 0; i < B.size(); ++i) b_order[i] = i;
  std::sort(a_order.begin(), a_order.end(), [&](uint32_t i, uint32_t j) { return A[i].u < A[j].u; });
  std::sort(b_order.begin(), b_order.end(), [&](uint32_t i, uint32_t j) { return B[i].u < B[j].u; });
  size_t next_b = 0;
  for (uint32_t i : a_order) {
    const StripPoint& a = A[i];
    const __int128 below = a.u - u_min;  // b enters when b.u < a.u - u_min
    for (; next_b < b_order.size() && B[b_order[next_b]].u < below; ++next_b) {
      const StripPoint& b = B[b_order[next_b]];
      size_t leaf = size + static_cast<size_t>(std::lower_bound(xs.begin(), xs.end(), b.x) - xs.begin());
      tree[leaf].add(b.v, b.id);
      for (leaf /= 2; leaf >= 1; leaf /= 2) {
        Top2 t = tree[2 * leaf];
        t.merge(tree[2 * leaf + 1]);
        tree[leaf] = t;
      }
    }
    if (next_b == 0) continue;
    // b.x in [a.x - x_hi, a.x - x_lo] (128-bit: no overflow at the ends).
    const __int128 lo_x = static_cast<__int128>(a.x) - x_hi, hi_x = static_cast<__int128>(a.x) - x_lo;
    size_t l = static_cast<size_t>(
        std::lower_bound(xs.begin(), xs.end(), lo_x, [](int64_t x, __int128 y) { return x < y; }) - xs.begin());
    size_t r = static_cast<size_t>(
        std::upper_bound(xs.begin(), xs.end(), hi_x, [](__int128 y, int64_t x) { return y < x; }) - xs.begin());
    if (l >= r) continue;
    Top2 best;
    for (l += size, r += size; l < r; l /= 2, r /= 2) {
      if (l & 1) best.merge(tree[l++]);
      if (r & 1) best.merge(tree[--r]);
    }
    const __int128 above = a.v - v_max;  // a pair needs b.v > a.v - v_max
    if (best.id1 != kNoId && best.id1 != a.id && best.v1 > above) return std::make_pair(a.id, best.id1);
    if (best.id2 != kNoId && best.id2 != a.id && best.v2 > above) return std::make_pair(a.id, best.id2);
  }
  return std::nullopt;
}

std::optional<std::pair<uint32_t, uint32_t>> strip_pair_naive(const std::vector<StripPoint>& A,
                                                              const std::vector<StripPoint>& B, int64_t x_lo,
                                                              int64_t x_hi, __int128 u_min, __int128 v_max) {
  for (const StripPoint& a : A)
    for (const StripPoint& b : B) {
      if (a.id == b.id) continue;
      const __int128 dx = static_cast<__int128>(a.x) - b.x;
      if (dx >= x_lo && dx <= x_hi && a.u - b.u > u_min && a.v - b.v < v_max) return std::make_pair(a.id, b.id);
    }
  return std::nullopt;
}

}  // namespace gridlock
