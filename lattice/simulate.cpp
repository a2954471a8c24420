#include "lattice/simulate.hpp"

#include <algorithm>
#include <array>
#include <climits>
#include <cstdint>
#include <numeric>
#include <stdexcept>

#include "common/int_math.hpp"
#include "common/internal/linear_interval.hpp"
#include "lattice/flat_map.hpp"

namespace gridlock {

namespace {

// A non-negative fraction of scaled time, den > 0; "none" when den == 0.
struct Frac {
  __int128 num = 0, den = 0;
  bool none() const { return den == 0; }
};
bool frac_less(const Frac& a, const Frac& b) { return a.num * b.den < b.num * a.den; }

// The earliest tau in [0, span] such that the rectangles A(t) = A + vA t and
// B(t) = B + vB t overlap with positive area right after tau; none if never.
// Eight strict inequalities a + b tau > 0 (the four overlap conditions and
// the four widths: a region of width 0 never collides) inside the open
// window (0, span) (common/linear_interval.hpp); span > 0.
Frac first_overlap(const int64_t* A, const int64_t* vA, const int64_t* B, const int64_t* vB, int64_t span) {
  const int64_t lin[8][2] = {
      {A[1] - B[0], vA[1] - vB[0]}, {B[1] - A[0], vB[1] - vA[0]}, {A[3] - B[2], vA[3] - vB[2]},
      {B[3] - A[2], vB[3] - vA[2]}, {A[1] - A[0], vA[1] - vA[0]}, {B[1] - B[0], vB[1] - vB[0]},
      {A[3] - A[2], vA[3] - vA[2]}, {B[3] - B[2], vB[3] - vB[2]},
  };
  LinearInterval<int64_t> when(Fraction{0, 1}, Fraction{span, 1});
  for (const auto& f : lin)
    if (!when.add(f[0], f[1])) return {};
  if (when.empty()) return {};
  return {when.lower().at.num, when.lower().at.den};
}

Rational to_rational(__int128 num, __int128 den) {
  if (den < 0) num = -num, den = -den;
  __int128 a = num < 0 ? -num : num, b = den;
  while (b != 0) {
    __int128 t = a % b;
    a = b;
    b = t;
  }
  if (a > 1) num /= a, den /= a;
  constexpr __int128 lim = INT64_MAX;
  if (num > lim || num < -lim || den > lim) throw std::overflow_error("collision time does not fit 64 bits");
  return Rational(static_cast<int64_t>(num), static_cast<int64_t>(den));
}

// Two boxes {xlo, xhi, ylo, yhi} overlap with positive area. Regions that
// collide during an interval have swept boxes (a static region: its
// rectangle) that do, so this is a filter before the exact test.
bool boxes_overlap(const std::array<int64_t, 4>& a, const std::array<int64_t, 4>& b) {
  return a[0] < b[1] && b[0] < a[1] && a[2] < b[3] && b[2] < a[3];
}

// Below this many moving regions the broad phase pairs them all (with the
// box filter) instead of sweeping cells.
constexpr size_t kAllMovingPairs = 48;

// The row sweep (Scratch::row_broad_phase) serves intervals in which at
// least a quarter of the regions move, no face faster than this many cells
// per unit of time: each swept box then spans at most 1 + kRowMaxSpeed
// cells of its row, so a region meets O(kRowMaxSpeed) others in the sweep.
// Faster faces (long rows of coupled expansions) keep the sub-step grid.
constexpr int64_t kRowMaxSpeed = 4;

}  // namespace

namespace {

// Regions by the cell of their lower-left corner, each cell holding the head
// of an intrusive doubly linked list of regions. Cells inside a box around
// the initial shape (given when it is at most a few times larger than the
// number of regions, as for compiled formulas) are an array indexed by
// position, so the 3 x 3 neighbourhood queries touch few cache lines; other
// cells go to an open-addressing hash table. reset() empties the table
// keeping its memory, so a simulator rebuilds it for each instance without
// allocating (once the instances stop growing).
class CellLists {
 public:
  // Empty, for num_regions regions; box: cells x0 .. x0 + w - 1,
  // y0 .. y0 + h - 1 (w = 0: none).
  void reset(size_t num_regions, int64_t x0, int64_t y0, int64_t w, int64_t h) {
    x0_ = x0, y0_ = y0, w_ = w, h_ = h;
    size_t cap = 16;
    while (cap < (w > 0 ? 64 : 4 * num_regions + 16)) cap <<= 1;
    slots_.assign(cap, Slot{});
    used_ = 0;
    dense_.assign(static_cast<size_t>(w * h), kNone);
    next_.assign(num_regions, kNone);
    prev_.assign(num_regions, kNone);
  }
  // The first region of the cell, kNone if none; then next(r) until kNone.
  uint32_t head(uint64_t key) const {
    if (size_t d = dense_index(key); d != kNoDense) return dense_[d];
    const size_t mask = slots_.size() - 1;
    for (size_t i = hash(key) & mask;; i = (i + 1) & mask) {
      if (!slots_[i].full) return kNone;
      if (slots_[i].key == key) return slots_[i].head;
    }
  }
  uint32_t next(uint32_t r) const { return next_[r]; }
  // The cell's index in the dense box, or kNoDense; the box has dense_size() cells.
  static constexpr size_t kNoDense = SIZE_MAX;
  size_t dense_index(uint64_t key) const {
    const int64_t x = static_cast<int32_t>(static_cast<uint32_t>(key >> 32)) - x0_;
    const int64_t y = static_cast<int32_t>(static_cast<uint32_t>(key)) - y0_;
    if (x < 0 || y < 0 || x >= w_ || y >= h_) return kNoDense;
    return static_cast<size_t>(y * w_ + x);
  }
  size_t dense_size() const { return dense_.size(); }
  // Cells that have a slot in the hash table (slots are never freed).
  size_t hashed_cells() const { return used_; }
  void insert(uint32_t r, uint64_t key) {
    uint32_t& h = head_ref(key);
    next_[r] = h;
    prev_[r] = kNone;
    if (h != kNone) prev_[h] = r;
    h = r;
  }
  // Requires r to be in key's list.
  void remove(uint32_t r, uint64_t key) {
    if (prev_[r] != kNone) next_[prev_[r]] = next_[r];
    else head_ref(key) = next_[r];
    if (next_[r] != kNone) prev_[next_[r]] = prev_[r];
  }

 private:
  struct Slot {
    uint64_t key = 0;
    uint32_t head = kNone;
    bool full = false;
  };
  static size_t hash(uint64_t key) {  // both coordinates reach the low bits
    key ^= key >> 33;
    key *= 0xFF51AFD7ED558CCDull;
    key ^= key >> 33;
    return static_cast<size_t>(key);
  }
  uint32_t& head_ref(uint64_t key) {
    if (size_t d = dense_index(key); d != kNoDense) return dense_[d];
    size_t mask = slots_.size() - 1;
    size_t i = hash(key) & mask;
    for (; slots_[i].full; i = (i + 1) & mask)
      if (slots_[i].key == key) return slots_[i].head;
    if (2 * (used_ + 1) > slots_.size()) {  // keep the load at most 1/2
      std::vector<Slot> old(slots_.size() * 2);
      old.swap(slots_);
      mask = slots_.size() - 1;
      for (const Slot& o : old)
        if (o.full) {
          size_t j = hash(o.key) & mask;
          while (slots_[j].full) j = (j + 1) & mask;
          slots_[j] = o;
        }
      i = hash(key) & mask;
      while (slots_[i].full) i = (i + 1) & mask;
    }
    ++used_;
    slots_[i].full = true;
    slots_[i].key = key;
    return slots_[i].head;
  }
  int64_t x0_ = 0, y0_ = 0, w_ = 0, h_ = 0;
  std::vector<Slot> slots_;
  std::vector<uint32_t> dense_;
  std::vector<uint32_t> next_, prev_;
  size_t used_ = 0;
};

// Empties `grid` for the regions' cells: a dense box of margin 2 around
// them when its area is at most 16 cells per region (plus a constant).
void reset_cell_lists(CellLists& grid, const Regions& regions) {
  const size_t nr = regions.size();
  if (nr == 0) return grid.reset(0, 0, 0, 0, 0);
  int64_t xlo = INT64_MAX, xhi = INT64_MIN, ylo = INT64_MAX, yhi = INT64_MIN;
  for (const RegionShape& sh : regions.shapes) {
    xlo = std::min(xlo, sh.base[0]), xhi = std::max(xhi, sh.base[0]);
    ylo = std::min(ylo, sh.base[2]), yhi = std::max(yhi, sh.base[2]);
  }
  constexpr int64_t margin = 2, both_margins = 4;
  const __int128 w = static_cast<__int128>(xhi) - xlo + 1 + both_margins,
                 h = static_cast<__int128>(yhi) - ylo + 1 + both_margins;
  if (w * h > static_cast<__int128>(nr) * 16 + 4096) return grid.reset(nr, 0, 0, 0, 0);
  grid.reset(nr, xlo - margin, ylo - margin, static_cast<int64_t>(w), static_cast<int64_t>(h));
}

}  // namespace

// Everything run() needs besides the prepared tables, kept between runs, and
// the steps of one run (docs/simulator.md): scale the start times, find the
// first cycle collision, then sweep the intervals between events; in each,
// cut the spanning tree, collect the moving regions, and test them.
struct Simulator::Scratch {
  struct Event {
    int64_t time;
    CouplingId q;
    bool start;
  };
  const PreparedInstance* prep = nullptr;
  const Deadline* deadline = nullptr;  // checked between intervals (Simulator::set_deadline)
  bool skip_rigid = true;              // Simulator::set_skip_rigid_pairs
  bool row_sweep = true;               // Simulator::set_row_sweep
  bool reuse = true;                   // Simulator::set_reuse_intervals: tight cells, solo tables
  // The state of the sweep. Between runs every region is back at its base
  // cell in grid and region_key except those in `touched` (moved by the last
  // run), and rect holds base * rect_D for the untouched ones. base_cells:
  // grid's hashed cells with every region at its base (a grid that grew
  // well beyond is built again by reset_positions).
  CellLists grid;
  std::vector<uint64_t> region_key;
  size_t base_cells = 0;
  int64_t rect_D = 0;
  std::vector<uint32_t> touched;
  std::vector<char> is_touched;
  std::vector<int64_t> T, ev;
  std::vector<std::array<int64_t, 4>> rect, rvel, swept;
  std::vector<Event> events;
  std::vector<char> running;
  std::vector<CouplingId> run_list;
  std::vector<uint32_t> node_stamp, region_stamp;
  uint32_t stamp = 0;
  std::vector<Vec2> node_vel;
  std::vector<NodeId> cuts;
  std::vector<OpId> running_ops;
  std::vector<int64_t> comp_size;
  std::vector<size_t> up, cut_stack;
  std::vector<std::pair<uint32_t, uint32_t>> ranges;
  std::vector<uint32_t> moving;
  std::vector<std::pair<uint32_t, Vec2>> vel_stack;
  std::vector<std::pair<uint64_t, uint32_t>> cell_hits;  // (cell, moving index) in one sub-step
  std::vector<uint64_t> moving_pairs;                    // (i << 32) | j, i < j
  // With sub-steps (S > 1) the same neighbours share a cell in step after
  // step: moving_pairs takes each pair once (the set of those taken), so it
  // stays as large as the distinct pairs, not S times that (a row of 25 000
  // expansions all running at once: 30 GB before).
  FlatMap64 pairs_taken;  // as a set (value 0): no allocation per pair, memory kept between runs
  // Per moving index j, the last two i of pairs (i, j) already taken: most
  // repeats are the same neighbours, so these spare most set look-ups.
  std::vector<std::array<uint32_t, 2>> recent_partners;
  bool dedupe_pairs = false;
  // Moving regions by cell in one sub-step, for cells of the dense box: the
  // latest hit of each cell, and per hit its moving index and the previous hit.
  std::vector<uint32_t> hit_head, hit_index, hit_prev;
  std::vector<size_t> hit_cells;
  // Rows (horizontal-only instances, rows_fixed): every region keeps the
  // y-extent [y D, (y + 1) D] of its base row y for ever, so only regions of
  // one row can overlap. row_sorted: the regions by (row, base x, id), built
  // on first use; row_end: where each row's run in it ends. row_items: one interval's
  // swept x-extents in that order, re-sorted by their left ends.
  struct RowItem {
    int64_t lo, hi;  // swept x-extent (a static region: its rectangle's)
    uint32_t r;      // the region
    uint32_t mi;     // its index in `moving`, or kNone if it stays put
  };
  bool rows_fixed = false;
  std::vector<uint32_t> row_sorted, row_end;
  std::vector<RowItem> row_items;
  std::vector<uint32_t> moving_index;  // per region: its index in `moving` (valid when stamped)
  // Per coupling q, what an interval in which q alone runs moves (it depends
  // on q only: the cut, the velocities relative to the largest component,
  // the running growth): the moving regions in collect_moving's order and
  // their face velocities, solo_regions / solo_vel [begin, end), and the
  // largest speed; begin == kNone until the first such interval after bind.
  // At most 8 entries per region in all (then no more are kept).
  struct Solo {
    uint32_t begin = kNone, end = 0;
    int64_t vmax = 1;
  };
  std::vector<Solo> solo;
  std::vector<uint32_t> solo_regions;
  std::vector<std::array<int64_t, 4>> solo_vel;

  // The run in progress: scale D, the first cycle collision (if any), stats,
  // and the earliest node collision of the current interval.
  int64_t D = 1;
  bool cycle_found = false;
  int64_t cycle_time = 0;
  size_t cycle_face = 0;
  SimStats stats;
  Frac best{};
  uint32_t best_a = kNone, best_b = kNone;

  explicit Scratch(const PreparedInstance& p) { bind(p); }

  // Points the scratch at p's tables (a new instance, or the first one),
  // keeping the arrays' memory. O(n + r) for r regions.
  // The marks (node_stamp, region_stamp) are only resized: entries kept
  // from the previous instance hold stamps up to `stamp`, which is not reset
  // (next_stamp only increases it, clearing all marks when it wraps), so
  // they stay below every later interval's stamp, as zeros would.
  void bind(const PreparedInstance& p) {
    prep = &p;
    const size_t nr = p.regions.size();
    rect.resize(nr);
    build_grid();
    for (uint32_t r : touched) is_touched[r] = 0;
    touched.clear();
    is_touched.resize(nr, 0);
    hit_head.assign(grid.dense_size(), kNone);
    node_stamp.resize(p.inst.num_nodes(), 0);
    region_stamp.resize(nr, 0);
    node_vel.resize(p.inst.num_nodes());
    rvel.resize(nr);
    moving_index.resize(nr);
    solo.assign(p.inst.couplings().size(), Solo{});
    solo_regions.clear();
    solo_vel.clear();
    bind_rows();
  }
  void bind_rows();
  void build_grid();

  SimResult run(const Schedule& s);

 private:
  const Instance& inst() const { return prep->inst; }
  const SpanningTree& tree() const { return prep->tree; }
  const Regions& regions() const { return prep->regions; }
  // The cell of region r's lower-left corner at its base.
  uint64_t base_key(uint32_t r) const {
    const RegionShape& sh = regions().shapes[r];
    return cell_key(Vec2{sh.base[0], sh.base[2]});
  }
  void scale_times(const Schedule& s);
  void find_cycle_collision();
  void reset_positions();
  void sort_events();
  void next_stamp();
  void cut_tree();
  void collect_moving();
  void add_moving(uint32_t r) {
    if (r != kNone && region_stamp[r] != stamp) region_stamp[r] = stamp, moving.push_back(r);
  }
  void add_op_regions(OpId k) {
    add_moving(regions().region_of_op[k]);
    if (inst().ops()[k].kind == OpKind::Contract) add_moving(inst().ops()[k].v);
  }
  int64_t sweep_boxes(int64_t span);
  // The swept box of moving region i over `span`, from its rect and rvel.
  void set_swept(size_t i, int64_t span) {
    const std::array<int64_t, 4>& p = rect[moving[i]];
    const std::array<int64_t, 4>& v = rvel[moving[i]];
    std::array<int64_t, 4>& sw = swept[i];
    for (size_t f = 0; f < 4; f += 2) {
      const int64_t a1 = p[f] + v[f] * span, b1 = p[f + 1] + v[f + 1] * span;
      sw[f] = std::min(p[f], a1);
      sw[f + 1] = std::max(p[f + 1], b1);
    }
  }
  int64_t find_moving(int64_t span);
  int64_t reuse_solo(const Solo& so, int64_t span);
  void test_pair(uint32_t a, uint32_t b, bool b_moves, int64_t span);
  void moving_against_static(int64_t span);
  bool use_rows(int64_t vmax) const {
    return rows_fixed && row_sweep && moving.size() > kAllMovingPairs && vmax <= kRowMaxSpeed &&
           4 * moving.size() >= regions().size();
  }
  void row_broad_phase(int64_t span);
  void sweep_row(size_t b, size_t e, int64_t span);
  void moving_against_moving(int64_t span, int64_t S);
  void few_moving_pairs(int64_t span);
  void pairs_in_dense_cell(size_t d, uint32_t i);
  bool rigid_apart(uint32_t a, uint32_t b) const;
  void add_moving_pair(uint32_t i, uint32_t j);
  void advance(int64_t span);
  SimResult cycle_result() const;
  SimResult node_result(int64_t now) const;
};

namespace {
// The cell of scaled coordinate a: floor(a / D); integer schedules (D = 1,
// every order) need no division.
int64_t cell_of(int64_t a, int64_t D) { return D == 1 ? a : floor_div(a, D); }
}  // namespace

void Simulator::Scratch::scale_times(const Schedule& s) {
  const size_t nq = inst().couplings().size();
  D = 1;
  for (const auto& t : s.start) D = std::lcm(D, t.den());
  T.resize(nq);
  for (size_t q = 0; q < nq; ++q) T[q] = s.start[q].num() * (D / s.start[q].den());
}

// The earliest cycle collision over all faces (an event time): the first
// moment the mismatch around a face is non-zero.
void Simulator::Scratch::find_cycle_collision() {
  cycle_found = false;
  cycle_time = 0;
  cycle_face = 0;
  const auto& faces = prep->faces.faces;
  for (size_t f = 0; f < faces.size(); ++f) {
    if (deadline && (f & 4095) == 0) deadline->check();
    const auto& nets = faces[f].nets;
    ev.clear();
    for (auto& [q, v] : nets) ev.push_back(T[q]), ev.push_back(T[q] + D);
    std::sort(ev.begin(), ev.end());
    ev.erase(std::unique(ev.begin(), ev.end()), ev.end());
    for (size_t i = 1; i < ev.size(); ++i) {
      Vec2 mis{0, 0};
      for (auto& [q, v] : nets) mis += std::clamp<int64_t>(ev[i] - T[q], 0, D) * v;
      if (!mis.is_zero()) {
        if (!cycle_found || ev[i - 1] < cycle_time) cycle_found = true, cycle_time = ev[i - 1], cycle_face = f;
        break;
      }
    }
  }
}

// The cell table with every region at its base cell (independent of D),
// built in place (the same table whenever it is built for one instance),
// and in the same pass every rectangle at its base for D = 1 (rect_D = 1:
// the first run after a bind, usually an order (D = 1), then resets only
// the regions it moves; a run with another D rescales them all).
void Simulator::Scratch::build_grid() {
  const Regions& R = regions();
  const auto nr = static_cast<uint32_t>(R.size());
  reset_cell_lists(grid, R);
  region_key.resize(nr);
  for (uint32_t r = 0; r < nr; ++r) {
    const int64_t* b = R.shapes[r].base;
    grid.insert(r, region_key[r] = cell_key(Vec2{b[0], b[2]}));
    rect[r] = {b[0], b[1], b[2], b[3]};
  }
  base_cells = grid.hashed_cells();
  rect_D = 1;
}

// Every region back at its base, scaled by D: only the regions the last run
// moved, unless D changed (or the cell table grew much: then built again).
void Simulator::Scratch::reset_positions() {
  const size_t nr = regions().size();
  if (grid.hashed_cells() > base_cells + nr + 64) {
    build_grid();
  } else {
    for (uint32_t r : touched)
      if (const uint64_t k = base_key(r); region_key[r] != k) {
        grid.remove(r, region_key[r]);
        grid.insert(r, k);
        region_key[r] = k;
      }
  }
  auto set_rect = [&](uint32_t r) {
    for (int f = 0; f < 4; ++f) rect[r][f] = regions().shapes[r].base[f] * D;
  };
  if (rect_D != D) {
    for (uint32_t r = 0; r < nr; ++r) set_rect(r);
    rect_D = D;
  } else {
    for (uint32_t r : touched) set_rect(r);
  }
  for (uint32_t r : touched) is_touched[r] = 0;
  touched.clear();
}

void Simulator::Scratch::sort_events() {
  const size_t nq = inst().couplings().size();
  events.clear();
  for (CouplingId q = 0; q < nq; ++q) events.push_back({T[q], q, true}), events.push_back({T[q] + D, q, false});
  std::sort(events.begin(), events.end(),
            [](const Event& a, const Event& b) { return a.time != b.time ? a.time < b.time : a.start < b.start; });
}

// A fresh stamp for the interval's node and region marks.
void Simulator::Scratch::next_stamp() {
  if (++stamp == 0) {  // the stamps wrapped around: start them afresh
    std::fill(node_stamp.begin(), node_stamp.end(), 0);
    std::fill(region_stamp.begin(), region_stamp.end(), 0);
    stamp = 1;
  }
}

// Cut the tree at the running operations' tree edges: `cuts` (by Euler
// position), the component above each cut (`up`), their sizes, and the
// Euler ranges of every component but the largest (which stays put).
void Simulator::Scratch::cut_tree() {
  const SpanningTree& t = tree();
  cuts.clear();
  running_ops.clear();
  for (CouplingId q : run_list)
    for (OpId k : inst().couplings()[q].ops) {
      running_ops.push_back(k);
      const Operation& op = inst().ops()[k];
      if (!op.is_edge_op()) continue;
      if (t.parent[op.v] == op.u && t.parent_op[op.v] == k) cuts.push_back(op.v);
      else if (t.parent[op.u] == op.v && t.parent_op[op.u] == k) cuts.push_back(op.u);
    }
  std::sort(cuts.begin(), cuts.end(), [&](NodeId a, NodeId b) { return t.tin[a] < t.tin[b]; });
  const size_t nc = cuts.size(), ROOT = nc;
  comp_size.assign(nc + 1, 0);
  up.assign(nc, ROOT);
  comp_size[ROOT] = static_cast<int64_t>(inst().num_nodes());
  cut_stack.clear();
  for (size_t i = 0; i < nc; ++i) {
    comp_size[i] = t.subtree[cuts[i]];
    while (!cut_stack.empty() && t.tout[cuts[cut_stack.back()]] <= t.tin[cuts[i]]) cut_stack.pop_back();
    up[i] = cut_stack.empty() ? ROOT : cut_stack.back();
    comp_size[up[i]] -= t.subtree[cuts[i]];
    cut_stack.push_back(i);
  }
  size_t L = ROOT;
  for (size_t i = 0; i < nc; ++i)
    if (comp_size[i] > comp_size[L]) L = i;
  // Ranges of Euler positions that move, in increasing order.
  ranges.clear();
  if (L == ROOT) {
    for (size_t i = 0; i < nc; ++i)
      if (up[i] == ROOT) ranges.push_back({t.tin[cuts[i]], t.tout[cuts[i]]});
  } else {
    ranges.push_back({0, t.tin[cuts[L]]});
    for (size_t i = 0; i < nc; ++i)
      if (up[i] == L) ranges.push_back({t.tin[cuts[i]], t.tout[cuts[i]]});
    ranges.push_back({t.tout[cuts[L]], static_cast<uint32_t>(inst().num_nodes())});
  }
  // The largest component's velocity, subtracted from every node's.
  Vec2 vel_L{0, 0};
  if (L != ROOT)
    for (size_t i = L;; i = up[i]) {
      vel_L += op_child_vector(inst(), t, cuts[i]);
      if (up[i] == ROOT) break;
    }
  vel_stack.clear();
  vel_stack.push_back({UINT32_MAX, Vec2{0, 0} - vel_L});  // the bottom: the root component
}

// The nodes of the moving ranges get their velocities (relative to the
// largest component); the moving regions are theirs, plus those of the
// running operations (whose width changes).
void Simulator::Scratch::collect_moving() {
  const SpanningTree& t = tree();
  const size_t nc = cuts.size();
  moving.clear();
  size_t ptr = 0;
  for (auto [b, e] : ranges)
    for (uint32_t p = b; p < e; ++p) {
      while (vel_stack.back().first <= p) vel_stack.pop_back();
      while (ptr < nc && t.tin[cuts[ptr]] <= p) {
        NodeId c = cuts[ptr++];
        while (vel_stack.back().first <= t.tin[c]) vel_stack.pop_back();
        if (t.tout[c] > p) vel_stack.push_back({t.tout[c], vel_stack.back().second + op_child_vector(inst(), t, c)});
      }
      NodeId w = t.order[p];
      node_vel[w] = vel_stack.back().second;
      node_stamp[w] = stamp;
      add_moving(w);
      if (OpId k = inst().op_of_node(w); k != kNone) add_op_regions(k);
    }
  for (OpId k : running_ops) add_op_regions(k);
  stats.moved_regions += moving.size();
}

// Velocities and swept boxes of the moving regions over `span`. Returns the
// largest speed of a moving face (at least 1).
int64_t Simulator::Scratch::sweep_boxes(int64_t span) {
  int64_t vmax = 1;
  swept.resize(moving.size());
  const auto vel_of = [&](NodeId w) { return node_stamp[w] == stamp ? node_vel[w] : Vec2{0, 0}; };
  for (size_t i = 0; i < moving.size(); ++i) {
    const uint32_t r = moving[i];
    moving_index[r] = static_cast<uint32_t>(i);
    const RegionShape& sh = regions().shapes[r];
    // Faces usually follow one node (all four for a node's own region):
    // each distinct node's velocity is looked up once.
    const Vec2 v0 = vel_of(sh.ref[0]);
    const Vec2 v1 = sh.ref[1] == sh.ref[0] ? v0 : vel_of(sh.ref[1]);
    const Vec2 v2 = sh.ref[2] == sh.ref[0] ? v0 : vel_of(sh.ref[2]);
    const Vec2 v3 = sh.ref[3] == sh.ref[2] ? v2 : vel_of(sh.ref[3]);
    std::array<int64_t, 4>& vel = rvel[r];
    vel = {v0.x, v1.x, v2.y, v3.y};
    if (sh.grow_op != kNone && running[inst().ops()[sh.grow_op].coupling])
      vel[static_cast<size_t>(sh.grow_face)] += sh.grow_sign;
    for (const int64_t vf : vel) vmax = std::max(vmax, vf < 0 ? -vf : vf);
    set_swept(i, span);
  }
  return vmax;
}

// The interval's moving regions, their velocities and swept boxes; returns
// the largest speed. When one coupling q alone runs, from q's solo table if
// it has one (recording it otherwise, within the budget).
int64_t Simulator::Scratch::find_moving(int64_t span) {
  const bool one = reuse && run_list.size() == 1;
  if (one && solo[run_list[0]].begin != kNone) return reuse_solo(solo[run_list[0]], span);
  cut_tree();
  collect_moving();
  const int64_t vmax = sweep_boxes(span);
  if (one && solo_regions.size() + moving.size() <= 8 * regions().size()) {
    const auto begin = static_cast<uint32_t>(solo_regions.size());
    for (uint32_t r : moving) solo_regions.push_back(r), solo_vel.push_back(rvel[r]);
    // Recorded only once its entries exist (an allocation failure above
    // leaves the coupling without a table, not with a dangling one).
    solo[run_list[0]] = Solo{begin, static_cast<uint32_t>(solo_regions.size()), vmax};
  }
  return vmax;
}

// What cut_tree, collect_moving and sweep_boxes give when so's coupling
// alone runs: the same moving regions in the same order, marked, with the
// same velocities (the stats count them alike).
int64_t Simulator::Scratch::reuse_solo(const Solo& so, int64_t span) {
  moving.assign(solo_regions.begin() + static_cast<std::ptrdiff_t>(so.begin),
                solo_regions.begin() + static_cast<std::ptrdiff_t>(so.end));
  swept.resize(moving.size());
  for (size_t i = 0; i < moving.size(); ++i) {
    const uint32_t r = moving[i];
    region_stamp[r] = stamp;
    moving_index[r] = static_cast<uint32_t>(i);
    rvel[r] = solo_vel[so.begin + i];
    set_swept(i, span);
  }
  stats.moved_regions += moving.size();
  ++stats.reused_intervals;
  return so.vmax;
}

// The exact test of one candidate pair; keeps the earliest collision (the
// smallest pair on ties), so the order of the tests does not matter.
void Simulator::Scratch::test_pair(uint32_t a, uint32_t b, bool b_moves, int64_t span) {
  static const int64_t zero4[4] = {0, 0, 0, 0};
  ++stats.candidate_pairs;
  Frac f = first_overlap(rect[a].data(), rvel[a].data(), rect[b].data(), b_moves ? rvel[b].data() : zero4, span);
  if (!f.none() &&
      (best.none() || frac_less(f, best) || (!frac_less(best, f) && std::minmax(a, b) < std::minmax(best_a, best_b))))
    best = f, best_a = std::min(a, b), best_b = std::max(a, b);
}

// Moving against static: each moving region queries the cells of its swept
// box (a static region's lower-left corner lies at most one cell before the
// box). Cells hold O(1) static regions: the shape has no overlaps.
// Tight cells (reuse, the default): a region is at most one cell
// wide and high (D scaled units), so one whose lower face is at or below
// sw[0] - D ends at or before sw[0] and fails boxes_overlap; the first
// column queried is then the cell of sw[0] - D + 1 (the box's own, not the
// one before, whenever sw[0] is the last unit of its cell: always when
// D = 1, as in every order), and likewise for rows. The skipped cells hold
// only regions that boxes_overlap rejects, so the pairs tested are the same.
void Simulator::Scratch::moving_against_static(int64_t span) {
  for (size_t i = 0; i < moving.size(); ++i) {
    uint32_t r = moving[i];
    const auto& sw = swept[i];
    if (sw[1] <= sw[0] || sw[3] <= sw[2]) continue;  // never of positive area
    const int64_t cx1 = cell_of(sw[1] - 1, D), cy1 = cell_of(sw[3] - 1, D);
    const int64_t cx0 = reuse ? cell_of(sw[0] - D + 1, D) : cell_of(sw[0], D) - 1;
    const int64_t cy0 = reuse ? cell_of(sw[2] - D + 1, D) : cell_of(sw[2], D) - 1;
    for (int64_t cx = cx0; cx <= cx1; ++cx)
      for (int64_t cy = cy0; cy <= cy1; ++cy)
        for (uint32_t x = grid.head(cell_key(Vec2{cx, cy})); x != kNone; x = grid.next(x))
          if (region_stamp[x] != stamp && boxes_overlap(sw, rect[x])) test_pair(r, x, false, span);
  }
}

// Regions a and b can first overlap inside this interval only if they move
// relative to each other or already overlap: when both translate (no face
// moves against its opposite one) with the same velocity, every one of the
// eight conditions of first_overlap keeps its value, so the pair never
// overlaps if it does not now. Skipping such pairs is exact (not a filter
// resting on an assumption about the shape). All couplings at once move
// whole gadgets rigidly: most neighbours then translate alike, and they
// share cells in every sub-step.
inline bool Simulator::Scratch::rigid_apart(uint32_t a, uint32_t b) const {
  const auto& va = rvel[a];
  return skip_rigid && va[0] == va[1] && va[2] == va[3] && va == rvel[b] && !boxes_overlap(rect[a], rect[b]);
}

// Moving regions i < j share a cell in some sub-step: a candidate pair.
void Simulator::Scratch::add_moving_pair(uint32_t i, uint32_t j) {
  if (rigid_apart(moving[i], moving[j])) return;
  const uint64_t ij = (static_cast<uint64_t>(i) << 32) | j;
  if (!dedupe_pairs) {
    moving_pairs.push_back(ij);
    return;
  }
  std::array<uint32_t, 2>& recent = recent_partners[j];
  if (recent[0] == i || recent[1] == i) return;
  recent[1] = recent[0];
  recent[0] = i;
  if (pairs_taken.emplace(ij, 0).second) moving_pairs.push_back(ij);
}

// Moving region i enters dense cell d in this sub-step: pair it with every
// earlier region of the cell (all of smaller index).
void Simulator::Scratch::pairs_in_dense_cell(size_t d, uint32_t i) {
  for (uint32_t h = hit_head[d]; h != kNone; h = hit_prev[h]) add_moving_pair(hit_index[h], i);
  if (hit_head[d] == kNone) hit_cells.push_back(d);
  hit_prev.push_back(hit_head[d]);
  hit_index.push_back(i);
  hit_head[d] = static_cast<uint32_t>(hit_index.size() - 1);
}

// The pairs of few moving regions (at most kAllMovingPairs: one coupling
// running, as in every order) that moving_against_moving's path without
// reuse tests: those whose swept boxes overlap and that rigid_apart keeps.
// Each region gets a rigid-velocity class: one per distinct velocity of the
// regions that translate (va[0] == va[1], va[2] == va[3]), kNone for the
// others (and for all when skip_rigid is off); rigid_apart(a, b) then holds
// exactly when a and b share a class (not kNone) and their rectangles do
// not overlap now. For such a pair, boxes_overlap of the swept boxes follows
// from boxes_overlap of the rectangles (a swept box contains its rectangle),
// so the old path tests a pair of one class iff its rectangles overlap.
// Two regions of one class whose rectangles both have positive width and
// height never do (so they are skipped without a check), by this invariant
// (I) of a run: at the start of every interval the run reaches, no two
// regions of positive width and height overlap. At the first event every
// region is at its base: the nodes' distinct unit cells, and regions of
// width 0. If a and b (positive extents) overlapped at the start `now` of a
// later interval, the eight strict conditions of first_overlap, continuous
// in time, would hold just before `now`, in the last interval that moved
// anything (nothing moves in between): either at its start too (then (I)
// fails there: induction), or from some moment inside it, which that
// interval's exact test finds (every broad phase passes each pair that
// collides in its interval: the static pairs keep their relative position,
// and its rigid skips are exact by this argument at its own start), so the
// run would have returned that collision. Pairs of different classes (or
// kNone) are tested iff their swept boxes overlap, as before; a pair of one
// class with a region of width or height 0 iff its rectangles overlap. So
// the pairs tested are the old path's (same results and stats), and
// test_pair does not depend on their order (nor on a pair's: first_overlap
// is symmetric in A and B). The largest class's regions of positive extents
// (an order's moved component) meet only the others, not each other.
void Simulator::Scratch::few_moving_pairs(int64_t span) {
  const auto m = static_cast<uint32_t>(moving.size());
  std::array<uint32_t, kAllMovingPairs> cls, size;  // class per index, regions per class
  std::array<bool, kAllMovingPairs> solid;          // positive width and height now
  std::array<std::array<int64_t, 2>, kAllMovingPairs> class_vel;
  uint32_t classes = 0, largest = kNone;
  for (uint32_t i = 0; i < m; ++i) {
    const std::array<int64_t, 4>& v = rvel[moving[i]];
    const std::array<int64_t, 4>& p = rect[moving[i]];
    solid[i] = p[1] > p[0] && p[3] > p[2];
    cls[i] = kNone;
    if (!skip_rigid || v[0] != v[1] || v[2] != v[3]) continue;
    uint32_t c = 0;
    while (c < classes && (class_vel[c][0] != v[0] || class_vel[c][1] != v[2])) ++c;
    if (c == classes) class_vel[classes] = {v[0], v[2]}, size[classes++] = 0;
    cls[i] = c;
    if (solid[i] && (++size[c], largest == kNone || size[c] > size[largest])) largest = c;
  }
  std::array<uint32_t, kAllMovingPairs> inside, outside;  // the largest class's solid regions, the rest
  uint32_t ni = 0, no = 0;
  for (uint32_t i = 0; i < m; ++i)
    (largest != kNone && cls[i] == largest && solid[i] ? inside[ni++] : outside[no++]) = i;
  const auto tested = [&](uint32_t i, uint32_t j) {
    if (cls[i] != cls[j] || cls[i] == kNone) return boxes_overlap(swept[i], swept[j]);
    return !(solid[i] && solid[j]) && boxes_overlap(rect[moving[i]], rect[moving[j]]);
  };
  // The inside regions' boxes, side by side: a region outside meets them by
  // their rectangles if it is of their class (then not solid), otherwise by
  // their swept boxes (what `tested` gives for these pairs).
  std::array<std::array<int64_t, 4>, kAllMovingPairs> in_rect, in_swept;
  for (uint32_t y = 0; y < ni; ++y) in_rect[y] = rect[moving[inside[y]]], in_swept[y] = swept[inside[y]];
  for (uint32_t x = 0; x < no; ++x) {
    const uint32_t i = outside[x];
    for (uint32_t y = x + 1; y < no; ++y)
      if (tested(i, outside[y])) test_pair(moving[i], moving[outside[y]], true, span);
    const bool same = cls[i] == largest;
    const std::array<int64_t, 4>& box = same ? rect[moving[i]] : swept[i];
    const auto& boxes = same ? in_rect : in_swept;
    for (uint32_t y = 0; y < ni; ++y)
      if (boxes_overlap(box, boxes[y])) test_pair(moving[i], moving[inside[y]], true, span);
  }
}

// Moving against moving. Up to kAllMovingPairs moving regions (one coupling
// running, as in every order): every pair whose swept boxes overlap. More:
// split the interval into S = max speed sub-steps
// (for the broad phase only), so that in each sub-step every region sweeps
// at most about two cells and a cell holds O(1) regions; pairs that share a
// cell in some sub-step go to the exact test over the whole interval.
// Without the split, long sweeps (many coupled operations in a row) would
// pile many regions into each cell: quadratic.
void Simulator::Scratch::moving_against_moving(int64_t span, int64_t S) {
  moving_pairs.clear();
  if (moving.size() <= kAllMovingPairs && reuse) {  // few, by rigid-velocity class (reuse)
    few_moving_pairs(span);
    return;
  }
  if (moving.size() <= kAllMovingPairs) {  // few: every pair whose swept boxes overlap
    // By the left end of the swept box: each box meets only the boxes that
    // start before its right end (the pairs and the tests are the same as
    // over all pairs; test_pair does not depend on their order).
    std::array<uint32_t, kAllMovingPairs> by_x;
    const size_t m = moving.size();
    for (uint32_t i = 0; i < m; ++i) by_x[i] = i;
    std::sort(by_x.begin(), by_x.begin() + static_cast<std::ptrdiff_t>(m),
              [&](uint32_t a, uint32_t b) { return swept[a][0] < swept[b][0]; });
    for (size_t x = 0; x < m; ++x)
      for (size_t y = x + 1; y < m && swept[by_x[y]][0] < swept[by_x[x]][1]; ++y)
        if (boxes_overlap(swept[by_x[x]], swept[by_x[y]]) && !rigid_apart(moving[by_x[x]], moving[by_x[y]]))
          test_pair(moving[by_x[x]], moving[by_x[y]], true, span);
    return;
  }
  dedupe_pairs = S > 1;
  if (dedupe_pairs) {
    pairs_taken.clear();
    recent_partners.assign(moving.size(), {kNone, kNone});
  }
  const __int128 unit = static_cast<__int128>(D) * S;  // one cell, in sub-step units
  auto floor128 = [](__int128 a, __int128 b) -> __int128 {
    if (a >= INT64_MIN && a <= INT64_MAX && b > 0 && b <= INT64_MAX)  // the usual case: a 64-bit division
      return floor_div(static_cast<int64_t>(a), static_cast<int64_t>(b));
    return a / b - ((a % b != 0) && ((a < 0) != (b < 0)) ? 1 : 0);
  };
  for (int64_t step = 0; step < S; ++step) {
    if (deadline && step % 64 == 63) deadline->check();  // S sub-steps of all moving regions: long
    cell_hits.clear();
    for (size_t i = 0; i < moving.size(); ++i) {
      int64_t c[4];  // cells x0, x1, y0, y1 of the sub-step's swept box
      if (S == 1) {  // the sub-step is the interval: its swept box
        const auto& sw = swept[i];
        if (sw[1] <= sw[0] || sw[3] <= sw[2]) continue;
        c[0] = cell_of(sw[0], D), c[1] = cell_of(sw[1] - 1, D), c[2] = cell_of(sw[2], D), c[3] = cell_of(sw[3] - 1, D);
      } else {
        const uint32_t r = moving[i];
        __int128 box[4];
        for (int f = 0; f < 4; ++f) {
          __int128 p0 = static_cast<__int128>(rect[r][f]) * S + static_cast<__int128>(rvel[r][f]) * span * step;
          __int128 p1 = p0 + static_cast<__int128>(rvel[r][f]) * span;
          box[f] = (f % 2 == 0) ? std::min(p0, p1) : std::max(p0, p1);
        }
        if (box[1] <= box[0] || box[3] <= box[2]) continue;
        c[0] = static_cast<int64_t>(floor128(box[0], unit)), c[1] = static_cast<int64_t>(floor128(box[1] - 1, unit));
        c[2] = static_cast<int64_t>(floor128(box[2], unit)), c[3] = static_cast<int64_t>(floor128(box[3] - 1, unit));
      }
      for (int64_t cx = c[0]; cx <= c[1]; ++cx)
        for (int64_t cy = c[2]; cy <= c[3]; ++cy) {
          const uint64_t key = cell_key(Vec2{cx, cy});
          const size_t d = grid.dense_index(key);
          if (d == CellLists::kNoDense) cell_hits.push_back({key, static_cast<uint32_t>(i)});
          else pairs_in_dense_cell(d, static_cast<uint32_t>(i));
        }
    }
    for (size_t d : hit_cells) hit_head[d] = kNone;
    hit_cells.clear();
    hit_index.clear();
    hit_prev.clear();
    // Regions sharing a cell outside the box in this sub-step: runs of equal
    // keys, indices increasing.
    std::sort(cell_hits.begin(), cell_hits.end());
    for (size_t x = 0; x < cell_hits.size();) {
      size_t y = x + 1;
      while (y < cell_hits.size() && cell_hits[y].first == cell_hits[x].first) ++y;
      for (size_t a = x; a < y; ++a)
        for (size_t b = a + 1; b < y; ++b) add_moving_pair(cell_hits[a].second, cell_hits[b].second);
      x = y;
    }
  }
  std::sort(moving_pairs.begin(), moving_pairs.end());
  moving_pairs.erase(std::unique(moving_pairs.begin(), moving_pairs.end()), moving_pairs.end());
  for (uint64_t ij : moving_pairs)
    test_pair(moving[static_cast<uint32_t>(ij >> 32)], moving[static_cast<uint32_t>(ij & 0xffffffffu)], true, span);
}

// Rows: horizontal-only instances whose regions are all one cell high (so
// always: compiled formulas, random horizontal families). No operation moves
// a face along y there, so each region stays in its base row.
void Simulator::Scratch::bind_rows() {
  const Regions& R = regions();
  rows_fixed = inst().horizontal_only() && std::all_of(R.shapes.begin(), R.shapes.end(), [](const RegionShape& sh) {
                 return sh.base[3] == sh.base[2] + 1;
               });
  row_sorted.clear();
  row_end.clear();
}

// The broad phase by rows, for intervals where many regions move slowly
// (verify's gap witness: every coupling at once). Regions of different rows
// never overlap (their y-extents are fixed unit rows), so the candidates
// are the pairs of one row, at least one of them moving, whose swept boxes
// overlap: the filter of the few-regions path, found by sorting each row by
// the left ends (from the base order, which they rarely leave: an insertion
// sort) and meeting each item only with those that start before its right
// end. Every pair that collides in the interval is among them, and
// test_pair keeps the earliest collision whatever the set, so the answer is
// the grid path's (SimulatorTwin.RowSweepAgreesWithCellGrid). O(r) per
// interval for r regions, plus the pairs.
void Simulator::Scratch::row_broad_phase(int64_t span) {
  if (row_sorted.size() != regions().size()) {
    // The prepared node order merged with the other regions (reuse), or the
    // counting sorts: the same order (PreparedRowOrder.RegionsByRowTwin).
    row_sorted = reuse ? regions_by_row(regions(), prep->rows) : regions_by_row(regions());
    const Regions& R = regions();
    const size_t nr = R.size();
    for (size_t i = 1; i <= nr; ++i)
      if (i == nr || R.shapes[row_sorted[i]].base[2] != R.shapes[row_sorted[i - 1]].base[2])
        row_end.push_back(static_cast<uint32_t>(i));
  }
  row_items.resize(row_sorted.size());
  for (size_t i = 0; i < row_sorted.size(); ++i) {
    const uint32_t r = row_sorted[i];
    if (region_stamp[r] == stamp) {
      const uint32_t mi = moving_index[r];
      row_items[i] = RowItem{swept[mi][0], swept[mi][1], r, mi};
    } else {
      row_items[i] = RowItem{rect[r][0], rect[r][1], r, kNone};
    }
  }
  size_t b = 0;
  for (const uint32_t e : row_end) {
    sweep_row(b, e, span);
    b = e;
  }
}

// One row's items [b, e): sort by left end, then meet the overlapping ones.
void Simulator::Scratch::sweep_row(size_t b, size_t e, int64_t span) {
  const auto first = row_items.begin() + static_cast<std::ptrdiff_t>(b);
  const auto last = row_items.begin() + static_cast<std::ptrdiff_t>(e);
  const auto by_lo = [](const RowItem& x, const RowItem& y) { return x.lo < y.lo; };
  size_t shifts = 0;  // an insertion sort while the items are nearly in order
  for (size_t i = b + 1; i < e && shifts <= 8 * (e - b); ++i) {
    const RowItem item = row_items[i];
    size_t j = i;
    for (; j > b && item.lo < row_items[j - 1].lo; --j, ++shifts) row_items[j] = row_items[j - 1];
    row_items[j] = item;
  }
  if (shifts > 8 * (e - b)) std::sort(first, last, by_lo);
  for (size_t x = b; x < e; ++x) {
    const RowItem& p = row_items[x];
    for (size_t y = x + 1; y < e && row_items[y].lo < p.hi; ++y) {
      const RowItem& q = row_items[y];
      if (p.mi == kNone && q.mi == kNone) continue;
      if (p.mi != kNone && q.mi != kNone) {
        if (boxes_overlap(swept[p.mi], swept[q.mi]) && !rigid_apart(p.r, q.r)) test_pair(p.r, q.r, true, span);
        continue;
      }
      const RowItem& mv = p.mi != kNone ? p : q;
      const uint32_t still = p.mi != kNone ? q.r : p.r;
      const auto& sw = swept[mv.mi];
      if (sw[1] > sw[0] && sw[3] > sw[2] && boxes_overlap(sw, rect[still])) test_pair(mv.r, still, false, span);
    }
  }
}

// Advance the moving regions to the end of the interval.
void Simulator::Scratch::advance(int64_t span) {
  for (uint32_t r : moving) {
    for (int f = 0; f < 4; ++f) rect[r][f] += rvel[r][f] * span;
    if (!is_touched[r]) is_touched[r] = 1, touched.push_back(r);
    const uint64_t k = cell_key(Vec2{cell_of(rect[r][0], D), cell_of(rect[r][2], D)});
    if (k != region_key[r]) {
      grid.remove(r, region_key[r]);
      grid.insert(r, k);
      region_key[r] = k;
    }
  }
}

SimResult Simulator::Scratch::cycle_result() const {
  SimResult result;
  result.stats = stats;
  Collision c;
  c.kind = Collision::Kind::Cycle;
  c.time = to_rational(cycle_time, D);
  c.cycle = prep->faces.faces[cycle_face].walk;
  for (CouplingId q = 0; q < inst().couplings().size(); ++q)
    if (T[q] <= cycle_time && cycle_time < T[q] + D) c.moving.push_back(q);
  result.collision = c;
  return result;
}

SimResult Simulator::Scratch::node_result(int64_t now) const {
  SimResult result;
  result.stats = stats;
  Collision c;
  c.kind = Collision::Kind::Node;
  c.time = to_rational(static_cast<__int128>(now) * best.den + best.num, best.den * D);
  c.a = best_a;
  c.b = best_b;
  c.moving = run_list;
  std::sort(c.moving.begin(), c.moving.end());
  result.collision = c;
  return result;
}

SimResult Simulator::Scratch::run(const Schedule& s) {
  stats = SimStats{};
  scale_times(s);
  find_cycle_collision();
  reset_positions();
  sort_events();
  running.assign(inst().couplings().size(), 0);
  run_list.clear();
  for (size_t ei = 0; ei < events.size();) {
    const int64_t now = events[ei].time;
    for (; ei < events.size() && events[ei].time == now; ++ei) {
      const CouplingId q = events[ei].q;
      running[q] = events[ei].start;
      if (events[ei].start) run_list.push_back(q);
      else run_list.erase(std::find(run_list.begin(), run_list.end(), q));
    }
    if (cycle_found && cycle_time <= now) return cycle_result();
    if (run_list.empty() || ei == events.size()) continue;
    if (deadline) deadline->check();
    const int64_t span = events[ei].time - now;
    ++stats.intervals;
    next_stamp();
    const int64_t vmax = find_moving(span);
    best = Frac{};
    best_a = best_b = kNone;
    if (use_rows(vmax)) {
      ++stats.row_sweeps;
      row_broad_phase(span);
    } else {
      moving_against_static(span);
      moving_against_moving(span, vmax);
    }
    if (!best.none()) return node_result(now);
    // After the last interval nothing reads the positions (reuse: skip the
    // advance; reset_positions then has nothing of this interval to undo).
    if (!reuse || events.back().time != events[ei].time) advance(span);
  }
  if (cycle_found) return cycle_result();
  SimResult result;
  result.stats = stats;
  return result;
}

Simulator::Simulator(const Instance& inst) : owned_(std::make_unique<PreparedInstance>(inst)), prep_(owned_.get()) {}
Simulator::Simulator(const PreparedInstance& prep) : prep_(&prep) {}
Simulator::~Simulator() = default;
Simulator::Simulator(Simulator&&) noexcept = default;

void Simulator::rebind(const PreparedInstance& prep) {
  owned_.reset();
  prep_ = &prep;
  if (scratch_) scratch_->bind(prep);
}

SimResult Simulator::run(const Schedule& s) {
  if (auto problem = check_schedule_bounds(prep_->inst, s)) throw std::invalid_argument(*problem);
  if (!scratch_) scratch_ = std::make_unique<Scratch>(*prep_);
  scratch_->deadline = deadline_;
  scratch_->skip_rigid = skip_rigid_;
  scratch_->row_sweep = row_sweep_;
  scratch_->reuse = reuse_;
  return scratch_->run(s);
}

std::vector<RectQ> configuration_at(const Instance& inst, const Schedule& s, const Rational& t) {
  SpanningTree tree = SpanningTree::build(inst);
  Regions regions = Regions::build(inst);
  auto progress = [&](CouplingId q) {
    Rational p = t - s.start[q];
    return p < Rational(0) ? Rational(0) : p > Rational(1) ? Rational(1) : p;
  };
  std::vector<Rational> dx(inst.num_nodes()), dy(inst.num_nodes());
  for (NodeId w : tree.order) {
    if (w == tree.root) continue;
    NodeId p = tree.parent[w];
    dx[w] = dx[p], dy[w] = dy[p];
    OpId k = tree.parent_op[w];
    if (k == kNone) continue;
    Rational pk = progress(inst.ops()[k].coupling);
    Vec2 v = op_child_vector(inst, tree, w);
    dx[w] = dx[w] + pk * Rational(v.x);
    dy[w] = dy[w] + pk * Rational(v.y);
  }
  std::vector<RectQ> out(regions.size());
  for (size_t r = 0; r < regions.size(); ++r) {
    const RegionShape& sh = regions.shapes[r];
    Rational c[4];
    for (int f = 0; f < 4; ++f) {
      c[f] = Rational(sh.base[f]) + (f < 2 ? dx[sh.ref[f]] : dy[sh.ref[f]]);
      if (sh.grow_op != kNone && f == sh.grow_face)
        c[f] = c[f] + Rational(sh.grow_sign) * progress(inst.ops()[sh.grow_op].coupling);
    }
    out[r] = RectQ{c[0], c[1], c[2], c[3]};
  }
  return out;
}

std::string describe(const Instance& inst, const Regions& regions, const Collision& c) {
  std::string s;
  if (c.kind == Collision::Kind::Node) {
    s = "node collision at time " + c.time.str() + " between " + region_label(inst, regions, c.a) + " and " +
        region_label(inst, regions, c.b);
  } else {
    s = "cycle collision at time " + c.time.str() + " around the cycle through";
    size_t shown = std::min<size_t>(c.cycle.size(), 12);
    for (size_t i = 0; i < shown; ++i) s += " " + inst.node_label(c.cycle[i]);
    if (shown < c.cycle.size()) s += " ... (" + std::to_string(c.cycle.size()) + " steps)";
  }
  return s;
}

}  // namespace gridlock
