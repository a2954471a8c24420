#include "solver/row_order.hpp"

#include <algorithm>
#include <cstdlib>

#include "common/assert.hpp"

namespace gridlock {

std::vector<NodeId> nodes_by_row(const Instance& inst) {
  const auto& cells = inst.cells();
  const size_t n = cells.size();
  // Shift both coordinates into [0, 2^31): kMaxCoordinate < 2^30.
  static_assert(kMaxCoordinate < (int64_t{1} << 30), "the radix key needs coordinates below 2^30");
  std::vector<uint64_t> key(n);
  for (size_t i = 0; i < n; ++i) {
    GRIDLOCK_ASSERT(std::abs(cells[i].x) <= kMaxCoordinate && std::abs(cells[i].y) <= kMaxCoordinate,
                    "nodes_by_row needs cells within +-kMaxCoordinate");
    auto y = static_cast<uint64_t>(cells[i].y + kMaxCoordinate);
    auto x = static_cast<uint64_t>(cells[i].x + kMaxCoordinate);
    key[i] = (y << 31) | x;
  }
  std::vector<NodeId> a(n), b(n);
  for (size_t i = 0; i < n; ++i) a[i] = static_cast<NodeId>(i);
  // LSD radix: each pass is a stable counting sort on 16 bits.
  std::vector<uint32_t> count((1 << 16) + 1);
  for (int shift = 0; shift < 64; shift += 16) {
    std::fill(count.begin(), count.end(), 0);
    for (NodeId w : a) ++count[((key[w] >> shift) & 0xFFFF) + 1];
    // A digit that every key shares (common for the high digits): the pass
    // would not change the order.
    if (n > 0 && count[((key[a[0]] >> shift) & 0xFFFF) + 1] == n) continue;
    for (size_t d = 1; d < count.size(); ++d) count[d] += count[d - 1];
    for (NodeId w : a) b[count[(key[w] >> shift) & 0xFFFF]++] = w;
    a.swap(b);
  }
  return a;
}

std::vector<RowRun> row_runs(const Instance& inst, const std::vector<NodeId>& order) {
  std::vector<RowRun> runs;
  const auto& cells = inst.cells();
  for (uint32_t i = 0; i < order.size();) {
    uint32_t j = i + 1;
    while (j < order.size() && cells[order[j]].y == cells[order[i]].y) ++j;
    runs.push_back({i, j});
    i = j;
  }
  return runs;
}

}  // namespace gridlock
