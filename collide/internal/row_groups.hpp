// One axis: the regions of each row in their order at the start, cut into
// groups at separators, and the pairs inside each group. Shared by the
// one-coupling test (single_coupling_one_axis: separators are the regions
// of positive width at t = 0) and the any-couplings one
// (one_axis_group_pairs: separators are the units); the proofs are
// docs/collide.md, "One coupling, one axis" and "One axis, any couplings".
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace gridlock {

// key(r) = {row, lo, hi} of region r at the start (r = 0 .. regions - 1);
// separator(r): r closes the group before it and opens the next. The
// regions are sorted by (row, lo, hi, r), so a region of width 0 at x
// comes after one ending at x and before one starting at x. A group is the
// regions between two consecutive separators of a row with both (and
// those before a row's first separator or after its last); every pair of
// a group is returned once, the earlier one in that order first.
// O(R log R + pairs).
template <class Key, class Separator>
std::vector<std::pair<uint32_t, uint32_t>> row_group_pairs(size_t regions, Key key, Separator separator) {
  std::vector<std::array<int64_t, 4>> keys(regions);
  std::vector<uint32_t> order(regions);
  for (uint32_t r = 0; r < regions; ++r) {
    const std::array<int64_t, 3> k = key(r);
    keys[r] = {k[0], k[1], k[2], r};
    order[r] = r;
  }
  std::sort(order.begin(), order.end(), [&](uint32_t x, uint32_t y) { return keys[x] < keys[y]; });
  std::vector<std::pair<uint32_t, uint32_t>> pairs;
  std::vector<uint32_t> group;
  auto emit = [&] {
    for (size_t i = 0; i < group.size(); ++i)
      for (size_t j = i + 1; j < group.size(); ++j) pairs.emplace_back(group[i], group[j]);
  };
  for (size_t k = 0; k < order.size();) {
    size_t e = k;
    while (e < order.size() && keys[order[e]][0] == keys[order[k]][0]) ++e;
    group.clear();
    for (size_t i = k; i < e; ++i) {
      group.push_back(order[i]);
      if (separator(order[i])) {  // closes the group, opens the next
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
