// A NO certificate of gridlock collide (certify/internal/collide_proof.hpp).
#include "certify/internal/collide_proof.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <map>
#include <numeric>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "certify/internal/certificate_text.hpp"
#include "certify/internal/geometry.hpp"

namespace gridlock {
namespace {

using i128 = __int128;
constexpr const char* kHeader = "gridlock-collide-no-certificate";

std::string at(size_t line, const std::string& what) { return "line " + std::to_string(line) + ": " + what; }

// One r line: the pair as written and its multipliers.
struct PairLine {
  size_t line = 0;
  uint32_t a = kNone, b = kNone;
  std::array<int64_t, 8> lambda{};
};

struct CollideText {
  bool header = false, couplings = false;
  bool one_axis = false;  // p line ends in one-axis: only the row groups' pairs need cover
  int kept_axis = -1;     // p line ends in kept-order x (0), y (1), separated (2) or slabs (3): the sweeps' pairs
  size_t header_line = 0;
  std::map<std::pair<uint32_t, uint32_t>, PairLine> pairs;  // by (smaller, larger) region
};

// The maximum over [0,1]^k of sum_i lambda_i f_i: its base plus its positive
// coefficients. nullopt on overflow.
std::optional<i128> max_over_cube(const std::vector<CouplingForm>& forms, const std::array<int64_t, 8>& lambda) {
  i128 base = 0;
  std::map<CouplingId, i128> coef;
  for (size_t i = 0; i < forms.size(); ++i) {
    if (lambda[i] == 0) continue;
    i128 t = 0;
    if (__builtin_mul_overflow(static_cast<i128>(lambda[i]), static_cast<i128>(forms[i].base), &t) ||
        __builtin_add_overflow(base, t, &base))
      return std::nullopt;
    for (auto [q, c] : forms[i].terms)
      if (__builtin_mul_overflow(static_cast<i128>(lambda[i]), static_cast<i128>(c), &t) ||
          __builtin_add_overflow(coef[q], t, &coef[q]))
        return std::nullopt;
  }
  for (const auto& [q, c] : coef)
    if (c > 0 && __builtin_add_overflow(base, c, &base)) return std::nullopt;
  return base;
}

// r A B L1 .. L8
std::optional<std::string> pair_line(const Instance& inst, const Regions& regions,
                                     const std::vector<std::string_view>& w, size_t line, CollideText& out) {
  if (w.size() != 11) return at(line, "expected 'r REGION REGION' and eight multipliers");
  PairLine p;
  p.line = line;
  if (auto e = read_region(inst, regions, w[1], p.a)) return at(line, *e);
  if (auto e = read_region(inst, regions, w[2], p.b)) return at(line, *e);
  if (p.a == p.b) return at(line, "a region paired with itself");
  bool any = false;
  for (size_t i = 0; i < 8; ++i) {
    if (!certificate_int(w[3 + i], p.lambda[i]) || p.lambda[i] < 0)
      return at(line, "multiplier '" + std::string(w[3 + i]) + "' is not an integer >= 0");
    any = any || p.lambda[i] != 0;
  }
  if (!any) return at(line, "every multiplier is zero");
  const auto key = std::minmax(p.a, p.b);
  if (!out.pairs.emplace(std::pair{key.first, key.second}, p).second)
    return at(line, "a second line for " + std::string(w[1]) + " and " + std::string(w[2]));
  return std::nullopt;
}

std::optional<std::string> read_collide_text(const Instance& inst, const Regions& regions, std::string_view text,
                                             CollideText& out) {
  auto one = [&](size_t line, const std::vector<std::string_view>& w) -> std::optional<std::string> {
    if (w[0] == "p") {
      if (out.header) return at(line, "a second p line");
      const bool kept = w.size() == 6 && w[4] == "kept-order" &&
                        (w[5] == "x" || w[5] == "y" || w[5] == "separated" || w[5] == "slabs");
      if (w.size() < 4 || w.size() > 6 || w[1] != kHeader || w[2] != "1" || w[3] != "continuous" ||
          (w.size() == 5 && w[4] != "one-axis") || (w.size() == 6 && !kept))
        return at(line, std::string("expected 'p ") + kHeader +
                            " 1 continuous', optionally followed by 'one-axis' or 'kept-order x|y|separated|slabs'");
      out.header = true;
      out.one_axis = w.size() == 5;
      if (kept) out.kept_axis = w[5] == "x" ? 0 : w[5] == "y" ? 1 : w[5] == "separated" ? 2 : 3;
      out.header_line = line;
      return std::nullopt;
    }
    if (!out.header) return at(line, std::string("expected 'p ") + kHeader + " 1 continuous' first");
    if (w[0] == "couplings") {
      if (out.couplings) return at(line, "a second couplings line");
      if (auto e = check_couplings_line(inst, w)) return at(line, *e);
      out.couplings = true;
      return std::nullopt;
    }
    if (w[0] != "r") return at(line, "unknown line kind '" + std::string(w[0]) + "'");
    if (!out.couplings) return at(line, "an r line before the couplings line");
    return pair_line(inst, regions, w, line, out);
  };
  if (auto e = for_each_certificate_line(text, one)) return e;
  if (!out.header) return std::string("no 'p ") + kHeader + " 1 continuous' line";
  if (!out.couplings) return std::string("no 'couplings COUNT DIGEST' line");
  return std::nullopt;
}

// Some single form of the pair is <= 0 over the whole cube.
bool one_form_rules_out(const std::vector<CouplingForm>& forms) {
  for (const CouplingForm& f : forms) {
    i128 m = f.base;
    for (auto [q, c] : f.terms)
      if (c > 0) m += c;
    if (m <= 0) return true;
  }
  return false;
}

// Every r line: its multipliers rule its pair out over the whole cube.
bool check_lines(const CertifyGeometry& geo, const CollideText& c, CertifyResult& r) {
  for (const auto& [key, p] : c.pairs) {
    const std::optional<i128> m = max_over_cube(geo.region_forms(p.a, p.b), p.lambda);
    if (!m) return r.reason = at(p.line, "overflow in the combination of the forms"), false;
    if (*m > 0)
      return r.reason = at(p.line,
                           "the combination of the forms is positive somewhere in the cube: it rules "
                           "nothing out"),
             false;
    ++r.inequalities;
  }
  return true;
}

// A pair with no r line: kept apart by the path bounds or by one form
// alone, or the reason it is not covered.
std::optional<std::string> uncovered(const Instance& inst, const CertifyGeometry& geo, const PathBounds& bounds,
                                     uint32_t a, uint32_t b) {
  if (bounds.apart(a, b) || one_form_rules_out(geo.region_forms(a, b))) return std::nullopt;
  return region_label(inst, geo.regions(), a) + " and " + region_label(inst, geo.regions(), b) +
         " have no r line, and no single form rules them out";
}

// Every pair of regions: a line, or apart by bounds or one form.
void check_every_pair(const Instance& inst, const CertifyGeometry& geo, const CollideText& c, CertifyResult& r) {
  // Pairs whose face bounds overlap in x, by a sweep in order of the
  // lowest left face: a later b whose left face is never left of a's
  // right face keeps them apart on its own (A.xhi - B.xlo <= 0 everywhere).
  const Regions& regions = geo.regions();
  const std::vector<CertifyGeometry::RegionBox> box = geo.region_boxes(geo.displacement_ranges());
  const PathBounds bounds(geo);
  std::vector<uint32_t> order(regions.size());
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::ranges::sort(order, [&](uint32_t p, uint32_t q) { return box[p].lo[0] < box[q].lo[0]; });
  for (size_t i = 0; i < order.size(); ++i)
    for (size_t j = i + 1; j < order.size() && box[order[j]].lo[0] < box[order[i]].hi[1]; ++j) {
      const uint32_t a = std::min(order[i], order[j]), b = std::max(order[i], order[j]);
      if (c.pairs.count({a, b}) || box[a].hi[3] <= box[b].lo[2] || box[b].hi[3] <= box[a].lo[2]) continue;
      if (auto e = uncovered(inst, geo, bounds, a, b)) return void(r.reason = *e);
    }
  r.lemmas = regions.size() * (regions.size() - 1) / 2 - c.pairs.size();
  r.proved = true;
}

// The one-axis kind: every operation along one axis, and every pair of
// every row group covered.
void check_row_groups(const Instance& inst, const CertifyGeometry& geo, const CollideText& c, CertifyResult& r) {
  const std::optional<int> axis = inst.moving_axis();
  if (!axis) return void(r.reason = at(c.header_line, "one-axis, but the operations move along both x and y"));
  const PathBounds bounds(geo);
  const std::vector<std::pair<uint32_t, uint32_t>> pairs = row_group_pairs_of(geo.regions(), *axis);
  for (auto [x, y] : pairs) {
    const uint32_t a = std::min(x, y), b = std::max(x, y);
    if (c.pairs.count({a, b})) continue;
    if (auto e = uncovered(inst, geo, bounds, a, b)) return void(r.reason = *e + " (a pair of one row group)");
    ++r.lemmas;
  }
  r.axioms = pairs.size();
  r.one_axis = true;
  r.proved = true;
}

// The kept-order kind: one coupling, the faces of the named axis keep
// their order, and every pair of certify's own sweep covered.
void check_kept_order(const Instance& inst, const CertifyGeometry& geo, const CollideText& c, CertifyResult& r) {
  const char* name = c.kept_axis == 0 ? "x" : c.kept_axis == 1 ? "y" : c.kept_axis == 2 ? "separated" : "slabs";
  if (inst.couplings().size() != 1)
    return void(r.reason = at(c.header_line, "kept-order, but the instance has " +
                                                 std::to_string(inst.couplings().size()) +
                                                 " couplings (the kind needs exactly one)"));
  std::vector<std::pair<uint32_t, uint32_t>> pairs;
  if (auto e = kept_order_pairs_of(inst, geo, c.kept_axis, pairs))
    return void(r.reason = at(c.header_line, std::string("kept-order ") + name + ", but " + *e));
  const PathBounds bounds(geo);
  for (auto [a, b] : pairs) {
    if (c.pairs.count({a, b})) continue;
    if (auto e = uncovered(inst, geo, bounds, a, b)) return void(r.reason = *e + " (a pair of the kept-order sweep)");
    ++r.lemmas;
  }
  r.axioms = pairs.size();
  r.kept_axis = c.kept_axis;
  r.proved = true;
}

// A face with one coupling: a + b p at progress p (b: the coupling's net
// along the face's axis, plus a growth's progress).
struct FaceLine {
  int64_t a = 0, b = 0;
};

// Is a + b p > 0 and c + d p > 0 at some common p in (0, 1)? Each holds
// on an open interval of (0, 1); they meet iff the larger start is below
// the smaller end (fractions compared exactly).
bool both_positive_somewhere(const FaceLine& w, const FaceLine& v) {
  struct End {
    i128 num, den;  // num / den, den > 0
  };
  End lo{0, 1}, hi{1, 1};
  auto less = [](const End& x, const End& y) { return x.num * y.den < y.num * x.den; };
  for (const FaceLine& f : {w, v}) {
    if (f.b == 0) {
      if (f.a <= 0) return false;
    } else if (f.b > 0) {  // p > -a / b
      const End e{-f.a, f.b};
      if (less(lo, e)) lo = e;
    } else {  // p < a / -b
      const End e{f.a, -f.b};
      if (less(e, hi)) hi = e;
    }
  }
  return less(lo, hi);
}

using FaceLines = std::array<FaceLine, 4>;  // xlo, xhi, ylo, yhi

// Every region's faces while the one coupling runs: the tree
// displacements of its operations (lattice/motion's op_child_vector), all
// done at progress 1, plus a growth's progress on its far face.
std::vector<FaceLines> one_coupling_faces(const Instance& inst, const CertifyGeometry& geo) {
  const Regions& regions = geo.regions();
  const SpanningTree& tree = geo.tree();
  std::vector<Vec2> disp(inst.num_nodes(), Vec2{0, 0});
  for (NodeId w : tree.order)
    if (tree.parent[w] != kNone) disp[w] = disp[tree.parent[w]] + op_child_vector(inst, tree, w);
  std::vector<FaceLines> face(regions.size());
  for (uint32_t r = 0; r < regions.size(); ++r) {
    const RegionShape& sh = regions.shapes[r];
    for (size_t f = 0; f < 4; ++f) {
      const Vec2 d = disp[sh.ref[f]];
      const int64_t grow = sh.grow_op != kNone && sh.grow_face == static_cast<int>(f) ? sh.grow_sign : 0;
      face[r][f] = {sh.base[f], (f < 2 ? d.x : d.y) + grow};
    }
  }
  return face;
}

FaceLine width_of(const FaceLines& f, size_t axis) {
  const FaceLine &lo = f[2 * axis], &hi = f[2 * axis + 1];
  return FaceLine{hi.a - lo.a, hi.b - lo.b};
}

// Do the faces of axis s of `members` keep their order? Sorted by the
// order just after 0, their values at 1 never decrease. Else two of the
// members whose faces change order.
std::optional<std::pair<uint32_t, uint32_t>> order_break(const std::vector<FaceLines>& face,
                                                         const std::vector<uint32_t>& members, size_t s) {
  struct Ordered {
    FaceLine f;
    uint32_t r;
  };
  std::vector<Ordered> ends;
  for (uint32_t r : members) ends.push_back({face[r][2 * s], r}), ends.push_back({face[r][2 * s + 1], r});
  std::ranges::sort(
      ends, [](const Ordered& x, const Ordered& y) { return std::pair(x.f.a, x.f.b) < std::pair(y.f.a, y.f.b); });
  for (size_t i = 0; i + 1 < ends.size(); ++i)
    if (ends[i + 1].f.a + ends[i + 1].f.b < ends[i].f.a + ends[i].f.b) return std::pair(ends[i].r, ends[i + 1].r);
  return std::nullopt;
}

// The faces of axis s of the live regions keep their order. Else the
// reason, naming two regions whose faces change order.
std::optional<std::string> order_changes(const Instance& inst, const Regions& regions,
                                         const std::vector<FaceLines>& face, const std::vector<uint32_t>& live,
                                         size_t s) {
  const auto broken = order_break(face, live, s);
  if (!broken) return std::nullopt;
  return std::string("the ") + (s == 0 ? "x" : "y") + " faces of " + region_label(inst, regions, broken->first) +
         " and " + region_label(inst, regions, broken->second) + " change order";
}

// The sweep along s at progress 1/2 (doubled: 2a + b), the regions on the
// sweep line kept by their low face across s at 1/2; each entering region
// is paired with its two neighbours there.
std::vector<std::pair<uint32_t, uint32_t>> sweep_pairs(const std::vector<FaceLines>& face,
                                                       const std::vector<uint32_t>& live, size_t s) {
  const size_t m = 1 - s;
  struct Event {
    int64_t x;
    int kind;  // 0 leaves, before 1 enters at one coordinate
    uint32_t r;
  };
  auto half = [](const FaceLine& f) { return 2 * f.a + f.b; };
  std::vector<Event> events;
  for (uint32_t r : live)
    events.push_back({half(face[r][2 * s + 1]), 0, r}), events.push_back({half(face[r][2 * s]), 1, r});
  std::ranges::sort(events, [](const Event& x, const Event& y) {
    return std::tuple(x.x, x.kind, x.r) < std::tuple(y.x, y.kind, y.r);
  });
  std::vector<std::pair<uint32_t, uint32_t>> out;
  std::map<int64_t, uint32_t> line;
  for (const Event& e : events) {
    const int64_t k = half(face[e.r][2 * m]);
    if (e.kind == 0) {
      if (auto it = line.find(k); it != line.end() && it->second == e.r) line.erase(it);
      continue;
    }
    const auto next = line.lower_bound(k);
    if (next != line.end()) out.emplace_back(std::min(e.r, next->second), std::max(e.r, next->second));
    if (next != line.begin()) {
      const uint32_t p = std::prev(next)->second;
      out.emplace_back(std::min(e.r, p), std::max(e.r, p));
    }
    line.emplace_hint(next, k, e.r);  // an equal key overlaps its neighbour at 1/2: that pair cannot be covered
  }
  return out;
}

// An affine width positive on all of (0, 1): >= 0 at both ends, not 0 at both.
bool positive_all_along(const FaceLine& w) { return w.a >= 0 && w.a + w.b >= 0 && (w.a != 0 || w.a + w.b != 0); }

// The axis a piece is a group along: its x (else y) faces keep their
// order and its widths across that axis stay positive all along; 2 when
// it is not a group.
size_t group_axis(const std::vector<FaceLines>& face, const std::vector<uint32_t>& members) {
  size_t s = 2;
  for (size_t axis : {size_t{0}, size_t{1}})
    if (s == 2 && !order_break(face, members, axis)) s = axis;
  if (s == 2 || !std::ranges::all_of(members, [&](uint32_t r) { return positive_all_along(width_of(face[r], 1 - s)); }))
    return 2;
  return s;
}

// A direction of a cut, (dx, dy): a region's extent along it is the
// interval of dx x + dy y over its rectangle, each end a sum of faces
// times integers, so linear in the progress.
struct CutDir {
  int64_t dx = 1, dy = 0;
};
std::array<FaceLine, 2> extent_along(const FaceLines& f, CutDir d) {
  const auto scaled = [](int64_t c, const FaceLine& u) { return FaceLine{c * u.a, c * u.b}; };
  const auto plus = [](const FaceLine& u, const FaceLine& v) { return FaceLine{u.a + v.a, u.b + v.b}; };
  const size_t xl = d.dx >= 0 ? 0 : 1, yl = d.dy >= 0 ? 2 : 3;
  return {plus(scaled(d.dx, f[xl]), scaled(d.dy, f[yl])), plus(scaled(d.dx, f[1 - xl]), scaled(d.dy, f[5 - yl]))};
}

// (x, y) divided by their gcd, its first non-zero coordinate made positive.
std::pair<int64_t, int64_t> reduced(int64_t x, int64_t y) {
  const int64_t g = std::gcd(x, y);
  x /= g, y /= g;
  if (x < 0 || (x == 0 && y < 0)) return {-x, -y};
  return {x, y};
}

// The most frequent of a non-empty list, the least on ties.
std::pair<int64_t, int64_t> most_frequent(std::vector<std::pair<int64_t, int64_t>> list) {
  std::ranges::sort(list);
  std::pair<int64_t, int64_t> best = list.front();
  size_t best_count = 0;
  for (size_t i = 0; i < list.size();) {
    size_t j = i;
    while (j < list.size() && list[j] == list[i]) ++j;
    if (j - i > best_count) best = list[i], best_count = j - i;
    i = j;
  }
  return best;
}

// The cut directions tried, in order: x, y, x + y, x - y, then the one
// from the motion of `members`: with v a region's velocity (its low x and
// low y faces' speeds) and m the most frequent v, u the most frequent of
// reduced(v - m) over the regions with v != m; the direction is
// reduced(u_y, -u_x) when it differs from the four and neither
// coordinate exceeds 64 in size.
std::vector<CutDir> cut_directions(const std::vector<FaceLines>& face, const std::vector<uint32_t>& members) {
  std::vector<CutDir> dirs{{1, 0}, {0, 1}, {1, 1}, {1, -1}};
  if (members.empty()) return dirs;
  std::vector<std::pair<int64_t, int64_t>> v, u;
  for (uint32_t r : members) v.emplace_back(face[r][0].b, face[r][2].b);
  const std::pair<int64_t, int64_t> m = most_frequent(v);
  for (const auto& w : v)
    if (w != m) u.push_back(reduced(w.first - m.first, w.second - m.second));
  if (u.empty()) return dirs;
  const std::pair<int64_t, int64_t> w = most_frequent(u);
  const auto [dx, dy] = reduced(w.second, -w.first);
  if (std::abs(dx) > 64 || std::abs(dy) > 64) return dirs;
  for (const CutDir& f : dirs)
    if (f.dx == dx && f.dy == dy) return dirs;
  dirs.push_back({dx, dy});
  return dirs;
}

// The pieces of `members` cut along direction d: sorted by (low end at
// 0, high end at 0, region), a cut falls after position i when the
// greatest high end of the regions up to i is at most the least low end
// of the rest, at progress 0 and at 1. Then every region before the cut
// lies at or below every region after it along d at 0 and at 1, so (ends
// linear in the progress) all along: their projections share no inner
// point, and no pair across a cut ever overlaps.
std::vector<std::vector<uint32_t>> cut_along(const std::vector<FaceLines>& face, const std::vector<uint32_t>& members,
                                             CutDir d) {
  std::vector<std::pair<std::array<FaceLine, 2>, uint32_t>> ext;
  ext.reserve(members.size());
  for (uint32_t r : members) ext.emplace_back(extent_along(face[r], d), r);
  std::ranges::sort(ext, [](const auto& x, const auto& y) {
    return std::tuple(x.first[0].a, x.first[1].a, x.second) < std::tuple(y.first[0].a, y.first[1].a, y.second);
  });
  const size_t k = ext.size();
  // rest[i]: the least low end at 0 and at 1 of members i, i + 1, ...
  std::vector<std::pair<int64_t, int64_t>> rest(k + 1, {INT64_MAX, INT64_MAX});
  for (size_t i = k; i-- > 0;) {
    const FaceLine& f = ext[i].first[0];
    rest[i] = {std::min(rest[i + 1].first, f.a), std::min(rest[i + 1].second, f.a + f.b)};
  }
  std::vector<std::vector<uint32_t>> pieces(1);
  int64_t hi0 = INT64_MIN, hi1 = INT64_MIN;  // the greatest high end at 0 and at 1 so far
  for (size_t i = 0; i < k; ++i) {
    const FaceLine& f = ext[i].first[1];
    hi0 = std::max(hi0, f.a), hi1 = std::max(hi1, f.a + f.b);
    pieces.back().push_back(ext[i].second);
    if (i + 1 < k && hi0 <= rest[i + 1].first && hi1 <= rest[i + 1].second) pieces.emplace_back();
  }
  return pieces;
}

// Why a piece is refused when first_cut finds nothing (cut_directions
// names the directions).
constexpr const char* kNoCut =
    "keeps neither order and no cut along x, y, x + y, x - y or across its motion separates it";

// The pieces of the direction (cut_directions, in order) whose cut
// leaves the smallest largest piece, the first such on ties, or none when
// no direction has a cut.
std::vector<std::vector<uint32_t>> first_cut(const std::vector<FaceLines>& face, const std::vector<uint32_t>& members) {
  std::vector<std::vector<uint32_t>> best;
  size_t best_largest = members.size();
  for (const CutDir& d : cut_directions(face, members)) {
    std::vector<std::vector<uint32_t>> pieces = cut_along(face, members, d);
    size_t largest = 0;
    for (const auto& piece : pieces) largest = std::max(largest, piece.size());
    if (pieces.size() > 1 && largest < best_largest) best = std::move(pieces), best_largest = largest;
  }
  return best;
}

// The separated kind: the live regions cut (first_cut,
// recursively, at most 64 levels) until every piece keeps the order of
// one axis (x first) with its widths across it positive all along; the
// pairs of each piece's sweep. Else the reason.
std::optional<std::string> separated_pairs(const Instance& inst, const Regions& regions,
                                           const std::vector<FaceLines>& face, std::vector<uint32_t> live,
                                           std::vector<std::pair<uint32_t, uint32_t>>& out) {
  std::vector<std::pair<std::vector<uint32_t>, int>> todo{{std::move(live), 0}};
  while (!todo.empty()) {
    auto [members, depth] = std::move(todo.back());
    todo.pop_back();
    if (const size_t s = group_axis(face, members); s != 2) {
      std::vector<std::pair<uint32_t, uint32_t>> pairs = sweep_pairs(face, members, s);
      out.insert(out.end(), pairs.begin(), pairs.end());
      continue;
    }
    auto group = [&, &piece = members] {  // named only when refused (a binding is captured by name)
      return "the group of " + std::to_string(piece.size()) + " regions with " +
             region_label(inst, regions, piece.front());
    };
    if (depth >= 64) return group() + " is cut more than 64 levels deep";
    std::vector<std::vector<uint32_t>> pieces = first_cut(face, members);
    if (pieces.empty()) return group() + " " + kNoCut;
    for (auto& p : pieces) todo.emplace_back(std::move(p), depth + 1);
  }
  return std::nullopt;
}

// The slabs kind: pieces over dyadic slabs of progress [m / 2^e,
// (m + 1) / 2^e], e <= 12, each with its faces rescaled to the slab
// (2^e a + m b, b: positions times 2^e over s in [0, 1]; overlaps are the
// same at matching moments). From the live regions over [0, 1], a piece
// first drops the regions with no common moment of positive widths inside
// its slab and is done with fewer than two; then it is a group when its x
// (else y) faces keep their order with its widths across that axis
// positive all along (its sweep's pairs); else cut (first_cut; not
// past 64 levels of cuts); else, with at most 8 regions, all its pairs;
// else its slab's two halves. Refused past 2^-12, past 32 (r + 1) members
// placed (summed over the pieces before the drop), or with a face beyond
// 2^40. Pairs as (smaller, larger), duplicates possible.
std::optional<std::string> slab_pairs(const std::vector<FaceLines>& face, const std::vector<uint32_t>& live,
                                      std::vector<std::pair<uint32_t, uint32_t>>& out) {
  constexpr int64_t kBig = int64_t{1} << 40;
  for (uint32_t r : live)
    for (const FaceLine& f : face[r])
      if (f.a > kBig || f.a < -kBig || f.b > kBig || f.b < -kBig)
        return std::string("a face's position or speed exceeds 2^40");
  struct Piece {
    std::vector<uint32_t> members;
    int64_t m = 0;
    int e = 0, depth = 0;
  };
  std::vector<Piece> todo{{live, 0, 0, 0}};
  const uint64_t budget = 32 * (live.size() + 1);
  uint64_t placed = 0;
  auto pair = [&](uint32_t x, uint32_t y) { out.emplace_back(std::min(x, y), std::max(x, y)); };
  while (!todo.empty()) {
    Piece p = std::move(todo.back());
    todo.pop_back();
    placed += p.members.size();
    if (placed > budget) return "the slabs place more than 32 (r + 1) = " + std::to_string(budget) + " regions";
    std::vector<uint32_t> members;  // global ids; local id i is members[i]
    std::vector<FaceLines> local;
    for (uint32_t r : p.members) {
      FaceLines g;
      for (size_t f = 0; f < 4; ++f) g[f] = {face[r][f].a * (int64_t{1} << p.e) + face[r][f].b * p.m, face[r][f].b};
      if (!both_positive_somewhere(width_of(g, 0), width_of(g, 1))) continue;
      members.push_back(r);
      local.push_back(g);
    }
    if (members.size() < 2) continue;
    std::vector<uint32_t> ids(members.size());
    for (uint32_t i = 0; i < ids.size(); ++i) ids[i] = i;
    if (const size_t s = group_axis(local, ids); s != 2) {
      for (auto [x, y] : sweep_pairs(local, ids, s)) pair(members[x], members[y]);
      continue;
    }
    if (p.depth < 64) {
      const std::vector<std::vector<uint32_t>> pieces = first_cut(local, ids);
      for (const std::vector<uint32_t>& q : pieces) {
        Piece next{{}, p.m, p.e, p.depth + 1};
        for (uint32_t i : q) next.members.push_back(members[i]);
        todo.push_back(std::move(next));
      }
      if (!pieces.empty()) continue;
    }
    if (members.size() <= 8) {
      for (size_t i = 0; i < members.size(); ++i)
        for (size_t j = i + 1; j < members.size(); ++j) pair(members[i], members[j]);
      continue;
    }
    if (p.e >= 12)
      return "a piece of " + std::to_string(members.size()) + " regions over the slab [" + std::to_string(p.m) +
             "/4096, " + std::to_string(p.m + 1) + "/4096] " + kNoCut;
    todo.push_back({members, 2 * p.m + 1, p.e + 1, p.depth});
    todo.push_back({std::move(members), 2 * p.m, p.e + 1, p.depth});
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> kept_order_pairs_of(const Instance& inst, const CertifyGeometry& geo, int axis,
                                               std::vector<std::pair<uint32_t, uint32_t>>& out) {
  const std::vector<FaceLines> face = one_coupling_faces(inst, geo);
  // Live: both widths positive at some common moment of (0, 1); no other
  // region ever overlaps anything.
  std::vector<uint32_t> live;
  for (uint32_t r = 0; r < face.size(); ++r)
    if (both_positive_somewhere(width_of(face[r], 0), width_of(face[r], 1))) live.push_back(r);
  if (axis == 2) return separated_pairs(inst, geo.regions(), face, std::move(live), out);
  if (axis == 3) {
    if (auto e = slab_pairs(face, live, out)) return e;
    std::ranges::sort(out);  // a pair met in several slabs is checked once
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return std::nullopt;
  }
  const size_t s = axis == 0 ? 0 : 1, m = 1 - s;
  if (auto e = order_changes(inst, geo.regions(), face, live, s)) return e;
  // Across s every live width must stay positive on (0, 1).
  for (uint32_t r : live)
    if (!positive_all_along(width_of(face[r], m)))
      return region_label(inst, geo.regions(), r) + "'s width across the kept axis is not positive all along";
  out = sweep_pairs(face, live, s);
  return std::nullopt;
}

std::vector<std::pair<uint32_t, uint32_t>> row_group_pairs_of(const Regions& regions, int axis) {
  const int m = 2 * axis, across = 2 - m;  // faces m, m + 1 move; face `across` names the row
  // A unit: a node whose two faces along the axis follow the same node
  // (every node but a contracting v): its width is 1 at every moment.
  auto unit = [&](uint32_t i) {
    const RegionShape& s = regions.shapes[i];
    return s.kind == RegionKind::Node && s.ref[m] == s.ref[m + 1];
  };
  // By row, then by (lo, hi) at the start: a width-0 region at x lands
  // after one ending at x and before one starting at x.
  std::vector<std::array<int64_t, 4>> keys(regions.size());
  for (uint32_t i = 0; i < keys.size(); ++i) {
    const RegionShape& s = regions.shapes[i];
    keys[i] = {s.base[across], s.base[m], s.base[m + 1], static_cast<int64_t>(i)};
  }
  std::ranges::sort(keys);
  std::vector<std::pair<uint32_t, uint32_t>> out;
  // Each maximal stretch of one row from a unit (or the row's start) to
  // the next unit (or the row's end), both ends included, is a group.
  auto emit = [&](size_t from, size_t to) {  // keys[from .. to)
    for (size_t i = from; i < to; ++i)
      for (size_t j = i + 1; j < to; ++j)
        out.emplace_back(static_cast<uint32_t>(keys[i][3]), static_cast<uint32_t>(keys[j][3]));
  };
  size_t start = 0;
  for (size_t i = 0; i < keys.size(); ++i) {
    const bool row_ends = i + 1 == keys.size() || keys[i + 1][0] != keys[i][0];
    if (unit(static_cast<uint32_t>(keys[i][3])) && i > start) emit(start, i + 1), start = i;
    if (row_ends) emit(start, i + 1), start = i + 1;
  }
  return out;
}

bool is_collide_certificate(std::string_view text) {
  bool collide = false;
  for_each_certificate_line(text, [&](size_t, const std::vector<std::string_view>& w) -> std::optional<std::string> {
    if (w[0] != "p") return std::nullopt;
    collide = w.size() >= 2 && w[1] == kHeader;
    return "";  // the first p line decides
  });
  return collide;
}

void check_collide_proof(const Instance& inst, std::string_view text, CertifyResult& r) {
  r.kind = "collide";
  const CertifyGeometry geo(inst);
  CollideText c;
  if (auto e = read_collide_text(inst, geo.regions(), text, c)) return void(r.reason = *e);
  if (auto e = geo.cycle_breaker()) return void(r.reason = *e);
  if (!check_lines(geo, c, r)) return;
  if (c.one_axis) check_row_groups(inst, geo, c, r);
  else if (c.kept_axis >= 0) check_kept_order(inst, geo, c, r);
  else check_every_pair(inst, geo, c, r);
}

}  // namespace gridlock
