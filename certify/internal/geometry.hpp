// What the checker derives from the instance itself, with the model's
// definitions only (lattice/motion.hpp: the spanning tree, the regions and
// which node each face follows). Horizontal displacements are linear forms
// in the couplings done: each tree edge with an operation moves the child's
// side by one unit (away from the parent for an expansion, toward it for a
// contraction) when the operation's coupling is done.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "certify/internal/certificate_text.hpp"
#include "lattice/instance.hpp"
#include "lattice/motion.hpp"

namespace gridlock {

// sum of coef * [coupling done] (+ base); terms sorted by coupling, no zeros.
struct CouplingForm {
  int64_t base = 0;
  std::vector<std::pair<CouplingId, int64_t>> terms;
};

// One gap inequality: sum of weight * [lit] <= bound, every weight > 0.
struct GapInequality {
  std::vector<std::pair<OrderLiteral, int64_t>> terms;
  int64_t bound = 0;
};

// The nodes sorted by row, then by x: by (y, x). Cells are distinct, so the
// order is unique; a two-pass counting sort (x, then y) when the coordinate
// ranges are within 4n + 64, std::sort otherwise. O(n) or O(n log n).
std::vector<NodeId> nodes_in_row_order(const std::vector<Vec2>& cells);

class CertifyGeometry {
 public:
  explicit CertifyGeometry(const Instance& inst);

  // Net displacement around the closed walk (consecutive nodes and the last
  // and first joined by edges) of the couplings with in[q] != 0, all done.
  // Reason if two consecutive nodes are not joined by an edge.
  std::optional<std::string> walk_net(const std::vector<NodeId>& walk, const std::vector<char>& in, Vec2& net) const;

  // The same for every coupling at once: nets[q] is coupling q's net around
  // the walk (alone done). O(walk + couplings).
  std::optional<std::string> walk_nets(const std::vector<NodeId>& walk, std::vector<Vec2>& nets) const;

  // Overlap form of the row neighbours a (left) and b: right(a) - left(b)
  // with a's growth toward +x and b's toward -x counted as part of the node
  // (> 0: the two overlap).
  CouplingForm overlap_form(NodeId a, NodeId b) const;

  // True iff a and b are in the same row, a left of b, no node between.
  bool row_neighbours(NodeId a, NodeId b) const;

  // The eight forms of regions ra and rb (lattice/motion.hpp), in the
  // order A.xhi - B.xlo, B.xhi - A.xlo, A.yhi - B.ylo, B.yhi - A.ylo, then
  // the widths A.x, B.x, A.y, B.y: the two overlap with positive area iff
  // all eight are > 0. Each face is its base plus the displacement of the
  // node it follows along its axis (plus the progress of a growth for a
  // grown region's far face). O(tree path lengths).
  std::vector<CouplingForm> region_forms(uint32_t ra, uint32_t rb) const;

  // A coupling whose operations alone do not sum to zero around some cycle:
  // the reason naming it and the edge that closes the cycle, or nullopt when
  // every coupling closes every cycle. Checks the fundamental cycle of each
  // edge outside the spanning tree (they generate the cycle space) against
  // the tree path between its ends, per coupling and axis.
  // O(sum of those tree paths).
  std::optional<std::string> cycle_breaker() const;

  // Per node, the range over [0,1]^k of its displacement from the root:
  // x low, x high, y low, y high, the sum over its tree path of
  // [min(0, v), max(0, v)] per axis (v each operation's child vector;
  // cancellations ignored, so the range may be larger than the reachable
  // set, never smaller). O(n).
  using Range = std::array<int64_t, 4>;
  std::vector<Range> displacement_ranges() const;

  // For every region, bounds on its four faces (xlo, xhi, ylo, yhi) that
  // hold at every progress vector: lo[f] <= face f <= hi[f]. O(regions).
  struct RegionBox {
    int64_t lo[4] = {0, 0, 0, 0}, hi[4] = {0, 0, 0, 0};
  };
  std::vector<RegionBox> region_boxes(const std::vector<Range>& ranges) const;

  const SpanningTree& tree() const { return tree_; }
  const std::vector<uint32_t>& depths() const { return depth_; }
  const Regions& regions() const { return regions_; }

  // Every gap inequality of a horizontal-only instance: for each pair of
  // row neighbours and each coupling t that narrows their gap, the gap is
  // <= 0 right after t (docs/certificates.md, "Gap inequalities").
  std::vector<GapInequality> gap_inequalities() const;

 private:
  // Displacement of node q minus that of node p along axis (0: x, 1: y), times sign.
  void add_path(NodeId p, NodeId q, int64_t sign, CouplingForm& f, int axis = 0) const;
  // Face fa of region a minus face fb of region b (faces 0..3: xlo, xhi, ylo, yhi; same axis).
  CouplingForm face_difference(uint32_t a, int fa, uint32_t b, int fb) const;
  const Instance& inst_;
  SpanningTree tree_;
  Regions regions_;
  std::vector<uint32_t> depth_;
};

// Upper bounds over the cube on the eight forms of a pair of regions from
// the displacement ranges along the tree path between the nodes two faces
// follow: D_u - D_v lies in the ranges from their lowest common ancestor
// (binary lifting), cancellations between the two branches ignored.
// O(n log n) to build, O(log n) per bound.
class PathBounds {
 public:
  explicit PathBounds(const CertifyGeometry& geo);
  // True iff some form of regions a, b (CertifyGeometry::region_forms) is
  // <= 0 on the whole cube by these bounds.
  bool apart(uint32_t a, uint32_t b) const;

 private:
  NodeId lca(NodeId u, NodeId v) const;
  // Bound on face fa of region a minus face fb of region b (same axis).
  int64_t face_difference_max(uint32_t a, int fa, uint32_t b, int fb) const;
  const CertifyGeometry& geo_;
  std::vector<CertifyGeometry::Range> range_;
  std::vector<std::vector<NodeId>> up_;  // up_[k][w]: the 2^k-th ancestor of w (the root above the root)
};

}  // namespace gridlock
