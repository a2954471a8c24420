// One axis, any couplings: the group pairs (collide/internal/collide_pairs.hpp,
// one_axis_group_pairs; the proof is docs/collide.md, "One axis, any
// couplings").
#include <algorithm>
#include <array>
#include <optional>
#include <utility>
#include <vector>

#include "collide/internal/collide_pairs.hpp"
#include "lattice/geometry.hpp"

namespace gridlock {

std::optional<std::vector<std::pair<uint32_t, uint32_t>>> one_axis_group_pairs(const Instance& inst,
                                                                               const Regions& regions) {
  bool along_x = true, along_y = true;
  for (const Operation& o : inst.ops()) (is_horizontal(o.dir) ? along_y : along_x) = false;
  if (!along_x && !along_y) return std::nullopt;
  const std::vector<RegionForm> forms = region_forms(inst, regions);
  const int m = along_x ? 0 : 2, c = 2 - m;  // faces m, m + 1 move along the axis; face c names the row
  // A unit: a node whose width never changes (no operation of its own
  // moves one of its faces against the other).
  auto unit = [&](uint32_t r) {
    const RegionForm& F = forms[r];
    return F.own == kNone && F.base[m + 1] - F.base[m] == 1;
  };
  // By row, then by place at p = 0: a region of width 0 at x comes after
  // one ending at x and before one starting at x.
  std::vector<uint32_t> order(forms.size());
  for (uint32_t r = 0; r < order.size(); ++r) order[r] = r;
  auto key = [&](uint32_t r) {
    return std::array<int64_t, 4>{forms[r].base[c], forms[r].base[m], forms[r].base[m + 1], r};
  };
  std::sort(order.begin(), order.end(), [&](uint32_t x, uint32_t y) { return key(x) < key(y); });
  std::vector<std::pair<uint32_t, uint32_t>> pairs;
  std::vector<uint32_t> group;
  auto emit = [&] {
    for (size_t i = 0; i < group.size(); ++i)
      for (size_t j = i + 1; j < group.size(); ++j) pairs.emplace_back(group[i], group[j]);
  };
  for (size_t k = 0; k < order.size();) {
    size_t e = k;
    while (e < order.size() && forms[order[e]].base[c] == forms[order[k]].base[c]) ++e;
    group.clear();
    for (size_t i = k; i < e; ++i) {
      group.push_back(order[i]);
      if (unit(order[i])) {  // closes the group, opens the next
        emit();
        group.assign(1, order[i]);
      }
    }
    emit();
    k = e;
  }
  return pairs;
}

}  // namespace gridlock
