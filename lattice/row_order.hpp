// Nodes grouped by row and ordered by x, in linear time.
//
// Both gap checkers (the continuous one in solver/gaps.hpp and the discrete
// gap constraints in solver/internal/constraints.hpp) need, for every row, its nodes
// from left to right. A comparison sort would cost O(n log n); the gap checker
// is promised linear time (solver/gaps.hpp), so this is an LSD radix sort on the key (y, x) shifted to
// start at zero: coordinates are bounded by kMaxCoordinate < 2^30, so the
// key fits 62 bits, and passes of 11 bits over the bits the key uses sort it.
// A PreparedInstance (lattice/prepared.hpp) holds one, so the checkers that
// share it sort once.
#pragma once

#include <cstdint>
#include <vector>

#include "lattice/instance.hpp"

namespace gridlock {

struct Regions;  // lattice/motion.hpp

// Returns every node id, ordered by (y, x) of its cell.
// Requires: cells within +-kMaxCoordinate (guaranteed by InstanceBuilder).
// Complexity: O(n) time (at most 6 counting passes of 2^11 buckets, one per
// 11 bits of the instance's extent) and O(n) memory.
std::vector<NodeId> nodes_by_row(const Instance& inst);

// A run [begin, end) of nodes_by_row's result that shares one y.
struct RowRun {
  uint32_t begin = 0, end = 0;
};
// The maximal runs of equal y in `order` (which nodes_by_row produced). O(n).
std::vector<RowRun> row_runs(const Instance& inst, const std::vector<NodeId>& order);

// Every region id (lattice/motion.hpp: the nodes, then one per expansion
// and growth) ordered by (row, x, id) of its base's lower-left corner: the
// simulator's row sweep's starting order. From `rows` (nodes_by_row of the
// regions' instance, a node's region has its cell as base) merged with the
// other regions, sorted: for m expansions and growths, O(n + m) by two
// counting sorts when their corners span at most 4 m + 64 cells each way
// (compiled formulas), otherwise O(n + m log m).
std::vector<uint32_t> regions_by_row(const Regions& regions, const std::vector<NodeId>& rows);
// The same order without the node order: two stable counting sorts (by x,
// then by row) when the base corners span at most 4 r + 64 cells each way
// for r regions, otherwise a comparison sort by (row, x) (which may order
// the regions of one corner differently). O(r + span). The simulator's
// previous path, kept as the twin of the one above.
std::vector<uint32_t> regions_by_row(const Regions& regions);

}  // namespace gridlock
