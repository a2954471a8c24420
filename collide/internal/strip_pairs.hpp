// Strip pairs: is there a in A and b in B whose difference lies in one
// vertical strip of a convex polygon? The query the motion-class test of
// one coupling asks once per strip of each class pair's polygon
// (collide/single_coupling.hpp, single_coupling_motion_classes;
// docs/collide.md, "One coupling: motion classes").
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace gridlock {

// A point with its x and two linear keys u, v (each an integer
// combination of the point's coordinates).
struct StripPoint {
  int64_t x = 0;
  __int128 u = 0, v = 0;
  uint32_t id = 0;
};

// Some (a.id, b.id), a in A, b in B, a.id != b.id, with
//   x_lo <= a.x - b.x <= x_hi,  a.u - b.u > u_min,  a.v - b.v < v_max,
// or nullopt when there is none. A and B may be the same set (then a
// point is never paired with itself).
// The sweep: A in the order of a.u - u_min, B in the order of b.u; each a
// first enters every b with b.u < a.u - u_min into a segment tree over the
// distinct b.x holding the two largest v of distinct ids, then asks for
// the largest v among b.x in [a.x - x_hi, a.x - x_lo]: the pair exists
// iff it exceeds a.v - v_max for some a. O((|A| + |B|) log |B|) time,
// O(|A| + |B|) memory.
std::optional<std::pair<uint32_t, uint32_t>> strip_pair(const std::vector<StripPoint>& A,
                                                        const std::vector<StripPoint>& B, int64_t x_lo, int64_t x_hi,
                                                        __int128 u_min, __int128 v_max);

// The brute-force twin: every pair, O(|A| |B|).
std::optional<std::pair<uint32_t, uint32_t>> strip_pair_naive(const std::vector<StripPoint>& A,
                                                              const std::vector<StripPoint>& B, int64_t x_lo,
                                                              int64_t x_hi, __int128 u_min, __int128 v_max);

}  // namespace gridlock
