// Learning precedence search for gap systems. Why it is exact and how the
// learning works: docs/solver.md, section Engine "precedence".
//
// Variables: one per pair of couplings that share a gap; its two literals
// are "a before b" and "b before a". The gap system is a set of weighted
// inequalities over them (solver/internal/gap_inequalities.hpp, one per narrower and
// gap). An assignment of every variable that meets every inequality and
// whose edges form no cycle gives a solution: any topological order of its
// edges (couplings that share no gap are free relative to each other).
//
// The search is CDCL over these literals: every derived "a before b" keeps
// its reason (a gap constraint, a learned nogood, or two edges it closes a
// triangle with); a dead end (a gap over its bound, a cycle of edges, a
// nogood all false) is analysed back to the first unique implication point
// into a nogood (a clause over precedence literals), which is learned and
// watched; the search jumps back to where the nogood asserts; it restarts
// on the Luby sequence, branches on the most active variable (bumped by
// conflicts), and forgets the learned nogoods of worst glue periodically.
// Node work is proportional to what changed: gap constraints keep running
// sums of their true literals, nogoods are watched by two literals, edges
// join and leave the graph in O(1), and longer cycles than triangles are
// looked for only when every variable is set (PrecedenceGraph).
#include <algorithm>
#include <stdexcept>
#include <unordered_map>

#include "common/assert.hpp"
#include "solver/internal/activity_heap.hpp"
#include "solver/internal/gap_inequalities.hpp"
#include "solver/internal/precedence_graph.hpp"
#include "solver/internal/search.hpp"

namespace gridlock {
namespace {

using Lit = uint32_t;  // 2v: lo(v) before hi(v); 2v + 1: hi(v) before lo(v)
constexpr Lit kNoLit = UINT32_MAX;
Lit neg(Lit l) { return l ^ 1; }
uint32_t var(Lit l) { return l >> 1; }

// Why a literal is true.
struct Reason {
  enum Kind : uint8_t { Decision, Nogood, Gap, Triangle } kind = Decision;
  uint32_t a = 0, b = 0;  // nogood index / gap constraint index / the two edges
};

struct GapConstraint {
  int64_t bound;        // K
  uint32_t begin, end;  // its literals in gap_lits_, by weight, heaviest first
};

struct Nogood {
  std::vector<Lit> lits;  // a clause: one of these holds; lits[0], lits[1] watched
  uint32_t glue = 0;      // distinct decision levels when learned (LBD)
  bool learned = false, deleted = false;
};

class LearningSearch {
 public:
  LearningSearch(const ConstraintSystem& sys, SearchBudget& budget, SolveStats& st, const PrecedenceHooks* hooks)
      : sys_(sys), budget_(budget), st_(st), hooks_(hooks), graph_(sys.num_couplings), heap_(activity_) {}

  SearchOutcome run() {
    SearchOutcome out;
    if (!build() || !start() || !closure_nogoods()) {
      out.status = Verdict::No;
      ++st_.refuted;
      return out;
    }
    out.status = search() ? Verdict::Yes : Verdict::No;
    if (out.status == Verdict::Yes) out.order = solution();
    return out;
  }

 private:
  // ---- variables and literals ----
  CouplingId from(Lit l) const { return (l & 1) ? hi_[var(l)] : lo_[var(l)]; }
  CouplingId to(Lit l) const { return (l & 1) ? lo_[var(l)] : hi_[var(l)]; }
  bool is_true(Lit l) const { return value_[var(l)] == static_cast<int8_t>(l & 1); }
  bool is_false(Lit l) const { return value_[var(l)] == static_cast<int8_t>((l & 1) ^ 1); }
  bool unassigned(Lit l) const { return value_[var(l)] < 0; }
  uint32_t level() const { return static_cast<uint32_t>(levels_.size()); }

  // The literal "a before b", kNoLit when a and b share no gap.
  Lit lit(CouplingId a, CouplingId b) const {
    const auto& p = partners_[a];
    auto it = std::lower_bound(p.begin(), p.end(), std::make_pair(b, uint32_t{0}));
    if (it == p.end() || it->first != b) return kNoLit;
    return 2 * it->second + (a == lo_[it->second] ? 0 : 1);
  }
  Lit make_lit(CouplingId a, CouplingId b, std::unordered_map<uint64_t, uint32_t>& index) {
    const CouplingId lo = std::min(a, b), hi = std::max(a, b);
    auto [it, fresh] = index.try_emplace((uint64_t{lo} << 32) | hi, static_cast<uint32_t>(lo_.size()));
    if (fresh) {
      lo_.push_back(lo);
      hi_.push_back(hi);
    }
    return 2 * it->second + (a == lo ? 0 : 1);
  }

  // ---- set-up ----
  // The gap constraints of every gap that can go negative. False if one
  // cannot be met at all (a gap already overlapping, or a bound below 0).
  bool build() {
    std::unordered_map<uint64_t, uint32_t> index;
    std::vector<std::pair<int64_t, Lit>> lits;
    std::vector<PrecedenceTerm> terms;
    for (const CollisionConstraint& c : sys_.constraints) {
      GRIDLOCK_REQUIRE(c.num_forms == 1, "precedence search needs one form per constraint");
      if (c.base[0] > 0) return false;  // overlapping from the start: the first step of c collides
      const bool ok = for_each_gap_inequality(c, terms, [&](auto& ts, int64_t bound) {
        if (bound < 0) return false;
        lits.clear();
        for (const PrecedenceTerm& x : ts) lits.push_back({x.weight, make_lit(x.first, x.second, index)});
        std::sort(lits.begin(), lits.end(), [](auto& p, auto& q) { return p.first > q.first; });
        gaps_.push_back(
            {bound, static_cast<uint32_t>(gap_lits_.size()), static_cast<uint32_t>(gap_lits_.size() + lits.size())});
        for (auto [w, l] : lits) gap_lits_.push_back(l), gap_weights_.push_back(w);
        return true;
      });
      if (!ok) return false;
      budget_.poll();
    }
    allocate();
    return true;
  }

  void allocate() {
    const size_t nv = lo_.size();
    partners_.assign(sys_.num_couplings, {});
    for (uint32_t v = 0; v < nv; ++v) {
      partners_[lo_[v]].push_back({hi_[v], v});
      partners_[hi_[v]].push_back({lo_[v], v});
    }
    for (auto& p : partners_) std::sort(p.begin(), p.end());
    occ_.assign(2 * nv, {});
    for (uint32_t g = 0; g < gaps_.size(); ++g)
      for (uint32_t k = gaps_[g].begin; k < gaps_[g].end; ++k) occ_[gap_lits_[k]].push_back({g, gap_weights_[k]});
    gap_sum_.assign(gaps_.size(), 0);
    value_.assign(nv, -1);
    level_.assign(nv, 0);
    pos_.assign(nv, 0);
    reason_.assign(nv, Reason{});
    in_order_.assign(nv, 0);
    seen_.assign(nv, 0);
    activity_.assign(nv, 0.0);
    phase_.assign(nv, -1);
    watches_.assign(2 * nv, {});
    heap_.reset(nv);
    for (uint32_t v = 0; v < nv; ++v) heap_.insert(v);
  }

  // Level 0: literals heavier than their gap's bound are false.
  bool start() {
    for (uint32_t g = 0; g < gaps_.size(); ++g)
      for (uint32_t k = gaps_[g].begin; k < gaps_[g].end && gap_weights_[k] > gaps_[g].bound; ++k) {
        const Lit l = gap_lits_[k];
        if (is_true(l)) return false;
        if (unassigned(l)) assign(neg(l), {Reason::Gap, g, 0});
      }
    return propagate();
  }

  // The transitive closure R of the relations set at level 0 (true in every
  // solution), as the SAT engine adds it (solver/search_sat.cpp): a pair R
  // orders is set; for a coupling x and partners c1 R c2 of x, the nogood
  // "x before c1 implies x before c2" carries the order along paths through
  // couplings that share no gap with x, which the triangles cannot.
  // False on a conflict. Skipped above kClosureLimit couplings (k^2 bits).
  bool closure_nogoods() {
    const size_t k = sys_.num_couplings, words = (k + 63) / 64;
    if (!graph_.sort(topo_, conflict_)) {  // the level-0 relations form a cycle
      report_cycle();
      return false;
    }
    first_pos_.assign(k, 0);
    for (size_t h = 0; h < k; ++h) first_pos_[topo_[h]] = static_cast<uint32_t>(h);
    if (k > kClosureLimit) return true;
    const std::vector<CouplingId>& topo = topo_;
    std::vector<uint64_t> reach(k * words, 0);
    auto r = [&](CouplingId a, CouplingId b) { return (reach[a * words + (b >> 6)] >> (b & 63)) & 1; };
    for (size_t h = k; h-- > 0;) {
      const CouplingId v = topo[h];
      uint64_t* row = reach.data() + v * words;
      for (const PrecedenceGraph::Edge& e : graph_.out(v)) {
        row[e.node >> 6] |= uint64_t{1} << (e.node & 63);
        const uint64_t* wr = reach.data() + e.node * words;
        for (size_t i = 0; i < words; ++i) row[i] |= wr[i];
      }
      budget_.poll();
    }
    for (uint32_t v = 0; v < lo_.size(); ++v)
      if (value_[v] < 0 && (r(lo_[v], hi_[v]) || r(hi_[v], lo_[v]))) assign(2 * v + (r(lo_[v], hi_[v]) ? 0 : 1), {});
    for (CouplingId x = 0; x < k; ++x) {
      budget_.poll();
      for (auto [c1, v1] : partners_[x])
        for (auto [c2, v2] : partners_[x])
          if (c1 != c2 && r(c1, c2)) add_nogood({neg(lit(x, c1)), lit(x, c2)});
    }
    return propagate();
  }
  // A nogood true in every solution (not learned), at level 0.
  void add_nogood(std::vector<Lit> lits) {
    if (is_true(lits[0]) || is_true(lits[1])) return;
    const auto ci = static_cast<uint32_t>(nogoods_.size());
    watches_[lits[0]].push_back(ci);
    watches_[lits[1]].push_back(ci);
    nogoods_.push_back({std::move(lits), 0, false, false});
  }

  // ---- assignment ----
  void assign(Lit l, Reason r) {
    const uint32_t v = var(l);
    value_[v] = static_cast<int8_t>(l & 1);
    level_[v] = level();
    pos_[v] = static_cast<uint32_t>(trail_.size());
    reason_[v] = r;
    trail_.push_back(l);
    for (auto [g, w] : occ_[l]) gap_sum_[g] += w;
    if (r.kind != Reason::Decision) ++st_.propagations;
  }

  void backjump(uint32_t lvl) {
    if (level() <= lvl) return;
    const size_t keep = levels_[lvl];
    while (trail_.size() > keep) {
      const Lit l = trail_.back();
      trail_.pop_back();
      const uint32_t v = var(l);
      if (in_order_[v]) graph_.pop(from(l), to(l)), in_order_[v] = 0;
      for (auto [g, w] : occ_[l]) gap_sum_[g] -= w;
      phase_[v] = value_[v];
      value_[v] = -1;
      heap_.insert(v);
    }
    levels_.resize(lvl);
    qhead_ = std::min(qhead_, trail_.size());
  }

  // ---- propagation: every theory, literal by literal ----
  // False on a conflict, whose true literals are left in conflict_.
  bool propagate() {
    while (qhead_ < trail_.size()) {
      const Lit p = trail_[qhead_++];
      budget_.poll();
      if (!propagate_order(p) || !propagate_nogoods(p) || !propagate_gaps(p)) return false;
    }
    return true;
  }

  // The edge of p joins the graph; edges it closes a triangle with imply
  // the third side (longer cycles are looked for when nothing is left to
  // decide, see search()).
  bool propagate_order(Lit p) {
    const CouplingId a = from(p), b = to(p);
    graph_.add(a, b, p);
    in_order_[var(p)] = 1;
    for (const PrecedenceGraph::Edge& e : graph_.out(b))  // a -> b -> x: a before x
      if (!imply_edge(lit(a, e.node), p, e.tag)) return false;
    for (const PrecedenceGraph::Edge& e : graph_.in(a))  // x -> a -> b: x before b
      if (!imply_edge(lit(e.node, b), e.tag, p)) return false;
    return true;
  }
  bool imply_edge(Lit q, Lit r1, Lit r2) {
    if (q == kNoLit || is_true(q)) return true;
    if (is_false(q)) {
      conflict_ = {r1, r2, neg(q)};
      return false;
    }
    assign(q, {Reason::Triangle, r1, r2});
    return true;
  }

  // Nogoods watching neg(p), now false (two watched literals).
  bool propagate_nogoods(Lit p) {
    const Lit fl = neg(p);
    std::vector<uint32_t>& ws = watches_[fl];
    size_t i = 0, j = 0;
    bool ok = true;
    while (i < ws.size() && ok) {
      const uint32_t ci = ws[i++];
      Nogood& c = nogoods_[ci];
      if (c.deleted) continue;  // forgotten: drop the watch
      if (c.lits[0] == fl) std::swap(c.lits[0], c.lits[1]);
      if (!is_true(c.lits[0]) && rewatch(c, ci)) continue;
      ws[j++] = ci;
      if (is_true(c.lits[0])) continue;
      if (is_false(c.lits[0])) {
        conflict_.clear();
        for (Lit l : c.lits) conflict_.push_back(neg(l));
        ok = false;
      } else {
        assign(c.lits[0], {Reason::Nogood, ci, 0});
      }
    }
    while (i < ws.size()) ws[j++] = ws[i++];
    ws.resize(j);
    return ok;
  }
  // Moves the second watch of c to a literal not false. False if none.
  bool rewatch(Nogood& c, uint32_t ci) {
    for (size_t k = 2; k < c.lits.size(); ++k)
      if (!is_false(c.lits[k])) {
        std::swap(c.lits[1], c.lits[k]);
        watches_[c.lits[1]].push_back(ci);
        return true;
      }
    return false;
  }

  // The gap constraints p takes part in: over the bound is a conflict; a
  // literal heavier than what is left is false.
  bool propagate_gaps(Lit p) {
    for (auto [g, w] : occ_[p]) {
      const int64_t slack = gaps_[g].bound - gap_sum_[g];
      if (slack < 0) {
        gap_reason(g, trail_.size(), gaps_[g].bound, conflict_);
        return false;
      }
      for (uint32_t k = gaps_[g].begin; k < gaps_[g].end && gap_weights_[k] > slack; ++k)
        if (unassigned(gap_lits_[k])) assign(neg(gap_lits_[k]), {Reason::Gap, g, 0});
    }
    return true;
  }

  // The true literals that implied v's literal (all earlier on the trail).
  void reason_lits(uint32_t v, std::vector<Lit>& out) const {
    out.clear();
    const Reason& r = reason_[v];
    switch (r.kind) {
      case Reason::Decision: break;
      case Reason::Triangle: out = {r.a, r.b}; break;
      case Reason::Nogood:
        for (size_t k = 1; k < nogoods_[r.a].lits.size(); ++k) out.push_back(neg(nogoods_[r.a].lits[k]));
        break;
      case Reason::Gap: gap_reason(r.a, pos_[v], bound_minus_weight(r.a, v), out); break;
    }
  }
  int64_t bound_minus_weight(uint32_t g, uint32_t v) const {
    for (uint32_t k = gaps_[g].begin; k < gaps_[g].end; ++k)
      if (var(gap_lits_[k]) == v) return gaps_[g].bound - gap_weights_[k];
    throw std::logic_error("precedence search: a gap reason without its literal");
  }
  // The earliest true literals of gap constraint g set before trail
  // position `before` that weigh more than `limit`: a shorter reason than
  // all of them, reaching back to lower levels less often.
  void gap_reason(uint32_t g, size_t before, int64_t limit, std::vector<Lit>& out) const {
    std::vector<std::pair<uint32_t, uint32_t>>& lits = gap_scratch_;  // (trail position, k)
    lits.clear();
    for (uint32_t k = gaps_[g].begin; k < gaps_[g].end; ++k) {
      const Lit l = gap_lits_[k];
      if (is_true(l) && pos_[var(l)] < before) lits.push_back({pos_[var(l)], k});
    }
    std::sort(lits.begin(), lits.end());
    int64_t sum = 0;
    out.clear();
    if (limit < 0) return;  // set at level 0 by weight alone
    for (auto [p, k] : lits) {
      out.push_back(gap_lits_[k]);
      if ((sum += gap_weights_[k]) > limit) return;
    }
    throw std::logic_error("precedence search: a gap reason that does not imply");
  }

  // ---- conflict analysis ----
  // First unique implication point: the learned nogood (asserting literal
  // first, then one of the highest other level) from conflict_.
  void analyze(std::vector<Lit>& learned) {
    learned.assign(1, kNoLit);
    size_t open = 0, idx = trail_.size();
    Lit p = kNoLit;
    std::vector<Lit>& from_lits = scratch_;
    from_lits = conflict_;
    for (;;) {
      for (Lit q : from_lits) {
        const uint32_t v = var(q);
        if (seen_[v] || level_[v] == 0) continue;
        seen_[v] = 1;
        bump(v);
        if (level_[v] == level()) ++open;
        else learned.push_back(neg(q));
      }
      do --idx;
      while (!seen_[var(trail_[idx])]);
      p = trail_[idx];
      seen_[var(p)] = 0;
      if (--open == 0) break;
      reason_lits(var(p), from_lits);
    }
    learned[0] = neg(p);
    minimize(learned);
    size_t hi = 1;
    for (size_t k = 2; k < learned.size(); ++k)
      if (level_[var(learned[k])] > level_[var(learned[hi])]) hi = k;
    if (learned.size() > 1) std::swap(learned[1], learned[hi]);
  }

  // Drops a literal whose reason lies wholly among the other literals of the
  // nogood (or at level 0); clears the marks.
  void minimize(std::vector<Lit>& learned) {
    std::vector<Lit>& rl = scratch_;
    keep_.assign(learned.size(), 1);
    for (size_t k = 1; k < learned.size(); ++k) {
      const uint32_t v = var(learned[k]);
      if (reason_[v].kind == Reason::Decision) continue;
      reason_lits(v, rl);
      bool redundant = true;
      for (Lit q : rl)
        if (!seen_[var(q)] && level_[var(q)] > 0) redundant = false;
      keep_[k] = redundant ? 0 : 1;
    }
    size_t j = 1;
    for (size_t k = 1; k < learned.size(); ++k) {
      seen_[var(learned[k])] = 0;
      if (keep_[k]) learned[j++] = learned[k];
    }
    learned.resize(j);
  }

  void bump(uint32_t v) {
    if ((activity_[v] += bump_) > 1e100) {
      for (double& a : activity_) a *= 1e-100;
      bump_ *= 1e-100;
    }
    heap_.increased(v);
  }

  uint32_t glue(const std::vector<Lit>& lits) {
    std::vector<uint32_t> lv;
    lv.reserve(lits.size());
    for (Lit l : lits) lv.push_back(level_[var(l)]);
    std::sort(lv.begin(), lv.end());
    return static_cast<uint32_t>(std::unique(lv.begin(), lv.end()) - lv.begin());
  }

  // Tells hooks_ (if any) of the cycle in conflict_.
  void report_cycle() const {
    if (!hooks_ || !hooks_->on_cycle) return;
    std::vector<std::pair<CouplingId, CouplingId>> edges;
    edges.reserve(conflict_.size());
    for (Lit l : conflict_) edges.push_back({from(l), to(l)});
    hooks_->on_cycle(edges);
  }

  // Learns the nogood, jumps back to where it asserts, asserts it.
  void learn(std::vector<Lit>& learned) {
    if (hooks_ && hooks_->on_learned) {
      std::vector<std::pair<CouplingId, CouplingId>> edges;
      edges.reserve(learned.size());
      for (Lit l : learned) edges.push_back({from(l), to(l)});
      hooks_->on_learned(edges);
    }
    if (learned.size() == 1) {
      backjump(0);
      assign(learned[0], {});
      return;
    }
    const uint32_t g = glue(learned);
    backjump(level_[var(learned[1])]);
    const auto ci = static_cast<uint32_t>(nogoods_.size());
    nogoods_.push_back({learned, g, true, false});
    watches_[learned[0]].push_back(ci);
    watches_[learned[1]].push_back(ci);
    ++live_learned_;
    assign(learned[0], {Reason::Nogood, ci, 0});
  }

  // Forgets half of the learned nogoods, those of highest glue, except the
  // ones of glue <= 2 and those that are reasons now.
  void reduce() {
    std::vector<uint32_t> cand;
    for (uint32_t ci = 0; ci < nogoods_.size(); ++ci) {
      const Nogood& c = nogoods_[ci];
      if (c.deleted || !c.learned || c.glue <= 2) continue;
      const uint32_t v = var(c.lits[0]);
      if (is_true(c.lits[0]) && reason_[v].kind == Reason::Nogood && reason_[v].a == ci) continue;
      cand.push_back(ci);
    }
    std::stable_sort(cand.begin(), cand.end(),
                     [&](uint32_t x, uint32_t y) { return nogoods_[x].glue > nogoods_[y].glue; });
    for (size_t k = 0; k < cand.size() / 2; ++k) {
      nogoods_[cand[k]].deleted = true;
      std::vector<Lit>().swap(nogoods_[cand[k]].lits);
      --live_learned_;
    }
  }

  static uint64_t luby(uint64_t i) {  // 1 1 2 1 1 2 4 1 1 2 ... (i from 0)
    uint64_t size = 1, seq = 0;
    while (size < i + 1) size = 2 * size + 1, ++seq;
    while (size - 1 != i) {
      size = (size - 1) / 2;
      --seq;
      i %= size;
    }
    return uint64_t{1} << seq;
  }

  // A literal of the most active unassigned variable, in its saved phase
  // (at first the side the order of the level-0 relations respects).
  // kNoLit when every variable is set.
  Lit pick() {
    while (!heap_.empty()) {
      const uint32_t v = heap_.pop();
      if (value_[v] >= 0) continue;
      if (phase_[v] >= 0) return 2 * v + static_cast<uint32_t>(phase_[v]);
      return 2 * v + (first_pos_[lo_[v]] < first_pos_[hi_[v]] ? 0 : 1);
    }
    return kNoLit;
  }

  bool search() {
    std::vector<Lit> learned;
    uint64_t restarts = 0, conflicts = 0, next_restart = kRestartUnit * luby(0);
    size_t max_learned = kFirstReduce;
    for (;;) {
      if (!propagate()) {
        ++st_.refuted;
        budget_.tick(st_);
        if (level() == 0) return false;
        analyze(learned);
        learn(learned);
        bump_ /= kDecay;
        if (++conflicts >= next_restart) {
          backjump(0);
          next_restart = conflicts + kRestartUnit * luby(++restarts);
        }
        if (live_learned_ >= max_learned) {
          reduce();
          max_learned += max_learned / 2;
        }
        continue;
      }
      const Lit d = pick();
      if (d == kNoLit) {
        if (graph_.sort(topo_, conflict_)) return true;
        // A cycle of set literals: a conflict at the highest level among them.
        report_cycle();
        uint32_t top = 0;
        for (Lit l : conflict_) top = std::max(top, level_[var(l)]);
        if (top == 0) return false;
        backjump(top);
        ++st_.refuted;
        analyze(learned);
        learn(learned);
        continue;
      }
      ++st_.decisions;
      budget_.tick(st_);
      budget_.set_depth(level());
      levels_.push_back(trail_.size());
      assign(d, {});
    }
  }

  // Every variable set, no gap constraint over its bound, no cycle: the
  // topological order topo_ of the set literals is a solution. Checked on
  // the constraints (a failure is a bug, never a wrong YES).
  std::vector<CouplingId> solution() const {
    if (replay_order(sys_, topo_).failed_step != topo_.size())
      throw std::logic_error("precedence search: an assignment whose order the constraints reject");
    return topo_;
  }

  static constexpr uint64_t kRestartUnit = 100;
  static constexpr size_t kFirstReduce = 2000;
  static constexpr size_t kClosureLimit = 1 << 15;
  static constexpr double kDecay = 0.95;

  const ConstraintSystem& sys_;
  SearchBudget& budget_;
  SolveStats& st_;
  const PrecedenceHooks* hooks_;
  std::vector<CouplingId> lo_, hi_;                                     // per variable
  std::vector<std::vector<std::pair<CouplingId, uint32_t>>> partners_;  // per coupling: (other, variable), sorted
  std::vector<GapConstraint> gaps_;
  std::vector<Lit> gap_lits_;
  std::vector<int64_t> gap_weights_, gap_sum_;  // gap_sum_: per gap constraint, weight of its true literals
  std::vector<std::vector<std::pair<uint32_t, int64_t>>> occ_;  // per literal: (gap constraint, weight)
  std::vector<int8_t> value_, phase_;                           // per variable: -1 unset, 0, 1
  std::vector<uint32_t> level_, pos_;
  std::vector<Reason> reason_;
  std::vector<char> in_order_, seen_, keep_;
  std::vector<Lit> trail_, conflict_, scratch_;
  mutable std::vector<std::pair<uint32_t, uint32_t>> gap_scratch_;
  std::vector<size_t> levels_;  // trail size at each decision
  size_t qhead_ = 0;
  PrecedenceGraph graph_;
  std::vector<CouplingId> topo_;     // a topological order of graph_, when last sorted
  std::vector<uint32_t> first_pos_;  // per coupling: its position in the order of the level-0 relations
  std::vector<Nogood> nogoods_;
  std::vector<std::vector<uint32_t>> watches_;  // per literal: nogoods watching it
  size_t live_learned_ = 0;
  std::vector<double> activity_;
  double bump_ = 1;
  ActivityHeap heap_;
};

}  // namespace

SearchOutcome search_precedence(const ConstraintSystem& sys, SearchBudget& budget, SolveStats& st,
                                const PrecedenceHooks* hooks) {
  LearningSearch s(sys, budget, st, hooks);
  return s.run();
}

}  // namespace gridlock
