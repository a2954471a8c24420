#include "collide/internal/angle_tree.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace gridlock {

namespace {

using i128 = __int128;

bool in_upper_half(i128 x, i128 y) { return y > 0 || (y == 0 && x > 0); }
i128 cross(WidePoint a, WidePoint b) { return a.x * b.y - a.y * b.x; }
WidePoint minus(WidePoint a, WidePoint b) { return {a.x - b.x, a.y - b.y}; }
WidePoint wide(Vec2 v) { return {v.x, v.y}; }

// The convex hull of p (sorted and deduplicated in place) into h,
// counter-clockwise, without collinear points, starting at the bottom-left
// vertex (least y, then least x): its edges then have strictly increasing
// angles in [0, 2 pi). Andrew's monotone chain.
void hull_from_bottom_left(std::vector<WidePoint>& p, std::vector<WidePoint>& h) {
  std::sort(p.begin(), p.end(), [](WidePoint a, WidePoint b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  h.assign(p.size() < 3 ? p.size() : 2 * p.size(), WidePoint{});
  if (p.size() < 3) return;
  size_t k = 0;
  for (const WidePoint& q : p) {
    while (k >= 2 && cross(minus(h[k - 1], h[k - 2]), minus(q, h[k - 2])) <= 0) --k;
    h[k++] = q;
  }
  for (size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(minus(h[k - 1], h[k - 2]), minus(p[i - 1], h[k - 2])) <= 0) --k;
    h[k++] = p[i - 1];
  }
  h.resize(k - 1);
  auto first = std::min_element(h.begin(), h.end(),
                                [](WidePoint a, WidePoint b) { return a.y != b.y ? a.y < b.y : a.x < b.x; });
  std::rotate(h.begin(), first, h.end());
}

}  // namespace

void AngleTree::update(Vec2 v, int sign) {
  if (v.is_zero()) return;
  Vec2 g = v;
  if (!in_upper_half(v.x, v.y)) {
    g = Vec2{-v.x, -v.y};
    flipped_ += sign * v;
  }
  const int64_t d = std::gcd(g.x < 0 ? -g.x : g.x, g.y);
  root_ = update_at(root_, Vec2{g.x / d, g.y / d}, g, sign);
}

uint32_t AngleTree::fresh(Vec2 dir, Vec2 g) {
  Node n;
  n.dir = dir, n.sum = g, n.subtree = g, n.count = 1, n.height = 1;
  if (!free_.empty()) {
    uint32_t x = free_.back();
    free_.pop_back();
    nodes_[x] = n;
    return x;
  }
  nodes_.push_back(n);
  return static_cast<uint32_t>(nodes_.size() - 1);
}

void AngleTree::pull(uint32_t x) {
  Node& n = nodes_[x];
  const Node& l = nodes_[n.left];
  const Node& r = nodes_[n.right];
  n.size = 1 + (n.left ? l.size : 0) + (n.right ? r.size : 0);
  n.height = 1 + std::max(n.left ? l.height : 0, n.right ? r.height : 0);
  n.subtree = n.sum + (n.left ? l.subtree : Vec2{}) + (n.right ? r.subtree : Vec2{});
}

uint32_t AngleTree::rotate_right(uint32_t x) {
  uint32_t l = nodes_[x].left;
  nodes_[x].left = nodes_[l].right;
  nodes_[l].right = x;
  pull(x), pull(l);
  return l;
}

uint32_t AngleTree::rotate_left(uint32_t x) {
  uint32_t r = nodes_[x].right;
  nodes_[x].right = nodes_[r].left;
  nodes_[r].left = x;
  pull(x), pull(r);
  return r;
}

int64_t AngleTree::height_of(uint32_t x) const { return x == 0 ? 0 : nodes_[x].height; }

uint32_t AngleTree::balance(uint32_t x) {
  const uint32_t l = nodes_[x].left, r = nodes_[x].right;
  const int64_t tilt = height_of(l) - height_of(r);
  if (tilt > 1) {
    if (height_of(nodes_[l].left) < height_of(nodes_[l].right)) nodes_[x].left = rotate_left(l);
    return rotate_right(x);
  }
  if (tilt < -1) {
    if (height_of(nodes_[r].right) < height_of(nodes_[r].left)) nodes_[x].right = rotate_right(r);
    return rotate_left(x);
  }
  pull(x);
  return x;
}

uint32_t AngleTree::detach_first(uint32_t x, uint32_t& first) {
  if (nodes_[x].left == 0) {
    first = x;
    return nodes_[x].right;
  }
  nodes_[x].left = detach_first(nodes_[x].left, first);
  return balance(x);
}

uint32_t AngleTree::unlink(uint32_t x) {
  const uint32_t l = nodes_[x].left, r = nodes_[x].right;
  free_.push_back(x);
  if (l == 0) return r;
  if (r == 0) return l;
  uint32_t next = 0;
  const uint32_t rest = detach_first(r, next);
  nodes_[next].left = l, nodes_[next].right = rest;
  return balance(next);
}

uint32_t AngleTree::update_at(uint32_t x, Vec2 dir, Vec2 g, int sign) {
  if (x == 0) {
    if (sign < 0) throw std::logic_error("AngleTree: removing a vector that was never added");
    return fresh(dir, g);
  }
  if (nodes_[x].dir == dir) {
    nodes_[x].sum += sign * g;
    nodes_[x].count = static_cast<uint32_t>(static_cast<int64_t>(nodes_[x].count) + sign);
    if (nodes_[x].count == 0) return unlink(x);
    pull(x);
    return x;
  }
  if (cross(wide(dir), wide(nodes_[x].dir)) > 0) {  // dir comes first
    uint32_t l = update_at(nodes_[x].left, dir, g, sign);
    nodes_[x].left = l;
  } else {
    uint32_t r = update_at(nodes_[x].right, dir, g, sign);
    nodes_[x].right = r;
  }
  return balance(x);
}

Vec2 AngleTree::prefix(uint32_t k) const {
  Vec2 s;
  uint32_t x = root_;
  while (k > 0 && x != 0) {
    const Node& n = nodes_[x];
    uint32_t ls = n.left ? nodes_[n.left].size : 0;
    if (k <= ls) {
      x = n.left;
      continue;
    }
    if (n.left) s += nodes_[n.left].subtree;
    s += n.sum;
    k -= ls + 1;
    x = n.right;
  }
  return s;
}

uint32_t AngleTree::count_not_after(WidePoint f) const {
  uint32_t c = 0;
  uint32_t x = root_;
  while (x != 0) {
    const Node& n = nodes_[x];
    if (cross(wide(n.dir), f) >= 0) {  // angle(dir) <= angle(f): both in the upper half-plane
      c += 1 + (n.left ? nodes_[n.left].size : 0);
      x = n.right;
    } else {
      x = n.left;
    }
  }
  return c;
}

bool AngleTree::contains_origin(int64_t scale, std::vector<WidePoint>& points) const {
  std::vector<WidePoint>& q = hull_;
  hull_from_bottom_left(points, q);
  const size_t r = q.size();
  if (r < 3) throw std::logic_error("AngleTree::contains_origin: the polygon has an empty interior");
  const uint64_t m = directions();
  const Vec2 total = root_ ? nodes_[root_].subtree : Vec2{};
  // Place of Q's edge j in the merged edge sequence of scale * Z + Q (ties:
  // Z's edges first; any order of parallel edges gives the same polygon).
  std::vector<uint64_t>& place = place_;
  place.resize(r);
  for (size_t j = 0; j < r; ++j) {
    WidePoint f = minus(q[(j + 1) % r], q[j]);
    uint64_t before = in_upper_half(f.x, f.y) ? count_not_after(f) : m + count_not_after(WidePoint{-f.x, -f.y});
    place[j] = j + before;
  }
  const uint64_t total_edges = 2 * m + r;
  // Vertex t of the sum: after t merged edges, j of them Q's and k Z's.
  auto vertex = [&](uint64_t t) {
    size_t j = 0;
    while (j < r && place[j] < t) ++j;
    const uint64_t k = t - j;
    const Vec2 w = k <= m ? prefix(static_cast<uint32_t>(k)) : total - prefix(static_cast<uint32_t>(k - m));
    const WidePoint& c = q[j % r];
    return WidePoint{static_cast<i128>(scale) * (flipped_.x + w.x) + c.x,
                     static_cast<i128>(scale) * (flipped_.y + w.y) + c.y};
  };
  // The origin o is interior iff it is strictly left of the first and the
  // last edge and strictly left of the edge that closes its fan wedge at V0.
  const WidePoint v0 = vertex(0), o0 = {-v0.x, -v0.y};
  if (cross(minus(vertex(1), v0), o0) <= 0) return false;
  const WidePoint vl = vertex(total_edges - 1);
  if (cross(minus(v0, vl), WidePoint{-vl.x, -vl.y}) <= 0) return false;
  uint64_t lo = 1, hi = total_edges - 2;  // the last t with o left of or on V0 -> V_t
  while (lo < hi) {
    uint64_t mid = (lo + hi + 1) / 2;
    if (cross(minus(vertex(mid), v0), o0) >= 0) lo = mid;
    else hi = mid - 1;
  }
  const WidePoint vt = vertex(lo), vn = vertex(lo + 1);
  return cross(minus(vn, vt), WidePoint{-vt.x, -vt.y}) > 0;
}

}  // namespace gridlock
