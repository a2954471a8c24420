#include "collide/internal/collide_tree.hpp"

#include <algorithm>
#include <stdexcept>

#include "common/assert.hpp"

namespace gridlock {

namespace {

struct Copy {
  uint32_t region;
  NodeId at;      // the node it is fixed to
  Vec2 cell;      // its cell when `at` has not moved
  uint32_t excl;  // instance edge it must not be compared across, or kNone
  OpId own;       // its own operation (done: Inserted/Grown), or kNone
  bool own_done;  // the state of `own` that gives the full width
};

struct Arc {
  NodeId to;
  uint32_t edge;  // instance edge index
  OpId op;
  Vec2 vec;  // displacement of `to` relative to the source at full progress
};

struct Model {
  std::vector<Copy> copies;
  std::vector<uint32_t> copy_start;  // CSR by node
  std::vector<uint32_t> copy_list;
  std::vector<uint32_t> arc_start;
  std::vector<Arc> arcs;
};

Model build_model(const Instance& inst, const SpanningTree& tree, const Regions& regions) {
  Model M;
  const auto& cells = inst.cells();
  const size_t n = inst.num_nodes();
  for (uint32_t r = 0; r < regions.size(); ++r) {
    const RegionShape& s = regions.shapes[r];
    if (s.kind == RegionKind::Node) {
      NodeId w = s.id;
      OpId k = inst.op_of_node(w);
      if (k != kNone && inst.ops()[k].kind == OpKind::Contract && inst.ops()[k].v == w) {
        const Operation& op = inst.ops()[k];
        uint32_t e = inst.edge_index(op.u, op.dir);
        M.copies.push_back({r, w, cells[w], e, k, false});
        M.copies.push_back({r, op.u, cells[w], e, k, false});
      } else {
        M.copies.push_back({r, w, cells[w], kNone, kNone, false});
      }
    } else {
      OpId k = s.id;
      const Operation& op = inst.ops()[k];
      if (s.kind == RegionKind::Inserted) {
        uint32_t e = inst.edge_index(op.u, op.dir);
        M.copies.push_back({r, op.u, cells[op.v], e, k, true});
        M.copies.push_back({r, op.v, cells[op.u], e, k, true});
      } else {
        M.copies.push_back({r, op.u, cells[op.u] + unit(op.dir), kNone, k, true});
      }
    }
  }
  M.copy_start.assign(n + 1, 0);
  for (const Copy& c : M.copies) ++M.copy_start[c.at + 1];
  for (size_t i = 0; i < n; ++i) M.copy_start[i + 1] += M.copy_start[i];
  M.copy_list.resize(M.copies.size());
  {
    std::vector<uint32_t> fill(M.copy_start.begin(), M.copy_start.end() - 1);
    for (uint32_t i = 0; i < M.copies.size(); ++i) M.copy_list[fill[M.copies[i].at]++] = i;
  }
  M.arc_start.assign(n + 1, 0);
  for (NodeId w = 0; w < n; ++w)
    if (tree.parent[w] != kNone) ++M.arc_start[w + 1], ++M.arc_start[tree.parent[w] + 1];
  for (size_t i = 0; i < n; ++i) M.arc_start[i + 1] += M.arc_start[i];
  M.arcs.resize(M.arc_start[n]);
  std::vector<uint32_t> fill(M.arc_start.begin(), M.arc_start.end() - 1);
  for (NodeId w = 0; w < n; ++w) {
    NodeId p = tree.parent[w];
    if (p == kNone) continue;
    uint32_t e = inst.edge_index(p, tree.parent_dir[w]);
    Vec2 v = op_child_vector(inst, tree, w);
    M.arcs[fill[p]++] = {w, e, tree.parent_op[w], v};
    M.arcs[fill[w]++] = {p, e, tree.parent_op[w], Vec2{-v.x, -v.y}};
  }
  return M;
}

// Max segment tree with range add (no push-down: value = max(children) + add).
class AddMaxTree {
 public:
  explicit AddMaxTree(size_t m) : m_(std::max<size_t>(m, 1)), mx_(4 * m_, 0), add_(4 * m_, 0) {}
  void add(size_t l, size_t r, int v) { add(1, 0, m_ - 1, l, r, v); }
  int max(size_t l, size_t r) const { return max(1, 0, m_ - 1, l, r); }

 private:
  void add(size_t node, size_t lo, size_t hi, size_t l, size_t r, int v) {
    if (r < lo || hi < l) return;
    if (l <= lo && hi <= r) {
      mx_[node] += v, add_[node] += v;
      return;
    }
    size_t mid = (lo + hi) / 2;
    add(2 * node, lo, mid, l, r, v);
    add(2 * node + 1, mid + 1, hi, l, r, v);
    mx_[node] = std::max(mx_[2 * node], mx_[2 * node + 1]) + add_[node];
  }
  int max(size_t node, size_t lo, size_t hi, size_t l, size_t r) const {
    if (r < lo || hi < l) return 0;
    if (l <= lo && hi <= r) return mx_[node];
    size_t mid = (lo + hi) / 2;
    return std::max(max(2 * node, lo, mid, l, r), max(2 * node + 1, mid + 1, hi, l, r)) + add_[node];
  }
  size_t m_;
  std::vector<int> mx_, add_;
};

struct Rect {
  int64_t x1, x2, y1, y2;  // inclusive cell ranges
  int color;
  uint32_t copy;
  NodeId node;
};

bool rects_meet(const Rect& a, const Rect& b) { return a.x1 <= b.x2 && b.x1 <= a.x2 && a.y1 <= b.y2 && b.y1 <= a.y2; }

// Red-blue (here: up to four colours) intersection by a plane sweep over x
// with one segment tree per colour over the compressed y coordinates.
// Returns the indices of two rectangles of different colours that share a
// cell. O(m log m).
std::optional<std::pair<size_t, size_t>> bichromatic_pair(const std::vector<Rect>& rects, int colors) {
  if (rects.size() < 2) return std::nullopt;
  std::vector<int64_t> ys;
  ys.reserve(2 * rects.size());
  for (const Rect& r : rects) ys.push_back(r.y1), ys.push_back(r.y2);
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  auto yi = [&](int64_t y) { return static_cast<size_t>(std::lower_bound(ys.begin(), ys.end(), y) - ys.begin()); };
  struct Ev {
    int64_t x;
    bool insert;
    size_t i;
  };
  std::vector<Ev> ev;
  ev.reserve(2 * rects.size());
  for (size_t i = 0; i < rects.size(); ++i)
    ev.push_back({rects[i].x1, true, i}), ev.push_back({rects[i].x2 + 1, false, i});
  std::sort(ev.begin(), ev.end(), [](const Ev& a, const Ev& b) {
    return a.x != b.x ? a.x < b.x : (a.insert != b.insert ? !a.insert : a.i < b.i);
  });
  std::vector<AddMaxTree> trees(static_cast<size_t>(colors), AddMaxTree(ys.size()));
  std::vector<std::vector<size_t>> active(static_cast<size_t>(colors));
  std::vector<size_t> where(rects.size(), 0);
  for (const Ev& e : ev) {
    const Rect& r = rects[e.i];
    size_t a = yi(r.y1), b = yi(r.y2);
    auto& act = active[static_cast<size_t>(r.color)];
    if (!e.insert) {
      trees[static_cast<size_t>(r.color)].add(a, b, -1);
      size_t p = where[e.i];
      act[p] = act.back();
      where[act[p]] = p;
      act.pop_back();
      continue;
    }
    for (int c = 0; c < colors; ++c) {
      if (c == r.color || trees[static_cast<size_t>(c)].max(a, b) <= 0) continue;
      for (size_t j : active[static_cast<size_t>(c)])
        if (rects_meet(r, rects[j])) return std::pair{j, e.i};
      throw std::logic_error("bichromatic_pair: segment tree and active lists disagree");
    }
    trees[static_cast<size_t>(r.color)].add(a, b, 1);
    where[e.i] = act.size();
    act.push_back(e.i);
  }
  return std::nullopt;
}

// Chooses operations on a path (given as its arcs' ops and vectors, from the
// fixed node outward) so that cell + sum of the chosen vectors == target.
void choose_ops(const std::vector<std::pair<OpId, Vec2>>& path, Vec2 cell, Vec2 target, std::vector<OpId>& done) {
  int64_t need_x = target.x - cell.x, need_y = target.y - cell.y;
  for (const auto& [k, v] : path) {
    if (k == kNone) continue;
    if (v.x != 0 && need_x != 0 && (v.x > 0) == (need_x > 0)) need_x -= v.x, done.push_back(k);
    else if (v.y != 0 && need_y != 0 && (v.y > 0) == (need_y > 0)) need_y -= v.y, done.push_back(k);
  }
  if (need_x != 0 || need_y != 0) throw std::logic_error("collide tree: the target cell is not reachable");
}

// The centroid decomposition of the spanning tree, searched for a collision
// one component at a time; run() is the whole search, the other members its
// steps on the component being searched.
class CentroidSearch {
 public:
  CentroidSearch(const Instance& inst, const SpanningTree& tree, const Regions& regions)
      : n(inst.num_nodes()),
        M(build_model(inst, tree, regions)),
        removed(n, 0),
        size(n, 0),
        bfs_parent(n, kNone),
        in_edge(n, kNone),
        in_op(n, kNone),
        in_vec(n),
        lo(n),
        hi(n),
        color(n, -1),
        comps{{tree.root, 0}} {}

  // Searches every component until a collision is found; st gets the counts.
  std::optional<TreeCollision> run(TreeStats& st) {
    while (!comps.empty() && !found) {
      auto [root, depth] = comps.back();
      comps.pop_back();
      st.levels = std::max<uint64_t>(st.levels, depth + 1);
      NodeId c = centroid_of(root);
      int colors = collect_rects(c);
      st.rectangles += rects.size();
      if (auto pr = bichromatic_pair(rects, colors)) {
        const Rect& A = rects[pr->first];
        const Rect& B = rects[pr->second];
        report(A.copy, B.copy, Vec2{std::max(A.x1, B.x1), std::max(A.y1, B.y1)});
        break;
      }
      check_centroid_copies(c);
      if (found) break;
      removed[c] = 1;
      for (uint32_t i = M.arc_start[c]; i < M.arc_start[c + 1]; ++i)
        if (!removed[M.arcs[i].to]) comps.push_back({M.arcs[i].to, depth + 1});
    }
    return found;
  }

 private:
  // The centroid of root's component (the nodes reachable without crossing a
  // removed one): BFS from root into order, subtree sizes, then the walk
  // toward any child holding more than half. O(component size).
  NodeId centroid_of(NodeId root) {
    order.clear();
    order.push_back(root);
    bfs_parent[root] = kNone;
    for (size_t h = 0; h < order.size(); ++h) {
      NodeId w = order[h];
      for (uint32_t i = M.arc_start[w]; i < M.arc_start[w + 1]; ++i) {
        NodeId x = M.arcs[i].to;
        if (removed[x] || x == bfs_parent[w]) continue;
        bfs_parent[x] = w;
        order.push_back(x);
      }
    }
    for (size_t h = order.size(); h-- > 0;) {
      NodeId w = order[h];
      size[w] = 1;
      for (uint32_t i = M.arc_start[w]; i < M.arc_start[w + 1]; ++i) {
        NodeId x = M.arcs[i].to;
        if (!removed[x] && x != bfs_parent[w]) size[w] += size[x];
      }
    }
    const uint32_t total = static_cast<uint32_t>(order.size());
    NodeId c = root;
    for (;;) {
      NodeId next = kNone;
      for (uint32_t i = M.arc_start[c]; i < M.arc_start[c + 1]; ++i) {
        NodeId x = M.arcs[i].to;
        if (!removed[x] && x != bfs_parent[c] && 2 * size[x] > total) next = x;
      }
      if (next == kNone) break;
      c = next;
    }
    return c;
  }

  // Fills rects with the box of every copy in c's component but c's own,
  // relative to the centroid c, one colour per neighbouring subtree (recorded
  // in edge_color by its first edge), and sets the BFS links toward c that
  // report() follows. Returns the number of colours.
  int collect_rects(NodeId c) {
    rects.clear();
    int colors = 0;
    edge_color.clear();
    bfs_parent[c] = kNone;
    lo[c] = hi[c] = Vec2{0, 0};
    for (uint32_t i = M.arc_start[c]; i < M.arc_start[c + 1]; ++i) {
      const Arc& a0 = M.arcs[i];
      if (removed[a0.to]) continue;
      int col = colors++;
      edge_color.push_back({a0.edge, col});
      order.clear();
      order.push_back(a0.to);
      bfs_parent[a0.to] = c, in_edge[a0.to] = a0.edge, in_op[a0.to] = a0.op, in_vec[a0.to] = a0.vec;
      for (size_t h = 0; h < order.size(); ++h) {
        NodeId w = order[h];
        color[w] = col;
        Vec2 v = in_vec[w];
        NodeId p = bfs_parent[w];
        lo[w] = lo[p] + Vec2{std::min<int64_t>(0, v.x), std::min<int64_t>(0, v.y)};
        hi[w] = hi[p] + Vec2{std::max<int64_t>(0, v.x), std::max<int64_t>(0, v.y)};
        for (uint32_t j = M.copy_start[w]; j < M.copy_start[w + 1]; ++j) {
          uint32_t ci = M.copy_list[j];
          const Copy& cp = M.copies[ci];
          if (cp.excl != kNone && cp.excl == in_edge[w]) continue;  // faces the centroid across its own edge
          rects.push_back(
              {cp.cell.x + lo[w].x, cp.cell.x + hi[w].x, cp.cell.y + lo[w].y, cp.cell.y + hi[w].y, col, ci, w});
        }
        for (uint32_t j = M.arc_start[w]; j < M.arc_start[w + 1]; ++j) {
          const Arc& a = M.arcs[j];
          if (removed[a.to] || a.to == p || a.to == c) continue;
          bfs_parent[a.to] = w, in_edge[a.to] = a.edge, in_op[a.to] = a.op, in_vec[a.to] = a.vec;
          order.push_back(a.to);
        }
      }
    }
    return colors;
  }

  // Copies fixed to the centroid c: a point each, against every subtree but
  // the one across their excluded edge, and against each other; reports the
  // first meeting found. Needs collect_rects(c) first.
  void check_centroid_copies(NodeId c) {
    for (uint32_t j = M.copy_start[c]; j < M.copy_start[c + 1] && !found; ++j) {
      uint32_t ci = M.copy_list[j];
      const Copy& cp = M.copies[ci];
      int skip = -1;
      for (auto [e, col] : edge_color)
        if (e == cp.excl) skip = col;
      for (const Rect& r : rects)
        if (r.color != skip && r.x1 <= cp.cell.x && cp.cell.x <= r.x2 && r.y1 <= cp.cell.y && cp.cell.y <= r.y2) {
          report(ci, r.copy, cp.cell);
          break;
        }
      for (uint32_t j2 = j + 1; j2 < M.copy_start[c + 1] && !found; ++j2) {
        const Copy& o = M.copies[M.copy_list[j2]];
        if (o.region != cp.region && o.cell == cp.cell) report(ci, M.copy_list[j2], cp.cell);
      }
    }
  }

  // The arcs (op and vector) from w up the BFS links to the centroid.
  std::vector<std::pair<OpId, Vec2>> path_to_center(NodeId w) const {
    std::vector<std::pair<OpId, Vec2>> path;
    for (NodeId x = w; bfs_parent[x] != kNone; x = bfs_parent[x]) path.push_back({in_op[x], in_vec[x]});
    return path;
  }

  // Sets found to the collision of copies cx and cy at cell target, with the
  // operations done that bring both there.
  void report(uint32_t cx, uint32_t cy, Vec2 target) {
    TreeCollision tc;
    const Copy& X = M.copies[cx];
    const Copy& Y = M.copies[cy];
    tc.a = std::min(X.region, Y.region), tc.b = std::max(X.region, Y.region);
    choose_ops(path_to_center(X.at), X.cell, target, tc.done);
    choose_ops(path_to_center(Y.at), Y.cell, target, tc.done);
    for (const Copy* cp : {&X, &Y})
      if (cp->own != kNone && cp->own_done) tc.done.push_back(cp->own);
    std::sort(tc.done.begin(), tc.done.end());
    tc.done.erase(std::unique(tc.done.begin(), tc.done.end()), tc.done.end());
    found = tc;
  }

  const size_t n;
  Model M;
  std::vector<char> removed;
  std::vector<uint32_t> size;
  std::vector<NodeId> bfs_parent;
  std::vector<uint32_t> in_edge;  // edge from the BFS parent (toward the centroid)
  std::vector<OpId> in_op;
  std::vector<Vec2> in_vec, lo, hi;
  std::vector<int> color;
  std::vector<std::pair<NodeId, uint32_t>> comps;  // components left to search, with their depth
  std::vector<NodeId> order;
  std::vector<Rect> rects;
  std::vector<std::pair<uint32_t, int>> edge_color;  // first edge of a subtree -> its colour
  std::optional<TreeCollision> found;
};

}  // namespace

bool tree_algorithm_applies(const Instance& inst) {
  for (const Coupling& c : inst.couplings())
    if (c.ops.size() != 1) return false;
  FaceNets f = FaceNets::build(inst);
  for (char b : f.coupling_breaks_cycle)
    if (b) return false;
  return true;
}

std::optional<TreeCollision> tree_collision(const Instance& inst, const SpanningTree& tree, const Regions& regions,
                                            TreeStats* stats) {
  GRIDLOCK_ASSERT(tree_algorithm_applies(inst), "tree_collision needs singleton couplings and no cycle broken");
  TreeStats st;
  std::optional<TreeCollision> found = CentroidSearch(inst, tree, regions).run(st);
  if (stats) *stats = st;
  return found;
}

std::optional<TreeCollision> tree_collision_pairwise(const Instance& inst, const SpanningTree& tree,
                                                     const Regions& regions, const Deadline* deadline) {
  GRIDLOCK_ASSERT(tree_algorithm_applies(inst),
                  "tree_collision_pairwise needs singleton couplings and no cycle broken");
  const size_t n = inst.num_nodes();
  Model M = build_model(inst, tree, regions);
  std::vector<Vec2> lo(n), hi(n);
  std::vector<uint32_t> first(n, kNone), last(n, kNone);  // first / last edge of the path from the source
  std::vector<NodeId> par(n, kNone), order;
  for (uint32_t xi = 0; xi < M.copies.size(); ++xi) {
    if (deadline) deadline->check();
    const Copy& X = M.copies[xi];
    NodeId s = X.at;
    order.assign(1, s);
    par[s] = kNone, lo[s] = hi[s] = Vec2{0, 0}, first[s] = last[s] = kNone;
    for (size_t h = 0; h < order.size(); ++h) {
      NodeId w = order[h];
      for (uint32_t j = M.copy_start[w]; j < M.copy_start[w + 1]; ++j) {
        uint32_t yi = M.copy_list[j];
        const Copy& Y = M.copies[yi];
        if (yi <= xi || Y.region == X.region) continue;
        if (X.excl != kNone && X.excl == first[w]) continue;
        if (Y.excl != kNone && Y.excl == last[w]) continue;
        Vec2 a = Y.cell + lo[w], b = Y.cell + hi[w];
        if (a.x <= X.cell.x && X.cell.x <= b.x && a.y <= X.cell.y && X.cell.y <= b.y)
          return TreeCollision{std::min(X.region, Y.region), std::max(X.region, Y.region), {}};
      }
      for (uint32_t i = M.arc_start[w]; i < M.arc_start[w + 1]; ++i) {
        const Arc& a = M.arcs[i];
        if (a.to == par[w]) continue;
        NodeId x = a.to;
        par[x] = w;
        lo[x] = lo[w] + Vec2{std::min<int64_t>(0, a.vec.x), std::min<int64_t>(0, a.vec.y)};
        hi[x] = hi[w] + Vec2{std::max<int64_t>(0, a.vec.x), std::max<int64_t>(0, a.vec.y)};
        first[x] = w == s ? a.edge : first[w];
        last[x] = a.edge;
        order.push_back(x);
      }
    }
  }
  return std::nullopt;
}

}  // namespace gridlock
