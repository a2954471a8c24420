#include "lattice/simulate.hpp"

#include <algorithm>
#include <array>
#include <climits>
#include <cstdint>
#include <numeric>
#include <stdexcept>

#include "common/int_math.hpp"

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
// Eight strict inequalities a + b tau > 0: the four overlap conditions and
// the four widths (a region of width 0 never collides).
Frac first_overlap(const int64_t* A, const int64_t* vA, const int64_t* B, const int64_t* vB, int64_t span) {
  const int64_t lin[8][2] = {
      {A[1] - B[0], vA[1] - vB[0]}, {B[1] - A[0], vB[1] - vA[0]}, {A[3] - B[2], vA[3] - vB[2]},
      {B[3] - A[2], vB[3] - vA[2]}, {A[1] - A[0], vA[1] - vA[0]}, {B[1] - B[0], vB[1] - vB[0]},
      {A[3] - A[2], vA[3] - vA[2]}, {B[3] - B[2], vB[3] - vB[2]},
  };
  bool has_lo = false, has_hi = false;
  Frac lo{0, 1}, hi{0, 1};
  for (const auto& f : lin) {
    __int128 a = f[0], b = f[1];
    if (b == 0) {
      if (a <= 0) return {};
    } else if (b > 0) {  // tau > -a/b
      Frac c{-a, b};
      if (!has_lo || frac_less(lo, c)) lo = c, has_lo = true;
    } else {  // tau < a/(-b)
      Frac c{a, -b};
      if (!has_hi || frac_less(c, hi)) hi = c, has_hi = true;
    }
  }
  Frac zero{0, 1}, end{span, 1};
  if (has_lo && has_hi && !frac_less(lo, hi)) return {};
  if (has_lo && !frac_less(lo, end)) return {};
  if (has_hi && !frac_less(zero, hi)) return {};
  if (!has_lo || frac_less(lo, zero)) return zero;
  return lo;
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

int axis_of(size_t face) { return face < 2 ? 0 : 1; }

}  // namespace

namespace {

// Regions by the cell of their lower-left corner, each cell holding the head
// of an intrusive doubly linked list of regions. Cells inside a box around
// the initial shape (given when it is at most a few times larger than the
// number of regions, as for compiled formulas) are an array indexed by
// position, so the 3 x 3 neighbourhood queries touch few cache lines; other
// cells go to an open-addressing hash table. Copy-assigning a table of the
// same capacity allocates nothing, so each run starts from the simulator's
// initial table at the cost of a copy.
class CellLists {
 public:
  CellLists() = default;
  // Box: cells x0 .. x0 + w - 1, y0 .. y0 + h - 1 (w = 0: none).
  CellLists(size_t num_regions, int64_t x0, int64_t y0, int64_t w, int64_t h) : x0_(x0), y0_(y0), w_(w), h_(h) {
    size_t cap = 16;
    while (cap < (w > 0 ? 64 : 4 * num_regions + 16)) cap <<= 1;
    slots_.assign(cap, Slot{});
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

// The initial table of the regions' cells: a dense box of margin 2 around
// them when its area is at most 16 cells per region (plus a constant).
CellLists make_cell_lists(const Regions& regions) {
  const size_t nr = regions.size();
  if (nr == 0) return CellLists(0, 0, 0, 0, 0);
  int64_t xlo = INT64_MAX, xhi = INT64_MIN, ylo = INT64_MAX, yhi = INT64_MIN;
  for (const RegionShape& sh : regions.shapes) {
    xlo = std::min(xlo, sh.base[0]), xhi = std::max(xhi, sh.base[0]);
    ylo = std::min(ylo, sh.base[2]), yhi = std::max(yhi, sh.base[2]);
  }
  constexpr int64_t margin = 2;
  const __int128 w = static_cast<__int128>(xhi) - xlo + 1 + 2 * margin,
                 h = static_cast<__int128>(yhi) - ylo + 1 + 2 * margin;
  if (w * h > static_cast<__int128>(16 * nr + 4096)) return CellLists(nr, 0, 0, 0, 0);
  return CellLists(nr, xlo - margin, ylo - margin, static_cast<int64_t>(w), static_cast<int64_t>(h));
}

}  // namespace

// Everything run() needs besides the prepared tables, kept between runs.
struct Simulator::Scratch {
  struct Event {
    int64_t time;
    CouplingId q;
    bool start;
  };
  CellLists initial_grid;  // every region at its base cell (independent of D)
  std::vector<uint64_t> initial_key;
  CellLists grid;
  std::vector<uint64_t> region_key;
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
  // Moving regions by cell in one sub-step, for cells of the dense box: the
  // latest hit of each cell, and per hit its moving index and the previous hit.
  std::vector<uint32_t> hit_head, hit_index, hit_prev;
  std::vector<size_t> hit_cells;

  explicit Scratch(const PreparedInstance& p) : initial_grid(make_cell_lists(p.regions)) {
    const size_t nr = p.regions.size();
    initial_key.resize(nr);
    for (uint32_t r = 0; r < nr; ++r) {
      const RegionShape& sh = p.regions.shapes[r];
      initial_grid.insert(r, initial_key[r] = cell_key(Vec2{sh.base[0], sh.base[2]}));
    }
    hit_head.assign(initial_grid.dense_size(), kNone);
    node_stamp.assign(p.inst.num_nodes(), 0);
    region_stamp.assign(nr, 0);
    node_vel.resize(p.inst.num_nodes());
    rect.resize(nr);
    rvel.resize(nr);
  }
};

Simulator::Simulator(const Instance& inst) : owned_(std::make_unique<PreparedInstance>(inst)), prep_(owned_.get()) {}
Simulator::Simulator(const PreparedInstance& prep) : prep_(&prep) {}
Simulator::~Simulator() = default;
Simulator::Simulator(Simulator&&) noexcept = default;

SimResult Simulator::run(const Schedule& s) {
  const Instance& inst_ = prep_->inst;
  const SpanningTree& tree_ = prep_->tree;
  const Regions& regions_ = prep_->regions;
  const FaceNets& faces_ = prep_->faces;
  if (auto problem = check_schedule_bounds(inst_, s)) throw std::invalid_argument(*problem);
  if (!scratch_) scratch_ = std::make_unique<Scratch>(*prep_);
  Scratch& sc = *scratch_;
  SimResult result;
  const size_t n = inst_.num_nodes(), nq = inst_.couplings().size(), nr = regions_.size();
  int64_t D = 1;
  for (const auto& t : s.start) D = std::lcm(D, t.den());
  std::vector<int64_t>& T = sc.T;
  T.resize(nq);
  for (size_t q = 0; q < nq; ++q) T[q] = s.start[q].num() * (D / s.start[q].den());

  // --- Cycle collisions: the earliest over all faces (an event time). ---
  bool cycle_found = false;
  int64_t cycle_time = 0;
  size_t cycle_face = 0;
  for (size_t f = 0; f < faces_.faces.size(); ++f) {
    const auto& nets = faces_.faces[f].nets;
    std::vector<int64_t>& ev = sc.ev;
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

  // --- Node collisions: sweep the intervals between events. ---
  auto& rect = sc.rect;
  for (size_t r = 0; r < nr; ++r)
    for (int f = 0; f < 4; ++f) rect[r][f] = regions_.shapes[r].base[f] * D;
  CellLists& grid = sc.grid;
  grid = sc.initial_grid;
  std::vector<uint64_t>& region_key = sc.region_key;
  region_key = sc.initial_key;
  auto key_of = [&](uint32_t r) { return cell_key(Vec2{floor_div(rect[r][0], D), floor_div(rect[r][2], D)}); };

  using Event = Scratch::Event;
  std::vector<Event>& events = sc.events;
  events.clear();
  for (CouplingId q = 0; q < nq; ++q) events.push_back({T[q], q, true}), events.push_back({T[q] + D, q, false});
  std::sort(events.begin(), events.end(),
            [](const Event& a, const Event& b) { return a.time != b.time ? a.time < b.time : a.start < b.start; });

  std::vector<char>& running = sc.running;
  running.assign(nq, 0);
  std::vector<CouplingId>& run_list = sc.run_list;
  run_list.clear();
  std::vector<uint32_t>& node_stamp = sc.node_stamp;
  std::vector<uint32_t>& region_stamp = sc.region_stamp;
  std::vector<Vec2>& node_vel = sc.node_vel;
  auto& rvel = sc.rvel;
  uint32_t& stamp = sc.stamp;

  auto report_cycle = [&]() {
    Collision c;
    c.kind = Collision::Kind::Cycle;
    c.time = to_rational(cycle_time, D);
    c.cycle = faces_.faces[cycle_face].walk;
    for (CouplingId q = 0; q < nq; ++q)
      if (T[q] <= cycle_time && cycle_time < T[q] + D) c.moving.push_back(q);
    result.collision = c;
    return result;
  };

  for (size_t ei = 0; ei < events.size();) {
    int64_t now = events[ei].time;
    for (; ei < events.size() && events[ei].time == now; ++ei) {
      CouplingId q = events[ei].q;
      if (events[ei].start) {
        running[q] = 1;
        run_list.push_back(q);
      } else {
        running[q] = 0;
        run_list.erase(std::find(run_list.begin(), run_list.end(), q));
      }
    }
    if (cycle_found && cycle_time <= now) return report_cycle();
    if (run_list.empty() || ei == events.size()) continue;
    const int64_t span = events[ei].time - now;
    ++result.stats.intervals;
    if (++stamp == 0) {  // the stamps wrapped around: start them afresh
      std::fill(node_stamp.begin(), node_stamp.end(), 0);
      std::fill(region_stamp.begin(), region_stamp.end(), 0);
      stamp = 1;
    }

    // Cut the tree at the running operations' tree edges.
    std::vector<NodeId>& cuts = sc.cuts;
    std::vector<OpId>& running_ops = sc.running_ops;
    cuts.clear();
    running_ops.clear();
    for (CouplingId q : run_list)
      for (OpId k : inst_.couplings()[q].ops) {
        running_ops.push_back(k);
        const Operation& op = inst_.ops()[k];
        if (!op.is_edge_op()) continue;
        if (tree_.parent[op.v] == op.u && tree_.parent_op[op.v] == k) cuts.push_back(op.v);
        else if (tree_.parent[op.u] == op.v && tree_.parent_op[op.u] == k) cuts.push_back(op.u);
      }
    std::sort(cuts.begin(), cuts.end(), [&](NodeId a, NodeId b) { return tree_.tin[a] < tree_.tin[b]; });
    const size_t nc = cuts.size();
    const size_t ROOT = nc;
    std::vector<int64_t>& comp_size = sc.comp_size;
    std::vector<size_t>& up = sc.up;
    comp_size.assign(nc + 1, 0);
    up.assign(nc, ROOT);
    comp_size[ROOT] = static_cast<int64_t>(n);
    {
      std::vector<size_t>& st = sc.cut_stack;
      st.clear();
      for (size_t i = 0; i < nc; ++i) {
        comp_size[i] = tree_.subtree[cuts[i]];
        while (!st.empty() && tree_.tout[cuts[st.back()]] <= tree_.tin[cuts[i]]) st.pop_back();
        up[i] = st.empty() ? ROOT : st.back();
        comp_size[up[i]] -= tree_.subtree[cuts[i]];
        st.push_back(i);
      }
    }
    size_t L = ROOT;
    for (size_t i = 0; i < nc; ++i)
      if (comp_size[i] > comp_size[L]) L = i;
    Vec2 vel_L{0, 0};
    if (L != ROOT)
      for (size_t i = L;; i = up[i]) {
        vel_L += op_child_vector(inst_, tree_, cuts[i]);
        if (up[i] == ROOT) break;
      }
    // Ranges of Euler positions that move, in increasing order.
    std::vector<std::pair<uint32_t, uint32_t>>& ranges = sc.ranges;
    ranges.clear();
    if (L == ROOT) {
      for (size_t i = 0; i < nc; ++i)
        if (up[i] == ROOT) ranges.push_back({tree_.tin[cuts[i]], tree_.tout[cuts[i]]});
    } else {
      ranges.push_back({0, tree_.tin[cuts[L]]});
      for (size_t i = 0; i < nc; ++i)
        if (up[i] == L) ranges.push_back({tree_.tin[cuts[i]], tree_.tout[cuts[i]]});
      ranges.push_back({tree_.tout[cuts[L]], static_cast<uint32_t>(n)});
    }
    std::vector<uint32_t>& moving = sc.moving;
    moving.clear();
    auto add_region = [&](uint32_t r) {
      if (r != kNone && region_stamp[r] != stamp) region_stamp[r] = stamp, moving.push_back(r);
    };
    {
      std::vector<std::pair<uint32_t, Vec2>>& st = sc.vel_stack;  // (tout, velocity) of enclosing cuts
      st.clear();
      size_t ptr = 0;
      for (auto [b, e] : ranges)
        for (uint32_t p = b; p < e; ++p) {
          while (!st.empty() && st.back().first <= p) st.pop_back();
          while (ptr < nc && tree_.tin[cuts[ptr]] <= p) {
            NodeId c = cuts[ptr++];
            while (!st.empty() && st.back().first <= tree_.tin[c]) st.pop_back();
            if (tree_.tout[c] > p) {
              Vec2 base = st.empty() ? Vec2{0, 0} : st.back().second;
              st.push_back({tree_.tout[c], base + op_child_vector(inst_, tree_, c)});
            }
          }
          NodeId w = tree_.order[p];
          node_vel[w] = (st.empty() ? Vec2{0, 0} : st.back().second) - vel_L;
          node_stamp[w] = stamp;
          add_region(w);
          OpId k = inst_.op_of_node(w);
          if (k != kNone) {
            add_region(regions_.region_of_op[k]);
            if (inst_.ops()[k].kind == OpKind::Contract) add_region(inst_.ops()[k].v);
          }
        }
    }
    for (OpId k : running_ops) {
      add_region(regions_.region_of_op[k]);
      if (inst_.ops()[k].kind == OpKind::Contract) add_region(inst_.ops()[k].v);
    }
    result.stats.moved_regions += moving.size();

    // Velocities and swept boxes of the moving regions.
    auto vel_of = [&](NodeId w) { return node_stamp[w] == stamp ? node_vel[w] : Vec2{0, 0}; };
    auto& swept = sc.swept;
    swept.resize(moving.size());
    for (size_t i = 0; i < moving.size(); ++i) {
      uint32_t r = moving[i];
      const RegionShape& sh = regions_.shapes[r];
      for (int f = 0; f < 4; ++f) {
        Vec2 v = vel_of(sh.ref[f]);
        int64_t vf = axis_of(f) == 0 ? v.x : v.y;
        if (sh.grow_op != kNone && f == sh.grow_face && running[inst_.ops()[sh.grow_op].coupling]) vf += sh.grow_sign;
        rvel[r][f] = vf;
      }
      for (int f = 0; f < 4; f += 2) {
        int64_t a0 = rect[r][f], a1 = rect[r][f] + rvel[r][f] * span;
        int64_t b0 = rect[r][f + 1], b1 = rect[r][f + 1] + rvel[r][f + 1] * span;
        swept[i][f] = std::min(a0, a1);
        swept[i][f + 1] = std::max(b0, b1);
      }
    }

    // Broad phase, then the exact test; keep the earliest (the smallest
    // pair on ties), so the order of the tests does not matter.
    Frac best{};
    uint32_t best_a = kNone, best_b = kNone;
    static const int64_t zero4[4] = {0, 0, 0, 0};
    auto test = [&](uint32_t a, uint32_t b, bool b_moves) {
      ++result.stats.candidate_pairs;
      Frac f = first_overlap(rect[a].data(), rvel[a].data(), rect[b].data(), b_moves ? rvel[b].data() : zero4, span);
      if (!f.none() && (best.none() || frac_less(f, best) ||
                        (!frac_less(best, f) && std::minmax(a, b) < std::minmax(best_a, best_b))))
        best = f, best_a = std::min(a, b), best_b = std::max(a, b);
    };
    // Moving against static: each moving region queries the cells of its
    // swept box (a static region's lower-left corner lies at most one cell
    // before the box). Cells hold O(1) static regions: the shape has no overlaps.
    int64_t vmax = 1;
    for (size_t i = 0; i < moving.size(); ++i) {
      uint32_t r = moving[i];
      for (int f = 0; f < 4; ++f) vmax = std::max(vmax, rvel[r][f] < 0 ? -rvel[r][f] : rvel[r][f]);
      const auto& sw = swept[i];
      if (sw[1] <= sw[0] || sw[3] <= sw[2]) continue;  // never of positive area
      int64_t cx0 = floor_div(sw[0], D), cx1 = floor_div(sw[1] - 1, D);
      int64_t cy0 = floor_div(sw[2], D), cy1 = floor_div(sw[3] - 1, D);
      for (int64_t cx = cx0 - 1; cx <= cx1; ++cx)
        for (int64_t cy = cy0 - 1; cy <= cy1; ++cy)
          for (uint32_t x = grid.head(cell_key(Vec2{cx, cy})); x != kNone; x = grid.next(x))
            if (region_stamp[x] != stamp) test(r, x, false);
    }
    // Moving against moving: split the interval into S = max speed sub-steps
    // (for the broad phase only), so that in each sub-step every region
    // sweeps at most about two cells and a cell holds O(1) regions; pairs that
    // share a cell in some sub-step go to the exact test over the whole
    // interval. Without the split, long sweeps (many coupled operations in a
    // row) would pile many regions into each cell: quadratic.
    const int64_t S = vmax;
    const __int128 unit = static_cast<__int128>(D) * S;  // one cell, in sub-step units
    auto floor128 = [](__int128 a, __int128 b) { return a / b - ((a % b != 0) && ((a < 0) != (b < 0)) ? 1 : 0); };
    auto& cell_hits = sc.cell_hits;
    auto& moving_pairs = sc.moving_pairs;
    moving_pairs.clear();
    for (int64_t step = 0; step < S; ++step) {
      cell_hits.clear();
      for (size_t i = 0; i < moving.size(); ++i) {
        uint32_t r = moving[i];
        __int128 box[4];
        for (int f = 0; f < 4; ++f) {
          __int128 p0 = static_cast<__int128>(rect[r][f]) * S + static_cast<__int128>(rvel[r][f]) * span * step;
          __int128 p1 = p0 + static_cast<__int128>(rvel[r][f]) * span;
          box[f] = (f % 2 == 0) ? std::min(p0, p1) : std::max(p0, p1);
        }
        if (box[1] <= box[0] || box[3] <= box[2]) continue;
        auto cx0 = static_cast<int64_t>(floor128(box[0], unit)), cx1 = static_cast<int64_t>(floor128(box[1] - 1, unit));
        auto cy0 = static_cast<int64_t>(floor128(box[2], unit)), cy1 = static_cast<int64_t>(floor128(box[3] - 1, unit));
        for (int64_t cx = cx0; cx <= cx1; ++cx)
          for (int64_t cy = cy0; cy <= cy1; ++cy) {
            const uint64_t key = cell_key(Vec2{cx, cy});
            const size_t d = grid.dense_index(key);
            if (d == CellLists::kNoDense) {
              cell_hits.push_back({key, static_cast<uint32_t>(i)});
              continue;
            }
            // Pair i with every earlier region of the cell (all of smaller index).
            for (uint32_t h = sc.hit_head[d]; h != kNone; h = sc.hit_prev[h])
              moving_pairs.push_back((static_cast<uint64_t>(sc.hit_index[h]) << 32) | i);
            if (sc.hit_head[d] == kNone) sc.hit_cells.push_back(d);
            sc.hit_prev.push_back(sc.hit_head[d]);
            sc.hit_index.push_back(static_cast<uint32_t>(i));
            sc.hit_head[d] = static_cast<uint32_t>(sc.hit_index.size() - 1);
          }
      }
      for (size_t d : sc.hit_cells) sc.hit_head[d] = kNone;
      sc.hit_cells.clear();
      sc.hit_index.clear();
      sc.hit_prev.clear();
      // Regions sharing a cell outside the box in this sub-step: runs of equal
      // keys, indices increasing.
      std::sort(cell_hits.begin(), cell_hits.end());
      for (size_t x = 0; x < cell_hits.size();) {
        size_t y = x + 1;
        while (y < cell_hits.size() && cell_hits[y].first == cell_hits[x].first) ++y;
        for (size_t a = x; a < y; ++a)
          for (size_t b = a + 1; b < y; ++b)
            moving_pairs.push_back((static_cast<uint64_t>(cell_hits[a].second) << 32) | cell_hits[b].second);
        x = y;
      }
    }
    std::sort(moving_pairs.begin(), moving_pairs.end());
    moving_pairs.erase(std::unique(moving_pairs.begin(), moving_pairs.end()), moving_pairs.end());
    for (uint64_t ij : moving_pairs)
      test(moving[static_cast<uint32_t>(ij >> 32)], moving[static_cast<uint32_t>(ij & 0xffffffffu)], true);
    if (!best.none()) {
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
    // Advance the moving regions to the end of the interval.
    for (uint32_t r : moving) {
      for (int f = 0; f < 4; ++f) rect[r][f] += rvel[r][f] * span;
      uint64_t k = key_of(r);
      if (k != region_key[r]) {
        grid.remove(r, region_key[r]);
        grid.insert(r, k);
        region_key[r] = k;
      }
    }
  }
  if (cycle_found) return report_cycle();
  return result;
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
