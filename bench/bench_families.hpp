// Instance families shared by the benchmarks (docs/performance.md).
//
// comb: a spine of length L along x with a tooth of height H on every spine
// node (n = L (H + 1)), and k expansions on random free edges:
//   Spine: all on spine edges (+x); Teeth: all inside teeth (+y);
//   Mixed: each on the spine or in a tooth at random.
// Expansions only push teeth apart (they slide along each other, touching),
// so no schedule of a comb collides. group > 1 couples consecutive
// expansions into couplings of `group` operations (0: one coupling of all).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "lattice/instance.hpp"
#include "lattice/random_instance.hpp"

namespace gridlock::bench {

enum class CombOps { Spine, Teeth, Mixed };

inline Instance comb(int64_t L, int64_t H, int64_t k, CombOps where, int64_t group, uint64_t seed) {
  InstanceBuilder b;
  for (int64_t x = 0; x < L; ++x)
    for (int64_t y = 0; y <= H; ++y) b.add_node({x, y});
  for (int64_t x = 0; x < L; ++x) {
    if (x + 1 < L) b.add_edge({x, 0}, {x + 1, 0});
    for (int64_t y = 0; y < H; ++y) b.add_edge({x, y}, {x, y + 1});
  }
  uint64_t s = seed;
  std::vector<std::string> names;
  std::vector<char> used(static_cast<size_t>(L * (H + 1)), 0);
  int64_t attempts = 0;
  while (static_cast<int64_t>(names.size()) < k && ++attempts < 50 * k) {
    bool tooth = where == CombOps::Teeth || (where == CombOps::Mixed && H > 0 && draw_below(s, 2) == 0);
    int64_t x = static_cast<int64_t>(draw_below(s, static_cast<uint64_t>(L - 1)));
    int64_t y = tooth ? static_cast<int64_t>(draw_below(s, static_cast<uint64_t>(H))) : 0;
    Vec2 u{x, y}, v = tooth ? Vec2{x, y + 1} : Vec2{x + 1, y};
    size_t iu = static_cast<size_t>(u.x * (H + 1) + u.y), iv = static_cast<size_t>(v.x * (H + 1) + v.y);
    if (used[iu] || used[iv]) continue;
    used[iu] = used[iv] = 1;
    std::string name = "e" + std::to_string(names.size());
    b.add_op(name, OpKind::Expand, u, tooth ? Dir::PosY : Dir::PosX);
    names.push_back(name);
  }
  if (group == 0) {
    b.add_coupling("all", names);
  } else if (group > 1) {
    for (size_t i = 0; i + 1 < names.size(); i += static_cast<size_t>(group)) {
      size_t end = std::min(names.size(), i + static_cast<size_t>(group));
      std::vector<std::string> g(names.begin() + static_cast<long>(i), names.begin() + static_cast<long>(end));
      if (g.size() > 1) b.add_coupling("Q" + std::to_string(i), g);
    }
  }
  Instance inst;
  if (auto e = b.finish(inst)) throw std::runtime_error(e->message);
  return inst;
}

}  // namespace gridlock::bench
