#include "solver/internal/constraints.hpp"

#include <algorithm>
#include <stdexcept>
#include <tuple>

#include "common/internal/linear_interval.hpp"
#include "common/random.hpp"
#include "lattice/row_order.hpp"
#include "solver/internal/op_tree.hpp"

namespace gridlock {

namespace {

using TermList = std::vector<std::pair<CouplingId, int64_t>>;

// Sorts terms by coupling, sums repeated couplings and drops zero sums.
void normalise_terms(TermList& terms) {
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

// A linear form: base + sum of coef * [coupling done]; terms may repeat a
// coupling until normalised.
struct LinForm {
  int64_t base = 0;
  TermList terms;
  void normalise() { normalise_terms(terms); }
  int64_t max_value() const {
    int64_t m = base;
    for (auto& t : terms) m += std::max<int64_t>(t.second, 0);
    return m;
  }
};

// Turns n normalised forms into a constraint; false if the pair can never
// collide (some form is never positive).
bool make_constraint(const LinForm* forms, size_t n, uint32_t ra, uint32_t rb, const std::shared_ptr<CoefRows>& table,
                     CollisionConstraint& out) {
  uint8_t kept[8];
  uint32_t num_kept = 0;
  size_t num_terms = 0;
  for (size_t i = 0; i < n; ++i) {
    const LinForm& f = forms[i];
    if (f.max_value() <= 0) return false;  // never positive: the pair never overlaps
    if (f.terms.empty()) continue;         // constant and positive: no information
    kept[num_kept++] = static_cast<uint8_t>(i);
    num_terms += f.terms.size();
  }
  if (num_kept == 0) {
    // Every form constant and positive: the two would overlap from the start,
    // which a valid instance excludes (nodes in distinct cells, new regions of
    // width 0). Reaching this is a bug in the builder, not bad input.
    throw std::logic_error("collision constraint with a permanent overlap");
  }
  out = CollisionConstraint{};
  out.region_a = ra;
  out.region_b = rb;
  out.num_forms = num_kept;
  out.form_index.assign(kept, kept + num_kept);
  out.base.reserve(num_kept);
  out.rel.reserve(num_terms);
  for (uint32_t i = 0; i < num_kept; ++i) {
    out.base.push_back(forms[kept[i]].base);
    for (auto& t : forms[kept[i]].terms) out.rel.push_back(t.first);
  }
  std::sort(out.rel.begin(), out.rel.end());
  out.rel.erase(std::unique(out.rel.begin(), out.rel.end()), out.rel.end());
  out.rel.shrink_to_fit();
  std::vector<int64_t> coef(out.rel.size() * out.num_forms, 0);
  for (uint32_t i = 0; i < num_kept; ++i)
    for (auto& t : forms[kept[i]].terms) {
      size_t j = static_cast<size_t>(std::lower_bound(out.rel.begin(), out.rel.end(), t.first) - out.rel.begin());
      coef[j * out.num_forms + i] = t.second;
    }
  out.set_coef(coef, table);
  return true;
}

// make_constraint for one normalised form f that is positive somewhere,
// without its copies: what make_constraint(&f, 1, ra, rb, table, out) gives
// (the gap builder calls this for each of some thousands of neighbouring pairs).
CollisionConstraint single_form_constraint(const LinForm& f, uint32_t ra, uint32_t rb,
                                           const std::shared_ptr<CoefRows>& table) {
  if (f.terms.empty()) throw std::logic_error("collision constraint with a permanent overlap");
  CollisionConstraint out;
  out.region_a = ra;
  out.region_b = rb;
  out.num_forms = 1;
  out.form_index.assign(1, 0);
  out.base.assign(1, f.base);
  out.rel.reserve(f.terms.size());
  out.coef_rows.reserve(f.terms.size());
  for (const auto& [q, coef] : f.terms) {  // normalised: couplings increasing, distinct, coefficients non-zero
    out.rel.push_back(q);
    out.coef_rows.push_back(table->intern(&coef, 1));
  }
  out.rows = table;
  return out;
}

}  // namespace

namespace {

// The slot hash of a row of n coefficients (its length included).
uint64_t row_hash(const int64_t* row, uint32_t n) {
  uint64_t h = splitmix64_mix(n);
  for (uint32_t i = 0; i < n; ++i) h = splitmix64_mix(h ^ static_cast<uint64_t>(row[i]));
  return h;
}

}  // namespace

const int64_t* CoefRows::intern_hashed(const int64_t* row, uint32_t n) {
  const uint64_t h = row_hash(row, n);
  if (2 * (rows_.size() + 1) > slots_.size()) grow();
  const size_t mask = slots_.size() - 1;
  for (size_t s = h & mask;; s = (s + 1) & mask) {
    if (slots_[s] == 0) {
      auto stored = std::make_unique<int64_t[]>(size_t{n} + 1);
      stored[0] = n;
      std::copy(row, row + n, stored.get() + 1);
      rows_.push_back(std::move(stored));
      slots_[s] = static_cast<uint32_t>(rows_.size());
      return rows_.back().get() + 1;
    }
    const int64_t* r = rows_[slots_[s] - 1].get();
    if (r[0] == n && std::equal(row, row + n, r + 1)) return r + 1;
  }
}

// Doubles the slots (at least 16) and places every row again. O(rows).
void CoefRows::grow() {
  slots_.assign(std::max<size_t>(16, 2 * slots_.size()), 0);
  const size_t mask = slots_.size() - 1;
  for (size_t k = 0; k < rows_.size(); ++k) {
    const int64_t* r = rows_[k].get();
    size_t s = row_hash(r + 1, static_cast<uint32_t>(r[0])) & mask;
    while (slots_[s] != 0) s = (s + 1) & mask;
    slots_[s] = static_cast<uint32_t>(k + 1);
  }
}

void CollisionConstraint::set_coef(const std::vector<int64_t>& coef, std::shared_ptr<CoefRows> table) {
  if (num_forms == 0 || coef.size() != rel.size() * num_forms)
    throw std::logic_error("CollisionConstraint::set_coef: not rel.size() * num_forms coefficients");
  if (!table) table = std::make_shared<CoefRows>();
  coef_rows.resize(rel.size());
  for (size_t j = 0; j < rel.size(); ++j) coef_rows[j] = table->intern(coef.data() + j * num_forms, num_forms);
  rows = std::move(table);
}

std::vector<int64_t> CollisionConstraint::coef() const {
  std::vector<int64_t> out;
  append_coef(out);
  return out;
}

void CollisionConstraint::append_coef(std::vector<int64_t>& out) const {
  out.reserve(out.size() + coef_rows.size() * num_forms);
  for (const int64_t* r : coef_rows) out.insert(out.end(), r, r + num_forms);
}

size_t ConstraintSystem::total_forms() const {
  size_t s = 0;
  for (auto& c : constraints) s += c.num_forms;
  return s;
}

void CouplingIndex::build(size_t num_couplings, const std::vector<CollisionConstraint>& cs) {
  start_.assign(num_couplings + 1, 0);
  for (const CollisionConstraint& c : cs)
    for (CouplingId q : c.rel) ++start_[q + 1];
  for (size_t q = 0; q < num_couplings; ++q) start_[q + 1] += start_[q];
  entries_.resize(start_[num_couplings]);
  std::vector<size_t> next(start_.begin(), start_.end() - 1);
  for (uint32_t ci = 0; ci < cs.size(); ++ci)
    for (uint32_t j = 0; j < cs[ci].rel.size(); ++j) entries_[next[cs[ci].rel[j]]++] = {ci, j};
}

void ConstraintSystem::index() { of_coupling.build(num_couplings, constraints); }

bool step_collides(const int64_t* s, const int64_t* c, uint32_t nf) {
  // Each form is s_i + c_i p > 0, inside the open window (0, 1).
  LinearInterval<int64_t> progress(Fraction{0, 1}, Fraction{1, 1});
  for (uint32_t i = 0; i < nf; ++i)
    if (!progress.add(s[i], c[i])) return false;
  return !progress.empty();
}

namespace {

// order and runs: nodes_by_row(inst) and its row_runs (a PreparedInstance's
// rows and runs, or built for the call).
ConstraintSystem gap_constraints(const Instance& inst, const SpanningTree& tree, const Regions& regions,
                                 const std::vector<NodeId>& order, const std::vector<RowRun>& runs,
                                 const Deadline* deadline) {
  ConstraintSystem sys;
  sys.kind = ConstraintKind::Gaps;
  sys.num_couplings = inst.couplings().size();
  const OpTree ot(inst, tree);
  const auto& cells = inst.cells();
  const auto& ops = inst.ops();
  const auto table = std::make_shared<CoefRows>();
  LinForm f;
  for (const RowRun& run : runs) {
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
      sys.constraints.push_back(single_form_constraint(f, a, b, table));
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

// Regions sorted by base cell (x, then y, then region), and the start of
// each column, for box queries in O(columns in the box * log n + output).
class RegionsByCell {
 public:
  explicit RegionsByCell(const std::vector<Vec2>& cell) : cell_(cell), sorted_(cell.size()) {
    for (uint32_t r = 0; r < sorted_.size(); ++r) sorted_[r] = r;
    std::sort(sorted_.begin(), sorted_.end(), [&](uint32_t p, uint32_t q) {
      return std::tie(cell[p].x, cell[p].y, p) < std::tie(cell[q].x, cell[q].y, q);
    });
    for (size_t i = 0; i < sorted_.size(); ++i)
      if (i == 0 || cell[sorted_[i]].x != cell[sorted_[i - 1]].x) column_start_.push_back(i);
    column_start_.push_back(sorted_.size());
  }

  // Calls fn(r) for every region whose base cell is in [x0, x1] x [y0, y1],
  // by increasing x, then y, then r.
  template <class Fn>
  void for_each_in_box(int64_t x0, int64_t x1, int64_t y0, int64_t y1, Fn&& fn) const {
    // The first column with x >= x0.
    size_t lo = 0, hi = column_start_.size() - 1;
    while (lo < hi) {
      const size_t mid = (lo + hi) / 2;
      if (x_of_column(mid) < x0) lo = mid + 1;
      else hi = mid;
    }
    for (size_t col = lo; col + 1 < column_start_.size() && x_of_column(col) <= x1; ++col) {
      auto first = sorted_.begin() + static_cast<std::ptrdiff_t>(column_start_[col]);
      auto last = sorted_.begin() + static_cast<std::ptrdiff_t>(column_start_[col + 1]);
      first = std::partition_point(first, last, [&](uint32_t r) { return cell_[r].y < y0; });
      for (; first != last && cell_[*first].y <= y1; ++first) fn(*first);
    }
  }

 private:
  int64_t x_of_column(size_t col) const { return cell_[sorted_[column_start_[col]]].x; }

  const std::vector<Vec2>& cell_;
  std::vector<uint32_t> sorted_;
  std::vector<size_t> column_start_;
};

// How far the tree path between two nodes can move one relative to the
// other, per axis and direction, in O(1). disp(b) - disp(a) is the sum of
// the vectors of the done operations on the path from lca(a, b) down to b
// minus those down to a (OpTree), so its x part lies in
//   [-(neg_x(l..b) + pos_x(l..a)), pos_x(l..b) + neg_x(l..a)]
// with pos_x / neg_x counting the operations whose vector has x = +1 / -1
// (the same in y): the counts from the root per rigid component, minus
// those of the lowest common ancestor l. OpTree numbers components in
// preorder (it creates them in tree.order, a depth-first preorder), so for
// components c < d, lca(c, d) is the parent of the shallowest component
// numbered in (c, d] (c itself when c is an ancestor of d), a range
// minimum. O(C log C) to build for C components.
class PathReach {
 public:
  PathReach(const SpanningTree& tree, const OpTree& ot) : ot_(ot) {
    const size_t nc = ot.num_components();
    parent_.assign(nc, kNone);
    depth_.assign(nc, 0);
    count_.assign(nc, Counts{});
    for (NodeId w : tree.order) {
      const OpId k = tree.parent_op[w];
      if (w == tree.root || k == kNone) continue;
      const uint32_t c = ot.component(w), p = ot.component(tree.parent[w]);
      parent_[c] = p;
      depth_[c] = depth_[p] + 1;
      count_[c] = count_[p];
      const Vec2 v = ot.child_vector(k);
      count_[c].pos_x += v.x > 0 ? 1 : 0;
      count_[c].neg_x += v.x < 0 ? 1 : 0;
      count_[c].pos_y += v.y > 0 ? 1 : 0;
      count_[c].neg_y += v.y < 0 ? 1 : 0;
      max_.pos_x = std::max(max_.pos_x, count_[c].pos_x), max_.neg_x = std::max(max_.neg_x, count_[c].neg_x);
      max_.pos_y = std::max(max_.pos_y, count_[c].pos_y), max_.neg_y = std::max(max_.neg_y, count_[c].neg_y);
    }
    // min_[j][i]: the shallowest component among i .. i + 2^j - 1.
    min_.push_back(std::vector<uint32_t>(nc));
    for (uint32_t i = 0; i < nc; ++i) min_[0][i] = i;
    for (size_t j = 1; (size_t{1} << j) <= nc; ++j) {
      const std::vector<uint32_t>& prev = min_[j - 1];
      std::vector<uint32_t> row(nc - (size_t{1} << j) + 1);
      for (size_t i = 0; i < row.size(); ++i) row[i] = shallower(prev[i], prev[i + (size_t{1} << (j - 1))]);
      min_.push_back(std::move(row));
    }
  }

  struct Counts {
    int64_t pos_x = 0, neg_x = 0, pos_y = 0, neg_y = 0;
  };
  // Operations with each sign of vector on node w's path from the root.
  const Counts& from_root(NodeId w) const { return count_[ot_.component(w)]; }
  // The largest of each count over all nodes.
  const Counts& maxima() const { return max_; }

  // False if two boxes, one on node a's displacement and one on node b's,
  // whose base cells differ by d = cell(a) - cell(b), can never overlap:
  // that needs disp(b) - disp(a) within (d - 1, d + 1) on both axes.
  bool may_meet(NodeId a, NodeId b, Vec2 d) const {
    const uint32_t ca = ot_.component(a), cb = ot_.component(b);
    const Counts& A = count_[ca];
    const Counts& B = count_[cb];
    const Counts& L = count_[lca(ca, cb)];
    const int64_t max_x = (B.pos_x - L.pos_x) + (A.neg_x - L.neg_x),
                  min_x = -((B.neg_x - L.neg_x) + (A.pos_x - L.pos_x));
    const int64_t max_y = (B.pos_y - L.pos_y) + (A.neg_y - L.neg_y),
                  min_y = -((B.neg_y - L.neg_y) + (A.pos_y - L.pos_y));
    return min_x <= d.x && d.x <= max_x && min_y <= d.y && d.y <= max_y;
  }

 private:
  uint32_t shallower(uint32_t x, uint32_t y) const { return depth_[y] < depth_[x] ? y : x; }
  uint32_t lca(uint32_t c, uint32_t d) const {
    if (c == d) return c;
    if (c > d) std::swap(c, d);
    const uint32_t lo = c + 1, len = d - c;  // the range (c, d]
    const auto j = static_cast<size_t>(31 - __builtin_clz(len));
    return parent_[shallower(min_[j][lo], min_[j][d + 1 - (uint32_t{1} << j)])];
  }

  const OpTree& ot_;
  std::vector<uint32_t> parent_, depth_;
  std::vector<Counts> count_;
  Counts max_;
  std::vector<std::vector<uint32_t>> min_;
};

// The pairwise pass of pair_constraints: tests candidate region pairs and
// appends their constraints to sys.
//
// Every face of region r is D_ref[f] plus its base (and its growth term);
// relative to the pivot P = main(a), a face of b is
//   (D_main(b) - D_main(a)) + (D_ref_b[f] - D_main(b)),
// tree path sums, so a pair needs one walk (main(a) to main(b), split by
// axis) and each region's local part (main to ref, growth), built once.
// On a tree these sums equal the walk from P to ref_b[f] term by term
// (shared edges cancel), so the forms are exactly the per-face ones
// (twin: tests/support/reference_constraints.cpp).
struct PairScan {
  const Instance& inst;
  const Regions& regions;
  const OpTree& ot;
  const PathReach& reach;
  const RegionAnchors& an;
  const Deadline* deadline;
  ConstraintSystem& sys;
  const std::shared_ptr<CoefRows> table = std::make_shared<CoefRows>();  // every constraint's rows

  using Terms = TermList;
  std::vector<LinForm> local;  // 4 per region: D_ref[f] - D_main along f's axis, growth included
  Terms path_x, path_y;        // D_main(b) - D_main(a) per axis, normalised
  LinForm forms[8];
  bool stop_at_refuting = false;

  PairScan(const Instance& i, const Regions& r, const OpTree& o, const PathReach& pr, const RegionAnchors& a,
           const Deadline* d, ConstraintSystem& s)
      : inst(i), regions(r), ot(o), reach(pr), an(a), deadline(d), sys(s) {
    const auto& ops = inst.ops();
    local.resize(4 * regions.size());
    for (uint32_t reg = 0; reg < regions.size(); ++reg) {
      const RegionShape& sh = regions.shapes[reg];
      for (int f = 0; f < 4; ++f) {
        LinForm& out = local[(4 * size_t{reg}) + static_cast<size_t>(f)];
        const int ax = axis_of_face(f);
        ot.for_each_op_on_path(an.main[reg], sh.ref[f], [&](OpId k, int sign) {
          const Vec2 v = ot.child_vector(k);
          const int64_t dv = ax == 0 ? v.x : v.y;
          if (dv != 0) out.terms.push_back({ops[k].coupling, sign * dv});
        });
        if (sh.grow_op != kNone && f == sh.grow_face) out.terms.push_back({ops[sh.grow_op].coupling, sh.grow_sign});
        out.normalise();
      }
    }
  }

  const LinForm& local_of(uint32_t r, int f) const { return local[(4 * size_t{r}) + static_cast<size_t>(f)]; }

  // out = base + sign_path * path + plus - minus (plus, minus: local parts),
  // normalised.
  static void combine(LinForm& out, int64_t base, int sign_path, const Terms* path, const LinForm& plus,
                      const LinForm& minus) {
    out.base = base;
    out.terms.clear();
    if (path)
      for (const auto& [q, c] : *path) out.terms.push_back({q, sign_path * c});
    const size_t sorted_end = out.terms.size();
    for (const auto& t : plus.terms) out.terms.push_back(t);
    for (const auto& [q, c] : minus.terms) out.terms.push_back({q, -c});
    if (out.terms.size() == sorted_end) return;  // the path alone: already normalised
    out.normalise();
  }

  // Counts the candidate pair (a, b) and adds its constraint unless the two
  // cannot meet (too far apart for the path between their main nodes, or
  // some overlap form never positive).
  void consider(uint32_t a, uint32_t b) {
    const auto& ops = inst.ops();
    if (deadline && (sys.candidate_pairs & 63) == 0) deadline->check();
    ++sys.candidate_pairs;
    const Vec2 d = an.cell[a] - an.cell[b];
    if (!reach.may_meet(an.main[a], an.main[b], d)) return;
    path_x.clear();
    path_y.clear();
    ot.for_each_op_on_path(an.main[a], an.main[b], [&](OpId k, int sign) {
      const Vec2 v = ot.child_vector(k);
      if (v.x != 0) path_x.push_back({ops[k].coupling, sign * v.x});
      if (v.y != 0) path_y.push_back({ops[k].coupling, sign * v.y});
    });
    normalise_terms(path_x);
    normalise_terms(path_y);
    const RegionShape& sa = regions.shapes[a];
    const RegionShape& sb = regions.shapes[b];
    // The eight forms of constraints.hpp, faces as base + local (+ path for b).
    combine(forms[0], sa.base[1] - sb.base[0], -1, &path_x, local_of(a, 1), local_of(b, 0));  // A.xhi - B.xlo
    combine(forms[1], sb.base[1] - sa.base[0], +1, &path_x, local_of(b, 1), local_of(a, 0));  // B.xhi - A.xlo
    combine(forms[2], sa.base[3] - sb.base[2], -1, &path_y, local_of(a, 3), local_of(b, 2));  // A.yhi - B.ylo
    combine(forms[3], sb.base[3] - sa.base[2], +1, &path_y, local_of(b, 3), local_of(a, 2));  // B.yhi - A.ylo
    combine(forms[4], sa.base[1] - sa.base[0], 0, nullptr, local_of(a, 1), local_of(a, 0));   // widths
    combine(forms[5], sb.base[1] - sb.base[0], 0, nullptr, local_of(b, 1), local_of(b, 0));
    combine(forms[6], sa.base[3] - sa.base[2], 0, nullptr, local_of(a, 3), local_of(a, 2));
    combine(forms[7], sb.base[3] - sb.base[2], 0, nullptr, local_of(b, 3), local_of(b, 2));
    CollisionConstraint c;
    if (!make_constraint(forms, 8, a, b, table, c)) return;
    const bool refutes = c.rel.size() == 1 && step_collides(c.base.data(), c.coef_of(0), c.num_forms);
    sys.constraints.push_back(std::move(c));
    if (refutes && stop_at_refuting) sys.refuting = static_cast<uint32_t>(sys.constraints.size() - 1);
  }

  bool stopped() const { return sys.refuting != kNone; }

  // Considers every region b > a that region a could meet: those whose base
  // cell can be close enough for some path between the two (PathReach with
  // the root's counts and their maxima: d.x = x(a) - x(b) lies within
  // [-(neg_x(b) + pos_x(a)), pos_x(b) + neg_x(a)]), in the order of their
  // cells (x, then y, then region); all of them if the box is larger than
  // the region list.
  void scan_from(uint32_t a, const RegionsByCell& by_cell) {
    const size_t nr = regions.size();
    const PathReach::Counts& A = reach.from_root(an.main[a]);
    const PathReach::Counts& M = reach.maxima();
    const Vec2 ca = an.cell[a];
    const int64_t x0 = ca.x - A.neg_x - M.pos_x, x1 = ca.x + A.pos_x + M.neg_x;
    const int64_t y0 = ca.y - A.neg_y - M.pos_y, y1 = ca.y + A.pos_y + M.neg_y;
    auto box = (static_cast<__int128>(x1) - x0 + 1) * (static_cast<__int128>(y1) - y0 + 1);
    if (box > 4 * static_cast<__int128>(nr) + 16) {
      for (uint32_t b = a + 1; b < nr && !stopped(); ++b) consider(a, b);
      return;
    }
    by_cell.for_each_in_box(x0, x1, y0, y1, [&](uint32_t b) {
      if (b > a && !stopped()) consider(a, b);
    });
  }
};

ConstraintSystem pair_constraints(const Instance& inst, const SpanningTree& tree, const Regions& regions,
                                  const Deadline* deadline, bool stop_at_refuting) {
  ConstraintSystem sys;
  sys.kind = ConstraintKind::Pairs;
  sys.num_couplings = inst.couplings().size();
  const OpTree ot(inst, tree);
  const size_t nr = regions.size();

  const RegionAnchors an = region_anchors(inst, regions);
  const RegionsByCell by_cell(an.cell);

  const PathReach reach(tree, ot);
  PairScan scan(inst, regions, ot, reach, an, deadline, sys);
  scan.stop_at_refuting = stop_at_refuting;
  for (uint32_t a = 0; a < nr && !scan.stopped(); ++a) {
    if (deadline) deadline->check();
    scan.scan_from(a, by_cell);
  }
  sys.index();
  return sys;
}

}  // namespace

ConstraintSystem build_gap_constraints(const Instance& inst, const SpanningTree& tree, const Deadline* deadline) {
  const std::vector<NodeId> order = nodes_by_row(inst);
  return gap_constraints(inst, tree, Regions::build(inst), order, row_runs(inst, order), deadline);
}
ConstraintSystem build_gap_constraints(const PreparedInstance& prep, const Deadline* deadline) {
  return gap_constraints(prep.inst, prep.tree, prep.regions, prep.rows, prep.runs, deadline);
}
ConstraintSystem build_pair_constraints(const Instance& inst, const SpanningTree& tree, const Deadline* deadline,
                                        bool stop_at_refuting) {
  return pair_constraints(inst, tree, Regions::build(inst), deadline, stop_at_refuting);
}
ConstraintSystem build_pair_constraints(const PreparedInstance& prep, const Deadline* deadline, bool stop_at_refuting) {
  return pair_constraints(prep.inst, prep.tree, prep.regions, deadline, stop_at_refuting);
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
