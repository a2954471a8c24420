// Motion: how operations move the shape (docs/model.md, "Motion").
//
// Positions are computed on a spanning tree rooted at the anchor. Every tree
// edge that carries an operation k moves the child's side relative to the
// parent's by s * p_k * unit(parent -> child), s = +1 for an expansion and -1
// for a contraction (p_k is the progress of k's coupling). Non-tree edges are
// checked by the cycle test instead (see FaceNets).
//
// Regions: every node is a region, and so is the node each expansion inserts
// and each growth grows. A region is an axis-parallel rectangle; each of its
// four coordinates (xlo, xhi, ylo, yhi) is base + the displacement of one
// node along that axis (+ the progress of a growth, for a grown node's far
// face). This one table gives every width that changes over time:
//   node w                 all four faces follow w
//   contracting v (into u) the face toward u follows u, the far face follows v
//   inserted by u->v       the face toward u follows u, the far face follows v
//   grown from u along d   both follow u, the far face also moves p along d
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "lattice/instance.hpp"

namespace gridlock {

// Rooted spanning tree (breadth first from the root) with an Euler tour:
// the subtree of w is the node range order[tin[w] .. tout[w]).
struct SpanningTree {
  NodeId root = 0;
  std::vector<NodeId> parent;       // kNone for the root
  std::vector<Dir> parent_dir;      // direction parent -> node
  std::vector<OpId> parent_op;      // operation on the edge to the parent, or kNone
  std::vector<uint32_t> tin, tout;  // Euler interval of each node
  std::vector<NodeId> order;        // nodes by tin
  std::vector<uint32_t> subtree;    // subtree sizes
  std::vector<char> tree_edge;      // per edge of the instance: 1 iff in the tree

  // O(n). root defaults to the instance's anchor.
  static SpanningTree build(const Instance& inst, NodeId root = kNone);
  bool in_subtree(NodeId w, NodeId top) const { return tin[top] <= tin[w] && tin[w] < tout[top]; }
};

// The signed unit vector by which operation k moves the child side of its
// tree edge relative to the parent side at full progress; zero for growths.
Vec2 op_child_vector(const Instance& inst, const SpanningTree& t, NodeId child);

enum class RegionKind : uint8_t { Node, Inserted, Grown };

struct RegionShape {
  RegionKind kind = RegionKind::Node;
  uint32_t id = 0;                 // node id (Node) or operation id (Inserted, Grown)
  int64_t base[4] = {0, 0, 0, 0};  // xlo, xhi, ylo, yhi at zero displacement
  NodeId ref[4] = {kNone, kNone, kNone, kNone};
  OpId grow_op = kNone;  // Grown: this op's progress moves face grow_face
  int grow_face = 0;
  int grow_sign = 0;
};

// All regions of an instance: ids 0..n-1 are the nodes, then one per
// expansion and growth in operation order.
struct Regions {
  std::vector<RegionShape> shapes;
  std::vector<uint32_t> region_of_op;  // Inserted/Grown region of op, or kNone
  static Regions build(const Instance& inst);
  size_t size() const { return shapes.size(); }
};

// "(3,1)", "node inserted by a", "node grown by g".
std::string region_label(const Instance& inst, const Regions& regions, uint32_t r);

// Cycle test data (docs/model.md "Cycle collision"). The face walks of the plane
// grid graph generate its cycle space, so the displacement summed around
// every cycle stays zero iff it does around every face walk. For each face
// walk we keep, per coupling with a non-zero sum, that coupling's net vector:
// the mismatch around the face at time t is sum_q p_q(t) * net_q.
// Built in O(n + e + couplings) plus a sort of each kept face's nets; total size O(e).
struct FaceNets {
  struct Face {
    std::vector<NodeId> walk;                       // the nodes in walk order
    std::vector<std::pair<CouplingId, Vec2>> nets;  // non-zero nets only
  };
  std::vector<Face> faces;  // only faces with at least one non-zero net
  // For each coupling: true iff it has a non-zero net around some face, so
  // that running it alone always makes a cycle collision.
  std::vector<char> coupling_breaks_cycle;
  static FaceNets build(const Instance& inst);
};

}  // namespace gridlock
