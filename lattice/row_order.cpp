#include "lattice/row_order.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstdlib>
#include <numeric>
#include <utility>

#include "common/assert.hpp"
#include "lattice/motion.hpp"

namespace gridlock {

std::vector<NodeId> nodes_by_row(const Instance& inst) {
  const auto& cells = inst.cells();
  const size_t n = cells.size();
  static_assert(kMaxCoordinate < (int64_t{1} << 30), "the radix key needs coordinates below 2^30");
  // The key (y - min y, x - min x) packed into as few bits as the instance's
  // extent needs (at most 62, as coordinates are below 2^30 in magnitude):
  // small instances then take one or two passes of 2^11 buckets instead of
  // four passes of 2^16 (the counters' clearing dominated on fuzz formulas).
  int64_t min_x = 0, min_y = 0, max_x = 0;
  for (size_t i = 0; i < n; ++i) {
    GRIDLOCK_ASSERT(std::abs(cells[i].x) <= kMaxCoordinate && std::abs(cells[i].y) <= kMaxCoordinate,
                    "nodes_by_row needs cells within +-kMaxCoordinate");
    if (i == 0 || cells[i].x < min_x) min_x = cells[i].x;
    if (i == 0 || cells[i].y < min_y) min_y = cells[i].y;
    if (i == 0 || cells[i].x > max_x) max_x = cells[i].x;
  }
  const auto x_bits = static_cast<int>(std::bit_width(static_cast<uint64_t>(max_x - min_x)));
  std::vector<uint64_t> key(n);
  uint64_t max_key = 0;
  for (size_t i = 0; i < n; ++i) {
    key[i] = (static_cast<uint64_t>(cells[i].y - min_y) << x_bits) | static_cast<uint64_t>(cells[i].x - min_x);
    max_key = std::max(max_key, key[i]);
  }
  std::vector<NodeId> a(n), b(n);
  for (size_t i = 0; i < n; ++i) a[i] = static_cast<NodeId>(i);
  // LSD radix: each pass is a stable counting sort on kDigit bits.
  constexpr int kDigit = 11;
  constexpr uint64_t kMask = (uint64_t{1} << kDigit) - 1;
  std::vector<uint32_t> count((size_t{1} << kDigit) + 1);
  const auto key_bits = static_cast<int>(std::bit_width(max_key));
  for (int shift = 0; shift < key_bits; shift += kDigit) {
    std::fill(count.begin(), count.end(), 0);
    for (NodeId w : a) ++count[((key[w] >> shift) & kMask) + 1];
    for (size_t d = 1; d < count.size(); ++d) count[d] += count[d - 1];
    for (NodeId w : a) b[count[(key[w] >> shift) & kMask]++] = w;
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

namespace {

// `ids` (in increasing id order) sorted by (row, x, id) of their bases'
// lower-left corners by two stable counting sorts (by x, then by row) when
// the corners span at most 4 m + 64 cells each way for m ids; false (ids
// unchanged) otherwise. O(m + span).
bool counting_by_row(const std::vector<RegionShape>& shapes, std::vector<uint32_t>& ids) {
  if (ids.empty()) return true;
  int64_t xlo = INT64_MAX, xhi = INT64_MIN, ylo = INT64_MAX, yhi = INT64_MIN;
  for (uint32_t r : ids) {
    const int64_t* b = shapes[r].base;
    xlo = std::min(xlo, b[0]), xhi = std::max(xhi, b[0]);
    ylo = std::min(ylo, b[2]), yhi = std::max(yhi, b[2]);
  }
  const int64_t limit = 4 * static_cast<int64_t>(ids.size()) + 64;
  if (xhi - xlo >= limit || yhi - ylo >= limit) return false;
  std::vector<uint32_t> by_x(ids.size()), count;
  const auto counting = [&](int face, int64_t lo, int64_t hi, const auto& from, std::vector<uint32_t>& to) {
    count.assign(static_cast<size_t>(hi - lo + 2), 0);
    for (uint32_t r : from) ++count[static_cast<size_t>(shapes[r].base[face] - lo + 1)];
    for (size_t i = 1; i < count.size(); ++i) count[i] += count[i - 1];
    for (uint32_t r : from) to[count[static_cast<size_t>(shapes[r].base[face] - lo)]++] = r;
  };
  counting(0, xlo, xhi, ids, by_x);
  counting(2, ylo, yhi, by_x, ids);
  return true;
}

}  // namespace

std::vector<uint32_t> regions_by_row(const Regions& regions, const std::vector<NodeId>& rows) {
  const auto& shapes = regions.shapes;
  const auto n = static_cast<uint32_t>(rows.size());
  const auto nr = static_cast<uint32_t>(shapes.size());
  GRIDLOCK_ASSERT(n <= nr, "regions_by_row needs the regions of the nodes' instance");
  const auto less = [&](uint32_t a, uint32_t b) {
    const int64_t* x = shapes[a].base;
    const int64_t* y = shapes[b].base;
    return x[2] != y[2] ? x[2] < y[2] : x[0] != y[0] ? x[0] < y[0] : a < b;
  };
  // The extras by (row, x, id): counting sorts when their corners are
  // compact (fuzz formulas), a comparison sort otherwise; (row, x, id) is a
  // total order, so both give the same.
  std::vector<uint32_t> extra(nr - n);
  std::iota(extra.begin(), extra.end(), n);
  if (!counting_by_row(shapes, extra)) std::sort(extra.begin(), extra.end(), less);
  std::vector<uint32_t> out(nr);
  std::merge(rows.begin(), rows.end(), extra.begin(), extra.end(), out.begin(), less);
  return out;
}

std::vector<uint32_t> regions_by_row(const Regions& regions) {
  const auto& shapes = regions.shapes;
  const size_t nr = shapes.size();
  std::vector<uint32_t> out(nr);
  std::iota(out.begin(), out.end(), 0u);
  if (!counting_by_row(shapes, out)) {
    const auto row = [&](uint32_t r) { return shapes[r].base[2]; };
    std::sort(out.begin(), out.end(), [&](uint32_t a, uint32_t b) {
      return std::pair(row(a), shapes[a].base[0]) < std::pair(row(b), shapes[b].base[0]);
    });
  }
  return out;
}

}  // namespace gridlock
