// Seeded random instances for tests, benchmarks and fuzzing.
//
// The shape grows cell by cell from (0,0): each new cell is a free neighbour
// of a random existing node and is joined to it by an edge, so the edges
// form a tree; with extra_edge_percent > 0, some other pairs of adjacent
// nodes are joined too (cycles). Operations are then placed on random nodes
// (each node in at most one), and grouped into random couplings.
// Deterministic: the same parameters and seed give the same instance on
// every machine (common/random.hpp).
#pragma once

#include <cstdint>

#include "lattice/instance.hpp"

namespace gridlock {

struct RandomInstanceParams {
  uint32_t nodes = 8;               // >= 1
  uint32_t ops = 3;                 // wanted; fewer if the nodes run out
  uint32_t max_coupling = 1;        // largest coupling size (1: no couplings)
  uint32_t extra_edge_percent = 0;  // chance to join other adjacent pairs
  bool allow_grow = true;
  bool allow_contract = true;
  bool horizontal_only = false;
  bool path_shape = false;  // grow only from the newest node (long paths)
  uint32_t spread = 0;      // 0: compact blobs; larger: sparser shapes
};

// O(nodes) expected.
Instance random_instance(const RandomInstanceParams& p, uint64_t seed);

}  // namespace gridlock
