#include "certify/internal/geometry.hpp"

#include <algorithm>
#include <array>

namespace gridlock {
namespace {

void normalise(CouplingForm& f) {
  std::sort(f.terms.begin(), f.terms.end());
  size_t out = 0;
  for (size_t i = 0; i < f.terms.size();) {
    int64_t sum = 0;
    size_t j = i;
    for (; j < f.terms.size() && f.terms[j].first == f.terms[i].first; ++j) sum += f.terms[j].second;
    if (sum != 0) f.terms[out++] = {f.terms[i].first, sum};
    i = j;
  }
  f.terms.resize(out);
}

// One stable counting-sort pass of `in` into `out` by key(node) - lo, keys
// in [lo, lo + span).
template <class Key>
void counting_pass(const std::vector<NodeId>& in, std::vector<NodeId>& out, int64_t lo, size_t span, Key key) {
  std::vector<uint32_t> start(span + 1, 0);
  for (NodeId w : in) ++start[static_cast<size_t>(key(w) - lo) + 1];
  for (size_t i = 1; i <= span; ++i) start[i] += start[i - 1];
  for (NodeId w : in) out[start[static_cast<size_t>(key(w) - lo)]++] = w;
}

// How far the other end of an edge operation's edge moves relative to end
// a when the operation is done: an expansion u->v moves v away from u, a
// contraction toward it.
Vec2 far_end_move(const Operation& op, NodeId a) {
  const Vec2 d = unit(op.dir);
  const int64_t s = int64_t{op.kind == OpKind::Expand ? 1 : -1} * (a == op.u ? 1 : -1);
  return Vec2{s * d.x, s * d.y};
}

}  // namespace

std::vector<NodeId> nodes_in_row_order(const std::vector<Vec2>& cells) {
  std::vector<NodeId> order(cells.size());
  for (NodeId w = 0; w < order.size(); ++w) order[w] = w;
  if (cells.empty()) return order;
  int64_t x0 = cells[0].x, x1 = x0, y0 = cells[0].y, y1 = y0;
  for (const Vec2& c : cells)
    x0 = std::min(x0, c.x), x1 = std::max(x1, c.x), y0 = std::min(y0, c.y), y1 = std::max(y1, c.y);
  // Spans in unsigned arithmetic: no overflow even for extreme int64 cells.
  const auto span_x = static_cast<uint64_t>(x1) - static_cast<uint64_t>(x0);
  const auto span_y = static_cast<uint64_t>(y1) - static_cast<uint64_t>(y0);
  const auto limit = static_cast<uint64_t>(4 * cells.size() + 64);
  if (span_x >= limit || span_y >= limit) {
    std::sort(order.begin(), order.end(), [&](NodeId p, NodeId q) {
      return cells[p].y != cells[q].y ? cells[p].y < cells[q].y : cells[p].x < cells[q].x;
    });
    return order;
  }
  std::vector<NodeId> by_x(cells.size());
  counting_pass(order, by_x, x0, static_cast<size_t>(span_x) + 1, [&](NodeId w) { return cells[w].x; });
  counting_pass(by_x, order, y0, static_cast<size_t>(span_y) + 1, [&](NodeId w) { return cells[w].y; });
  return order;
}

CertifyGeometry::CertifyGeometry(const Instance& inst)
    : inst_(inst), tree_(SpanningTree::build(inst)), regions_(Regions::build(inst)), depth_(inst.num_nodes(), 0) {
  for (NodeId w : tree_.order)  // parents come before children in the Euler order
    if (tree_.parent[w] != kNone) depth_[w] = depth_[tree_.parent[w]] + 1;
}

void CertifyGeometry::add_path(NodeId p, NodeId q, int64_t sign, CouplingForm& f, int axis) const {
  const auto& ops = inst_.ops();
  while (p != q) {
    // Step up from the deeper end: its tree edge lies on the path.
    const bool up_q = depth_[q] >= depth_[p];
    const NodeId w = up_q ? q : p;
    const OpId k = tree_.parent_op[w];
    const Vec2 v = op_child_vector(inst_, tree_, w);
    const int64_t dx = axis == 0 ? v.x : v.y;
    if (k != kNone && dx != 0) f.terms.push_back({ops[k].coupling, (up_q ? sign : -sign) * dx});
    (up_q ? q : p) = tree_.parent[w];
  }
}

std::optional<std::string> CertifyGeometry::walk_net(const std::vector<NodeId>& walk, const std::vector<char>& in,
                                                     Vec2& net) const {
  std::vector<Vec2> nets;
  if (auto e = walk_nets(walk, nets)) return e;
  net = {0, 0};
  for (size_t q = 0; q < nets.size(); ++q)
    if (in[q]) net = net + nets[q];
  return std::nullopt;
}

std::optional<std::string> CertifyGeometry::walk_nets(const std::vector<NodeId>& walk, std::vector<Vec2>& nets) const {
  nets.assign(inst_.couplings().size(), Vec2{0, 0});
  for (size_t i = 0; i < walk.size(); ++i) {
    const NodeId a = walk[i], b = walk[(i + 1) % walk.size()];
    uint32_t e = kNone;
    for (Dir d : kDirs)
      if (inst_.neighbour(a, d) == b) e = inst_.edge_index(a, d);
    if (e == kNone) return inst_.node_label(a) + " and " + inst_.node_label(b) + " are not joined by an edge";
    const OpId k = inst_.edges()[e].op;
    if (k == kNone) continue;
    const Operation& op = inst_.ops()[k];
    nets[op.coupling] = nets[op.coupling] + far_end_move(op, a);
  }
  return std::nullopt;
}

std::optional<std::string> CertifyGeometry::cycle_breaker() const {
  const auto& edges = inst_.edges();
  for (size_t e = 0; e < edges.size(); ++e) {
    if (tree_.tree_edge[e]) continue;
    const NodeId a = edges[e].a, b = edges[e].b;
    for (int axis = 0; axis < 2; ++axis) {
      // (D_b - D_a along the tree) minus what the edge's own operation moves b by.
      CouplingForm f;
      add_path(a, b, 1, f, axis);
      if (edges[e].op != kNone) {
        const Operation& op = inst_.ops()[edges[e].op];
        const Vec2 m = far_end_move(op, a);
        f.terms.push_back({op.coupling, -(axis == 0 ? m.x : m.y)});
      }
      normalise(f);
      if (!f.terms.empty())
        return "coupling " + inst_.couplings()[f.terms[0].first].name +
               " has a non-zero net around the cycle closed by " + inst_.node_label(a) + " - " + inst_.node_label(b) +
               ": running it alone collides";
    }
  }
  return std::nullopt;
}

std::vector<CertifyGeometry::Range> CertifyGeometry::displacement_ranges() const {
  std::vector<Range> range(inst_.num_nodes(), {0, 0, 0, 0});
  for (NodeId w : tree_.order) {  // parents first
    if (tree_.parent[w] == kNone) continue;
    const Vec2 v = op_child_vector(inst_, tree_, w);
    const Range& up = range[tree_.parent[w]];
    range[w] = {up[0] + std::min<int64_t>(0, v.x), up[1] + std::max<int64_t>(0, v.x), up[2] + std::min<int64_t>(0, v.y),
                up[3] + std::max<int64_t>(0, v.y)};
  }
  return range;
}

std::vector<CertifyGeometry::RegionBox> CertifyGeometry::region_boxes(const std::vector<Range>& ranges) const {
  std::vector<RegionBox> boxes(regions_.size());
  for (size_t r = 0; r < regions_.size(); ++r) {
    const RegionShape& s = regions_.shapes[r];
    for (int f = 0; f < 4; ++f) {
      const Range& d = ranges[s.ref[f]];
      const size_t lo = f < 2 ? 0 : 2;  // the axis's entries of a Range: low, then high
      const int64_t grow = s.grow_op != kNone && s.grow_face == f ? s.grow_sign : 0;
      boxes[r].lo[f] = s.base[f] + d[lo] + std::min<int64_t>(0, grow);
      boxes[r].hi[f] = s.base[f] + d[lo + 1] + std::max<int64_t>(0, grow);
    }
  }
  return boxes;
}

PathBounds::PathBounds(const CertifyGeometry& geo) : geo_(geo), range_(geo.displacement_ranges()) {
  const SpanningTree& t = geo.tree();
  const size_t n = t.parent.size();
  up_.emplace_back(n);
  for (NodeId w = 0; w < n; ++w) up_[0][w] = t.parent[w] == kNone ? w : t.parent[w];
  for (size_t k = 1; (size_t{1} << k) < n; ++k) {
    up_.emplace_back(n);
    for (NodeId w = 0; w < n; ++w) up_[k][w] = up_[k - 1][up_[k - 1][w]];
  }
}

NodeId PathBounds::lca(NodeId u, NodeId v) const {
  const std::vector<uint32_t>& depth = geo_.depths();
  if (depth[u] < depth[v]) std::swap(u, v);
  for (size_t k = up_.size(); k-- > 0;)
    if (depth[u] - depth[v] >= (uint32_t{1} << k)) u = up_[k][u];
  if (u == v) return u;
  for (size_t k = up_.size(); k-- > 0;)
    if (up_[k][u] != up_[k][v]) u = up_[k][u], v = up_[k][v];
  return up_[0][u];
}

int64_t PathBounds::face_difference_max(uint32_t a, int fa, uint32_t b, int fb) const {
  const RegionShape &sa = geo_.regions().shapes[a], &sb = geo_.regions().shapes[b];
  const NodeId u = sa.ref[fa], v = sb.ref[fb];
  const CertifyGeometry::Range &ru = range_[u], &rv = range_[v], &rl = range_[lca(u, v)];
  const size_t lo = fa < 2 ? 0 : 2, hi = lo + 1;  // the axis's entries of a Range
  // D_u - D_v = (D_u - D_l) - (D_v - D_l), each within its range from l.
  int64_t m = sa.base[fa] - sb.base[fb] + (ru[hi] - rl[hi]) - (rv[lo] - rl[lo]);
  if (sa.grow_op != kNone && sa.grow_face == fa) m += std::max(0, sa.grow_sign);
  if (sb.grow_op != kNone && sb.grow_face == fb) m += std::max(0, -sb.grow_sign);
  return m;
}

bool PathBounds::apart(uint32_t a, uint32_t b) const {
  return face_difference_max(a, 1, b, 0) <= 0 || face_difference_max(b, 1, a, 0) <= 0 ||
         face_difference_max(a, 3, b, 2) <= 0 || face_difference_max(b, 3, a, 2) <= 0 ||
         face_difference_max(a, 1, a, 0) <= 0 || face_difference_max(b, 1, b, 0) <= 0 ||
         face_difference_max(a, 3, a, 2) <= 0 || face_difference_max(b, 3, b, 2) <= 0;
}

CouplingForm CertifyGeometry::overlap_form(NodeId a, NodeId b) const {
  CouplingForm f;
  f.base = inst_.cells()[a].x + 1 - inst_.cells()[b].x;
  // right(a) follows node ref[1] of a, left(b) node ref[0] of b: overlap = base + dx(ra) - dx(lb).
  add_path(regions_.shapes[b].ref[0], regions_.shapes[a].ref[1], 1, f);
  const auto& ops = inst_.ops();
  const OpId ka = inst_.op_of_node(a), kb = inst_.op_of_node(b);
  if (ka != kNone && ops[ka].kind == OpKind::Grow && ops[ka].u == a && ops[ka].dir == Dir::PosX)
    f.terms.push_back({ops[ka].coupling, 1});
  if (kb != kNone && ops[kb].kind == OpKind::Grow && ops[kb].u == b && ops[kb].dir == Dir::NegX)
    f.terms.push_back({ops[kb].coupling, 1});
  normalise(f);
  return f;
}

CouplingForm CertifyGeometry::face_difference(uint32_t a, int fa, uint32_t b, int fb) const {
  const RegionShape &sa = regions_.shapes[a], &sb = regions_.shapes[b];
  CouplingForm f;
  f.base = sa.base[fa] - sb.base[fb];
  add_path(sb.ref[fb], sa.ref[fa], 1, f, fa / 2);
  const auto& ops = inst_.ops();
  if (sa.grow_op != kNone && sa.grow_face == fa) f.terms.push_back({ops[sa.grow_op].coupling, sa.grow_sign});
  if (sb.grow_op != kNone && sb.grow_face == fb) f.terms.push_back({ops[sb.grow_op].coupling, -sb.grow_sign});
  normalise(f);
  return f;
}

std::vector<CouplingForm> CertifyGeometry::region_forms(uint32_t ra, uint32_t rb) const {
  return {face_difference(ra, 1, rb, 0), face_difference(rb, 1, ra, 0), face_difference(ra, 3, rb, 2),
          face_difference(rb, 3, ra, 2), face_difference(ra, 1, ra, 0), face_difference(rb, 1, rb, 0),
          face_difference(ra, 3, ra, 2), face_difference(rb, 3, rb, 2)};
}

bool CertifyGeometry::row_neighbours(NodeId a, NodeId b) const {
  const Vec2 ca = inst_.cells()[a], cb = inst_.cells()[b];
  if (ca.y != cb.y || ca.x >= cb.x) return false;
  for (int64_t x = ca.x + 1; x < cb.x; ++x)
    if (inst_.node_at({x, ca.y}) != kNone) return false;
  return true;
}

std::vector<GapInequality> CertifyGeometry::gap_inequalities() const {
  const std::vector<NodeId> by_row = nodes_in_row_order(inst_.cells());
  const auto& cells = inst_.cells();
  std::vector<GapInequality> out;
  for (size_t i = 0; i + 1 < by_row.size(); ++i) {
    const NodeId a = by_row[i], b = by_row[i + 1];
    if (cells[a].y != cells[b].y) continue;
    const CouplingForm f = overlap_form(a, b);
    int64_t narrow = 0, widen = 0;
    for (auto [q, c] : f.terms) (c > 0 ? narrow : widen) += c > 0 ? c : -c;
    if (f.base + narrow <= 0) continue;  // never overlapping: no inequality
    // After t runs: base + coef_t + sum of the coefs of those before t <= 0, i.e.
    // sum_{u narrows} coef_u [u<t] + sum_{w widens} |coef_w| [t<w] <= -base - coef_t + sum |coef_w|.
    for (auto [t, ct] : f.terms) {
      if (ct <= 0) continue;
      GapInequality g;
      g.bound = -f.base - ct + widen;
      for (auto [q, c] : f.terms) {
        if (q == t) continue;
        if (c > 0) g.terms.push_back({{q, t}, c});
        else g.terms.push_back({{t, q}, -c});
      }
      out.push_back(std::move(g));
    }
  }
  return out;
}

}  // namespace gridlock
