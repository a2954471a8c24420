// The paper's angle-sorted augmented tree for the zonotope of a path's nets
// (docs/collide.md, "The angle tree").
//
// Z = { sum_q p_q v_q : p in [0,1]^K } for a multiset of integer vectors v_q
// (zero vectors ignored). Every v is written as +g or -g with g in the
// half-open upper half-plane (g.y > 0, or g.y == 0 and g.x > 0); then
// Z = N + sum_g [0,1] g with N the sum of the flipped vectors. The g are
// grouped by primitive direction and kept in an AVL tree ordered by angle
// (compared by cross products, never atan2), each node with the sum of its
// direction's vectors and the subtree sums: the boundary of Z, walked
// counter-clockwise from its bottom-left vertex N, has the edges
// s_1 .. s_m, -s_1 .. -s_m (s_i the direction sums in angle order), so any
// vertex is N plus a prefix sum, found in O(log m).
#pragma once

#include <cstdint>
#include <vector>

#include "lattice/geometry.hpp"

namespace gridlock {

// A point with exact 128-bit coordinates (scaled, see contains_origin).
struct WidePoint {
  __int128 x = 0, y = 0;
  friend bool operator==(WidePoint a, WidePoint b) = default;
};

class AngleTree {
 public:
  // Adds / removes one vector (remove needs an equal vector added before).
  // O(log m) worst case, m = distinct directions (an AVL tree: height at
  // most 1.44 log2(m + 2)). |coordinates| and their
  // sums must stay below 2^62.
  void add(Vec2 v) { update(v, +1); }
  void remove(Vec2 v) { update(v, -1); }
  // Distinct directions present (m).
  size_t directions() const { return root_ == 0 ? 0 : nodes_[root_].size; }
  // Height of the tree (0 when empty), for the balance test.
  uint32_t height() const { return root_ == 0 ? 0 : nodes_[root_].height; }

  // Is the origin in the interior of scale * Z + Q, Q the convex hull of
  // `points` (scaled integer coordinates; Q must have a non-empty interior,
  // else std::logic_error)? Exact. O(r log r + log^2 m) for r points: a
  // binary search over the vertices of the Minkowski sum (the edges of Z
  // and of Q merged by angle), each vertex a prefix sum of the tree.
  // Requires |scale * coordinates| < 2^60 and |points| < 2^60. Sorts and
  // deduplicates `points` in place.
  bool contains_origin(int64_t scale, std::vector<WidePoint>& points) const;

 private:
  struct Node {
    Vec2 dir;            // primitive, upper half-plane
    Vec2 sum;            // sum of this direction's vectors (flipped up)
    Vec2 subtree;        // sum over the subtree
    uint32_t count = 0;  // vectors in this direction
    uint32_t size = 1;   // nodes in the subtree
    uint32_t left = 0, right = 0;
    uint32_t height = 0;  // 1 for a leaf; the sentinel nodes_[0] stays 0
  };
  void update(Vec2 v, int sign);
  uint32_t update_at(uint32_t x, Vec2 dir, Vec2 g, int sign);
  // AVL: balance restores |height(left) - height(right)| <= 1 at x (its
  // children balanced) with at most two rotations, and updates x's fields.
  int64_t height_of(uint32_t x) const;
  uint32_t balance(uint32_t x);
  // Takes the subtree's first node out (into `first`), rebalancing.
  uint32_t detach_first(uint32_t x, uint32_t& first);
  // Removes node x from its subtree (its count reached 0); the new root.
  uint32_t unlink(uint32_t x);
  uint32_t rotate_left(uint32_t x);
  uint32_t rotate_right(uint32_t x);
  void pull(uint32_t x);
  uint32_t fresh(Vec2 dir, Vec2 g);
  // Sum of the first k direction sums in angle order. O(log m).
  Vec2 prefix(uint32_t k) const;
  // Directions d with angle(d) <= angle(f), f in the upper half-plane.
  uint32_t count_not_after(WidePoint f) const;

  std::vector<Node> nodes_{Node{}};  // nodes_[0]: the empty subtree
  std::vector<uint32_t> free_;
  uint32_t root_ = 0;
  Vec2 flipped_;                         // N
  mutable std::vector<WidePoint> hull_;  // scratch of contains_origin (no allocation per query)
  mutable std::vector<uint64_t> place_;
};

}  // namespace gridlock
