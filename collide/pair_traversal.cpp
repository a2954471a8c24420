// The O(n^2)-pairs traversal (collide/internal/collide_pairs.hpp, pairwise_collision):
// a walk of the spanning tree from every node keeping the path's nets (and,
// in the continuous model, their zonotope's supports or angle tree), with
// every pair of regions met tested.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "collide/internal/angle_tree.hpp"
#include "collide/internal/collide_pairs.hpp"
#include "collide/internal/zonotope.hpp"

namespace gridlock {

using namespace pairs;

namespace {

// A spanning-tree arc with the vector (at full progress) from one end to the
// other and the coupling of the operation on it (kNone: rigid).
struct TreeArc {
  NodeId to;
  CouplingId q;
  Vec2 vec;
};

// Both directions of every spanning-tree edge, by node.
std::vector<std::vector<TreeArc>> tree_adjacency(const Instance& inst, const SpanningTree& tree) {
  const size_t n = inst.num_nodes();
  std::vector<std::vector<TreeArc>> adj(n);
  for (NodeId w = 0; w < n; ++w) {
    NodeId p = tree.parent[w];
    if (p == kNone) continue;
    OpId k = tree.parent_op[w];
    CouplingId q = k == kNone ? kNone : inst.ops()[k].coupling;
    Vec2 v = op_child_vector(inst, tree, w);
    adj[p].push_back({w, q, v});
    adj[w].push_back({p, q, Vec2{-v.x, -v.y}});
  }
  return adj;
}

bool on_axis(Vec2 w) { return w.x == 0 || w.y == 0; }

// The net vector of each coupling along a tree path that grows and shrinks
// one arc at a time: net[q]; active, the couplings with a non-zero net
// (pos[q] their place there, kNone if absent); reach_x / reach_y, the sums
// of |net| per axis. O(1) per apply(); with `supports` on, also the
// SupportTable: O(lines) per apply(), plus O(active) when a new line appears.
struct PathNetTracker {
  std::vector<Vec2> net;
  std::vector<uint32_t> pos;
  std::vector<CouplingId> active;
  int64_t reach_x = 0, reach_y = 0;
  bool supports = false;
  SupportTable table;
  uint64_t purges = 0;
  bool angles_on = false;
  AngleTree angles;                // the non-zero nets sorted by angle (ZonotopeTest::AngleTree)
  std::vector<WidePoint> polygon;  // scratch: the own progresses' polygon of the pair being tested

  explicit PathNetTracker(size_t nq) : net(nq), pos(nq, kNone) {}
  void apply(CouplingId q, Vec2 v) {
    Vec2& w = net[q];
    reach_x -= std::abs(w.x), reach_y -= std::abs(w.y);
    bool was = !w.is_zero();
    if (supports && was) forget_line(w);
    if (angles_on) angles.remove(w), angles.add(w + v);
    w += v;
    reach_x += std::abs(w.x), reach_y += std::abs(w.y);
    bool now = !w.is_zero();
    if (now && !was) pos[q] = static_cast<uint32_t>(active.size()), active.push_back(q);
    if (!now && was) {
      CouplingId last = active.back();
      active[pos[q]] = last;
      pos[last] = pos[q];
      active.pop_back();
      pos[q] = kNone;
    }
    if (supports && now) learn_line(q, w);
  }
  size_t live_lines() const { return table.lines.size() - table.empty_lines; }
  // Removes net w (about to change) from the table.
  void forget_line(Vec2 w) {
    table.contribute(w, -1);
    if (on_axis(w)) return;
    Vec2 d = line_direction(w);
    // Kept at count 0 (no O(K) rebuild when it returns) until the empty
    // lines outnumber twice the live ones; then all empty ones go at once
    // (amortised O(1) per forget), so steps and pairs cost O(live lines).
    if (--table.lines.find({d.x, d.y})->second.count == 0 && ++table.empty_lines > 2 * live_lines() + 8)
      std::erase_if(table.lines, [](const auto& kv) { return kv.second.count == 0; }), table.empty_lines = 0, ++purges;
  }
  // Adds q's new net w to the table; a new line gets its supports over the
  // other active nets first.
  void learn_line(CouplingId q, Vec2 w) {
    if (!on_axis(w)) {
      Vec2 d = line_direction(w);
      auto [it, fresh] = table.lines.try_emplace({d.x, d.y});
      if (!fresh && it->second.count == 0) --table.empty_lines;
      if (fresh)
        for (CouplingId r : active) {
          if (r == q) continue;
          i128 t = SupportTable::dot_plus(d, net[r]);
          it->second.h_plus += SupportTable::pos(t), it->second.h_minus += SupportTable::pos(-t);
        }
      ++it->second.count;
    }
    table.contribute(w, +1);
  }
  // The non-zero nets, as the pair tests take them.
  PathNets nets() const {
    PathNets out;
    out.reserve(active.size());
    for (CouplingId q : active) out.push_back({q, net[q]});
    return out;
  }
};

// The continuous test from the tracker's supports: only the own couplings'
// nets are taken out of the zonotope. Same answer as
// continuous_pair_collides(A, B, path.nets()).
bool continuous_pair_collides_supported(const RegionForm& A, const RegionForm& B, const PathNetTracker& path) {
  PathNets own;
  for (CouplingId q : {A.own, B.own})
    if (q != kNone && !path.net[q].is_zero() && (own.empty() || own.front().first != q))
      own.push_back({q, path.net[q]});
  PairSystem S = build_system(A, B, own);
  Normals N = path.table.normals();
  for (const auto& [q, w] : own)
    for (size_t k = 0; k < N.u.size(); ++k)
      N.h[k] -= SupportTable::pos(static_cast<i128>(N.u[k].x) * w.x + static_cast<i128>(N.u[k].y) * w.y);
  return projected_feasible(S, N);
}

// The continuous test from the angle tree: the own couplings' nets are
// taken out of the tree for the query (and put back), the own progresses
// become the polygon -cl U, and the pair can overlap iff 0 lies in the
// interior of Z' - cl U = Z' + (-cl U). nullopt: a vertex of cl J with a
// denominator too large to scale (never seen; the caller decides per pair).
std::optional<bool> continuous_pair_collides_angles(const RegionForm& A, const RegionForm& B, PathNetTracker& path) {
  PathNets own;
  for (CouplingId q : {A.own, B.own})
    if (q != kNone && !path.net[q].is_zero() && (own.empty() || own.front().first != q))
      own.push_back({q, path.net[q]});
  PairSystem S = build_system(A, B, own);
  int64_t scale = 1;
  std::vector<WidePoint>& pts = path.polygon;
  OwnPolygon poly = own_polygon(S, &scale, &pts);
  if (poly == OwnPolygon::Empty) return false;
  if (poly == OwnPolygon::TooFine) return std::nullopt;
  for (const auto& [q, w] : own) path.angles.remove(w);
  bool hit = path.angles.contains_origin(scale, pts);
  for (const auto& [q, w] : own) path.angles.add(w);
  return hit;
}

bool continuous_decision(const std::vector<RegionForm>& forms, uint32_t a, uint32_t b, PathNetTracker& path,
                         ZonotopeTest ztest, PairwiseStats& st) {
  if (ztest == ZonotopeTest::PerPair) return continuous_pair_collides(forms[a], forms[b], path.nets());
  if (ztest == ZonotopeTest::AngleTree || ztest == ZonotopeTest::AngleBoth) {
    std::optional<bool> tree = continuous_pair_collides_angles(forms[a], forms[b], path);
    if (!tree) ++st.angle_fallbacks;
    if (!tree || ztest == ZonotopeTest::AngleBoth) {
      bool slow = continuous_pair_collides(forms[a], forms[b], path.nets());
      if (tree && *tree != slow)
        throw std::logic_error("collide: angle-tree and per-pair zonotope tests disagree on regions " +
                               std::to_string(a) + ", " + std::to_string(b));
      return slow;
    }
    return *tree;
  }
  bool fast = continuous_pair_collides_supported(forms[a], forms[b], path);
  if (ztest == ZonotopeTest::Both && fast != continuous_pair_collides(forms[a], forms[b], path.nets()))
    throw std::logic_error("collide: incremental and per-pair zonotope tests disagree on regions " + std::to_string(a) +
                           ", " + std::to_string(b));
  return fast;
}

// Regions a and b with the path's nets between their reference nodes: the
// reach filter, then the exact test of the model, counted in st; on a
// meeting, the collision with its witness.
std::optional<PairCollision> test_pair(const std::vector<RegionForm>& forms, uint32_t a, uint32_t b,
                                       PathNetTracker& path, TimeModel model, ZonotopeTest ztest, PairwiseStats& st,
                                       const ApartFn& on_apart) {
  ++st.pairs;
  if (!pair_may_meet(forms[a], forms[b], path.reach_x, path.reach_y)) return std::nullopt;
  ++st.full_tests;
  const bool hit = model == TimeModel::Continuous   ? continuous_decision(forms, a, b, path, ztest, st)
                   : ztest == ZonotopeTest::PerPair ? discrete_pair_collides_per_vector(forms[a], forms[b], path.nets())
                                                    : discrete_pair_collides(forms[a], forms[b], path.nets());
  if (!hit) {
    if (on_apart) on_apart(a, b, path.nets());
    return std::nullopt;
  }
  PairCollision pc;
  pc.a = a, pc.b = b;
  PathNets nets = path.nets();
  bool again = model == TimeModel::Continuous ? continuous_pair_collides(forms[a], forms[b], nets, &pc.witness)
                                              : discrete_pair_collides(forms[a], forms[b], nets, &pc.witness);
  if (!again) throw std::logic_error("collide: the pair test gave no witness for a meeting it found");
  return pc;
}

}  // namespace

std::optional<PairCollision> pairwise_collision(const Instance& inst, const SpanningTree& tree, const Regions& regions,
                                                TimeModel model, PairwiseStats* stats, const Deadline* deadline,
                                                ZonotopeTest ztest,
                                                const std::function<void(uint64_t, uint64_t)>& on_source,
                                                const ApartFn& on_apart, const std::vector<uint32_t>* around) {
  const size_t n = inst.num_nodes(), nq = inst.couplings().size();
  std::vector<RegionForm> forms = region_forms(inst, regions);
  std::vector<std::vector<uint32_t>> regs_of(n);
  for (uint32_t r = 0; r < forms.size(); ++r) regs_of[forms[r].ref].push_back(r);
  const std::vector<std::vector<TreeArc>> adj = tree_adjacency(inst, tree);
  PathNetTracker path(nq);
  path.supports = model == TimeModel::Continuous && (ztest == ZonotopeTest::Incremental || ztest == ZonotopeTest::Both);
  path.angles_on = model == TimeModel::Continuous &&
                   (ztest == ZonotopeTest::AngleTree || ztest == ZonotopeTest::AngleBoth);
  PairwiseStats st;
  std::optional<PairCollision> found;
  auto test = [&](uint32_t a, uint32_t b) {
    found = test_pair(forms, a, b, path, model, ztest, st, on_apart);
    return found.has_value();
  };
  struct Frame {
    NodeId w;
    NodeId from;
    size_t next;
    CouplingId q;
    Vec2 vec;
  };
  // The source nodes: all (each pair once, from its smaller node), or the
  // nodes that the faces of the `around` regions follow (each against
  // every other node).
  std::vector<NodeId> sources;
  if (around) {
    auto add = [&](NodeId v) {
      if (v < n && std::find(sources.begin(), sources.end(), v) == sources.end()) sources.push_back(v);
    };
    for (uint32_t r : *around) {
      if (r >= forms.size()) continue;
      add(forms[r].ref);
      for (NodeId v : regions.shapes[r].ref) add(v);
    }
  } else {
    sources.resize(n);
    for (NodeId s = 0; s < n; ++s) sources[s] = s;
  }
  uint64_t steps = 0;
  for (size_t si = 0; si < sources.size() && !found; ++si) {
    const NodeId s = sources[si];
    if (deadline) deadline->check();
    if (on_source) on_source(si, sources.size());
    if (regs_of[s].empty()) continue;
    const auto& mine = regs_of[s];
    for (size_t i = 0; i < mine.size() && !found; ++i)
      for (size_t j = i + 1; j < mine.size(); ++j)
        if (test(mine[i], mine[j])) break;
    std::vector<Frame> stack{{s, kNone, 0, kNone, {0, 0}}};
    while (!stack.empty() && !found) {
      if (deadline && (++steps & 4095) == 0) deadline->check();
      Frame& f = stack.back();
      if (f.next < adj[f.w].size()) {
        const TreeArc& a = adj[f.w][f.next++];
        if (a.to == f.from) continue;
        if (a.q != kNone) path.apply(a.q, a.vec);
        stack.push_back({a.to, f.w, 0, a.q, a.vec});
        NodeId w = a.to;
        if (w > s || around)
          for (uint32_t ra : mine) {
            for (uint32_t rb : regs_of[w])
              if (test(ra, rb)) break;
            if (found) break;
          }
      } else {
        if (f.q != kNone) path.apply(f.q, Vec2{-f.vec.x, -f.vec.y});
        stack.pop_back();
      }
    }
    // Unwind what is left (after an early stop) so the state stays clean.
    while (!stack.empty()) {
      Frame& f = stack.back();
      if (f.q != kNone) path.apply(f.q, Vec2{-f.vec.x, -f.vec.y});
      stack.pop_back();
    }
  }
  st.line_purges = path.purges;
  if (stats) *stats = st;
  return found;
}

std::optional<PairCollision> listed_pairs_collision(const Instance& inst, const SpanningTree& tree,
                                                    const Regions& regions, TimeModel model,
                                                    const std::vector<std::pair<uint32_t, uint32_t>>& pairs,
                                                    PairwiseStats* stats, const Deadline* deadline,
                                                    const ApartFn& on_apart) {
  const size_t n = inst.num_nodes();
  const std::vector<RegionForm> forms = region_forms(inst, regions);
  // Per node: depth, the coupling and vector of the edge from its parent
  // (X(w) - X(parent) per coupling), and its place in the Euler walk of
  // the tree (2 tin - depth: every earlier node is entered and left, every
  // ancestor only entered), which bounds the tree distance between nodes.
  std::vector<uint32_t> depth(n, 0);
  std::vector<CouplingId> up_q(n, kNone);
  std::vector<Vec2> down(n, Vec2{0, 0});
  for (NodeId w : tree.order) {
    if (tree.parent[w] == kNone) continue;
    depth[w] = depth[tree.parent[w]] + 1;
    if (tree.parent_op[w] == kNone) continue;
    up_q[w] = inst.ops()[tree.parent_op[w]].coupling;
    down[w] = op_child_vector(inst, tree, w);
  }
  auto euler = [&](NodeId w) { return 2 * static_cast<uint64_t>(tree.tin[w]) - depth[w]; };
  // Mo's order: by block of the first end's place, then by the second's
  // (alternating), so the ends move O(n sqrt(P)) edges in all.
  const uint64_t block = std::max<uint64_t>(
      1, static_cast<uint64_t>(2.0 * static_cast<double>(n) /
                               std::sqrt(static_cast<double>(std::max<size_t>(1, pairs.size())))));
  std::vector<uint32_t> idx(pairs.size());
  for (uint32_t i = 0; i < idx.size(); ++i) idx[i] = i;
  auto mo_key = [&](uint32_t i) {
    const uint64_t b = euler(forms[pairs[i].first].ref) / block, e = euler(forms[pairs[i].second].ref);
    return std::array<uint64_t, 3>{b, b % 2 == 0 ? e : ~e, i};
  };
  std::sort(idx.begin(), idx.end(), [&](uint32_t x, uint32_t y) { return mo_key(x) < mo_key(y); });

  PathNetTracker path(inst.couplings().size());
  path.supports = model == TimeModel::Continuous;
  uint64_t steps = 0;
  // The path's nets are X(b) - X(a) per coupling: moving end b one edge
  // adds that edge's change of X, moving end a subtracts it.
  auto step = [&](NodeId child, int sign) {  // an end crosses the edge child - parent; sign: +1 down, -1 up, for b
    if (deadline && (++steps & 4095) == 0) deadline->check();
    if (up_q[child] != kNone) path.apply(up_q[child], Vec2{sign * down[child].x, sign * down[child].y});
  };
  auto move = [&](NodeId& end, NodeId target, int side) {  // side: +1 for end b, -1 for end a
    NodeId x = end, y = target;
    while (depth[x] > depth[y]) step(x, -side), x = tree.parent[x];
    while (depth[y] > depth[x]) step(y, side), y = tree.parent[y];
    while (x != y) step(x, -side), x = tree.parent[x], step(y, side), y = tree.parent[y];
    end = target;
  };
  PairwiseStats st;
  std::optional<PairCollision> found;
  NodeId end_a = tree.root, end_b = tree.root;
  for (uint32_t i : idx) {
    const auto [a, b] = pairs[i];
    move(end_a, forms[a].ref, -1);
    move(end_b, forms[b].ref, +1);
    found = test_pair(forms, a, b, path, model, ZonotopeTest::Incremental, st, on_apart);
    if (found) break;
  }
  if (stats) *stats = st;
  return found;
}

}  // namespace gridlock
