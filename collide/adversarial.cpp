#include "collide/adversarial.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "common/random.hpp"

namespace gridlock {

namespace {

void must(const std::optional<std::string>& e) {
  if (e) throw std::logic_error("adversarial family: " + *e);
}

// The w x w blob above `tip` (cells tip + (a, 1 + c)), the diagonal and
// band sweeps' load: rows joined along x, each cell to the one below it,
// the first row's left cell to the tip.
void add_blob(InstanceBuilder& bl, Vec2 tip, int64_t w) {
  for (int64_t c = 0; c < w; ++c)
    for (int64_t a = 0; a < w; ++a) {
      const Vec2 cell{tip.x + a, tip.y + 1 + c};
      must(bl.add_node(cell));
      if (a > 0) must(bl.add_edge(Vec2{cell.x - 1, cell.y}, cell));
      if (c > 0 || a == 0) must(bl.add_edge(Vec2{cell.x, cell.y - 1}, cell));
    }
}

// The cell of the k-th node (in walking order) of column i.
Vec2 serpentine_cell(int64_t i, int64_t k, int64_t H) { return {i, i % 2 == 0 ? k : H - 1 - k}; }

// Groups `ops` (shuffled) into couplings of `size`; a group of one stays a
// singleton.
void add_groups(InstanceBuilder& b, std::vector<std::string> ops, size_t size, Rng& rng) {
  rng.shuffle(ops);
  for (size_t i = 0; i < ops.size(); i += size) {
    std::vector<std::string> g;
    for (size_t j = i; j < ops.size() && j < i + size; ++j) g.push_back(ops[j]);
    if (g.size() > 1) must(b.add_coupling("Q" + std::to_string(i / size), g));
  }
}

// The fan's directions (a, b): coprime, 1 <= a + b <= L.
std::vector<std::pair<uint32_t, uint32_t>> fan_directions(uint32_t L) {
  std::vector<std::pair<uint32_t, uint32_t>> out;
  for (uint32_t s = 1; s <= L; ++s)
    for (uint32_t a = 0; a <= s; ++a)
      if (std::gcd(a, s - a) == 1) out.emplace_back(a, s - a);
  return out;
}

// Fan couplings: per direction (a, b) of the largest fan that fits, a of
// the (shuffled) connectors and b of the column operations.
void add_fan(InstanceBuilder& b, std::vector<std::string> connectors, std::vector<std::string> column_ops, Rng& rng) {
  rng.shuffle(connectors);
  rng.shuffle(column_ops);
  size_t x = 0, y = 0;
  for (const auto& [a, c] : fan_directions(fan_size(connectors.size(), column_ops.size()))) {
    std::vector<std::string> g(connectors.begin() + static_cast<std::ptrdiff_t>(x),
                               connectors.begin() + static_cast<std::ptrdiff_t>(x + a));
    g.insert(g.end(), column_ops.begin() + static_cast<std::ptrdiff_t>(y),
             column_ops.begin() + static_cast<std::ptrdiff_t>(y + c));
    x += a, y += c;
    if (g.size() > 1) must(b.add_coupling("F" + std::to_string(a) + "_" + std::to_string(c), g));
  }
}

}  // namespace

uint32_t fan_size(uint64_t x, uint64_t y) {
  uint32_t L = 0;
  uint64_t need_x = 0, need_y = 0;
  for (uint32_t s = L + 1;; ++s) {
    for (uint32_t a = 0; a <= s; ++a)
      if (std::gcd(a, s - a) == 1) need_x += a, need_y += s - a;
    if (need_x > x || need_y > y) return L;
    L = s;
  }
}

Instance serpentine_instance(const SerpentineParams& p, uint64_t seed) {
  if (p.columns == 0 || p.height < 2 || p.contract_percent > 100)
    throw std::invalid_argument("serpentine_instance: needs columns >= 1, height >= 2, contract_percent <= 100");
  const int64_t C = p.columns, H = p.height;
  Rng rng(seed);
  InstanceBuilder b;
  for (int64_t i = 0; i < C; ++i)
    for (int64_t k = 0; k < H; ++k) must(b.add_node(serpentine_cell(i, k, H)));
  for (int64_t i = 0; i < C; ++i) {
    for (int64_t k = 0; k + 1 < H; ++k) must(b.add_edge(serpentine_cell(i, k, H), serpentine_cell(i, k + 1, H)));
    if (i + 1 < C) must(b.add_edge(serpentine_cell(i, H - 1, H), serpentine_cell(i + 1, 0, H)));
  }
  auto kind = [&] { return rng.below(100) < p.contract_percent ? OpKind::Contract : OpKind::Expand; };
  std::vector<std::string> connectors, column_ops;
  for (int64_t i = 0; i + 1 < C; ++i) {
    std::string name = "x" + std::to_string(i);
    must(b.add_op(name, kind(), serpentine_cell(i, H - 1, H), Dir::PosX));
    connectors.push_back(name);
  }
  for (int64_t i = 0; i < C; ++i)
    for (int64_t k = 1; k + 2 < H; k += 2) {
      std::string name = "y" + std::to_string(i) + "_" + std::to_string(k);
      must(b.add_op(name, kind(), serpentine_cell(i, k, H), i % 2 == 0 ? Dir::PosY : Dir::NegY));
      column_ops.push_back(name);
    }
  size_t size = p.coupling_size;
  if (size == 0) {
    size_t total = connectors.size() + column_ops.size();
    size = static_cast<size_t>(std::ceil(std::sqrt(static_cast<double>(total))));
  }
  if (p.couplings == SerpentineCouplings::Fan) {
    add_fan(b, connectors, column_ops, rng);
  } else if (size > 1) {
    if (p.couplings == SerpentineCouplings::Mixed)
      column_ops.insert(column_ops.end(), connectors.begin(), connectors.end());
    add_groups(b, column_ops, size, rng);
  }
  Instance inst;
  if (auto e = b.finish(inst)) throw std::logic_error("serpentine_instance: " + e->message);
  return inst;
}

SerpentineParams square_serpentine(int64_t n, uint32_t coupling_size, SerpentineCouplings couplings) {
  int64_t side = static_cast<int64_t>(std::llround(std::sqrt(static_cast<double>(std::max<int64_t>(n, 16)))));
  side += side % 2;
  SerpentineParams p;
  p.columns = static_cast<uint32_t>(side);
  p.height = static_cast<uint32_t>(side);
  p.coupling_size = coupling_size;
  p.couplings = couplings;
  return p;
}

SerpentineParams fan_serpentine(int64_t n) {
  SerpentineParams p;
  p.columns = static_cast<uint32_t>(std::max<int64_t>(2, n / 4));
  p.height = 4;
  p.couplings = SerpentineCouplings::Fan;
  return p;
}

Instance diagonal_sweep_instance(uint32_t K, uint32_t b, bool hits) {
  if (K == 0 || b < 3) throw std::invalid_argument("diagonal_sweep_instance: needs K >= 1 and b >= 3");
  InstanceBuilder bl;
  std::vector<std::string> ops;
  // The staircase, anchor first.
  Vec2 at{0, 0};
  must(bl.add_node(at));
  const Dir steps[4] = {Dir::PosX, Dir::PosX, Dir::PosY, Dir::PosY};
  for (uint32_t m = 0; m < K; ++m)
    for (int e = 0; e < 4; ++e) {
      const Vec2 next = at + unit(steps[e]);
      must(bl.add_node(next));
      must(bl.add_edge(at, next));
      if (e % 2 == 0) {
        ops.push_back("s" + std::to_string(ops.size()));
        must(bl.add_op(ops.back(), OpKind::Expand, at, steps[e]));
      }
      at = next;
    }
  const int64_t k = K, w = b, X = 3 * k + w + 1;
  add_blob(bl, Vec2{2 * k, 2 * k}, w);
  // The floor and the static triangle, each row joined along x and to the row below.
  for (int64_t y = -1; y + w + 2 <= X; ++y) {
    const int64_t x0 = y < 0 ? 0 : y + w + 2;
    for (int64_t x = x0; x <= X; ++x) {
      must(bl.add_node(Vec2{x, y}));
      if (x > x0) must(bl.add_edge(Vec2{x - 1, y}, Vec2{x, y}));
      if (y >= 0) must(bl.add_edge(Vec2{x, y - 1}, Vec2{x, y}));
      if (y < 0 && x == 0) must(bl.add_edge(Vec2{0, 0}, Vec2{0, -1}));
    }
  }
  if (hits) {
    // The post: up from the triangle's top row (y = 3K - 1) at x = X, then
    // left along y = 3K + b to x = 3K + b - 1, where the blob's top right
    // cell, (2K + b - 1, 2K + b) + t (K, K), arrives at t = 1 - 1/K.
    for (int64_t y = 3 * k; y <= 3 * k + w; ++y) {
      must(bl.add_node(Vec2{X, y}));
      must(bl.add_edge(Vec2{X, y - 1}, Vec2{X, y}));
    }
    for (int64_t x = X - 1; x >= 3 * k + w - 1; --x) {
      must(bl.add_node(Vec2{x, 3 * k + w}));
      must(bl.add_edge(Vec2{x + 1, 3 * k + w}, Vec2{x, 3 * k + w}));
    }
  }
  must(bl.add_coupling("Q", ops));
  Instance inst;
  if (auto e = bl.finish(inst)) throw std::logic_error("diagonal_sweep_instance: " + e->message);
  return inst;
}

Instance diagonal_sweep_of_size(int64_t n, bool hits) {
  const auto K = static_cast<uint32_t>(
      std::max<int64_t>(6, std::llround(std::sqrt(static_cast<double>(std::max<int64_t>(n, 1)) / 4.75))));
  return diagonal_sweep_instance(K, K / 2, hits);
}

Instance band_sweep_instance(uint32_t K, uint32_t p, uint32_t w, bool hits) {
  if (K == 0 || w == 0 || p == 0 || p > 3)
    throw std::invalid_argument("band_sweep_instance: needs K >= 1, w >= 1 and p in 1..3");
  if (hits && w > 4 * p) throw std::invalid_argument("band_sweep_instance: a hit needs w <= 4p");
  InstanceBuilder bl;
  std::vector<std::string> ops;
  const int64_t P = p, W = w, k = K, G = hits ? 4 * P : std::max<int64_t>(4 * P + 1, W) + 1, top = 3 * k + W + 1;
  // The staircase, anchor first: 2p rights (an expansion on the odd ones), 2 ups (one on the first).
  Vec2 at{0, 0};
  must(bl.add_node(at));
  for (int64_t m = 0; m < k; ++m)
    for (int64_t e = 0; e < 2 * P + 2; ++e) {
      const Dir d = e < 2 * P ? Dir::PosX : Dir::PosY;
      const Vec2 next = at + unit(d);
      must(bl.add_node(next));
      must(bl.add_edge(at, next));
      if (e % 2 == 0 && e <= 2 * P) {
        ops.push_back("s" + std::to_string(ops.size()));
        must(bl.add_op(ops.back(), OpKind::Expand, at, d));
      }
      at = next;
    }
  add_blob(bl, at, W);
  // The floor and the band: row y holds x = p y + G .. p y + G + p, its
  // left end joined to the row below (which reaches p cells further left).
  for (int64_t x = 0; x <= G + P; ++x) {
    must(bl.add_node(Vec2{x, -1}));
    if (x > 0) must(bl.add_edge(Vec2{x - 1, -1}, Vec2{x, -1}));
  }
  must(bl.add_edge(Vec2{0, 0}, Vec2{0, -1}));
  for (int64_t y = 0; y <= top; ++y) {
    const int64_t x0 = P * y + G;
    for (int64_t x = x0; x <= x0 + P; ++x) {
      must(bl.add_node(Vec2{x, y}));
      if (x > x0) must(bl.add_edge(Vec2{x - 1, y}, Vec2{x, y}));
    }
    must(bl.add_edge(Vec2{x0, y - 1}, Vec2{x0, y}));
  }
  must(bl.add_coupling("Q", ops));
  Instance inst;
  if (auto e = bl.finish(inst)) throw std::logic_error("band_sweep_instance: " + e->message);
  return inst;
}

Instance band_sweep_of_size(int64_t n, uint32_t p) {
  const int64_t per = 5 * static_cast<int64_t>(std::max<uint32_t>(p, 1)) + 5;
  return band_sweep_instance(static_cast<uint32_t>(std::clamp<int64_t>(n / per, 2, int64_t{1} << 30)), p);
}

Instance arc_sweep_instance(uint32_t J, uint32_t g) {
  if (J == 0 || g == 0) throw std::invalid_argument("arc_sweep_instance: needs J >= 1 and g >= 1");
  InstanceBuilder bl;
  std::vector<std::string> ops;
  std::vector<Vec2> arc{{0, 0}};
  must(bl.add_node(arc.back()));
  uint64_t edge = 0;
  const auto step = [&](Dir d) {
    const Vec2 from = arc.back(), to = from + unit(d);
    must(bl.add_node(to));
    must(bl.add_edge(from, to));
    if (edge++ % 2 == 0) {
      ops.push_back("s" + std::to_string(ops.size()));
      must(bl.add_op(ops.back(), OpKind::Expand, from, d));
    }
    arc.push_back(to);
  };
  for (int64_t j = 0; j < J; ++j) {
    for (int64_t a = 0; a < J - j; ++a) step(Dir::PosX);
    for (int64_t b = 0; b <= j; ++b) step(Dir::PosY);
  }
  // The band: a static path left from the anchor to (-g, 0), up to
  // (-g, g - 1), then the staircase moved by (-g, g).
  const int64_t G = g;
  Vec2 prev{0, 0};
  const auto static_cell = [&](Vec2 c) {
    if (bl.add_node(c)) throw std::logic_error("arc_sweep_instance: the band meets the staircase");
    must(bl.add_edge(prev, c));
    prev = c;
  };
  for (int64_t x = -1; x >= -G; --x) static_cell(Vec2{x, 0});
  for (int64_t y = 1; y < G; ++y) static_cell(Vec2{-G, y});
  for (const Vec2& c : arc) static_cell(Vec2{c.x - G, c.y + G});
  must(bl.add_coupling("Q", ops));
  Instance inst;
  if (auto e = bl.finish(inst)) throw std::logic_error("arc_sweep_instance: " + e->message);
  return inst;
}

Instance arc_sweep_of_size(int64_t n) {
  const auto J = static_cast<uint32_t>(
      std::max<int64_t>(4, std::llround(std::sqrt(static_cast<double>(std::max<int64_t>(n, 1)) / 2))));
  return arc_sweep_instance(J, std::max<uint32_t>(3, J / 3));
}

}  // namespace gridlock
