#include "collide/single_coupling.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <iterator>
#include <map>
#include <numeric>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

#include "collide/internal/row_groups.hpp"
#include "collide/internal/strip_pairs.hpp"
#include "common/int_math.hpp"

namespace gridlock {

namespace {

// a + b t.
struct Lin {
  int64_t a = 0, b = 0;
};
// A region's faces xlo, xhi, ylo, yhi as functions of t.
using Faces = std::array<Lin, 4>;

// num / den, den > 0.
struct Frac {
  int64_t num = 0, den = 1;
};
bool less(const Frac& x, const Frac& y) {
  return static_cast<__int128>(x.num) * y.den < static_cast<__int128>(y.num) * x.den;
}

// An open time interval (lo, hi) inside (0, 1); empty when lo >= hi.
struct Span {
  Frac lo{0, 1}, hi{1, 1};
  bool empty() const { return !less(lo, hi); }
  // Keeps the t with a + b t > 0.
  void cut(int64_t a, int64_t b) {
    if (b == 0) {
      if (a <= 0) hi = lo;
    } else if (b > 0) {  // t > -a / b
      const Frac c{-a, b};
      if (less(lo, c)) lo = c;
    } else {  // t < a / -b
      const Frac c{a, -b};
      if (less(c, hi)) hi = c;
    }
  }
};

// The times in (0, 1) at which both of r's widths are positive.
Span alive(const Faces& r) {
  Span s;
  s.cut(r[1].a - r[0].a, r[1].b - r[0].b);
  s.cut(r[3].a - r[2].a, r[3].b - r[2].b);
  return s;
}

// A region's motion: 1 + its largest x face speed + its largest y face
// speed (the cell sweep's items for it, up to a constant).
uint64_t region_motion(const Faces& f) {
  const auto speed = [&](size_t lo) {
    return static_cast<uint64_t>(std::max(std::abs(f[lo].b), std::abs(f[lo + 1].b)));
  };
  return 1 + speed(0) + speed(2);
}

// The times in (0, 1) at which A and B overlap with positive area: eight
// strict linear inequalities (four overlaps, four widths), an open interval
// (empty when they never overlap). An overlap at t = 1 is one just before
// it too (strict inequalities hold on a neighbourhood), so the open
// interval loses nothing.
Span overlap_span(const Faces& A, const Faces& B) {
  Span s = alive(A);
  const Span b = alive(B);
  if (s.empty()) return s;
  if (b.empty()) return b;
  if (less(s.lo, b.lo)) s.lo = b.lo;
  if (less(b.hi, s.hi)) s.hi = b.hi;
  for (size_t lo = 0; lo < 4; lo += 2) {
    const Lin &alo = A[lo], &ahi = A[lo + 1], &blo = B[lo], &bhi = B[lo + 1];
    s.cut(ahi.a - blo.a, ahi.b - blo.b);
    s.cut(bhi.a - alo.a, bhi.b - alo.b);
  }
  return s;
}

// The value of f at time q, floored / ceiled.
int64_t floor_at(const Lin& f, const Frac& q) {
  const __int128 num = static_cast<__int128>(f.a) * q.den + static_cast<__int128>(f.b) * q.num;
  return static_cast<int64_t>(floor_div<__int128>(num, q.den));
}
int64_t ceil_at(const Lin& f, const Frac& q) {
  const __int128 num = static_cast<__int128>(f.a) * q.den + static_cast<__int128>(f.b) * q.num;
  return static_cast<int64_t>(ceil_div<__int128>(num, q.den));
}

// Every region's faces over t in [0, 1], all operations running, in the
// frame moving with the coordinatewise median of the nodes' displacements.
std::vector<Faces> region_faces(const Instance& inst, const SpanningTree& t, const Regions& regions) {
  const size_t n = inst.num_nodes();
  std::vector<Vec2> disp(n, Vec2{0, 0});
  for (NodeId w : t.order)
    if (t.parent[w] != kNone) disp[w] = disp[t.parent[w]] + op_child_vector(inst, t, w);
  Vec2 frame{0, 0};
  if (n > 0) {
    std::vector<int64_t> xs(n), ys(n);
    for (size_t i = 0; i < n; ++i) xs[i] = disp[i].x, ys[i] = disp[i].y;
    std::nth_element(xs.begin(), xs.begin() + static_cast<std::ptrdiff_t>(n / 2), xs.end());
    std::nth_element(ys.begin(), ys.begin() + static_cast<std::ptrdiff_t>(n / 2), ys.end());
    frame = Vec2{xs[n / 2], ys[n / 2]};
  }
  std::vector<Faces> out(regions.size());
  for (size_t r = 0; r < regions.size(); ++r) {
    const RegionShape& sh = regions.shapes[r];
    for (int f = 0; f < 4; ++f) {
      const Vec2 v = disp[sh.ref[f]] - frame;
      out[r][f] = Lin{sh.base[f], f < 2 ? v.x : v.y};
      if (sh.grow_op != kNone && f == sh.grow_face) out[r][f].b += sh.grow_sign;
    }
  }
  return out;
}

struct Item {
  uint64_t cell = 0;
  Frac lo, hi;
  uint32_t region = 0;
};

// Cells are keyed relative to an origin below every region's sweep, so a
// key needs 32 bits per axis only for the extent of the motion (O(n) for a
// connected shape), not for the coordinates themselves.
struct CellKeys {
  int64_t x0 = 0, y0 = 0;
  uint64_t key(int64_t x, int64_t y) const {
    const int64_t dx = x - x0, dy = y - y0;
    if (dx < 0 || dy < 0 || dx > UINT32_MAX || dy > UINT32_MAX)
      throw std::overflow_error("single_coupling_sweep: the motion spans more than 2^32 cells");
    return (static_cast<uint64_t>(dx) << 32) | static_cast<uint64_t>(dy);
  }
};

// The columns a region's sweep can meet over [0, 1]: [first, last).
int64_t first_column(const Faces& f) { return std::min(f[0].a, f[0].a + f[0].b); }
int64_t last_column(const Faces& f) { return std::max(f[1].a, f[1].a + f[1].b); }

// The least row a region's sweep can meet over [0, 1] (ylo's smaller end).
int64_t first_row(const Faces& f) { return std::min(f[2].a, f[2].a + f[2].b); }

// The origin: the least x and y any region reaches over [0, 1].
CellKeys cell_keys(const std::vector<Faces>& faces) {
  CellKeys k;
  bool first = true;
  for (const Faces& f : faces) {
    const int64_t x = first_column(f), y = first_row(f);
    if (first || x < k.x0) k.x0 = x;
    if (first || y < k.y0) k.y0 = y;
    first = false;
  }
  k.y0 -= 1;  // rows start at the floor of ylo, which may lie one below at an interval end
  k.x0 -= 1;
  return k;
}

// Visits r's items in columns [c0, c1) (absolute x): for each column the
// region meets, the time span it does; for each row it meets during that
// span, the common span. Columns: at most 1 + |speed of xlo| + |speed of
// xhi|; rows of one column: at most 3 + the y extent swept during its span,
// and the spans of the columns cover each t at most twice (a region is at
// most one cell wide), so at most 3 + 6 speed_x + 4 speed_y cells are
// visited (docs/collide.md).
template <typename Sink>
void each_item(const Faces& f, int64_t c0, int64_t c1, Sink&& sink) {
  const Span life = alive(f);
  if (life.empty()) return;
  const int64_t x0 = std::max(c0, first_column(f)), x1 = std::min(c1, last_column(f));
  for (int64_t i = x0; i < x1; ++i) {
    Span sx = life;
    sx.cut(i + 1 - f[0].a, -f[0].b);  // xlo < i + 1
    sx.cut(f[1].a - i, f[1].b);       // xhi > i
    if (sx.empty()) continue;
    const int64_t y0 = std::min(floor_at(f[2], sx.lo), floor_at(f[2], sx.hi));
    const int64_t y1 = std::max(ceil_at(f[3], sx.lo), ceil_at(f[3], sx.hi));
    for (int64_t j = y0; j < y1; ++j) {
      Span s = sx;
      s.cut(j + 1 - f[2].a, -f[2].b);  // ylo < j + 1
      s.cut(f[3].a - j, f[3].b);       // yhi > j
      if (!s.empty()) sink(i, j, s);
    }
  }
}

// Bands of whole columns, each with at most `band_items` items (or one
// column), so that the items in memory at once are bounded by the band,
// not by the total motion. Band b is columns [cuts[b], cuts[b + 1]).
// Costs one counting pass over the items (O(mu) time, O(columns) memory).
std::vector<int64_t> column_bands(const std::vector<Faces>& faces, const CellKeys& keys, uint64_t band_items,
                                  const Deadline* deadline) {
  int64_t hi = keys.x0;
  for (const Faces& f : faces)
    if (!alive(f).empty()) hi = std::max(hi, last_column(f));
  if (hi - keys.x0 > UINT32_MAX)
    throw std::overflow_error("single_coupling_sweep: the motion spans more than 2^32 cells");
  std::vector<uint64_t> per_column(static_cast<size_t>(hi - keys.x0) + 1, 0);
  for (size_t r = 0; r < faces.size(); ++r) {
    if (deadline && r % 4096 == 4095) deadline->check();
    each_item(faces[r], keys.x0, hi,
              [&](int64_t i, int64_t, const Span&) { ++per_column[static_cast<size_t>(i - keys.x0)]; });
  }
  std::vector<int64_t> cuts{keys.x0};
  uint64_t in_band = 0;
  for (size_t c = 0; c < per_column.size(); ++c) {
    if (in_band > 0 && in_band + per_column[c] > band_items) {
      cuts.push_back(keys.x0 + static_cast<int64_t>(c));
      in_band = 0;
    }
    in_band += per_column[c];
  }
  cuts.push_back(hi + 1);
  return cuts;
}

// More items present in one cell at one moment than this prove a
// collision (docs/collide.md, "One coupling", the packing lemma): in a
// configuration without overlaps at most 18 regions at least 1/2 wide and
// 25 thinner ones meet one open unit cell.
constexpr size_t kPackingBound = 43;

// The earliest overlap found so far: its pair and its overlap span
// (lo: the time the pair starts to overlap). Earlier means a smaller lo,
// then a smaller pair, as the simulator orders its first collision.
struct Earliest {
  bool found = false;
  RegionPair pair;
  Span span;
  // Does an item starting at `start` start after the earliest overlap (so
  // that it can no longer matter)?
  bool passed(const Frac& start) const { return found && less(span.lo, start); }
  // The exact test on regions x and y; their overlap is kept if earlier.
  void test(const std::vector<Faces>& faces, uint32_t x, uint32_t y) { keep(x, y, overlap_span(faces[x], faces[y])); }
  // x and y overlap during s (when not empty): kept if earlier, or as
  // early and a smaller pair.
  void keep(uint32_t x, uint32_t y, const Span& s) {
    if (s.empty()) return;
    const RegionPair p{std::min(x, y), std::max(x, y)};
    if (found && (less(span.lo, s.lo) || (!less(s.lo, span.lo) && std::pair(pair.a, pair.b) < std::pair(p.a, p.b))))
      return;
    *this = Earliest{true, p, s};
  }
};

// One cell's items [b, e), sorted by start: each entering item is tested
// against the items still present (open spans: present iff hi > lo of the
// entering one), and an overlap found earlier than `best` (Earliest's
// order) replaces it. Items that start after best's start are not
// entered: a pair starting to overlap at t* meets a common cell with items
// that both start at or before t* (docs/collide.md, "The sweep's first
// collision"). Returns false when more than kPackingBound items are
// present: a collision that the items do not name (best is then not
// necessarily the first).
bool sweep_cell(const std::vector<Item>& items, size_t b, size_t e, const std::vector<Faces>& faces,
                std::vector<uint32_t>& active, SingleCouplingStats& st, Earliest& best) {
  active.clear();
  for (size_t k = b; k < e; ++k) {
    const Item& x = items[k];
    if (best.passed(x.lo)) break;  // starts are sorted: the rest start later too
    size_t keep = 0;
    for (uint32_t y : active)
      if (less(x.lo, items[y].hi)) active[keep++] = y;
    active.resize(keep);
    st.max_active = std::max<uint64_t>(st.max_active, keep);
    if (keep > kPackingBound) return false;
    for (uint32_t y : active) {
      ++st.tests;
      best.test(faces, x.region, items[y].region);
    }
    active.push_back(static_cast<uint32_t>(k));
  }
  return true;
}

// The answer naming `best` as the first collision: `first` its start,
// `during` the middle of its overlap.
SingleCouplingAnswer named(const Earliest& best) {
  SingleCouplingAnswer ans;
  if (!best.found) return ans;
  ans.collides = true;
  ans.pair = best.pair;
  ans.first = Rational(best.span.lo.num, best.span.lo.den);
  ans.during = (*ans.first + Rational(best.span.hi.num, best.span.hi.den)) * Rational(1, 2);
  return ans;
}

}  // namespace

SingleCouplingAnswer single_coupling_sweep(const Instance& inst, const SpanningTree& t, const Regions& regions,
                                           SingleCouplingStats* stats, const Deadline* deadline, uint64_t band_items,
                                           const std::function<void(uint64_t, uint64_t)>& on_band) {
  SingleCouplingStats st;
  const std::vector<Faces> faces = region_faces(inst, t, regions);
  const CellKeys keys = cell_keys(faces);
  std::vector<uint32_t> live;  // regions of positive width at some t, by first column
  for (uint32_t r = 0; r < faces.size(); ++r) {
    const Faces& f = faces[r];
    if (alive(f).empty()) continue;
    live.push_back(r);
    st.motion += region_motion(f);
  }
  st.regions = live.size();
  std::stable_sort(live.begin(), live.end(),
                   [&](uint32_t x, uint32_t y) { return first_column(faces[x]) < first_column(faces[y]); });
  const std::vector<int64_t> cuts = column_bands(faces, keys, std::max<uint64_t>(band_items, 1), deadline);
  st.bands = cuts.size() - 1;
  // Bands left to right; cells are keyed by column first, so the cells are
  // swept in the same order as one global sort would (the same answer for
  // every band size).
  Earliest best;
  bool packed = false;  // the packing bound fired: a collision, not named
  std::vector<Item> items;
  std::vector<uint32_t> active, open;  // open: live regions whose columns reach the band
  size_t next = 0, cells = 0;
  for (size_t band = 0; band + 1 < cuts.size() && !packed; ++band) {
    if (on_band) on_band(band, st.bands);
    const int64_t c0 = cuts[band], c1 = cuts[band + 1];
    for (; next < live.size() && first_column(faces[live[next]]) < c1; ++next) open.push_back(live[next]);
    size_t keep = 0;
    for (uint32_t r : open)
      if (last_column(faces[r]) > c0) open[keep++] = r;
    open.resize(keep);
    items.clear();
    for (uint32_t r : open) {
      if (deadline && ++cells % 4096 == 0) deadline->check();
      each_item(faces[r], c0, c1, [&](int64_t i, int64_t j, const Span& s) {
        // An item that starts after the earliest overlap found in the
        // bands before would not enter (sweep_cell): not kept at all.
        if (!best.passed(s.lo)) items.push_back(Item{keys.key(i, j), s.lo, s.hi, r});
      });
    }
    if (items.size() >= UINT32_MAX) throw std::overflow_error("single_coupling_sweep: too many items in one column");
    st.items += items.size();
    st.peak_items = std::max<uint64_t>(st.peak_items, items.size());
    // A total order (a region has one item per cell), so the cells are
    // swept the same way whatever order the items were made in.
    std::sort(items.begin(), items.end(), [](const Item& x, const Item& y) {
      if (x.cell != y.cell) return x.cell < y.cell;
      if (less(x.lo, y.lo)) return true;
      if (less(y.lo, x.lo)) return false;
      return x.region < y.region;
    });
    for (size_t b = 0, e = 0; b < items.size() && !packed; b = e) {
      if (deadline && ++cells % 4096 == 0) deadline->check();
      for (e = b + 1; e < items.size() && items[e].cell == items[b].cell;) ++e;
      packed = !sweep_cell(items, b, e, faces, active, st, best);
    }
  }
  if (stats) *stats = st;
  if (packed) return SingleCouplingAnswer{true, std::nullopt, std::nullopt, std::nullopt};
  return named(best);
}

std::optional<SingleCouplingAnswer> single_coupling_one_axis(const Instance& inst, const SpanningTree& t,
                                                             const Regions& regions, uint64_t* tests) {
  const std::optional<int> axis = inst.moving_axis();
  if (!axis) return std::nullopt;
  const std::vector<Faces> faces = region_faces(inst, t, regions);
  const size_t m = 2 * static_cast<size_t>(*axis), c = 2 - m;  // faces m, m + 1 move; c, c + 1 stay one unit apart
  for (const Faces& f : faces) {
    if (f[c].b != 0 || f[c + 1].b != 0 || f[c + 1].a - f[c].a != 1) return std::nullopt;  // never, on one axis
    // The proof needs every width positive on (0, 1): affine, so >= 0 at
    // both ends and not 0 at both. Not so only when the coupling breaks a
    // cycle (a contracting v's faces then follow inconsistent paths).
    const int64_t w0 = f[m + 1].a - f[m].a, w1 = w0 + f[m + 1].b - f[m].b;
    if (w0 < 0 || w1 < 0 || w0 + w1 == 0) return std::nullopt;
  }
  // By row, then by position at t = 0; the groups are cut at the regions of
  // positive width at t = 0. Every pair of a group is tested, and the pair
  // that starts overlapping first is kept, the smallest on ties, as the
  // simulator does (the proof: every pair that overlaps right after the
  // first moment is in one group).
  const std::vector<std::pair<uint32_t, uint32_t>> pairs = row_group_pairs(
      faces.size(),
      [&](uint32_t r) {
        return std::array<int64_t, 3>{faces[r][c].a, faces[r][m].a, faces[r][m + 1].a};
      },
      [&](uint32_t r) { return faces[r][m + 1].a > faces[r][m].a; });
  Earliest best;
  for (const auto& [x, y] : pairs) best.test(faces, x, y);
  if (tests) *tests = pairs.size();
  return named(best);
}

namespace {

// The faces of one axis (2 axis, 2 axis + 1) of every live region keep
// their order on (0, 1): sorted by the order just after 0 (value at 0,
// then slope), their values at 1 do not decrease. Then for i < j, f_i -
// f_j is < 0 just after 0 (or f_i = f_j) and <= 0 at 1, so, linear, < 0
// on all of (0, 1): no two ever swap. Neighbours suffice (<= is
// transitive); a pair that swaps makes some neighbours decrease at 1.
// O(r log r).
bool order_fixed(const std::vector<Faces>& faces, const std::vector<uint32_t>& live, size_t axis) {
  std::vector<Lin> ends;
  ends.reserve(2 * live.size());
  for (uint32_t r : live) ends.push_back(faces[r][2 * axis]), ends.push_back(faces[r][2 * axis + 1]);
  std::sort(ends.begin(), ends.end(), [](const Lin& f, const Lin& g) { return f.a != g.a ? f.a < g.a : f.b < g.b; });
  for (size_t i = 0; i + 1 < ends.size(); ++i) {
    if (ends[i + 1].a + ends[i + 1].b < ends[i].a + ends[i].b) return false;
  }
  return true;
}

// Along axis m, a width positive on all of (0, 1): affine, so >= 0 at
// both ends and not 0 at both.
bool width_positive(const Faces& f, size_t m) {
  const int64_t w0 = f[2 * m + 1].a - f[2 * m].a, w1 = w0 + f[2 * m + 1].b - f[2 * m].b;
  return w0 >= 0 && w1 >= 0 && w0 + w1 > 0;
}

// An end of a live region's interval along the kept axis at t = 1/2
// (doubled: 2a + b, an integer).
struct AxisEvent {
  int64_t x;
  int kind;  // 0 leaves (before any entry at the same x: touching is no overlap), 1 enters
  uint32_t r;
};

// Does some pair of live regions overlap at some t in (0, T), T <= 1?
// The faces of the kept axis keep their order, so two regions overlap
// along it at every t in (0, 1) or at none (the events at t = 1/2 say
// which). The sweep along it keeps the regions that contain the sweep
// line; their intervals along m sweep strips of the (m, t) plane over
// (0, T), which, with no overlap found so far, are pairwise disjoint and
// so ordered below/above on all of (0, T): kept by their low m face at
// T/2. A new region overlapping some kept one overlaps one of its two
// neighbours there (docs/collide.md, "One coupling: one axis keeps its
// order": the proof). The first overlap met is kept in best. O(r log r).
// Checks deadline (if given) every 4096 events.
bool collides_before(const std::vector<Faces>& faces, const std::vector<AxisEvent>& events, size_t m, const Frac& T,
                     Earliest& best, uint64_t& tests, const Deadline* deadline,
                     std::vector<std::pair<uint32_t, uint32_t>>* tested = nullptr) {
  if (T.num <= 0) return false;  // (0, T) is empty (a first moment at t = 0)
  // The low m face at T/2, times 2 T.den.
  auto key = [&](uint32_t r) {
    const Lin& f = faces[r][2 * m];
    return 2 * static_cast<__int128>(f.a) * T.den + static_cast<__int128>(f.b) * T.num;
  };
  auto meets = [&](uint32_t x, uint32_t y) {
    ++tests;
    if (tested) tested->emplace_back(std::min(x, y), std::max(x, y));
    const Span s = overlap_span(faces[x], faces[y]);
    if (s.empty() || !less(s.lo, T)) return false;
    best.keep(x, y, s);
    return true;
  };
  std::map<__int128, uint32_t> active;  // distinct keys: equal ones overlap at T/2
  size_t seen = 0;
  for (const AxisEvent& e : events) {
    if (deadline && (++seen & 4095) == 0) deadline->check();
    const __int128 lo = key(e.r);
    if (e.kind == 0) {
      active.erase(lo);
      continue;
    }
    const auto next = active.lower_bound(lo);
    if (next != active.end() && meets(e.r, next->second)) return true;
    if (next != active.begin() && meets(e.r, std::prev(next)->second)) return true;
    active.emplace_hint(next, lo, e.r);
  }
  return false;
}

// One group of the fixed-axis sweep: its kept axis s (the sweep orders
// along 1 - s) and its events along s (sorted).
struct KeptGroup {
  size_t s = 0;
  std::vector<AxisEvent> events;
};

// The group of `members` if the faces of one of its axes keep their order
// (x first) and every member's width along the other is positive all
// along (0, 1); else nullopt.
std::optional<KeptGroup> kept_group(const std::vector<Faces>& faces, const std::vector<uint32_t>& members) {
  size_t s = 2;
  for (size_t axis : {size_t{0}, size_t{1}}) {
    if (order_fixed(faces, members, axis)) {
      s = axis;
      break;
    }
  }
  if (s == 2) return std::nullopt;
  const size_t m = 1 - s;
  // A live region's width along s keeps its sign on (0, 1) (two faces of
  // s in order), so it is positive there; along m it must be too.
  for (uint32_t r : members)
    if (!width_positive(faces[r], m)) return std::nullopt;
  KeptGroup g;
  g.s = s;
  g.events.reserve(2 * members.size());
  for (uint32_t r : members) {
    const Faces& f = faces[r];
    g.events.push_back({2 * f[2 * s + 1].a + f[2 * s + 1].b, 0, r});
    g.events.push_back({2 * f[2 * s].a + f[2 * s].b, 1, r});
  }
  std::sort(g.events.begin(), g.events.end(), [](const AxisEvent& e, const AxisEvent& f) {
    return e.x != f.x ? e.x < f.x : e.kind != f.kind ? e.kind < f.kind : e.r < f.r;
  });
  return g;
}

// The directions a cut may run along: x, y, the two diagonals x + y and
// x - y (a staircase carried along a diagonal past a static band beside
// it, the band sweep of slope 1, has no cut along an axis but one along
// x - y), and one taken from the piece's motion: perpendicular to the
// commonest direction of motion relative to the commonest velocity (the
// band sweep of slope p is cut along x - p y). A region's extent along
// d = (dx, dy) is the interval of dx x + dy y over its rectangle, each
// end a sum of faces times integers, so linear in t.
struct CutDirection {
  int64_t dx = 1, dy = 0;
};
constexpr std::array<CutDirection, 4> kFixedCutDirections = {{{1, 0}, {0, 1}, {1, 1}, {1, -1}}};
// A direction from the motion is used only with |dx|, |dy| <= this (so
// extents stay below 2^60 with the time slabs' faces below 2^53: the
// positions 2^e a + m b with a, b <= 2^40, e <= 12).
constexpr int64_t kMaxCutSlope = 64;

std::array<Lin, 2> extent(const Faces& f, CutDirection d) {
  const auto times = [](int64_t c, const Lin& u) { return Lin{c * u.a, c * u.b}; };
  const auto add = [](const Lin& u, const Lin& v) { return Lin{u.a + v.a, u.b + v.b}; };
  const Lin x_lo = times(d.dx, f[d.dx >= 0 ? 0 : 1]), x_hi = times(d.dx, f[d.dx >= 0 ? 1 : 0]);
  const Lin y_lo = times(d.dy, f[d.dy >= 0 ? 2 : 3]), y_hi = times(d.dy, f[d.dy >= 0 ? 3 : 2]);
  return {add(x_lo, y_lo), add(x_hi, y_hi)};
}

// (x, y) / gcd, with the first non-zero coordinate positive.
CutDirection primitive(int64_t x, int64_t y) {
  const int64_t g = std::gcd(x, y);
  x /= g, y /= g;
  if (x < 0 || (x == 0 && y < 0)) x = -x, y = -y;
  return {x, y};
}

// The most frequent value of a sorted list (the least on ties).
std::pair<int64_t, int64_t> commonest(const std::vector<std::pair<int64_t, int64_t>>& sorted) {
  std::pair<int64_t, int64_t> best = sorted.front();
  size_t best_run = 0;
  for (size_t i = 0, j = 0; i < sorted.size(); i = j) {
    while (j < sorted.size() && sorted[j] == sorted[i]) ++j;
    if (j - i > best_run) best = sorted[i], best_run = j - i;
  }
  return best;
}

// The direction from the motion of `members`: velocities (the speeds of
// the low x and low y faces), m the commonest; u the commonest primitive
// direction of v - m over the members moving otherwise; the cut runs
// perpendicular to u. None when all move alike, when it is one of the
// fixed directions, or when it is steeper than kMaxCutSlope.
// Frame-free: a common motion added to every face changes no v - m.
// O(k log k).
std::optional<CutDirection> motion_direction(const std::vector<Faces>& faces, const std::vector<uint32_t>& members) {
  if (members.empty()) return std::nullopt;
  std::vector<std::pair<int64_t, int64_t>> v;
  v.reserve(members.size());
  for (uint32_t r : members) v.emplace_back(faces[r][0].b, faces[r][2].b);
  std::sort(v.begin(), v.end());
  const std::pair<int64_t, int64_t> m = commonest(v);
  std::vector<std::pair<int64_t, int64_t>> u;
  for (const auto& [x, y] : v)
    if (std::pair(x, y) != m) {
      const CutDirection p = primitive(x - m.first, y - m.second);
      u.emplace_back(p.dx, p.dy);
    }
  if (u.empty()) return std::nullopt;
  std::sort(u.begin(), u.end());
  const std::pair<int64_t, int64_t> w = commonest(u);
  const CutDirection d = primitive(w.second, -w.first);
  if (std::abs(d.dx) > kMaxCutSlope || std::abs(d.dy) > kMaxCutSlope) return std::nullopt;
  for (const CutDirection& f : kFixedCutDirections)
    if (f.dx == d.dx && f.dy == d.dy) return std::nullopt;
  return d;
}

// Cuts `members` along direction `dir` (extent) wherever every member
// before the cut lies at or below every member after it at t = 0 and at
// t = 1 (in the order of the low end at 0, then the high end at 0): the
// prefix maximum of the high ends at most the suffix minimum of the low
// ends, at both ends of time. For a before and b after a cut,
// hi_a(t) <= lo_b(t) then holds at 0 and at 1, so, both linear, on all of
// [0, 1]: their projections share no interior point, so neither do the
// rectangles, and no pair across a cut ever overlaps. Returns the pieces
// (one when there is no cut). O(k log k).
std::vector<std::vector<uint32_t>> separated_pieces(const std::vector<Faces>& faces,
                                                    const std::vector<uint32_t>& members, CutDirection dir) {
  struct Extent {
    Lin lo, hi;
    uint32_t r;
  };
  std::vector<Extent> ext;
  ext.reserve(members.size());
  for (uint32_t r : members) {
    const std::array<Lin, 2> e = extent(faces[r], dir);
    ext.push_back({e[0], e[1], r});
  }
  std::sort(ext.begin(), ext.end(), [](const Extent& f, const Extent& g) {
    if (f.lo.a != g.lo.a) return f.lo.a < g.lo.a;
    if (f.hi.a != g.hi.a) return f.hi.a < g.hi.a;
    return f.r < g.r;
  });
  const size_t k = ext.size();
  // Suffix minima of the low end at 0 and at 1.
  std::vector<std::array<int64_t, 2>> low(k + 1, {INT64_MAX, INT64_MAX});
  for (size_t i = k; i-- > 0;) {
    const Lin& f = ext[i].lo;
    low[i] = {std::min(low[i + 1][0], f.a), std::min(low[i + 1][1], f.a + f.b)};
  }
  std::vector<std::vector<uint32_t>> pieces(1);
  int64_t high0 = INT64_MIN, high1 = INT64_MIN;  // prefix maxima of the high end at 0 and at 1
  for (size_t i = 0; i < k; ++i) {
    const Lin& f = ext[i].hi;
    high0 = std::max(high0, f.a), high1 = std::max(high1, f.a + f.b);
    pieces.back().push_back(ext[i].r);
    if (i + 1 < k && high0 <= low[i + 1][0] && high1 <= low[i + 1][1]) pieces.emplace_back();
  }
  return pieces;
}

// The pieces of the direction (x, y, x + y, x - y, then the one from the
// motion) whose cut leaves the smallest largest piece (the first such on
// ties: a cut that peels a few regions off a staircase would cost a level
// per few regions), or none when no direction has a cut. Checks deadline
// (if given) before each direction. O(k log k).
std::vector<std::vector<uint32_t>> first_cut(const std::vector<Faces>& faces, const std::vector<uint32_t>& members,
                                             const Deadline* deadline) {
  std::vector<CutDirection> dirs(kFixedCutDirections.begin(), kFixedCutDirections.end());
  if (const std::optional<CutDirection> d = motion_direction(faces, members)) dirs.push_back(*d);
  std::vector<std::vector<uint32_t>> best;
  size_t best_largest = members.size();
  for (const CutDirection& dir : dirs) {
    if (deadline) deadline->check();
    std::vector<std::vector<uint32_t>> pieces = separated_pieces(faces, members, dir);
    if (pieces.size() < 2) continue;
    size_t largest = 0;
    for (const auto& piece : pieces) largest = std::max(largest, piece.size());
    if (largest < best_largest) best = std::move(pieces), best_largest = largest;
  }
  return best;
}

// Cuts past this depth are not followed (the cell sweep decides): the
// cost stays O(r log r) per level, 64 levels at most. And the members of
// the pieces placed, summed, stay within kCutWork per live region: a
// staircase (the diagonal sweep) peels a few regions per level off a
// piece of nearly all of them, and past that the cuts cost more than
// the cell sweep they would spare.
constexpr int kMaxCutDepth = 64;
constexpr uint64_t kCutWork = 4;

// A motion class: regions whose four faces move at the same speeds and
// whose widths at t = 0 agree. Two regions of classes P and Q then
// overlap at some t iff the difference of their low corners lies in one
// open convex polygon that depends on P and Q alone.
struct MotionClass {
  std::vector<uint32_t> members;
};

// The speeds of xlo, xhi, ylo, yhi; the widths at 0.
std::array<int64_t, 6> class_key(const Faces& f) {
  return {f[0].b, f[1].b, f[2].b, f[3].b, f[1].a - f[0].a, f[3].a - f[2].a};
}

// Face speeds at most kMaxClassSpeed (so each s below at most 2^20) and
// T's denominator at most kMaxClassDen keep the hull's corners below 2^61
// and every product in classes_meet below 2^126. Starts then have
// denominators of at most 2^20, so two distinct ones differ by more than
// 2^-40: halving to denominator 2^40 separates them (the bisection's
// O(log) rounds).
constexpr int64_t kMaxClassSpeed = int64_t{1} << 19;
constexpr int64_t kMaxClassDen = int64_t{1} << 40;

struct Point {
  int64_t x, y;
};
__int128 cross(const Point& o, const Point& a, const Point& b) {
  return static_cast<__int128>(a.x - o.x) * (b.y - o.y) - static_cast<__int128>(a.y - o.y) * (b.x - o.x);
}

// A in P, B in Q (the same class allowed), d = A's low corner - B's at
// t = 0. Along x they overlap at t iff -wA - s1 t < dx < wB + s2 t
// (s1 = A's xhi speed - B's xlo speed, s2 = B's xhi speed - A's xlo
// speed), along y likewise: d in an open box B(t) whose sides move
// linearly. With both widths of every member positive on (0, 1) (so
// nonnegative at 0 and 1), B(t) = (1 - t/T) B(0) + (t/T) B(T)
// (Minkowski), and the d for which some t in (0, T) works form an open
// convex set whose closure is the union of the closed B(t) over [0, T],
// conv(B(0) u B(T)): the set is the interior of that hull (an open
// convex set is the interior of its closure). With T = p/q, q times the
// hull has integer vertices: q B(0) and q B(T). Cut by the verticals
// through its vertices, it is a union of strips: q dx in [x_i, x_i+1]
// strictly inside the hull's x range, q d strictly above the strip's
// lower edge and below its upper edge; for integer d, "e_x q dy - e_y q dx
// > c" is "e_x dy - e_y dx > floor(c / q)" (and "< c'" is "< ceil(c' / q)").
// Each strip is one strip_pair query. Returns an overlapping pair (A's
// region first), or nullopt. queries counts the strips asked. Requires
// face speeds within kMaxClassSpeed and 0 < T <= 1 with T.den within
// kMaxClassDen.
std::optional<std::pair<uint32_t, uint32_t>> classes_meet(const std::vector<Faces>& faces, const MotionClass& P,
                                                          const MotionClass& Q, const Frac& T, uint64_t& queries) {
  const Faces &fa = faces[P.members.front()], &fb = faces[Q.members.front()];
  const int64_t wA = fa[1].a - fa[0].a, wB = fb[1].a - fb[0].a, hA = fa[3].a - fa[2].a, hB = fb[3].a - fb[2].a;
  const int64_t s1 = fa[1].b - fb[0].b, s2 = fb[1].b - fa[0].b, s3 = fa[3].b - fb[2].b, s4 = fb[3].b - fa[2].b;
  const int64_t p = T.num, q = T.den;
  std::vector<Point> pts;
  for (const auto& [x0, x1, y0, y1] :
       {std::array<int64_t, 4>{-wA * q, wB * q, -hA * q, hB * q},
        std::array<int64_t, 4>{-wA * q - s1 * p, wB * q + s2 * p, -hA * q - s3 * p, hB * q + s4 * p}})
    for (int64_t x : {x0, x1})
      for (int64_t y : {y0, y1}) pts.push_back({x, y});
  std::sort(pts.begin(), pts.end(), [](const Point& a, const Point& b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
  // Andrew's monotone chains, left to right: lower (turning left) and
  // upper (turning right); collinear points dropped.
  std::vector<Point> lower, upper;
  for (const Point& pt : pts) {
    while (lower.size() >= 2 && cross(lower[lower.size() - 2], lower.back(), pt) <= 0) lower.pop_back();
    lower.push_back(pt);
    while (upper.size() >= 2 && cross(upper[upper.size() - 2], upper.back(), pt) >= 0) upper.pop_back();
    upper.push_back(pt);
  }
  const int64_t x_min = pts.front().x, x_max = pts.back().x;
  // Integer dx with x_min < q dx < x_max.
  const int64_t dx_min = floor_div<int64_t>(x_min, q) + 1, dx_max = ceil_div<int64_t>(x_max, q) - 1;
  if (dx_min > dx_max) return std::nullopt;
  // Non-vertical edges only (vertical ones lie at x_min or x_max).
  auto edges = [](const std::vector<Point>& chain) {
    std::vector<std::pair<Point, Point>> out;
    for (size_t i = 0; i + 1 < chain.size(); ++i)
      if (chain[i].x < chain[i + 1].x) out.emplace_back(chain[i], chain[i + 1]);
    return out;
  };
  const auto lo_edges = edges(lower), hi_edges = edges(upper);
  const bool same = &P == &Q;
  std::vector<StripPoint> A(P.members.size()), B;
  if (!same) B.resize(Q.members.size());
  size_t i = 0, j = 0;
  for (int64_t x = x_min; x < x_max;) {
    const auto& [l1, l2] = lo_edges[i];
    const auto& [h1, h2] = hi_edges[j];
    const int64_t end = std::min(l2.x, h2.x);
    const int64_t X1 = std::max(ceil_div<int64_t>(x, q), dx_min), X2 = std::min(floor_div<int64_t>(end, q), dx_max);
    if (X1 <= X2) {
      // Strictly above the lower edge: ex q dy - ey q dx > ex y1 - ey x1;
      // with d = a - b, u(a) - u(b) > floor(c / q) for u(p) = ex p.y -
      // ey p.x. Strictly below the upper edge: v(a) - v(b) < ceil(c' / q).
      const int64_t ex = l2.x - l1.x, ey = l2.y - l1.y, fx = h2.x - h1.x, fy = h2.y - h1.y;
      const __int128 cu = floor_div<__int128>(static_cast<__int128>(ex) * l1.y - static_cast<__int128>(ey) * l1.x, q);
      const __int128 cv = ceil_div<__int128>(static_cast<__int128>(fx) * h1.y - static_cast<__int128>(fy) * h1.x, q);
      auto fill = [&](const MotionClass& C, std::vector<StripPoint>& out) {
        for (size_t k = 0; k < C.members.size(); ++k) {
          const Faces& f = faces[C.members[k]];
          out[k] = {f[0].a, static_cast<__int128>(ex) * f[2].a - static_cast<__int128>(ey) * f[0].a,
                    static_cast<__int128>(fx) * f[2].a - static_cast<__int128>(fy) * f[0].a, C.members[k]};
        }
      };
      fill(P, A);
      if (!same) fill(Q, B);
      ++queries;
      if (auto pair = strip_pair(A, same ? A : B, X1, X2, cu, cv)) return pair;
    }
    if (l2.x == end) ++i;
    if (h2.x == end) ++j;
    x = end;
  }
  return std::nullopt;
}

// The motion classes of `members` and their total motion (sum of 1 +
// |speed_x| + |speed_y|); nullopt when some width is not positive all
// along (0, 1), some width at 0 exceeds 2 or some face speed exceeds
// kMaxClassSpeed. O(r log k).
std::optional<std::vector<MotionClass>> motion_classes_of(const std::vector<Faces>& faces,
                                                          const std::vector<uint32_t>& members, uint64_t& motion) {
  std::map<std::array<int64_t, 6>, size_t> index;
  std::vector<MotionClass> classes;
  for (uint32_t r : members) {
    const Faces& f = faces[r];
    if (!width_positive(f, 0) || !width_positive(f, 1)) return std::nullopt;
    if (f[1].a - f[0].a > 2 || f[3].a - f[2].a > 2) return std::nullopt;  // widths at 0 are 0 or 1 (bounds above)
    for (const Lin& l : f)
      if (l.b > kMaxClassSpeed || l.b < -kMaxClassSpeed) return std::nullopt;
    motion += region_motion(f);
    const auto [it, fresh] = index.emplace(class_key(f), classes.size());
    if (fresh) classes.emplace_back();
    classes[it->second].members.push_back(r);
  }
  return classes;
}

// What the fixed-axis sweep needs: the faces, the live regions and their
// groups. The live regions are cut into pieces that never overlap one
// another (separated_pieces, along x, then along y, recursively) until
// every piece keeps the order of one axis (kept_group); a single group
// when all of them do. nullopt when some piece keeps neither order and
// has no cut, or the cuts nest deeper than kMaxCutDepth. Checks deadline
// (if given) once per piece.
// With class groups (single_coupling_motion_classes), the pieces that
// no cut separates are decided by motion classes instead.
struct FixedAxisSetup {
  std::vector<Faces> faces;
  std::vector<uint32_t> live;
  std::vector<KeptGroup> groups;
  std::vector<std::vector<MotionClass>> class_groups;
  mutable uint64_t class_pairs = 0, queries = 0;  // asked of the class groups
  const Deadline* deadline = nullptr;             // checked per class pair and in the sweeps
};

// The faces and the live regions (positive widths at some t), no groups
// yet. O(n).
FixedAxisSetup live_regions(const Instance& inst, const SpanningTree& t, const Regions& regions) {
  FixedAxisSetup out;
  out.faces = region_faces(inst, t, regions);
  for (uint32_t r = 0; r < out.faces.size(); ++r)
    if (!alive(out.faces[r]).empty()) out.live.push_back(r);
  return out;
}

// uncut (optional): the pieces that keep neither order and have no cut
// are appended there instead of failing (the motion-class test's).
std::optional<FixedAxisSetup> fixed_axis_setup(const Instance& inst, const SpanningTree& t, const Regions& regions,
                                               const Deadline* deadline = nullptr,
                                               std::vector<std::vector<uint32_t>>* uncut = nullptr) {
  FixedAxisSetup out = live_regions(inst, t, regions);
  out.deadline = deadline;
  const std::vector<Faces>& faces = out.faces;
  // Pieces to place, with their depth of cuts.
  std::vector<std::pair<std::vector<uint32_t>, int>> todo;
  todo.emplace_back(out.live, 0);
  uint64_t work = 0;
  const uint64_t cap = kCutWork * (out.live.size() + 1);
  while (!todo.empty()) {
    if (deadline) deadline->check();
    auto [members, depth] = std::move(todo.back());
    todo.pop_back();
    work += members.size();
    if (work > cap) return std::nullopt;
    if (std::optional<KeptGroup> g = kept_group(faces, members)) {
      out.groups.push_back(std::move(*g));
      continue;
    }
    if (depth < kMaxCutDepth) {
      std::vector<std::vector<uint32_t>> pieces = first_cut(faces, members, deadline);
      for (auto& p : pieces) todo.emplace_back(std::move(p), depth + 1);
      if (!pieces.empty()) continue;
    }
    if (!uncut) return std::nullopt;
    uncut->push_back(std::move(members));
  }
  return out;
}

// Ties of the first moment t*: the simulator names the smallest pair that
// starts to overlap then. Such a pair overlaps just after t*, so its
// closed boxes meet at t*, and so share a unit cell (each box is entered
// in every cell it meets, closed). Every pair sharing a cell is tested;
// best (already at t*, the least start) keeps the smallest pair starting
// at t*. O(r log r) for boxes of bounded size and a configuration
// without overlaps at t* (so few regions per cell).
void smallest_first_pair(const std::vector<Faces>& faces, const std::vector<uint32_t>& live, Earliest& best) {
  const Frac t = best.span.lo;
  // (cell, region), the cell packed into one key: x and y as offsets from
  // their least values (spans below 2^32: coordinates within kMaxCoordinate).
  std::vector<std::array<int64_t, 4>> box(live.size());
  int64_t x_min = INT64_MAX, y_min = INT64_MAX;
  for (size_t i = 0; i < live.size(); ++i) {
    const Faces& f = faces[live[i]];
    box[i] = {floor_at(f[0], t), floor_at(f[1], t), floor_at(f[2], t), floor_at(f[3], t)};
    x_min = std::min(x_min, box[i][0]), y_min = std::min(y_min, box[i][2]);
  }
  std::vector<std::pair<uint64_t, uint32_t>> cells;
  cells.reserve(4 * live.size());
  for (size_t i = 0; i < live.size(); ++i)
    for (int64_t x = box[i][0]; x <= box[i][1]; ++x)
      for (int64_t y = box[i][2]; y <= box[i][3]; ++y)
        cells.emplace_back(static_cast<uint64_t>(x - x_min) << 32 | static_cast<uint64_t>(y - y_min), live[i]);
  std::sort(cells.begin(), cells.end());
  for (size_t b = 0, e = 0; b < cells.size(); b = e) {
    for (e = b + 1; e < cells.size() && cells[e].first == cells[b].first;) ++e;
    for (size_t i = b; i < e; ++i)
      for (size_t j = i + 1; j < e; ++j) best.test(faces, cells[i].second, cells[j].second);
  }
}

// Is there an overlap at some t in (0, T) within some group? Groups never
// overlap one another, so this is the question for every live pair.
bool any_collides_before(const FixedAxisSetup& setup, const Frac& T, Earliest& best, uint64_t& tests,
                         std::vector<std::pair<uint32_t, uint32_t>>* tested = nullptr) {
  for (const KeptGroup& g : setup.groups)
    if (collides_before(setup.faces, g.events, 1 - g.s, T, best, tests, setup.deadline, tested)) return true;
  if (T.num <= 0) return false;
  for (const std::vector<MotionClass>& classes : setup.class_groups)
    for (size_t p = 0; p < classes.size(); ++p)
      for (size_t q = p; q < classes.size(); ++q) {
        if (setup.deadline) setup.deadline->check();
        ++setup.class_pairs;
        const auto pair = classes_meet(setup.faces, classes[p], classes[q], T, setup.queries);
        if (!pair) continue;
        // Checked by the exact pair test (a disagreement would be a bug).
        const Span s = overlap_span(setup.faces[pair->first], setup.faces[pair->second]);
        if (s.empty() || !less(s.lo, T))
          throw std::logic_error("single_coupling_motion_classes: a pair found apart by the exact test");
        best.keep(pair->first, pair->second, s);
        return true;
      }
  return false;
}

// A YES (best holds an overlapping pair): finds the first moment t*, the
// least start of an overlapping pair, and the smallest pair starting
// then. lo <= t* <= c <= hi (dyadic, den 2^k), c best's start. Each round
// asks for an overlap before c (none: c = t*), then halves [lo, hi].
// Distinct starts differ by more than the interval once it is short
// enough, so the rounds end; O(log) rounds for bounded speeds. The
// halving stops at denominator max_den (then starts alone shrink c).
// name_smallest false (time slabs, whose faces are scaled): best keeps the
// first moment and a pair starting then, not necessarily the smallest.
void first_collision(const FixedAxisSetup& setup, Earliest& best, uint64_t& tests, uint64_t& sweeps,
                     const Deadline* deadline, int64_t max_den, bool name_smallest = true) {
  int64_t lo = 0, hi = 1, den = 1;
  for (;;) {
    if (deadline) deadline->check();
    ++sweeps;
    if (!any_collides_before(setup, best.span.lo, best, tests)) break;
    if (den >= max_den) continue;  // the interval is as fine as allowed: shrink by starts alone
    lo *= 2, hi *= 2, den *= 2;
    const Frac mid{lo + (hi - lo) / 2, den};
    if (!less(mid, best.span.lo)) {
      hi = mid.num;  // t* <= c <= mid
    } else {
      ++sweeps;
      if (any_collides_before(setup, mid, best, tests)) hi = mid.num;  // best now starts before mid
      else lo = mid.num;
    }
  }
  if (name_smallest) smallest_first_pair(setup.faces, setup.live, best);
}

// Time slabs: a piece that keeps neither order over (0, 1) and has no cut
// may have cuts over parts of it (the stalactite combs: teeth and
// stalactites apart along y before t = 1/2, along x after). A dyadic
// slab [num / 2^exp, (num + 1) / 2^exp] of [0, 1].
struct Slab {
  int64_t num = 0;
  int exp = 0;
};

// Slabs are split no finer than 2^-kMaxSlabExp, and the pieces placed
// (their members summed over every slab) stay within the smaller of
// kSlabWork per live region and a quarter of the motion (the cell
// sweep's items; placing a member costs a few times an item, measured)
// plus kSlabFloor (on small instances either is fast): past either, the
// time slabs give up and the cell sweep is the faster. A piece of at
// most kSmallPiece members that has no cut and keeps neither order is not
// split: every pair of it is tested over its slab.
constexpr int kMaxSlabExp = 12;
constexpr uint64_t kSlabWork = 32;
constexpr size_t kSmallPiece = 8;
constexpr uint64_t kSlabFloor = 1024;
// Positions and speeds within 2^40 keep a slab's faces below 2^53, and
// the sweeps' products (times denominators up to 2^61) within __int128.
constexpr int64_t kMaxSlabValue = int64_t{1} << 40;

// f over the slab, time rescaled to s in [0, 1] (t = (num + s) / 2^exp)
// and space scaled by 2^exp: 2^exp f(t) = (2^exp a + num b) + b s. Two
// regions overlap (open, positive area) at t iff their scaled boxes do at
// the matching s, so every test below applies to the slab unchanged.
Faces in_slab(const Faces& f, const Slab& sl) {
  Faces g;
  for (size_t i = 0; i < 4; ++i) g[i] = Lin{f[i].a * (int64_t{1} << sl.exp) + f[i].b * sl.num, f[i].b};
  return g;
}

// The faces and live regions for the time slabs; nullopt when some face's
// position or speed exceeds kMaxSlabValue.
std::optional<FixedAxisSetup> slab_live_regions(const Instance& inst, const SpanningTree& t, const Regions& regions) {
  FixedAxisSetup out = live_regions(inst, t, regions);
  for (uint32_t r : out.live)
    for (const Lin& l : out.faces[r])
      if (l.a > kMaxSlabValue || l.a < -kMaxSlabValue || l.b > kMaxSlabValue || l.b < -kMaxSlabValue)
        return std::nullopt;
  return out;
}

// A group over one slab: the global ids of its members, and a setup of
// their faces over the slab with one kept-order group (local ids: index
// into members), or none: a small piece, every pair tested.
struct SlabGroup {
  Slab slab;
  std::vector<uint32_t> members;
  FixedAxisSetup setup;
};

// Places `live` into kept-order groups over slabs: a piece is cut as
// fixed_axis_setup cuts it, over its slab; one that keeps neither order
// and has no cut there is split into the two halves of its slab. Regions
// not alive in a slab leave it, and a piece of one region is done; a
// small one is a group of every pair. Every pair of live regions that
// overlaps at some t then lies, at every such t but the slabs' ends, in
// one group of the slab holding t (pairs across a cut never overlap in
// its slab). nullopt past kMaxSlabExp or the work budget (work: members
// placed). Checks deadline (if given) per piece.
std::optional<std::vector<SlabGroup>> slab_groups(const std::vector<Faces>& faces, const std::vector<uint32_t>& live,
                                                  int first_exp, uint64_t budget, const Deadline* deadline,
                                                  uint64_t& work) {
  struct Piece {
    std::vector<uint32_t> members;
    Slab slab;
    int depth = 0;  // cuts
  };
  std::vector<Piece> todo;
  for (int64_t num = (int64_t{1} << first_exp) - 1; num >= 0; --num) todo.push_back({live, Slab{num, first_exp}, 0});
  std::vector<SlabGroup> out;
  while (!todo.empty()) {
    if (deadline) deadline->check();
    Piece p = std::move(todo.back());
    todo.pop_back();
    work += p.members.size();
    if (work > budget) return std::nullopt;
    std::vector<uint32_t> members;
    std::vector<Faces> local;
    for (uint32_t r : p.members) {
      const Faces g = in_slab(faces[r], p.slab);
      if (alive(g).empty()) continue;
      members.push_back(r);
      local.push_back(g);
    }
    if (members.size() < 2) continue;
    std::vector<uint32_t> ids(members.size());
    for (uint32_t i = 0; i < ids.size(); ++i) ids[i] = i;
    // A group: kept-order (one group in its setup) or small (none).
    auto place = [&](std::optional<KeptGroup> g) {
      SlabGroup& sg = out.emplace_back();
      sg.slab = p.slab;
      sg.members = std::move(members);
      sg.setup.faces = std::move(local);
      sg.setup.live = std::move(ids);
      if (g) sg.setup.groups.push_back(std::move(*g));
    };
    if (std::optional<KeptGroup> g = kept_group(local, ids)) {
      place(std::move(g));
      continue;
    }
    if (p.depth < kMaxCutDepth) {
      const std::vector<std::vector<uint32_t>> pieces = first_cut(local, ids, deadline);
      for (const std::vector<uint32_t>& q : pieces) {
        Piece next{{}, p.slab, p.depth + 1};
        next.members.reserve(q.size());
        for (uint32_t i : q) next.members.push_back(members[i]);
        todo.push_back(std::move(next));
      }
      if (!pieces.empty()) continue;
    }
    if (members.size() <= kSmallPiece) {
      place(std::nullopt);
      continue;
    }
    if (p.slab.exp >= kMaxSlabExp) return std::nullopt;
    todo.push_back({members, Slab{2 * p.slab.num + 1, p.slab.exp + 1}, p.depth});
    todo.push_back({std::move(members), Slab{2 * p.slab.num, p.slab.exp + 1}, p.depth});
  }
  return out;
}

}  // namespace

std::optional<FixedAxisAnswer> single_coupling_fixed_axis(const Instance& inst, const SpanningTree& t,
                                                          const Regions& regions, const Deadline* deadline) {
  const std::optional<FixedAxisSetup> setup = fixed_axis_setup(inst, t, regions, deadline);
  if (!setup) return std::nullopt;
  FixedAxisAnswer out;
  out.groups = setup->groups.size();
  out.axis = out.groups == 1 ? static_cast<int>(setup->groups[0].s) : -1;
  Earliest best;
  ++out.sweeps;
  if (!any_collides_before(*setup, Frac{1, 1}, best, out.tests)) return out;
  first_collision(*setup, best, out.tests, out.sweeps, deadline, int64_t{1} << 60);
  out.answer = named(best);
  return out;
}

std::optional<KeptOrderPairs> single_coupling_kept_order_pairs(const Instance& inst, const SpanningTree& t,
                                                               const Regions& regions, const Deadline* deadline) {
  const std::optional<FixedAxisSetup> setup = fixed_axis_setup(inst, t, regions, deadline);
  if (!setup) return std::nullopt;
  KeptOrderPairs out;
  out.axis = setup->groups.size() == 1 ? static_cast<int>(setup->groups[0].s) : 2;
  Earliest best;
  uint64_t tests = 0;
  if (any_collides_before(*setup, Frac{1, 1}, best, tests, &out.pairs)) return std::nullopt;
  return out;
}

std::optional<KeptOrderPairs> single_coupling_slab_pairs(const Instance& inst, const SpanningTree& t,
                                                         const Regions& regions, const Deadline* deadline) {
  const std::optional<FixedAxisSetup> live = slab_live_regions(inst, t, regions);
  if (!live) return std::nullopt;
  const FixedAxisSetup& whole = *live;
  uint64_t work = 0;
  std::optional<std::vector<SlabGroup>> groups = slab_groups(whole.faces, whole.live, 0,
                                                             kSlabWork * (whole.live.size() + 1), deadline, work);
  if (!groups) return std::nullopt;
  KeptOrderPairs out;
  out.axis = 3;
  for (SlabGroup& g : *groups) {
    std::vector<std::pair<uint32_t, uint32_t>> local;
    if (g.setup.groups.empty()) {  // a small piece: every pair
      for (uint32_t i = 0; i < g.members.size(); ++i)
        for (uint32_t j = i + 1; j < g.members.size(); ++j) {
          if (!overlap_span(g.setup.faces[i], g.setup.faces[j]).empty()) return std::nullopt;
          local.emplace_back(i, j);
        }
    } else {
      Earliest best;
      uint64_t tests = 0;
      g.setup.deadline = deadline;
      if (any_collides_before(g.setup, Frac{1, 1}, best, tests, &local)) return std::nullopt;
    }
    for (auto [i, j] : local)
      out.pairs.emplace_back(std::min(g.members[i], g.members[j]), std::max(g.members[i], g.members[j]));
  }
  return out;
}

std::optional<MotionClassAnswer> single_coupling_motion_classes(const Instance& inst, const SpanningTree& t,
                                                                const Regions& regions, const Deadline* deadline,
                                                                bool whole, bool any_cost) {
  std::vector<std::vector<uint32_t>> uncut;
  std::optional<FixedAxisSetup> setup;
  if (whole) {
    setup = live_regions(inst, t, regions);
    uncut.push_back(setup->live);
  } else {
    setup = fixed_axis_setup(inst, t, regions, deadline, &uncut);
    if (!setup) return std::nullopt;
  }
  const std::vector<Faces>& faces = setup->faces;
  if (!uncut.empty())  // every start then has a denominator of at most 2 kMaxClassSpeed
    for (uint32_t r : setup->live)
      for (const Lin& l : faces[r])
        if (l.b > kMaxClassSpeed || l.b < -kMaxClassSpeed) return std::nullopt;
  setup->deadline = deadline;
  MotionClassAnswer out;
  out.groups = setup->groups.size() + uncut.size();
  out.class_groups = uncut.size();
  // Every class group: widths positive on (0, 1), and (unless any_cost) k r no more than its motion (the
  // cell sweep's cost), k classes and r regions.
  for (const std::vector<uint32_t>& members : uncut) {
    uint64_t motion = 0;
    std::optional<std::vector<MotionClass>> classes = motion_classes_of(faces, members, motion);
    if (!classes) return std::nullopt;
    if (!any_cost && classes->size() * members.size() > motion) return std::nullopt;
    out.classes = std::max(out.classes, classes->size());
    setup->class_groups.push_back(std::move(*classes));
  }
  Earliest best;
  ++out.sweeps;
  if (any_collides_before(*setup, Frac{1, 1}, best, out.tests)) {
    // Halving to kMaxClassDen separates the starts (see kMaxClassSpeed).
    first_collision(*setup, best, out.tests, out.sweeps, deadline, kMaxClassDen);
    out.answer = named(best);
  }
  out.class_pairs = setup->class_pairs;
  out.queries = setup->queries;
  return out;
}

std::optional<TimeSlabAnswer> single_coupling_time_slabs(const Instance& inst, const SpanningTree& t,
                                                         const Regions& regions, const Deadline* deadline,
                                                         int first_exp, bool any_cost) {
  if (first_exp < 0 || first_exp > kMaxSlabExp) return std::nullopt;
  const std::optional<FixedAxisSetup> live = slab_live_regions(inst, t, regions);
  if (!live) return std::nullopt;
  const FixedAxisSetup& whole = *live;
  uint64_t motion = 0;
  for (uint32_t r : whole.live) motion += region_motion(whole.faces[r]);
  TimeSlabAnswer out;
  const uint64_t budget = any_cost ? UINT64_MAX
                                   : std::min<uint64_t>(kSlabWork * (whole.live.size() + 1), motion / 4 + kSlabFloor)
                                         << first_exp;
  std::optional<std::vector<SlabGroup>> groups = slab_groups(whole.faces, whole.live, first_exp, budget, deadline,
                                                             out.work);
  if (!groups) return std::nullopt;
  // In the order of their slabs' starts.
  auto start = [](const Slab& sl) { return sl.num << (kMaxSlabExp - sl.exp); };
  std::stable_sort(groups->begin(), groups->end(), [&](const SlabGroup& a, const SlabGroup& b) {
    return start(a.slab) != start(b.slab) ? start(a.slab) < start(b.slab) : a.slab.exp < b.slab.exp;
  });
  out.groups = groups->size();
  for (size_t i = 0; i < groups->size(); ++i) {
    const Slab& sl = (*groups)[i].slab;
    out.finest = std::max(out.finest, sl.exp);
    if (i == 0 || sl.num != (*groups)[i - 1].slab.num || sl.exp != (*groups)[i - 1].slab.exp) ++out.slabs;
  }
  // The first moment t* lies in (or at the start of) a slab S in which
  // the first pair overlaps just after t*, so in one group of S; that
  // group's first moment, mapped back, is t* (no pair starts earlier).
  // Groups of slabs starting at or after the earliest start found can
  // only tie it: the smallest pair at t* is named from every live region.
  Earliest best;
  for (SlabGroup& g : *groups) {
    if (best.found && !less(Frac{g.slab.num, int64_t{1} << g.slab.exp}, best.span.lo)) break;
    if (g.setup.groups.empty()) {  // a small piece: every pair, over the slab (its overlaps are global ones)
      for (uint32_t i = 0; i < g.members.size(); ++i)
        for (uint32_t j = i + 1; j < g.members.size(); ++j) {
          ++out.tests;
          if (overlap_span(g.setup.faces[i], g.setup.faces[j]).empty()) continue;
          const uint32_t a = g.members[i], b = g.members[j];
          best.keep(a, b, overlap_span(whole.faces[a], whole.faces[b]));
        }
      continue;
    }
    g.setup.deadline = deadline;
    Earliest local;
    ++out.sweeps;
    if (!any_collides_before(g.setup, Frac{1, 1}, local, out.tests)) continue;
    first_collision(g.setup, local, out.tests, out.sweeps, deadline, int64_t{1} << 60, false);
    const uint32_t a = g.members[local.pair.a], b = g.members[local.pair.b];
    best.keep(a, b, overlap_span(whole.faces[a], whole.faces[b]));
  }
  if (best.found) {
    smallest_first_pair(whole.faces, whole.live, best);
    out.answer = named(best);
  }
  return out;
}

std::optional<std::optional<RegionPair>> single_coupling_classes_before(const Instance& inst, const SpanningTree& t,
                                                                        const Regions& regions, const Rational& T) {
  if (T <= Rational(0) || T > Rational(1) || T.den() > kMaxClassDen) return std::nullopt;
  FixedAxisSetup setup = live_regions(inst, t, regions);
  uint64_t motion = 0;
  std::optional<std::vector<MotionClass>> classes = motion_classes_of(setup.faces, setup.live, motion);
  if (!classes) return std::nullopt;
  setup.class_groups.push_back(std::move(*classes));
  Earliest best;
  uint64_t tests = 0;
  if (!any_collides_before(setup, Frac{T.num(), T.den()}, best, tests)) return std::optional<RegionPair>{};
  return std::optional<RegionPair>{best.pair};
}

std::optional<RegionPair> single_coupling_pairwise_before(const Instance& inst, const SpanningTree& t,
                                                          const Regions& regions, const Rational& T) {
  const std::vector<Faces> faces = region_faces(inst, t, regions);
  const Frac end{T.num(), T.den()};
  for (uint32_t a = 0; a < faces.size(); ++a)
    for (uint32_t b = a + 1; b < faces.size(); ++b) {
      const Span s = overlap_span(faces[a], faces[b]);
      if (!s.empty() && less(s.lo, end)) return RegionPair{a, b};
    }
  return std::nullopt;
}

// An overlap span lies in (0, 1), so "before 1" is "at all".
std::optional<RegionPair> single_coupling_pairwise(const Instance& inst, const SpanningTree& t,
                                                   const Regions& regions) {
  return single_coupling_pairwise_before(inst, t, regions, Rational(1));
}

}  // namespace gridlock
