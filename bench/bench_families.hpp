// Instance families shared by the benchmarks (docs/performance.md).
//
// comb: a spine of length L along x with a tooth of height H on every spine
// node (n = L (H + 1)), and k expansions on random free edges:
//   Spine: all on spine edges (+x); Teeth: all inside teeth (+y);
//   Mixed: each on the spine or in a tooth at random.
// Expansions only push teeth apart (they slide along each other, touching),
// so no schedule of a comb collides. With `lid`, a static column at x = -1
// joined to (0, 0) carries a row at y = H + 1 + r out to x = L + k, over
// the teeth wherever the spine's expansions take them; a tooth holds at
// most r = floor((H + 1) / 2) expansions (no node in two operations), so
// its top only touches the lid: still no collision, but the teeth's x
// faces now pass the lid's and their y faces each other's. group > 1 couples consecutive
// expansions into couplings of `group` operations (0: one coupling of all).
//
// hook: a row of L nodes along y = 0 (L >= 2) with an expansion (+x) on
// every other edge, all in one coupling, under a static row of L + 2 nodes
// along y = 1 joined to it at x = 0, whose end comes down to (L + 1, 0):
// the row's end, pushed at speed floor(L / 2) (one unit per expansion), enters
// the free cell (L, 0) and meets the static node (n = 2 L + 3, one axis,
// YES at the first moment 1 / (number of expansions)). group > 0 couples
// consecutive expansions into couplings of `group` instead (still YES).
//
// stalactite_comb: teeth that pass under static stalactites, then grow
// past their tips. A spine of L nodes along y = 0 with teeth of nodes
// y = 1 .. 4; k = 4L + 2 expansions (+x) on every other edge of a tail
// of 2k nodes left of it carry all teeth right by k, rigidly. Every even
// tooth has two expansions (+y, edges y = 1-2 and 3-4): its top rises
// from 5 to 7, past 6 at t = 1/2. A static column at x = -2k - 1 joined
// to the tail's end carries a row at y = 8 over everything, and m = L
// stalactites of nodes y = 6, 7 hang from it at x = L .. 2L - 1, just
// right of the teeth. Each tooth passes under every stalactite before
// t = 1/2 (its top below 6) and rises past their tips after it: NO.
// Both axes change order, no cut separates the teeth from the
// stalactites (they meet along x while passing and along y after), and
// the total motion is Theta(n^2). About 24 L nodes. With own_speeds,
// expansions (+x) also on the spine edges from even x carry each pair of
// teeth at its own speed (k, k + 1, ..., about k + L / 2; the lid's row
// is longer to match): still NO, with about L / 2 kinds of motion
// among the teeth instead of 3. With hit, the middle stalactite
// (x = L + floor(m / 2)) reaches down to y = 4, into the teeth's path:
// YES: the last tooth (x = L - 1) reaches it first, at
// t = floor(m / 2) / k (< 1/2).
//
// awning_comb: a comb that collides late while its x faces keep their
// order. A spine of L nodes along y = 0 (L >= 3); even x carries a tooth of
// nodes y = 1 .. 9 and an awning node (x + 1, 9) joined to its top; odd x
// a short tooth of y = 1 .. 6, under the awning of x - 1 (two free cells
// between). Expansions: +x on the spine edges from even x (so the speeds
// grow to about L / 2: total motion Theta(n^2)), and +y in the short
// teeth, on edges (x, y)-(x, y + 1) for y = 1, 3, 5 (no node in two
// operations): all 3 in the middle one (x0 = 2 floor(L / 4) + 1), 0 .. 2
// at random in the others; all in one coupling. The spine only pushes to the
// right what is to the right, so no two x faces ever swap; the short
// teeth's y faces pass their neighbours'. YES: only the middle short
// tooth reaches its awning, at t = 2/3 (n about 9 L). Deterministic for
// a seed.
//
// separation_chain: n separation gadgets in a row, the shape of the
// continuous reduction's contract t_b >= t_a + 1. Gadget i (x0 = 3i): a
// column (x0,0)-(x0,1) and (x0+1,0)-(x0+1,1) on a spine along y = 0;
// a_i contracts (x0,1) into (x0,0), b_i grows (x0+1,1) along -x into the
// cell a_i empties, so b_i collides iff it starts before a_i has finished
// (at exactly t_a + 1 the two only touch). Couplings Q0 = {a_0},
// Qi = {b_(i-1), a_i}, Qn = {b_(n-1)}: the only collision-free schedules have
// t_Qi >= t_Q(i-1) + 1, a chain of n + 1 couplings. With rows = true every
// coupling also gets a horizontal expansion in a row below (y = -2, hung
// from (0,-1)), so couplings have 3 operations as in compiled formulas.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/random.hpp"
#include "lattice/instance.hpp"
#include "lattice/random_instance.hpp"

namespace gridlock::bench {

enum class CombOps { Spine, Teeth, Mixed };

// Couplings of the operations `names`: group 0 one coupling "all" of
// them; group > 1 consecutive ones in couplings "Q<first index>" of
// `group` (a last one left alone stays a singleton); group 1 none.
inline void couple_consecutive(InstanceBuilder& b, const std::vector<std::string>& names, int64_t group) {
  if (group == 0) {
    b.add_coupling("all", names);
    return;
  }
  if (group < 2) return;
  for (size_t i = 0; i + 1 < names.size(); i += static_cast<size_t>(group)) {
    const size_t end = std::min(names.size(), i + static_cast<size_t>(group));
    std::vector<std::string> g(names.begin() + static_cast<long>(i), names.begin() + static_cast<long>(end));
    if (g.size() > 1) b.add_coupling("Q" + std::to_string(i), g);
  }
}

inline Instance comb(int64_t L, int64_t H, int64_t k, CombOps where, int64_t group, uint64_t seed, bool lid = false) {
  InstanceBuilder b;
  for (int64_t x = 0; x < L; ++x)
    for (int64_t y = 0; y <= H; ++y) b.add_node({x, y});
  for (int64_t x = 0; x < L; ++x) {
    if (x + 1 < L) b.add_edge({x, 0}, {x + 1, 0});
    for (int64_t y = 0; y < H; ++y) b.add_edge({x, y}, {x, y + 1});
  }
  if (lid) {  // a static column at x = -1 and a row over the teeth and their motion
    const int64_t top = H + 1 + (H + 1) / 2;
    for (int64_t y = 0; y <= top; ++y) b.add_node({-1, y});
    for (int64_t y = 0; y < top; ++y) b.add_edge({-1, y}, {-1, y + 1});
    b.add_edge({-1, 0}, {0, 0});
    for (int64_t x = 0; x <= L + k; ++x) b.add_node({x, top}), b.add_edge({x - 1, top}, {x, top});
  }
  Rng rng(seed);
  std::vector<std::string> names;
  std::vector<char> used(static_cast<size_t>(L * (H + 1)), 0);
  int64_t attempts = 0;
  while (static_cast<int64_t>(names.size()) < k && ++attempts < 50 * k) {
    bool tooth = where == CombOps::Teeth || (where == CombOps::Mixed && H > 0 && rng.below(2) == 0);
    int64_t x = static_cast<int64_t>(rng.below(static_cast<uint64_t>(L - 1)));
    int64_t y = tooth ? static_cast<int64_t>(rng.below(static_cast<uint64_t>(H))) : 0;
    Vec2 u{x, y}, v = tooth ? Vec2{x, y + 1} : Vec2{x + 1, y};
    size_t iu = static_cast<size_t>(u.x * (H + 1) + u.y), iv = static_cast<size_t>(v.x * (H + 1) + v.y);
    if (used[iu] || used[iv]) continue;
    used[iu] = used[iv] = 1;
    std::string name = "e" + std::to_string(names.size());
    b.add_op(name, OpKind::Expand, u, tooth ? Dir::PosY : Dir::PosX);
    names.push_back(name);
  }
  couple_consecutive(b, names, group);
  Instance inst;
  if (auto e = b.finish(inst)) throw std::runtime_error(e->message);
  return inst;
}

inline Instance hook(int64_t L, int64_t group = 0) {
  InstanceBuilder b;
  for (int64_t x = 0; x < L; ++x) b.add_node({x, 0});
  for (int64_t x = 0; x < L + 2; ++x) b.add_node({x, 1});
  b.add_node({L + 1, 0});
  for (int64_t x = 0; x + 1 < L; ++x) b.add_edge({x, 0}, {x + 1, 0});
  for (int64_t x = 0; x + 1 < L + 2; ++x) b.add_edge({x, 1}, {x + 1, 1});
  b.add_edge({0, 0}, {0, 1});
  b.add_edge({L + 1, 1}, {L + 1, 0});
  std::vector<std::string> names;
  for (int64_t x = 0; x + 1 < L; x += 2) {
    names.push_back("e" + std::to_string(x));
    b.add_op(names.back(), OpKind::Expand, {x, 0}, Dir::PosX);
  }
  couple_consecutive(b, names, group);
  Instance inst;
  if (auto e = b.finish(inst)) throw std::runtime_error(e->message);
  return inst;
}

inline Instance awning_comb(int64_t L, uint64_t seed) {
  if (L < 3) throw std::invalid_argument("awning_comb: L >= 3");
  InstanceBuilder b;
  auto must = [](std::optional<std::string> e) {
    if (e) throw std::runtime_error(*e);
  };
  const int64_t x0 = 2 * (L / 4) + 1;
  Rng rng(seed);
  std::vector<std::string> names;
  for (int64_t x = 0; x < L; ++x) {
    const int64_t top = x % 2 == 0 ? 9 : 6;
    for (int64_t y = 0; y <= top; ++y) must(b.add_node({x, y}));
    for (int64_t y = 0; y < top; ++y) must(b.add_edge({x, y}, {x, y + 1}));
    if (x > 0) must(b.add_edge({x - 1, 0}, {x, 0}));
    if (x % 2 == 0 && x + 1 < L) {
      must(b.add_node({x + 1, 9}));
      must(b.add_edge({x, 9}, {x + 1, 9}));
    }
  }
  for (int64_t x = 0; x < L; ++x) {
    if (x % 2 == 0) {
      if (x + 1 == L) break;
      names.push_back("s" + std::to_string(x));
      must(b.add_op(names.back(), OpKind::Expand, {x, 0}, Dir::PosX));
    } else {
      const uint64_t k = x == x0 ? 3 : rng.below(3);
      for (uint64_t i = 0; i < k; ++i) {
        names.push_back("t" + std::to_string(x) + "_" + std::to_string(i));
        must(b.add_op(names.back(), OpKind::Expand, {x, static_cast<int64_t>(2 * i + 1)}, Dir::PosY));
      }
    }
  }
  couple_consecutive(b, names, 0);
  Instance inst;
  if (auto e = b.finish(inst)) throw std::runtime_error(e->message);
  return inst;
}

// The stalactite combs' spine and tail: nodes x = -2k .. L - 1 along
// y = 0, and k expansions (+x, named s0, s1, ...) on every other edge of
// the tail x < 0.
inline void stalactite_tail(InstanceBuilder& b, int64_t L, int64_t k, std::vector<std::string>& names) {
  auto must = [](std::optional<std::string> e) {
    if (e) throw std::runtime_error(*e);
  };
  for (int64_t x = -2 * k; x < L; ++x) must(b.add_node({x, 0}));
  for (int64_t x = -2 * k; x + 1 < L; ++x) must(b.add_edge({x, 0}, {x + 1, 0}));
  for (int64_t i = 0; i < k; ++i) {
    names.push_back("s" + std::to_string(i));
    must(b.add_op(names.back(), OpKind::Expand, {-2 * k + 2 * i, 0}, Dir::PosX));
  }
}

// The stalactite combs' static lid: a column x = left, y = 0 .. 8, joined
// to (left + 1, 0), and a row y = 8 from left + 1 to right.
inline void stalactite_lid(InstanceBuilder& b, int64_t left, int64_t right) {
  auto must = [](std::optional<std::string> e) {
    if (e) throw std::runtime_error(*e);
  };
  for (int64_t y = 0; y <= 8; ++y) must(b.add_node({left, y}));
  for (int64_t y = 0; y < 8; ++y) must(b.add_edge({left, y}, {left, y + 1}));
  must(b.add_edge({left, 0}, {left + 1, 0}));
  for (int64_t x = left + 1; x <= right; ++x) must(b.add_node({x, 8})), must(b.add_edge({x - 1, 8}, {x, 8}));
}

inline Instance stalactite_comb(int64_t L, bool own_speeds = false, bool hit = false) {
  if (L < 1) throw std::invalid_argument("stalactite_comb: L >= 1");
  InstanceBuilder b;
  auto must = [](std::optional<std::string> e) {
    if (e) throw std::runtime_error(*e);
  };
  const int64_t m = L, k = 2 * (L + m) + 2, left = -2 * k - 1, right = L + k + 1 + (own_speeds ? L / 2 + 1 : 0);
  std::vector<std::string> names;
  stalactite_tail(b, L, k, names);
  for (int64_t x = 0; x < L; ++x) {
    for (int64_t y = 1; y <= 4; ++y) must(b.add_node({x, y})), must(b.add_edge({x, y - 1}, {x, y}));
    if (x % 2 == 0)
      for (int64_t y : {1, 3}) {
        names.push_back("t" + std::to_string(x) + "_" + std::to_string(y));
        must(b.add_op(names.back(), OpKind::Expand, {x, y}, Dir::PosY));
      }
  }
  for (int64_t x = 0; own_speeds && x + 1 < L; x += 2) {
    names.push_back("p" + std::to_string(x));
    must(b.add_op(names.back(), OpKind::Expand, {x, 0}, Dir::PosX));
  }
  stalactite_lid(b, left, right);
  for (int64_t x = L; x < L + m; ++x) {
    must(b.add_node({x, 7})), must(b.add_node({x, 6}));
    must(b.add_edge({x, 8}, {x, 7})), must(b.add_edge({x, 7}, {x, 6}));
  }
  if (hit) {
    const int64_t x = L + m / 2;
    must(b.add_node({x, 5})), must(b.add_node({x, 4}));
    must(b.add_edge({x, 6}, {x, 5})), must(b.add_edge({x, 5}, {x, 4}));
  }
  couple_consecutive(b, names, 0);
  Instance inst;
  if (auto e = b.finish(inst)) throw std::runtime_error(e->message);
  return inst;
}

// A random stalactite comb (stalactite_comb with its parts drawn at
// random, deterministic for a seed), small enough for every twin: L teeth of random
// heights 1 .. 4 on a spine along y = 0, carried right by k expansions
// (+x) on a tail, some teeth rising (+y expansions on their nodes y = 1
// and 3), some spine edges from even x expanding too (pairs of teeth at
// their own speeds); a static lid (a column left of the tail, a row at
// y = 8) with stalactites hanging to random depths (y = 4 .. 7) at random
// columns, clear of the teeth at t = 0. Teeth pass under the
// stalactites, rise, or hit them: both answers, first moments anywhere
// in (0, 1), and pieces that no cut separates over (0, 1).
inline Instance random_stalactite_comb(uint64_t seed) {
  Rng rng(seed);
  InstanceBuilder b;
  auto must = [](std::optional<std::string> e) {
    if (e) throw std::runtime_error(*e);
  };
  const auto L = static_cast<int64_t>(1 + rng.below(16)), k = static_cast<int64_t>(1 + rng.below(24));
  const int64_t left = -2 * k - 1, right = 2 * L + k + 4;
  std::vector<std::string> names;
  stalactite_tail(b, L, k, names);
  std::vector<int64_t> top(static_cast<size_t>(L));
  for (int64_t x = 0; x < L; ++x) {
    const auto h = static_cast<int64_t>(1 + rng.below(4));
    top[static_cast<size_t>(x)] = h;
    for (int64_t y = 1; y <= h; ++y) must(b.add_node({x, y})), must(b.add_edge({x, y - 1}, {x, y}));
    for (int64_t y : {1, 3})
      if (y < h && rng.below(2) == 0) {
        names.push_back("t" + std::to_string(x) + "_" + std::to_string(y));
        must(b.add_op(names.back(), OpKind::Expand, {x, y}, Dir::PosY));
      }
    if (x % 2 == 0 && x + 1 < L && rng.below(3) == 0) {
      names.push_back("p" + std::to_string(x));
      must(b.add_op(names.back(), OpKind::Expand, {x, 0}, Dir::PosX));
    }
  }
  stalactite_lid(b, left, right);
  const auto stalactites = static_cast<int64_t>(1 + rng.below(static_cast<uint64_t>(L + 2)));
  for (int64_t i = 0; i < stalactites; ++i) {
    const auto x = static_cast<int64_t>(rng.below(static_cast<uint64_t>(2 * L + k + 3)));
    int64_t bottom = 4 + static_cast<int64_t>(rng.below(4));
    if (x < L) bottom = std::max(bottom, top[static_cast<size_t>(x)] + 1);
    if (bottom > 7 || b.add_node({x, 7})) continue;  // taken already: one stalactite per column
    must(b.add_edge({x, 8}, {x, 7}));
    for (int64_t y = 6; y >= bottom; --y) must(b.add_node({x, y})), must(b.add_edge({x, y + 1}, {x, y}));
  }
  couple_consecutive(b, names, 0);
  Instance inst;
  if (auto e = b.finish(inst)) throw std::runtime_error(e->message);
  return inst;
}

inline Instance separation_chain(int64_t n, bool rows) {
  InstanceBuilder b;
  auto must = [](std::optional<std::string> e) {
    if (e) throw std::runtime_error(*e);
  };
  const int64_t W = 3 * n + 1;
  for (int64_t x = 0; x < W; ++x) must(b.add_node({x, 0}));
  for (int64_t x = 0; x + 1 < W; ++x) must(b.add_edge({x, 0}, {x + 1, 0}));
  for (int64_t i = 0; i < n; ++i) {
    int64_t x0 = 3 * i;
    must(b.add_node({x0, 1}));
    must(b.add_node({x0 + 1, 1}));
    must(b.add_edge({x0, 0}, {x0, 1}));
    must(b.add_edge({x0 + 1, 0}, {x0 + 1, 1}));
    must(b.add_op("a" + std::to_string(i), OpKind::Contract, {x0, 0}, Dir::PosY));
    must(b.add_op("b" + std::to_string(i), OpKind::Grow, {x0 + 1, 1}, Dir::NegX));
  }
  if (rows) {
    must(b.add_node({0, -1}));
    must(b.add_edge({0, 0}, {0, -1}));
    for (int64_t x = 0; x <= 2 * (n + 1); ++x) must(b.add_node({x, -2}));
    for (int64_t x = 0; x < 2 * (n + 1); ++x) must(b.add_edge({x, -2}, {x + 1, -2}));
    must(b.add_edge({0, -1}, {0, -2}));
    for (int64_t i = 0; i <= n; ++i) must(b.add_op("h" + std::to_string(i), OpKind::Expand, {2 * i, -2}, Dir::PosX));
  }
  for (int64_t i = 0; i <= n; ++i) {
    std::vector<std::string> ops;
    if (i > 0) ops.push_back("b" + std::to_string(i - 1));
    if (i < n) ops.push_back("a" + std::to_string(i));
    if (rows) ops.push_back("h" + std::to_string(i));
    must(b.add_coupling("Q" + std::to_string(i), ops));
  }
  Instance inst;
  if (auto e = b.finish(inst)) throw std::runtime_error(e->message);
  return inst;
}

}  // namespace gridlock::bench
