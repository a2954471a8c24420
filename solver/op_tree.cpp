#include "solver/internal/op_tree.hpp"

namespace gridlock {

OpTree::OpTree(const Instance& inst, const SpanningTree& tree) {
  const size_t n = inst.num_nodes();
  comp_.assign(n, kNone);
  op_vec_.assign(inst.ops().size(), Vec2{0, 0});
  // tree.order is a preorder (Euler tour), so a parent comes before its child.
  for (NodeId w : tree.order) {
    if (w == tree.root) {
      comp_[w] = 0;
      parent_.push_back(kNone);
      parent_op_.push_back(kNone);
      depth_.push_back(0);
      continue;
    }
    NodeId p = tree.parent[w];
    OpId k = tree.parent_op[w];
    if (k == kNone) {
      comp_[w] = comp_[p];
      continue;
    }
    auto c = static_cast<uint32_t>(parent_.size());
    comp_[w] = c;
    parent_.push_back(comp_[p]);
    parent_op_.push_back(k);
    depth_.push_back(depth_[comp_[p]] + 1);
    op_vec_[k] = op_child_vector(inst, tree, w);
  }
}

}  // namespace gridlock
