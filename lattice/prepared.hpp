// A prepared instance: the motion tables every exact check needs (the
// spanning tree, the regions, the face walks; lattice/motion.hpp), built once
// and shared by the simulator (lattice/simulate.hpp), the exact solver
// (solver/solve.hpp), the constraint builders (solver/internal/constraints.hpp) and
// collide (solver/collide.hpp). verify builds one per formula instead of one
// per check (docs/performance.md, "Fuzzing throughput").
//
// The tables are exactly what SpanningTree::build(inst), Regions::build(inst),
// FaceNets::build(inst) and nodes_by_row(inst) (lattice/row_order.hpp)
// return: every entry point that takes a `const Instance&` builds a
// PreparedInstance, or the table it needs, and gives the same answers.
#pragma once

#include "lattice/instance.hpp"
#include "lattice/motion.hpp"
#include "lattice/row_order.hpp"

namespace gridlock {

struct PreparedInstance {
  // O(n + e log e) time and memory. Keeps a reference to inst, which must
  // outlive it (and must not change).
  explicit PreparedInstance(const Instance& instance)
      : inst(instance),
        tree(SpanningTree::build(instance)),
        regions(Regions::build(instance)),
        faces(FaceNets::build(instance)),
        rows(nodes_by_row(instance)),
        runs(row_runs(instance, rows)) {}
  PreparedInstance(const PreparedInstance&) = delete;
  PreparedInstance& operator=(const PreparedInstance&) = delete;

  const Instance& inst;
  const SpanningTree tree;  // rooted at the anchor
  const Regions regions;
  const FaceNets faces;
  const std::vector<NodeId> rows;  // every node, by (y, x): the gap checkers' order
  const std::vector<RowRun> runs;  // row_runs(inst, rows)
};

}  // namespace gridlock
