// Colliding Schedule without couplings: the paper's O(n log^2 n) algorithm
// (centroid decomposition + red-blue rectangle intersection), extended to
// inserted, grown and contracting nodes (docs/collide.md).
//
// Without couplings every operation moves independently, so the positions a
// node can take relative to a fixed node form a box of cells, and a region
// whose width changes can be replaced by its full-width unit square: the
// widths are nested (a grown or inserted node of width p lies inside the one
// of width 1; a contracting node of width 1 - p inside the one of width 1),
// and its own progress appears in no other distance. Only the frame differs
// by side: an inserted node is a square fixed to u as seen from u's side and
// fixed to v as seen from v's side, so it gets two "copies", each compared
// only with what lies on its own side of the operation's edge (the excluded
// edge). Likewise a contracting v: as seen from u's side it is the square at
// v's cell fixed to u; from v's side the node v itself. A grown node is one
// square fixed to u. Two copies collide iff their boxes share a cell.
//
// Requires: every coupling is a singleton and no operation breaks a cycle (so
// every operation edge is a bridge, hence a tree edge).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "common/limits.hpp"
#include "lattice/instance.hpp"
#include "lattice/motion.hpp"

namespace gridlock {

struct TreeCollision {
  uint32_t a = kNone, b = kNone;  // regions
  std::vector<OpId> done;         // run these first (any order): the pair then overlaps
};

struct TreeStats {
  uint64_t levels = 0;      // centroid recursion depth reached
  uint64_t rectangles = 0;  // rectangles swept, summed over all centroids
};

// O(n log^2 n).
std::optional<TreeCollision> tree_collision(const Instance& inst, const SpanningTree& tree, const Regions& regions,
                                            TreeStats* stats = nullptr);

// The same model by brute force over all pairs of copies: O(n^2). For
// benchmarks (the crossover) and as a twin in tests. `done` is left empty.
// deadline (optional) is checked once per copy: LimitReached when passed.
std::optional<TreeCollision> tree_collision_pairwise(const Instance& inst, const SpanningTree& tree,
                                                     const Regions& regions, const Deadline* deadline = nullptr);

// True iff the instance meets the requirements above.
bool tree_algorithm_applies(const Instance& inst);

}  // namespace gridlock
