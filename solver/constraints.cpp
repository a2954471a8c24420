#include "solver/internal/constraints.hpp"

#include <algorithm>
#include <stdexcept>
#include <unordered_map>

#include "common/internal/linear_interval.hpp"
#include "solver/internal/op_tree.hpp"
#include "solver/internal/row_order.hpp"

namespace gridlock {

namespace {

// A linear form: base + sum of coef * [coupling done]; terms may repeat a
// coupling until normalised.
struct LinForm {
  int64_t base = 0;
  std::vector<std::pair<CouplingId, int64_t>> terms;
  void normalise() {
    std::sort(terms.begin(), terms.end());
    size_t out = 0;
    for (size_t i = 0; i < terms.size();) {
      size_t j = i;
      int64_t sum = 0;
      while (j < terms.size() && terms[j].first == terms[i].first) sum += terms[j++].second;
      if (sum != 0) terms[out++] = {terms[i].first, sum};
      i = j;
    }
    terms.resize(out);
  }
  int64_t max_value() const {
    int64_t m = base;
    for (auto& t : terms) m += std::max<int64_t>(t.second, 0);
    return m;
  }
};

LinForm operator-(const LinForm& a, const LinForm& b) {
  LinForm r;
  r.base = a.base - b.base;
  r.terms = a.terms;
  for (auto& t : b.terms) r.terms.push_back({t.first, -t.second});
  r.normalise();
  return r;
}

// Turns normalised forms into a constraint; false if the pair can never
// collide (some form is never positive).
bool make_constraint(std::vector<LinForm> forms, uint32_t ra, uint32_t rb, CollisionConstraint& out) {
  std::vector<LinForm> kept;
  std::vector<uint8_t> index;
  for (size_t i = 0; i < forms.size(); ++i) {
    LinForm& f = forms[i];
    if (f.max_value() <= 0) return false;  // never positive: the pair never overlaps
    if (f.terms.empty()) continue;         // constant and positive: no information
    kept.push_back(std::move(f));
    index.push_back(static_cast<uint8_t>(i));
  }
  if (kept.empty()) {
    // Every form constant and positive: the two would overlap from the start,
    // which a valid instance excludes (nodes in distinct cells, new regions of
    // width 0). Reaching this is a bug in the builder, not bad input.
    throw std::logic_error("collision constraint with a permanent overlap");
  }
  out = CollisionConstraint{};
  out.region_a = ra;
  out.region_b = rb;
  out.num_forms = static_cast<uint32_t>(kept.size());
  out.form_index = std::move(index);
  for (auto& f : kept) {
    out.base.push_back(f.base);
    for (auto& t : f.terms) out.rel.push_back(t.first);
  }
  std::sort(out.rel.begin(), out.rel.end());
  out.rel.erase(std::unique(out.rel.begin(), out.rel.end()), out.rel.end());
  out.coef.assign(out.rel.size() * out.num_forms, 0);
  for (uint32_t i = 0; i < out.num_forms; ++i)
    for (auto& t : kept[i].terms) {
      size_t j = static_cast<size_t>(std::lower_bound(out.rel.begin(), out.rel.end(), t.first) - out.rel.begin());
      out.coef[j * out.num_forms + i] = t.second;
    }
  return true;
}

// make_constraint for one normalised form f that is positive somewhere,
// without its copies: what make_constraint({f}, ra, rb, out) gives (the gap
// builder calls this for each of some thousands of neighbouring pairs).
CollisionConstraint single_form_constraint(const LinForm& f, uint32_t ra, uint32_t rb) {
  if (f.terms.empty()) throw std::logic_error("collision constraint with a permanent overlap");
  CollisionConstraint out;
  out.region_a = ra;
  out.region_b = rb;
  out.num_forms = 1;
  out.form_index.assign(1, 0);
  out.base.assign(1, f.base);
  out.rel.reserve(f.terms.size());
  out.coef.reserve(f.terms.size());
  for (const auto& [q, coef] : f.terms) {  // normalised: couplings increasing, distinct, coefficients non-zero
    out.rel.push_back(q);
    out.coef.push_back(coef);
  }
  return out;
}

}  // namespace

size_t ConstraintSystem::total_forms() const {
  size_t s = 0;
  for (auto& c : constraints) s += c.num_forms;
  return s;
}

void ConstraintSystem::index() {
  of_coupling.assign(num_couplings, {});
  for (uint32_t ci = 0; ci < constraints.size(); ++ci)
    for (uint32_t j = 0; j < constraints[ci].rel.size(); ++j) of_coupling[constraints[ci].rel[j]].push_back({ci, j});
}

bool step_collides(const int64_t* s, const int64_t* c, uint32_t nf) {
  // Each form is s_i + c_i p > 0, inside the open window (0, 1).
  LinearInterval<int64_t> progress(Fraction{0, 1}, Fraction{1, 1});
  for (uint32_t i = 0; i < nf; ++i)
    if (!progress.add(s[i], c[i])) return false;
  return !progress.empty();
}

namespace {

ConstraintSystem gap_constraints(const Instance& inst, const SpanningTree& tree, const Regions& regions,
                                 const Deadline* deadline) {
  ConstraintSystem sys;
  sys.kind = ConstraintKind::Gaps;
  sys.num_couplings = inst.couplings().size();
  const OpTree ot(inst, tree);
  const auto& cells = inst.cells();
  const auto& ops = inst.ops();
  std::vector<NodeId> order = nodes_by_row(inst);
  LinForm f;
  for (const RowRun& run : row_runs(inst, order)) {
    for (uint32_t i = run.begin; i + 1 < run.end; ++i) {
      NodeId a = order[i], b = order[i + 1];
      if (deadline && (sys.candidate_pairs & 63) == 0) deadline->check();
      ++sys.candidate_pairs;
      // Overlap form right(a) - left(b); a growth counts as part of its node.
      f.terms.clear();  // one form for every pair: its memory is reused
      f.base = cells[a].x + 1 - cells[b].x;
      NodeId ra = regions.shapes[a].ref[1], lb = regions.shapes[b].ref[0];
      ot.for_each_op_on_path(ra, lb, [&](OpId k, int sign) {
        // The path gives left(b)'s node minus right(a)'s node; the overlap is its negative.
        int64_t dx = ot.child_vector(k).x;
        if (dx != 0) f.terms.push_back({ops[k].coupling, -sign * dx});
      });
      OpId ka = inst.op_of_node(a), kb = inst.op_of_node(b);
      if (ka != kNone && ops[ka].kind == OpKind::Grow && ops[ka].u == a && ops[ka].dir == Dir::PosX)
        f.terms.push_back({ops[ka].coupling, 1});
      if (kb != kNone && ops[kb].kind == OpKind::Grow && ops[kb].u == b && ops[kb].dir == Dir::NegX)
        f.terms.push_back({ops[kb].coupling, 1});
      f.normalise();
      if (f.max_value() <= 0) continue;  // never positive: the pair never overlaps
      sys.constraints.push_back(single_form_constraint(f, a, b));
    }
  }
  sys.index();
  return sys;
}

int axis_of_face(int f) { return f < 2 ? 0 : 1; }

// Each region's base cell and main node: the region stays inside its base
// cell shifted by the displacement of its main node (the node itself; u for
// the region an operation creates and for a contracting v, whose near face
// follows u).
struct RegionAnchors {
  std::vector<Vec2> cell;
  std::vector<NodeId> main;
};

// Fills the base cell and main node of every region.
RegionAnchors region_anchors(const Instance& inst, const Regions& regions) {
  const auto& cells = inst.cells();
  const auto& ops = inst.ops();
  const size_t nr = regions.size();
  RegionAnchors an;
  an.cell.resize(nr);
  an.main.resize(nr);
  for (uint32_t r = 0; r < nr; ++r) {
    const RegionShape& sh = regions.shapes[r];
    if (sh.kind == RegionKind::Node) {
      an.cell[r] = cells[sh.id];
      OpId k = inst.op_of_node(sh.id);
      an.main[r] = (k != kNone && ops[k].kind == OpKind::Contract && ops[k].v == sh.id) ? ops[k].u : sh.id;
    } else {
      const Operation& op = ops[sh.id];
      an.cell[r] = cells[op.u] + unit(op.dir);
      an.main[r] = op.u;
    }
  }
  return an;
}

// Operations per axis on each node's root path, and their maxima.
struct AxisDepths {
  std::vector<int64_t> h, v;
  int64_t hmax = 0, vmax = 0;
};

// Counts horizontal and vertical operations on every root path of the tree
// (bounds for the scan box).
AxisDepths axis_depths(const Instance& inst, const SpanningTree& tree) {
  const auto& ops = inst.ops();
  const size_t n = inst.num_nodes();
  AxisDepths dp;
  dp.h.assign(n, 0);
  dp.v.assign(n, 0);
  for (NodeId w : tree.order) {
    if (w == tree.root) continue;
    NodeId p = tree.parent[w];
    dp.h[w] = dp.h[p], dp.v[w] = dp.v[p];
    OpId k = tree.parent_op[w];
    if (k != kNone) (is_horizontal(ops[k].dir) ? dp.h[w] : dp.v[w]) += 1;
    dp.hmax = std::max(dp.hmax, dp.h[w]), dp.vmax = std::max(dp.vmax, dp.v[w]);
  }
  return dp;
}

// The pairwise pass of pair_constraints: tests candidate region pairs and
// appends their constraints to sys.
struct PairScan {
  const Instance& inst;
  const Regions& regions;
  const OpTree& ot;
  const RegionAnchors& an;
  const Deadline* deadline;
  ConstraintSystem& sys;

  // The face f of region r as a linear form, relative to pivot node P.
  void face_form(uint32_t r, int f, NodeId P, LinForm& out) const {
    const auto& ops = inst.ops();
    const RegionShape& sh = regions.shapes[r];
    out.base = sh.base[f];
    out.terms.clear();
    int ax = axis_of_face(f);
    ot.for_each_op_on_path(P, sh.ref[f], [&](OpId k, int sign) {
      Vec2 v = ot.child_vector(k);
      int64_t d = ax == 0 ? v.x : v.y;
      if (d != 0) out.terms.push_back({ops[k].coupling, sign * d});
    });
    if (sh.grow_op != kNone && f == sh.grow_face) out.terms.push_back({ops[sh.grow_op].coupling, sh.grow_sign});
    out.normalise();
  }

  // Counts the candidate pair (a, b) and adds its constraint unless the two
  // cannot meet (too far apart for the path between their main nodes, or
  // some overlap form never positive).
  void consider(uint32_t a, uint32_t b) {
    const auto& ops = inst.ops();
    if (deadline && (sys.candidate_pairs & 63) == 0) deadline->check();
    ++sys.candidate_pairs;
    Vec2 d = an.cell[a] - an.cell[b];
    int64_t H = 0, V = 0;
    ot.for_each_op_on_path(an.main[a], an.main[b], [&](OpId k, int) { (is_horizontal(ops[k].dir) ? H : V) += 1; });
    if ((d.x < 0 ? -d.x : d.x) > H || (d.y < 0 ? -d.y : d.y) > V) return;
    NodeId P = an.main[a];
    LinForm fa[4], fb[4];
    for (int f = 0; f < 4; ++f) face_form(a, f, P, fa[f]), face_form(b, f, P, fb[f]);
    std::vector<LinForm> forms = {fa[1] - fb[0], fb[1] - fa[0], fa[3] - fb[2], fb[3] - fa[2],
                                  fa[1] - fa[0], fb[1] - fb[0], fa[3] - fa[2], fb[3] - fb[2]};
    CollisionConstraint c;
    if (make_constraint(std::move(forms), a, b, c)) sys.constraints.push_back(std::move(c));
  }

  // Considers every region b > a that region a could meet: those in the box
  // of cells around a (half-widths hx, vy), or all of them if the box is
  // larger than the region list.
  void scan_from(uint32_t a, int64_t hx, int64_t vy,
                 const std::unordered_map<uint64_t, std::vector<uint32_t>>& by_cell) {
    const size_t nr = regions.size();
    auto box = (2 * static_cast<__int128>(hx) + 1) * (2 * static_cast<__int128>(vy) + 1);
    if (box > 4 * static_cast<__int128>(nr) + 16) {
      for (uint32_t b = a + 1; b < nr; ++b) consider(a, b);
      return;
    }
    const Vec2 ca = an.cell[a];
    for (int64_t x = ca.x - hx; x <= ca.x + hx; ++x)
      for (int64_t y = ca.y - vy; y <= ca.y + vy; ++y) {
        auto it = by_cell.find(cell_key(Vec2{x, y}));
        if (it == by_cell.end()) continue;
        for (uint32_t b : it->second)
          if (b > a) consider(a, b);
      }
  }
};

ConstraintSystem pair_constraints(const Instance& inst, const SpanningTree& tree, const Regions& regions,
                                  const Deadline* deadline) {
  ConstraintSystem sys;
  sys.kind = ConstraintKind::Pairs;
  sys.num_couplings = inst.couplings().size();
  const OpTree ot(inst, tree);
  const size_t nr = regions.size();

  const RegionAnchors an = region_anchors(inst, regions);
  const AxisDepths dp = axis_depths(inst, tree);
  std::unordered_map<uint64_t, std::vector<uint32_t>> by_cell;
  by_cell.reserve(nr * 2);
  for (uint32_t r = 0; r < nr; ++r) by_cell[cell_key(an.cell[r])].push_back(r);

  PairScan scan{inst, regions, ot, an, deadline, sys};
  for (uint32_t a = 0; a < nr; ++a) {
    if (deadline) deadline->check();
    scan.scan_from(a, dp.h[an.main[a]] + dp.hmax, dp.v[an.main[a]] + dp.vmax, by_cell);
  }
  sys.index();
  return sys;
}

}  // namespace

ConstraintSystem build_gap_constraints(const Instance& inst, const SpanningTree& tree, const Deadline* deadline) {
  return gap_constraints(inst, tree, Regions::build(inst), deadline);
}
ConstraintSystem build_gap_constraints(const PreparedInstance& prep, const Deadline* deadline) {
  return gap_constraints(prep.inst, prep.tree, prep.regions, deadline);
}
ConstraintSystem build_pair_constraints(const Instance& inst, const SpanningTree& tree, const Deadline* deadline) {
  return pair_constraints(inst, tree, Regions::build(inst), deadline);
}
ConstraintSystem build_pair_constraints(const PreparedInstance& prep, const Deadline* deadline) {
  return pair_constraints(prep.inst, prep.tree, prep.regions, deadline);
}

std::string constraint_label(const Instance& inst, const Regions& regions, const CollisionConstraint& c) {
  if (c.region_a < inst.num_nodes() && c.region_b < inst.num_nodes() && c.num_forms == 1 &&
      inst.cells()[c.region_a].y == inst.cells()[c.region_b].y)
    return "gap between " + inst.node_label(c.region_a) + " and " + inst.node_label(c.region_b);
  return region_label(inst, regions, c.region_a) + " and " + region_label(inst, regions, c.region_b);
}

ReplayResult replay_order(const ConstraintSystem& sys, const std::vector<CouplingId>& order) {
  std::vector<std::vector<int64_t>> cur(sys.constraints.size());
  for (size_t i = 0; i < cur.size(); ++i) cur[i] = sys.constraints[i].base;
  for (size_t step = 0; step < order.size(); ++step) {
    CouplingId q = order[step];
    for (auto [ci, j] : sys.of_coupling[q]) {
      const CollisionConstraint& c = sys.constraints[ci];
      if (step_collides(cur[ci].data(), c.coef_of(j), c.num_forms)) return {step, ci};
    }
    for (auto [ci, j] : sys.of_coupling[q]) {
      const CollisionConstraint& c = sys.constraints[ci];
      for (uint32_t i = 0; i < c.num_forms; ++i) cur[ci][i] += c.coef_of(j)[i];
    }
  }
  return {order.size(), kNone};
}

}  // namespace gridlock
