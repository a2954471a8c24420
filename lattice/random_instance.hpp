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
#include <string>

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
  bool path_shape = false;   // grow only from the newest node (long paths)
  uint32_t spread = 0;       // 0: compact blobs; larger: sparser shapes
  bool allow_expand = true;  // false: an expansion roll becomes a contraction or growth
  // > 0: cut the operations into exactly this many couplings of 1 to
  // max_coupling operations (fewer if the operations run out; operations
  // beyond couplings * max_coupling stay singletons); 0: random cuts of 1 to
  // max_coupling operations.
  uint32_t couplings = 0;
};

// O(nodes) expected. Requires p.nodes >= 1 and, with allow_expand false,
// allow_contract or allow_grow.
Instance random_instance(const RandomInstanceParams& p, uint64_t seed);

// The named families of `gridlock random` (docs/grid-format.md, "Random
// instances"): connected shapes of a chosen number of couplings.
enum class ShapeFamily {
  Tree,    // a tree of edges, compact
  Cycles,  // a compact shape with about a third of the other adjacent pairs joined (faces)
  Sparse,  // a tree grown mostly from recent cells: long thin arms, few neighbours
  Dense,   // a compact shape with most adjacent pairs joined and an operation on most nodes
  Path,    // one long path
};
// "tree", "cycles", "sparse", "dense", "path"; false for another name.
bool parse_shape_family(const std::string& name, ShapeFamily& out);
const char* shape_family_name(ShapeFamily f);

struct RandomFamilyParams {
  ShapeFamily family = ShapeFamily::Tree;
  uint32_t couplings = 100;   // wanted (>= 1)
  uint32_t max_coupling = 3;  // operations per coupling: 1 to this
  bool expand = true;         // operation kinds allowed (at least one)
  bool contract = true;
  bool grow = true;
  bool horizontal_only = false;  // only +x / -x operations
};

// The parameters random_family_instance hands to random_instance: operations
// = couplings * (1 + max_coupling) / 2 (rounded up), nodes per operation 3
// (tree, cycles, path), 4 (sparse) or 1.5 (dense). Throws
// std::invalid_argument for couplings == 0, max_coupling == 0, or no kind.
RandomInstanceParams family_params(const RandomFamilyParams& f);
// A seeded instance of the family; deterministic on every machine. O(nodes)
// expected; about 2 700 nodes for 300 couplings of up to 3 operations.
Instance random_family_instance(const RandomFamilyParams& f, uint64_t seed);

}  // namespace gridlock
