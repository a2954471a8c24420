// The spanning tree with its operation-free edges contracted.
//
// In the discrete model the position of a node is its cell plus the sum of
// the vectors of the done operations on its tree path from the anchor
// (docs/model.md, "Motion"). The solvers need relative positions as sums over
// couplings: disp(b) - disp(a) = sum over the operations k on the tree path
// between a and b of (+-) vec(k) * [coupling(k) done]. Contracting every tree
// edge without an operation leaves a tree of rigid components whose edges are
// exactly the operation edges, so walking a path costs the number of
// operations on it, not its length in nodes.
//
// Valid as a description of positions only when no coupling breaks a cycle
// (FaceNets::coupling_breaks_cycle all false): then every cycle's sum is zero
// coupling by coupling, and any spanning tree gives the same positions.
#pragma once

#include <cstdint>
#include <vector>

#include "lattice/instance.hpp"
#include "lattice/motion.hpp"

namespace gridlock {

class OpTree {
 public:
  // O(n). Keeps no reference to inst or tree.
  OpTree(const Instance& inst, const SpanningTree& tree);

  uint32_t component(NodeId w) const { return comp_[w]; }
  size_t num_components() const { return parent_.size(); }

  // Calls fn(op, sign) for every operation on the tree path from a to b, so
  // that disp(b) - disp(a) = sum of sign * child_vector(op) * [op done].
  // Each operation is reported once. O(number of operations on the path).
  template <class Fn>
  void for_each_op_on_path(NodeId a, NodeId b, Fn&& fn) const {
    uint32_t ca = comp_[a], cb = comp_[b];
    while (ca != cb) {
      if (depth_[ca] >= depth_[cb]) {
        fn(parent_op_[ca], -1);  // leaving a's side upward: a's side moved by +vec, so b - a gets -vec
        ca = parent_[ca];
      } else {
        fn(parent_op_[cb], +1);
        cb = parent_[cb];
      }
    }
  }
  // The displacement of the child side of op's tree edge relative to the
  // parent side at full progress (unit vector, signed for contractions).
  Vec2 child_vector(OpId op) const { return op_vec_[op]; }

 private:
  std::vector<uint32_t> comp_;    // per node
  std::vector<uint32_t> parent_;  // per component; kNone at the root
  std::vector<OpId> parent_op_;   // per component: the operation on the edge to the parent
  std::vector<uint32_t> depth_;   // per component
  std::vector<Vec2> op_vec_;      // per operation (zero for growths and non-tree edges)
};

}  // namespace gridlock
