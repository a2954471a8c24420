#include "solver/internal/continuous_sat.hpp"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <numeric>
#include <stdexcept>
#include <thread>
#include <unordered_map>

#include <z3++.h>

#include "cnf/internal/incremental_sat.hpp"
#include "common/input_too_large.hpp"
#include "solver/internal/z3_lemmas.hpp"

namespace gridlock {

const std::vector<OffsetInterval>& cached_free_offsets(const CollisionConstraint& c, FreeOffsetsCache& cache) {
  std::vector<int64_t> key(c.base);
  c.append_coef(key);
  key.push_back(c.num_forms);
  auto it = cache.find(key);
  if (it == cache.end()) it = cache.emplace(std::move(key), free_offsets(c)).first;
  return it->second;
}

namespace {

// t_x - t_y <= v (< v when strict), x and y local coupling indices.
struct Bound {
  uint32_t x = 0, y = 0;
  Rational v;
  bool strict = false;
};

// A difference bound that holds whenever every literal of guard is true:
// what the event t_runner + delta of pair constraint `constraint` asks.
struct DiffRule {
  std::vector<int> guard;
  Bound b;
  uint32_t constraint = 0, runner = 0;
  int delta = 0;
};

// Why a clause holds (proof mode): see ContinuousProof.
struct ClauseReason {
  ContinuousProof::Reason reason = ContinuousProof::Reason::Theory;
  uint32_t constraint = 0, runner = 0;  // runner: local coupling index
  int delta = 0;
};

// A two-coupling pair's interval of free offsets t_b - t_a (proof mode).
struct SelectorInfo {
  uint32_t constraint = 0, a = 0, b = 0;  // a, b: local coupling indices
  OffsetInterval iv;
};

// K + sum over terms (q, c) of c * (t_r + delta - t_q) <= 0 whenever every
// literal of guard is true.
struct LinRule {
  std::vector<int> guard;
  Rational k;
  uint32_t r = 0;
  int delta = 0;
  std::vector<std::pair<uint32_t, int64_t>> terms;
};

// What a SAT variable stands for.
struct VarMeaning {
  enum class Kind { Atom, Selector, Guard } kind = Kind::Guard;
  Bound when_true;    // Atom, Selector (first bound)
  Bound when_true2;   // Selector: second bound (lo side); unused if !has2
  bool has2 = false;  // Selector only
  bool has1 = false;  // Selector only: when_true is set
  Bound when_false;   // Atom only
};

// Atom thresholds on D = t_a - t_b: index 0: D <= -1, 1: D < 0, 2: D <= 0, 3: D < 1.
constexpr int64_t kThreshold[4] = {-1, 0, 0, 1};
constexpr bool kStrict[4] = {false, true, false, true};

// A scaled edge for Bellman-Ford: t_to - t_from <= w / scale, strictness in
// the low part of w (see Engine::scaled).
struct Edge {
  uint32_t from = 0, to = 0;
  int64_t w = 0;
  int lit = 0;        // the SAT literal it comes from (0: none)
  int32_t rule = -1;  // or the DiffRule it comes from
};

// Calls visit(choice) for every choice of 0, 1 or 2 per index below m but
// `skip` (kept 0): 3^(m-1) calls (the branches of the other couplings at an
// event, or how the other couplings of a face start).
template <class Visit>
void each_choice(size_t m, size_t skip, Visit visit) {
  std::vector<int> choice(m, 0);
  for (;;) {
    visit(static_cast<const std::vector<int>&>(choice));
    size_t p = 0;
    for (; p < m; ++p) {
      if (p == skip) continue;
      if (++choice[p] < 3) break;
      choice[p] = 0;
    }
    if (p == m) return;
  }
}

class Engine {
 public:
  Engine(const ConstraintSystem& sys, const std::vector<CouplingId>& couplings, const std::vector<uint32_t>& pairs,
         const ComponentFaces& faces, FreeOffsetsCache& cache, SearchBudget& budget, SolveStats& stats)
      : sys_(sys), couplings_(couplings), pairs_(pairs), faces_(faces), cache_(cache), budget_(budget), stats_(stats) {
    for (uint32_t j = 0; j < couplings.size(); ++j) local_.emplace(couplings[j], j);
  }

  bool z3_for_linear = false;         // see solve_component_sat
  bool relax_covers = false;          // see ContinuousSatOptions
  bool difference_logic = false;      // see solve_component_sat
  ContinuousProof* proof_ = nullptr;  // see ContinuousSatOptions::proof

  ContinuousSatOutcome run() {
    ContinuousSatOutcome out;
    if (!encode()) {
      if (proof_) proof_of_failed_pair();
      out.verdict = Verdict::No;
      return out;
    }
    compute_scale();
    // Proof mode leaves the static unit clauses to Z3 (they would need
    // their own theory lemmas; Z3 derives them).
    if (!proof_ && !propagate_static()) {
      out.verdict = Verdict::No;
      return out;
    }
    if (difference_logic) return run_difference_logic();
    for (;;) {
      budget_.tick(stats_);
      ++stats_.decisions;
      const uint64_t before = sat_.conflicts();
      Verdict v = sat_.solve([&](uint64_t conf) { return budget_.exhausted(stats_, conf - before); });
      stats_.refuted += sat_.conflicts() - before;
      stats_.states += sat_.conflicts() - before;
      if (v == Verdict::No) {
        out.verdict = Verdict::No;
        return out;
      }
      if (v == Verdict::Unknown) throw LimitReached{};
      std::vector<Rational> t;
      if (!check_model(t) || !check_faces(t)) continue;
      return answer_yes(std::move(t));
    }
  }

 private:
  int lit_of(bool value, int var) const { return value ? var : -var; }

  // Every clause goes to CaDiCaL and is kept for the difference-logic mode
  // (and, in proof mode, with reason_ as its reason).
  void add_clause(const std::vector<int>& c) {
    clauses_.push_back(c);
    if (proof_) reasons_.push_back(reason_);
    sat_.add_clause(c);
  }

  // The first of the four atoms of local couplings a < b.
  int atoms(uint32_t a, uint32_t b) {
    auto key = (static_cast<uint64_t>(a) << 32) | b;
    auto it = atom_base_.find(key);
    if (it != atom_base_.end()) return it->second;
    const int first = sat_.num_vars() + 1;
    for (int i = 0; i < 4; ++i) {
      int v = sat_.new_var();
      VarMeaning m;
      m.kind = VarMeaning::Kind::Atom;
      m.when_true = {a, b, Rational(kThreshold[i]), kStrict[i]};
      // not (D <= c): t_b - t_a < -c; not (D < c): t_b - t_a <= -c.
      m.when_false = {b, a, Rational(-kThreshold[i]), !kStrict[i]};
      meaning_.push_back(m);
      if (i > 0) {  // the chain D <= -1 -> D < 0 -> D <= 0 -> D < 1
        const ClauseReason outer = reason_;
        reason_ = {};
        add_clause({-(v - 1), v});
        reason_ = outer;
      }
    }
    atom_base_.emplace(key, first);
    return first;
  }

  // The literal of "t_r - t_q <= -1" (which 0), "< 0" (1), "<= 0" (2), "< 1" (3).
  int diff_lit(uint32_t r, uint32_t q, int which) {
    if (r < q) return atoms(r, q) + which;
    return -(atoms(q, r) + 3 - which);
  }

  int new_var(VarMeaning m) {
    int v = sat_.new_var();
    meaning_.push_back(m);
    return v;
  }

  // Encodes every face and pair; false if some pair can never be free (NO
  // at once).
  bool encode() {
    for (uint32_t fi = 0; fi < faces_.size(); ++fi) encode_face(fi);
    for (uint32_t ci : pairs_) {
      budget_.poll();
      const CollisionConstraint& c = sys_.constraints[ci];
      failed_ = ci;
      reason_ = {ContinuousProof::Reason::Interval, ci, 0, 0};
      if (c.rel.size() == 1) {
        if (!pair_free_at_offset(c, Rational(0))) return false;
      } else if (c.rel.size() == 2) {
        if (!encode_two(c)) return false;
      } else if (c.num_forms > 1 && relax_covers && !forms_never_both_nonpositive(c)) {
        encode_cover_events(c);
      } else if (c.num_forms == 1) {
        if (!encode_gap(c, 0, 0)) return false;
      } else {
        std::vector<int> some;
        for (uint32_t i = 0; i < c.num_forms; ++i) {
          int g = new_var({});
          some.push_back(g);
          if (proof_) guards_.emplace(g, std::make_pair(ci, i));
          encode_gap(c, i, g);
        }
        reason_ = {ContinuousProof::Reason::Forms, ci, 0, 0};
        add_clause(some);
      }
    }
    return true;
  }

  // Face fi stays closed (see the header): for each coupling q of the face
  // and each way the others start (0: before q, 1: with q, 2: after q)
  // whose nets with q's do not sum to zero, the clause "not this way". A
  // face of more than kEagerFaceCouplings couplings only gets its atoms
  // here; check_faces adds its clauses when a model opens it.
  void encode_face(uint32_t fi) {
    const auto& nets = faces_[fi]->nets;
    const size_t m = nets.size();
    if (m > kEagerFaceCouplings) {
      lazy_faces_.push_back(fi);
      for (size_t j = 0; j < m; ++j)  // every atom now: Z3's copy of the encoding is built once
        for (size_t p = j + 1; p < m; ++p) diff_lit(local_.at(nets[p].first), local_.at(nets[j].first), 1);
      return;
    }
    for (size_t j = 0; j < m; ++j)
      each_choice(m, j, [&](const std::vector<int>& state) {
        budget_.poll();
        face_clause(fi, j, state);
      });
  }

  // The clause "coupling j of face fi does not start so (state, as in
  // encode_face)" if the nets of j and of those that start with it do not
  // sum to zero; true if it added it.
  bool face_clause(uint32_t fi, size_t j, const std::vector<int>& state) {
    const auto& nets = faces_[fi]->nets;
    Vec2 sum = nets[j].second;
    for (size_t p = 0; p < nets.size(); ++p)
      if (p != j && state[p] == 1) sum += nets[p].second;
    if (sum.is_zero()) return false;
    const uint32_t q = local_.at(nets[j].first);
    std::vector<int> clause;
    for (size_t p = 0; p < nets.size(); ++p) {
      if (p == j) continue;
      const uint32_t r = local_.at(nets[p].first);
      if (state[p] != 2) clause.push_back(-diff_lit(r, q, state[p] == 0 ? 1 : 2));  // not t_r < / <= t_q
      if (state[p] != 0) clause.push_back(diff_lit(r, q, state[p] == 1 ? 1 : 2));   // t_r < t_q / <= t_q
    }
    const ClauseReason outer = reason_;
    reason_ = {ContinuousProof::Reason::Face, fi, q, 0};
    add_clause(clause);
    reason_ = outer;
    return true;
  }

  // The lazy faces at the start times t: for each face that opens, the
  // clause of how its couplings start in t (one per face). True if none
  // opens. O(m^2) per lazy face of m couplings.
  bool check_faces(const std::vector<Rational>& t) {
    bool closed = true;
    for (uint32_t fi : lazy_faces_) {
      const auto& nets = faces_[fi]->nets;
      for (size_t j = 0; j < nets.size(); ++j) {
        const Rational& tq = t[local_.at(nets[j].first)];
        std::vector<int> state(nets.size(), 1);
        for (size_t p = 0; p < nets.size(); ++p) {
          const Rational& tr = t[local_.at(nets[p].first)];
          state[p] = tr < tq ? 0 : tr == tq ? 1 : 2;
        }
        if (face_clause(fi, j, state)) {
          closed = false;
          break;
        }
      }
    }
    return closed;
  }

  // The relaxation of a pair of several forms that can be <= 0 together
  // (ContinuousSatOptions::relax_covers): at every event t_r + delta of its
  // couplings and every branch choice of the others (0: not started, 1:
  // done, 2: partial) that makes every form positive on the whole box, the
  // pair collides: the clause "not this choice". 3^(r-1) per event.
  void encode_cover_events(const CollisionConstraint& c) {
    const size_t m = c.rel.size();
    for (size_t j = 0; j < m; ++j)
      for (int delta = 0; delta <= 1; ++delta)
        each_choice(m, j, [&](const std::vector<int>& branch) {
          budget_.poll();
          cover_choice(c, j, delta, branch);
        });
  }

  void cover_choice(const CollisionConstraint& c, size_t j, int delta, const std::vector<int>& branch) {
    for (uint32_t i = 0; i < c.num_forms; ++i) {
      int64_t k = c.base[i] + c.coef_of(j)[i] * delta, lo = 0;
      bool partial = false;
      for (size_t p = 0; p < c.rel.size(); ++p) {
        if (p == j) continue;
        const int64_t cp = c.coef_of(p)[i];
        if (branch[p] == 1) k += cp;
        if (branch[p] == 2 && cp != 0) partial = true, lo += std::min<int64_t>(0, cp);
      }
      if (partial ? k + lo < 0 : k <= 0) return;  // this form can be <= 0 here
    }
    const uint32_t r = local_.at(c.rel[j]);
    std::vector<int> clause;
    for (size_t p = 0; p < c.rel.size(); ++p)
      if (p != j) branch_guard(r, local_.at(c.rel[p]), delta, branch[p], clause);
    for (int& l : clause) l = -l;
    const ClauseReason outer = reason_;
    reason_ = {ContinuousProof::Reason::Event, outer.constraint, r, delta};
    add_clause(clause);
    reason_ = outer;
  }

  // A two-coupling pair: t_b - t_a in one of its free intervals.
  bool encode_two(const CollisionConstraint& c) {
    const auto& iv = cached_free_offsets(c, cache_);
    if (iv.empty()) return false;
    const uint32_t a = local_.at(c.rel[0]), b = local_.at(c.rel[1]);
    std::vector<int> some;
    for (const OffsetInterval& x : iv) {
      VarMeaning m;
      m.kind = VarMeaning::Kind::Selector;
      if (x.hi) m.when_true = {b, a, *x.hi, false}, m.has1 = true;
      if (x.lo) m.when_true2 = {a, b, Rational(0) - *x.lo, false}, m.has2 = true;
      if (iv.size() == 1) {
        if (m.has1) static_.push_back(m.when_true);
        if (m.has2) static_.push_back(m.when_true2);
        if (proof_) static_selectors_.push_back({reason_.constraint, a, b, x});
        return true;
      }
      some.push_back(new_var(m));
      if (proof_) selectors_.emplace(some.back(), SelectorInfo{reason_.constraint, a, b, x});
    }
    add_clause(some);
    return true;
  }

  // Form i of c must be <= 0 at every event (when guard g is true; g == 0:
  // always). Enumerates every event and every branch choice of the other
  // clamps. False if the gap can never hold (only when g == 0).
  bool encode_gap(const CollisionConstraint& c, uint32_t i, int g) {
    std::vector<uint32_t> qs;
    std::vector<int64_t> cs;
    for (size_t j = 0; j < c.rel.size(); ++j)
      if (c.coef_of(j)[i] != 0) qs.push_back(local_.at(c.rel[j])), cs.push_back(c.coef_of(j)[i]);
    if (c.base[i] > 0) {
      if (g == 0) return false;
      const ClauseReason outer = reason_;
      reason_ = {ContinuousProof::Reason::Event, outer.constraint, kNone, 0};  // before every start
      add_clause({-g});
      reason_ = outer;
      return true;
    }
    for (size_t j = 0; j < qs.size(); ++j)
      for (int delta = 0; delta <= 1; ++delta) encode_event(c.base[i], qs, cs, j, delta, g);
    return true;
  }

  // The event t_(qs[j]) + delta of one gap: every choice of branches (0:
  // not started, 1: done, 2: partial) of the other couplings.
  void encode_event(int64_t base, const std::vector<uint32_t>& qs, const std::vector<int64_t>& cs, size_t j, int delta,
                    int g) {
    each_choice(qs.size(), j, [&](const std::vector<int>& branch) {
      budget_.poll();
      encode_choice(base, qs, cs, j, delta, g, branch);
    });
  }

  // The literals that say coupling q's clamp at the event t_r + delta is
  // branch (0: not started, 1: done, 2: partial), appended to guard.
  void branch_guard(uint32_t r, uint32_t q, int delta, int branch, std::vector<int>& guard) {
    // delta 0: zero iff t_r - t_q <= 0, done iff >= 1; delta 1: <= -1 and >= 0.
    const int zero_which = delta == 0 ? 2 : 0, below_done_which = delta == 0 ? 3 : 1;
    if (branch == 0) {
      guard.push_back(diff_lit(r, q, zero_which));
    } else if (branch == 1) {
      guard.push_back(-diff_lit(r, q, below_done_which));
    } else {
      guard.push_back(-diff_lit(r, q, zero_which));
      guard.push_back(diff_lit(r, q, below_done_which));
    }
  }

  void encode_choice(int64_t base, const std::vector<uint32_t>& qs, const std::vector<int64_t>& cs, size_t j, int delta,
                     int g, const std::vector<int>& branch) {
    const uint32_t r = qs[j];
    int64_t k = base + cs[j] * delta, lo = 0, hi = 0;
    std::vector<int> guard;
    if (g != 0) guard.push_back(g);
    std::vector<std::pair<uint32_t, int64_t>> partial;
    for (size_t p = 0; p < qs.size(); ++p) {
      if (p == j) continue;
      const uint32_t q = qs[p];
      branch_guard(r, q, delta, branch[p], guard);
      if (branch[p] == 1) {
        k += cs[p];
      } else if (branch[p] == 2) {
        partial.emplace_back(q, cs[p]);
        lo += std::min<int64_t>(0, cs[p]), hi += std::max<int64_t>(0, cs[p]);
      }
    }
    const bool violated = partial.empty() ? k > 0 : k + lo >= 0;
    const bool holds = partial.empty() ? k <= 0 : k + hi <= 0;
    if (violated) {
      std::vector<int> clause(guard.size());
      std::transform(guard.begin(), guard.end(), clause.begin(), [](int l) { return -l; });
      const ClauseReason outer = reason_;
      reason_ = {ContinuousProof::Reason::Event, outer.constraint, r, delta};
      add_clause(clause);
      reason_ = outer;
      return;
    }
    if (holds) return;
    if (partial.size() == 1) {
      const auto [q, cq] = partial[0];
      // K + cq (t_r + delta - t_q) <= 0.
      DiffRule rule;
      rule.guard = guard;
      if (cq > 0) rule.b = {r, q, Rational(-k - cq * delta, cq), false};
      else rule.b = {q, r, Rational(k + cq * delta, cq), false};
      rule.constraint = reason_.constraint, rule.runner = r, rule.delta = delta;
      diff_rules_.push_back(std::move(rule));
      return;
    }
    lin_rules_.push_back({guard, Rational(k), r, delta, partial});
  }

  // scale_ = (n + 1) * lcm of every bound's denominator: w = scale * v - strict
  // is an integer, and a cycle's weights sum to < 0 iff its bounds sum to < 0
  // or to 0 with a strict one (at most n strict edges on a simple cycle).
  void compute_scale() {
    int64_t l = 1;
    auto add = [&](const Bound& b) { l = std::lcm(l, b.v.den()); };
    for (const Bound& b : static_) add(b);
    for (const VarMeaning& m : meaning_) {
      if (m.kind == VarMeaning::Kind::Selector) {
        if (m.has1) add(m.when_true);
        if (m.has2) add(m.when_true2);
      }
    }
    for (const DiffRule& r : diff_rules_) add(r.b);
    if (l > (int64_t{1} << 20)) throw InputTooLarge("continuous sat: denominators too large");
    scale_ = static_cast<int64_t>(couplings_.size() + 1) * l;
  }

  // Shortest paths over the bounds that hold in every schedule (the
  // intervals of two-coupling pairs with one interval: separation and order
  // gadgets), from every coupling that has atoms: each atom they decide is
  // a unit clause. The static potentials also give every atom its first
  // phase. False if the static bounds alone are contradictory (NO).
  bool propagate_static() {
    std::vector<Edge> es;
    for (const Bound& b : static_) es.push_back(edge(b, 0, -1));
    std::vector<char> off(es.size(), 0);
    std::vector<int64_t> pot;
    if (!negative_cycle(es, off, pot).empty()) return false;
    const size_t n = couplings_.size();
    std::vector<std::vector<uint32_t>> out(n);
    for (uint32_t i = 0; i < es.size(); ++i) out[es[i].from].push_back(i);
    std::vector<std::vector<std::pair<uint32_t, int>>> atoms_of(n);  // (other end b, first var) per a
    for (auto [key, first] : atom_base_) atoms_of[key >> 32].emplace_back(static_cast<uint32_t>(key), first);
    constexpr int64_t kInf = INT64_MAX / 4;
    std::vector<int64_t> from_a(n), to_a(n);
    for (uint32_t a = 0; a < n; ++a) {
      if (atoms_of[a].empty()) continue;
      budget_.check();
      paths_from(a, es, out, false, from_a, kInf);
      paths_from(a, es, out, true, to_a, kInf);
      for (auto [b, first] : atoms_of[a]) {
        for (int i = 0; i < 4; ++i) {
          const VarMeaning& m = meaning_[static_cast<size_t>(first + i - 1)];
          // t_a - t_b <= to_a[b] (path b -> a); t_b - t_a <= from_a[b] (path a -> b).
          if (to_a[b] < kInf && to_a[b] <= scaled(m.when_true)) add_clause({first + i});
          if (from_a[b] < kInf && from_a[b] <= scaled(m.when_false)) add_clause({-(first + i)});
        }
      }
    }
    for (auto [key, first] : atom_base_) {
      const uint32_t a = static_cast<uint32_t>(key >> 32), b = static_cast<uint32_t>(key);
      for (int i = 0; i < 4; ++i) {
        const VarMeaning& m = meaning_[static_cast<size_t>(first + i - 1)];
        const bool val = pot[a] - pot[b] <= scaled(m.when_true);
        sat_.set_phase(val ? first + i : -(first + i));
      }
    }
    return true;
  }

  // Shortest path weights from a (reverse: to a) over the static edges, by
  // a queue-based Bellman-Ford (no negative cycle: checked before).
  void paths_from(uint32_t a, const std::vector<Edge>& es, const std::vector<std::vector<uint32_t>>& out, bool reverse,
                  std::vector<int64_t>& d, int64_t inf) {
    std::fill(d.begin(), d.end(), inf);
    d[a] = 0;
    std::deque<uint32_t> queue{a};
    std::vector<std::vector<uint32_t>>* rev = nullptr;
    if (reverse) {
      if (rev_.empty()) {
        rev_.assign(couplings_.size(), {});
        for (uint32_t i = 0; i < es.size(); ++i) rev_[es[i].to].push_back(i);
      }
      rev = &rev_;
    }
    while (!queue.empty()) {
      const uint32_t u = queue.front();
      queue.pop_front();
      for (uint32_t ei : reverse ? (*rev)[u] : out[u]) {
        const uint32_t v = reverse ? es[ei].from : es[ei].to;
        if (d[u] + es[ei].w < d[v]) d[v] = d[u] + es[ei].w, queue.push_back(v);
      }
    }
  }

  int64_t scaled(const Bound& b) const {
    __int128 w = static_cast<__int128>(b.v.num()) * (scale_ / b.v.den()) - (b.strict ? 1 : 0);
    if (w > (int64_t{1} << 50) || w < -(int64_t{1} << 50)) throw InputTooLarge("continuous sat: bound too large");
    return static_cast<int64_t>(w);
  }

  Edge edge(const Bound& b, int lit, int32_t rule) const { return {b.y, b.x, scaled(b), lit, rule}; }

  bool guard_true(const std::vector<int>& guard) const {
    for (int l : guard)
      if (sat_.value(std::abs(l)) != (l > 0)) return false;
    return true;
  }

  std::vector<Edge> active_edges() const {
    std::vector<Edge> es;
    for (const Bound& b : static_) es.push_back(edge(b, 0, -1));
    for (size_t v = 1; v <= meaning_.size(); ++v) {
      const VarMeaning& m = meaning_[v - 1];
      const bool val = sat_.value(static_cast<int>(v));
      if (m.kind == VarMeaning::Kind::Atom) {
        es.push_back(edge(val ? m.when_true : m.when_false, lit_of(val, static_cast<int>(v)), -1));
      } else if (m.kind == VarMeaning::Kind::Selector && val) {
        if (m.has1) es.push_back(edge(m.when_true, static_cast<int>(v), -1));
        if (m.has2) es.push_back(edge(m.when_true2, static_cast<int>(v), -1));
      }
    }
    for (size_t r = 0; r < diff_rules_.size(); ++r)
      if (guard_true(diff_rules_[r].guard)) es.push_back(edge(diff_rules_[r].b, 0, static_cast<int32_t>(r)));
    return es;
  }

  // Queue-based Bellman-Ford from a virtual source (every distance 0).
  // Returns the edges of a negative cycle, or empty with dist the potentials.
  std::vector<uint32_t> negative_cycle(const std::vector<Edge>& es, const std::vector<char>& off,
                                       std::vector<int64_t>& dist) {
    const size_t n = couplings_.size();
    std::vector<uint32_t> start(n + 1, 0), adj(es.size());
    for (const Edge& e : es) ++start[e.from + 1];
    for (size_t i = 0; i < n; ++i) start[i + 1] += start[i];
    {
      std::vector<uint32_t> fill(start.begin(), start.end() - 1);
      for (uint32_t i = 0; i < es.size(); ++i) adj[fill[es[i].from]++] = i;
    }
    dist.assign(n, 0);
    std::vector<uint32_t> len(n, 0), parent(n, UINT32_MAX);
    std::vector<char> queued(n, 1);
    std::deque<uint32_t> queue(n);
    std::iota(queue.begin(), queue.end(), 0u);
    size_t relaxed = 0;
    while (!queue.empty()) {
      budget_.poll();
      const uint32_t u = queue.front();
      queue.pop_front();
      queued[u] = 0;
      for (uint32_t a = start[u]; a < start[u + 1]; ++a) {
        const uint32_t ei = adj[a];
        if (off[ei]) continue;
        const Edge& e = es[ei];
        if (dist[u] + e.w >= dist[e.to]) continue;
        dist[e.to] = dist[u] + e.w;
        parent[e.to] = ei;
        len[e.to] = len[u] + 1;
        // Walking the parent graph every n relaxations finds a cycle soon
        // after it forms (waiting for a path of n edges can take n rounds).
        if (len[e.to] >= n || ++relaxed % n == 0) {
          std::vector<uint32_t> cyc = any_parent_cycle(es, parent, e.to);
          if (!cyc.empty()) return cyc;
        }
        if (!queued[e.to]) queued[e.to] = 1, queue.push_back(e.to);
      }
    }
    return {};
  }

  // A cycle of the parent graph (first from v, then from every node), or
  // empty. O(n).
  std::vector<uint32_t> any_parent_cycle(const std::vector<Edge>& es, const std::vector<uint32_t>& parent, uint32_t v) {
    std::vector<uint32_t> cyc = parent_cycle(es, parent, v);
    if (!cyc.empty()) return cyc;
    // Nodes marked by earlier walks of this scan lead to a root or to a walk
    // already done: skip them (marks of older scans are smaller stamps).
    const uint64_t scan = stamp_ + 1;
    for (uint32_t u = 0; u < couplings_.size(); ++u) {
      if (seen_[u] >= scan) continue;
      cyc = parent_cycle(es, parent, u, scan);
      if (!cyc.empty()) return cyc;
    }
    return {};
  }

  // A cycle of the parent graph reached from v, or empty if the walk ends
  // at a root. Every cycle of the parent graph of a shortest-path relaxation
  // is negative (checked: a positive one would be a bug).
  // Nodes of this walk get a fresh stamp; a walk that meets a node of an
  // earlier walk of the same scan (stamp >= scan) stops: it ends where that
  // one ended. scan == 0: a walk on its own.
  std::vector<uint32_t> parent_cycle(const std::vector<Edge>& es, const std::vector<uint32_t>& parent, uint32_t v,
                                     uint64_t scan = 0) {
    ++stamp_;
    if (seen_.size() != couplings_.size()) seen_.assign(couplings_.size(), 0);
    while (seen_[v] != stamp_) {
      if (scan != 0 && seen_[v] >= scan) return {};
      seen_[v] = stamp_;
      if (parent[v] == UINT32_MAX) return {};
      v = es[parent[v]].from;
    }
    std::vector<uint32_t> cyc;
    uint32_t u = v;
    do {
      cyc.push_back(parent[u]);
      u = es[parent[u]].from;
    } while (u != v);
    int64_t sum = 0;
    for (uint32_t ei : cyc) sum += es[ei].w;
    if (sum >= 0) throw std::logic_error("continuous sat: parent cycle is not negative");
    return cyc;
  }

  // Checks the current model; true with t the start times if it is a
  // schedule. Else learns clauses (at least one) and returns false.
  bool check_model(std::vector<Rational>& t) {
    std::vector<Edge> es = active_edges();
    std::vector<char> off(es.size(), 0);
    std::vector<int64_t> dist;
    size_t learned = 0;
    for (int round = 0; round < 256; ++round) {
      std::vector<uint32_t> cyc = negative_cycle(es, off, dist);
      if (cyc.empty()) break;
      std::vector<int> clause;
      for (uint32_t ei : cyc) {
        const Edge& e = es[ei];
        if (e.lit != 0) clause.push_back(-e.lit);
        if (e.rule >= 0)
          for (int l : diff_rules_[static_cast<size_t>(e.rule)].guard) clause.push_back(-l);
        off[ei] = 1;
      }
      std::sort(clause.begin(), clause.end());
      clause.erase(std::unique(clause.begin(), clause.end()), clause.end());
      add_clause(clause);
      ++stats_.propagations;
      ++learned;
    }
    if (learned > 0) {
      if (dist.size() == couplings_.size()) phases_from(dist);
      return false;
    }
    t.assign(couplings_.size(), Rational(0));
    for (size_t q = 0; q < t.size(); ++q) t[q] = Rational(dist[q], scale_);
    bool linear_ok = true;
    for (const LinRule& r : lin_rules_)
      if (guard_true(r.guard) && (z3_for_linear || !holds(r, t))) {
        linear_ok = false;
        break;
      }
    if (linear_ok) return true;
    return check_with_z3(t);
  }

  // Points the next search at the potentials of the edges that survived
  // the cycles just learned: every atom's and selector's phase is its value
  // there, so CaDiCaL's next model starts from a nearly consistent one.
  void phases_from(const std::vector<int64_t>& dist) {
    for (size_t v = 1; v <= meaning_.size(); ++v) {
      const VarMeaning& m = meaning_[v - 1];
      const int var = static_cast<int>(v);
      auto sat_at = [&](const Bound& b) { return dist[b.x] - dist[b.y] <= scaled(b); };
      if (m.kind == VarMeaning::Kind::Atom) {
        sat_.set_phase(sat_at(m.when_true) ? var : -var);
      } else if (m.kind == VarMeaning::Kind::Selector) {
        const bool in = (!m.has1 || sat_at(m.when_true)) && (!m.has2 || sat_at(m.when_true2));
        sat_.set_phase(in ? var : -var);
      }
    }
  }

  static bool holds(const LinRule& r, const std::vector<Rational>& t) {
    Rational v = r.k;
    for (auto [q, c] : r.terms) v = v + Rational(c) * (t[r.r] + Rational(r.delta) - t[q]);
    return v <= Rational(0);
  }

  // Difference-logic mode: the clauses, every atom's and selector's meaning,
  // the static bounds and the difference rules go to Z3 as one problem of
  // difference constraints (its arithmetic solver propagates bounds during
  // the search, which CaDiCaL 1.5.3 cannot). The linear rules are left out:
  // a NO without them is a NO with them (fewer constraints), and a model is
  // checked against every linear rule whose guard it makes true. If one
  // fails (or z3_for_linear and one is active), Z3 decides the whole
  // encoding, linear rules included, and its answer is final.
  ContinuousSatOutcome run_difference_logic() {
    ContinuousSatOutcome out;
    bool with_linear = false;
    for (;;) {
      build_z3(with_linear, true);
      size_t given = 0;  // clauses_ given to Z3
      for (;;) {
        for (; given < clauses_.size(); ++given) {
          z3::expr_vector lits(*z3ctx_);
          for (int l : clauses_[given]) lits.push_back(z3_lit(l));
          z3s_->add(z3::mk_or(lits));
        }
        if (decide_once(with_linear, out)) return out;
        if (with_linear_next_) break;
      }
      with_linear = true;
    }
  }

  // One Z3 call of run_difference_logic: true with out set if decided;
  // false if check_faces added clauses (run again) or, with
  // with_linear_next_ set, a linear rule failed (run again with them).
  bool decide_once(bool with_linear, ContinuousSatOutcome& out) {
    with_linear_next_ = false;
    const z3::check_result cr = check_interruptible();
    if (cr == z3::unknown) throw LimitReached{};
    if (cr == z3::unsat) {
      if (proof_) write_proof(with_linear);
      out.verdict = Verdict::No;
      return true;
    }
    const z3::model model = z3s_->get_model();
    std::vector<Rational> t = z3_times(model);
    if (!check_faces(t)) return false;
    bool linear_ok = true;
    for (const LinRule& r : lin_rules_) {
      bool guard = true;
      for (int l : r.guard) guard = guard && model.eval(z3_lit(l), true).is_true();
      if (guard && (z3_for_linear || !holds(r, t))) linear_ok = false;
    }
    if (!linear_ok && !with_linear) {
      with_linear_next_ = true;
      return false;
    }
    out = answer_yes(std::move(t));
    return true;
  }

  // Proof mode: the canonical variable of bound b (local indices) as a
  // literal; t_x - t_y <= v with x > y is the negation of t_y - t_x < -v.
  // Creates the variable (kind bound) if it is new.
  int bound_lit(const Bound& b) {
    const bool flip = b.x > b.y;
    const Bound c = flip ? Bound{b.y, b.x, Rational(0) - b.v, !b.strict} : b;
    const auto key = std::make_tuple(c.x, c.y, c.v.num(), c.v.den(), c.strict);
    auto it = bound_var_.find(key);
    if (it == bound_var_.end()) {
      ContinuousProof::Var v;
      v.x = couplings_[c.x], v.y = couplings_[c.y], v.v = c.v, v.strict = c.strict;
      proof_->vars.push_back(v);
      it = bound_var_.emplace(key, static_cast<int>(proof_->vars.size())).first;
    }
    return flip ? -it->second : it->second;
  }

  // Proof mode: clause c for the proof, with its reason.
  void proof_clause(const ClauseReason& why, std::vector<int> lits, const std::vector<uint32_t>* movers = nullptr) {
    ContinuousProof::Clause cl;
    cl.reason = why.reason;
    if (why.reason == ContinuousProof::Reason::Interval || why.reason == ContinuousProof::Reason::Event ||
        why.reason == ContinuousProof::Reason::Forms) {
      const CollisionConstraint& c = sys_.constraints[why.constraint];
      cl.region_a = c.region_a, cl.region_b = c.region_b;
      if (why.reason == ContinuousProof::Reason::Event)
        cl.runner = why.runner == kNone ? kNone : couplings_[why.runner], cl.delta = why.delta;
      else if (movers)
        for (uint32_t q : *movers) cl.movers.push_back(couplings_[q]);
      else if (why.reason == ContinuousProof::Reason::Interval) cl.movers = c.rel;
    }
    if (why.reason == ContinuousProof::Reason::Face)
      cl.runner = couplings_[why.runner], cl.walk = faces_[why.constraint]->walk;
    cl.lits = std::move(lits);
    proof_->clauses.push_back(std::move(cl));
  }

  // Proof mode: a selector variable for interval s (v: its SAT variable, or
  // 0 for a new one) and the clauses that define it.
  int proof_selector(const SelectorInfo& s, int v) {
    ContinuousProof::Var var;
    var.selector = true, var.x = couplings_[s.a], var.y = couplings_[s.b], var.lo = s.iv.lo, var.hi = s.iv.hi;
    if (v == 0) {
      proof_->vars.push_back(var);
      v = static_cast<int>(proof_->vars.size());
    } else {
      proof_->vars[static_cast<size_t>(v - 1)] = var;
    }
    const ClauseReason def{ContinuousProof::Reason::Definition, 0, 0, 0};
    // lo <= t_b - t_a: t_a - t_b <= -lo; t_b - t_a <= hi.
    if (s.iv.lo) proof_clause(def, {-v, bound_lit({s.a, s.b, Rational(0) - *s.iv.lo, false})});
    if (s.iv.hi) proof_clause(def, {-v, bound_lit({s.b, s.a, *s.iv.hi, false})});
    return v;
  }

  // Proof mode, after Z3's NO: the encoding's clauses with their reasons,
  // the difference rules as event clauses, the static intervals as
  // selectors, and the theory lemmas of Z3's proof.
  void write_proof(bool with_linear) {
    ContinuousProof& p = *proof_;
    p = {};
    if (with_linear)
      return void(
          p.why_none = "the NO needed the linear rules (two couplings part-way at an event): not certified yet");
    p.vars.resize(meaning_.size());
    for (auto [key, first] : atom_base_)
      for (int i = 0; i < 4; ++i) {
        const VarMeaning& m = meaning_[static_cast<size_t>(first + i - 1)];
        ContinuousProof::Var& v = p.vars[static_cast<size_t>(first + i - 1)];
        v.x = couplings_[m.when_true.x], v.y = couplings_[m.when_true.y], v.v = m.when_true.v,
        v.strict = m.when_true.strict;
        bound_var_.emplace(
            std::make_tuple(m.when_true.x, m.when_true.y, m.when_true.v.num(), m.when_true.v.den(), m.when_true.strict),
            first + i);
      }
    for (const auto& [v, info] : selectors_) proof_selector(info, v);
    for (const auto& [v, cf] : guards_) {
      const CollisionConstraint& c = sys_.constraints[cf.first];
      ContinuousProof::Var& var = p.vars[static_cast<size_t>(v - 1)];
      var.guard = true, var.form = c.form_index.at(cf.second), var.region_a = c.region_a, var.region_b = c.region_b;
    }
    for (size_t i = 0; i < clauses_.size(); ++i) proof_clause(reasons_[i], clauses_[i]);
    for (const SelectorInfo& s : static_selectors_) {
      const int v = proof_selector(s, 0);
      const std::vector<uint32_t> movers{s.a, s.b};
      proof_clause({ContinuousProof::Reason::Interval, s.constraint, 0, 0}, {v}, &movers);
    }
    for (const DiffRule& r : diff_rules_) {
      std::vector<int> lits;
      for (int l : r.guard) lits.push_back(-l);
      lits.push_back(bound_lit(r.b));
      proof_clause({ContinuousProof::Reason::Event, r.constraint, r.runner, r.delta}, std::move(lits));
    }
    try {
      for (const std::vector<DiffLiteral>& lemma : z3_theory_lemmas(z3s_->proof())) {
        std::vector<int> lits = cycle_lemma(lemma);
        if (lits.empty()) throw std::runtime_error("a theory lemma of Z3 without a negative cycle");
        proof_clause({}, std::move(lits));
      }
    } catch (const std::runtime_error& e) {
      p = {};
      return void(p.why_none = e.what());
    } catch (const InputTooLarge& e) {  // a bound past 2^50: no proof, the NO stands
      p = {};
      return void(p.why_none = e.what());
    }
    p.complete = true;
  }

  // Proof mode: a theory lemma cut down to a negative cycle of its
  // literals' negations, in cycle order (each negation's second start time
  // is the next one's first, docs/certificates.md "Kind bounds"): what the
  // checker adds up. Empty if there is none (or a constant's denominator
  // does not divide scale_). O(couplings + lemma) per relaxation pass.
  std::vector<int> cycle_lemma(const std::vector<DiffLiteral>& lemma) {
    std::vector<Edge> es;
    for (size_t i = 0; i < lemma.size(); ++i) {
      const DiffLiteral& d = lemma[i];
      const Bound neg{d.y, d.x, Rational(0) - d.v, !d.strict};  // not (t_x - t_y <= v)
      if (scale_ % neg.v.den() != 0) return {};
      es.push_back(edge(neg, static_cast<int>(i), -1));
    }
    std::vector<char> off(es.size(), 0);
    std::vector<int64_t> dist;
    std::vector<int> out;
    for (uint32_t ei : negative_cycle(es, off, dist)) {
      const DiffLiteral& d = lemma[static_cast<size_t>(es[ei].lit)];
      out.push_back(bound_lit({d.x, d.y, d.v, d.strict}));
    }
    return out;
  }

  // Proof mode, when a pair can never be free (encode() failed): one
  // interval clause without literals, or for a gap an event clause before
  // every start.
  void proof_of_failed_pair() {
    ContinuousProof& p = *proof_;
    p = {};
    const CollisionConstraint& c = sys_.constraints[failed_];
    if (c.rel.size() > 2)  // a gap open before anything starts: the pair collides then
      proof_clause({ContinuousProof::Reason::Event, failed_, kNone, 0}, {});
    else proof_clause({ContinuousProof::Reason::Interval, failed_, 0, 0}, {});
    p.complete = true;
  }

  // A YES of either search: times shifted so the earliest is 0, checked pair
  // by pair (verify).
  ContinuousSatOutcome answer_yes(std::vector<Rational> t) const {
    if (relax_covers) return {};  // a model of the relaxation proves nothing
    const Rational lo = *std::min_element(t.begin(), t.end());
    for (Rational& x : t) x = x - lo;
    verify(t);
    ContinuousSatOutcome out;
    out.verdict = Verdict::Yes;
    out.start = std::move(t);
    return out;
  }

  // While alive, a thread that every 20 ms interrupts Z3 if the budget is
  // exhausted and otherwise draws the progress line; the destructor stops
  // and joins it.
  class Z3Watcher {
   public:
    explicit Z3Watcher(Engine& e) : thread_([this, &e] { watch(e); }) {}
    Z3Watcher(const Z3Watcher&) = delete;
    Z3Watcher& operator=(const Z3Watcher&) = delete;
    ~Z3Watcher() {
      {
        std::lock_guard<std::mutex> lock(m_);
        done_ = true;
      }
      cv_.notify_all();
      thread_.join();
    }

   private:
    void watch(Engine& e) {
      std::unique_lock<std::mutex> lock(m_);
      while (!cv_.wait_for(lock, std::chrono::milliseconds(20), [this] { return done_; })) {
        if (e.budget_.exhausted(e.stats_)) {
          e.z3ctx_->interrupt();
          return;
        }
        e.budget_.show_activity("continuous difference-logic engine (Z3)");
      }
    }
    std::mutex m_;
    std::condition_variable cv_;
    bool done_ = false;   // guarded by m_
    std::thread thread_;  // last: starts after the members it uses exist
  };

  // z3s_->check() while a watcher thread interrupts Z3 when the budget is
  // exhausted (time, stop request, nodes: Z3's conflicts count as nodes)
  // and draws the progress line. Z3's decisions and conflicts go to stats.
  z3::check_result check_interruptible() {
    budget_.check(stats_);
    if (budget_.max_states() != 0) {
      const uint64_t left = budget_.max_states() - stats_.states;  // > 0: checked above
      z3s_->set("max_conflicts", static_cast<unsigned>(std::min<uint64_t>(left, UINT32_MAX)));
    }
    z3::check_result cr = z3::unknown;
    {
      Z3Watcher watcher(*this);  // stops and joins its thread however check() ends
      cr = z3s_->check();
    }
    const z3::stats st = z3s_->statistics();
    for (unsigned i = 0; i < st.size(); ++i) {
      if (!st.is_uint(i)) continue;
      if (st.key(i) == "decisions") stats_.decisions += st.uint_value(i);
      if (st.key(i) == "conflicts") stats_.refuted += st.uint_value(i), stats_.states += st.uint_value(i);
    }
    ++stats_.memo_hits;
    return cr;
  }

  std::vector<Rational> z3_times(const z3::model& model) {
    std::vector<Rational> t(couplings_.size(), Rational(0));
    for (size_t q = 0; q < couplings_.size(); ++q) {
      auto parsed = Rational::parse(Z3_get_numeral_string((*z3ctx_), model.eval(zt_[q], true)));
      if (!parsed) throw InputTooLarge("continuous sat: a Z3 time is no 64-bit rational");
      t[q] = *parsed;
    }
    return t;
  }

  void verify(const std::vector<Rational>& t) const {
    for (const FaceNets::Face* f : faces_)
      for (const auto& [q, v] : f->nets) {
        Vec2 sum{0, 0};
        for (const auto& [r, w] : f->nets)
          if (t[local_.at(r)] == t[local_.at(q)]) sum += w;
        if (!sum.is_zero()) throw std::logic_error("continuous sat engine: a face opens at the times of a model");
      }
    for (uint32_t ci : pairs_) {
      const CollisionConstraint& c = sys_.constraints[ci];
      std::vector<Rational> st;
      for (CouplingId q : c.rel) st.push_back(t[local_.at(q)]);
      if (!pair_free_at_times(c, st))
        throw std::logic_error("continuous sat engine: a pair collides at the times of a model");
    }
  }

  z3::expr z3_bound(const Bound& b) {
    z3::expr d = zt_[b.x] - zt_[b.y];
    z3::expr v = (*z3ctx_).real_val(b.v.str().c_str());
    return b.strict ? d < v : d <= v;
  }

  z3::expr z3_lit(int l) { return l > 0 ? zb_[static_cast<size_t>(l)] : !zb_[static_cast<size_t>(-l)]; }

  z3::expr z3_guard(const std::vector<int>& guard) {
    z3::expr_vector v((*z3ctx_));
    for (int l : guard) v.push_back(z3_lit(l));
    return z3::mk_and(v);
  }

  // Builds the Z3 twin of the encoding: a real per coupling, a Boolean per
  // SAT variable, every meaning as an implication. Without the linear rules
  // (with_linear false) every constraint is a difference bound.
  // direct_atoms: an atom's Boolean is its difference bound itself (its
  // false meaning is the bound's negation), so Z3's theory solver sees and
  // propagates the atoms (not for assumptions: those must be Boolean
  // constants).
  void build_z3(bool with_linear = true, bool direct_atoms = false) {
    zt_.clear();
    zb_.clear();
    z3s_.reset();
    {
      z3::config cfg;
      if (proof_) cfg.set("proof", true);
      z3ctx_ = std::make_unique<z3::context>(cfg);
    }
    if (with_linear) {
      z3s_ = std::make_unique<z3::solver>(*z3ctx_, "QF_LRA");
    } else {
      // Difference constraints only: the SMT kernel alone (no tactic
      // pipeline: ~1 ms to create instead of ~25 ms for a QF_RDL solver),
      // configured by Z3 from the problem's features, with arith.solver=3.
      // Measured on compiled formulas: 10-100x fewer conflicts and seconds
      // than a QF_RDL or QF_LRA solver (docs/performance.md, "Continuous
      // learning engine"). It cannot take linear rules (Z3 answers unknown).
      z3s_ = std::make_unique<z3::solver>(*z3ctx_, z3::solver::simple());
      z3s_->set("arith.solver", 3u);
    }
    for (size_t q = 0; q < couplings_.size(); ++q)
      zt_.push_back((*z3ctx_).real_const(("t" + std::to_string(q)).c_str()));
    zb_.push_back((*z3ctx_).bool_val(true));
    for (size_t v = 1; v <= meaning_.size(); ++v) {
      const VarMeaning& m = meaning_[v - 1];
      if (direct_atoms && m.kind == VarMeaning::Kind::Atom) zb_.push_back(z3_bound(m.when_true));
      else zb_.push_back((*z3ctx_).bool_const(("b" + std::to_string(v)).c_str()));
    }
    for (const Bound& b : static_) z3s_->add(z3_bound(b));
    for (size_t v = 1; v <= meaning_.size(); ++v) {
      const VarMeaning& m = meaning_[v - 1];
      if (direct_atoms && m.kind == VarMeaning::Kind::Atom) continue;
      if (m.kind == VarMeaning::Kind::Atom) {
        z3s_->add(z3::implies(zb_[v], z3_bound(m.when_true)));
        z3s_->add(z3::implies(!zb_[v], z3_bound(m.when_false)));
      } else if (m.kind == VarMeaning::Kind::Selector) {
        if (m.has1) z3s_->add(z3::implies(zb_[v], z3_bound(m.when_true)));
        if (m.has2) z3s_->add(z3::implies(zb_[v], z3_bound(m.when_true2)));
      }
    }
    for (const DiffRule& r : diff_rules_) z3s_->add(z3::implies(z3_guard(r.guard), z3_bound(r.b)));
    for (const LinRule& r : lin_rules_) {
      if (!with_linear) break;
      z3::expr sum = (*z3ctx_).real_val(r.k.str().c_str());
      for (auto [q, c] : r.terms)
        sum = sum + (*z3ctx_).real_val(std::to_string(c).c_str()) * (zt_[r.r] + (*z3ctx_).real_val(r.delta) - zt_[q]);
      z3s_->add(z3::implies(z3_guard(r.guard), sum <= 0));
    }
  }

  // Z3 on the model's conjunction (every SAT variable assumed at its value).
  bool check_with_z3(std::vector<Rational>& t) {
    if (!z3s_) build_z3();
    ++stats_.memo_hits;
    z3::expr_vector assume((*z3ctx_));
    std::unordered_map<unsigned, int> lit_of_id;
    for (size_t v = 1; v <= meaning_.size(); ++v) {
      const int l = lit_of(sat_.value(static_cast<int>(v)), static_cast<int>(v));
      z3::expr e = z3_lit(l);
      lit_of_id.emplace(e.id(), l);
      assume.push_back(e);
    }
    if (budget_.deadline().limit() > 0) {
      const double left = budget_.deadline().limit() - budget_.elapsed();
      if (left <= 0) throw LimitReached{};
      z3s_->set("timeout", static_cast<unsigned>(std::max(1.0, left * 1000)));
    }
    const z3::check_result cr = z3s_->check(assume);
    if (cr == z3::unknown) throw LimitReached{};
    if (cr == z3::unsat) {
      std::vector<int> clause;
      for (const z3::expr& e : z3s_->unsat_core()) clause.push_back(-lit_of_id.at(e.id()));
      add_clause(clause);
      ++stats_.propagations;
      return false;
    }
    t = z3_times(z3s_->get_model());
    return true;
  }

  const ConstraintSystem& sys_;
  const std::vector<CouplingId>& couplings_;
  const std::vector<uint32_t>& pairs_;
  const ComponentFaces& faces_;
  FreeOffsetsCache& cache_;
  SearchBudget& budget_;
  SolveStats& stats_;
  std::unordered_map<CouplingId, uint32_t> local_;
  IncrementalSat sat_;
  std::unordered_map<uint64_t, int> atom_base_;
  std::vector<VarMeaning> meaning_;  // meaning_[v - 1] for SAT variable v
  std::vector<Bound> static_;
  std::vector<DiffRule> diff_rules_;
  std::vector<LinRule> lin_rules_;
  std::vector<uint32_t> lazy_faces_;  // faces of more than kEagerFaceCouplings couplings
  bool with_linear_next_ = false;     // see decide_once
  int64_t scale_ = 1;
  std::vector<uint64_t> seen_;
  std::vector<std::vector<uint32_t>> rev_;
  std::vector<std::vector<int>> clauses_;  // every clause given to sat_
  // Proof mode (proof_ set):
  std::vector<ClauseReason> reasons_;  // per clause of clauses_
  ClauseReason reason_;                // of the clauses being added
  uint32_t failed_ = 0;                // the pair being encoded (encode() false: the one that is never free)
  std::map<int, std::pair<uint32_t, uint32_t>> guards_;  // guard variable: (pair constraint, form)
  std::map<int, SelectorInfo> selectors_;
  std::vector<SelectorInfo> static_selectors_;
  std::map<std::tuple<uint32_t, uint32_t, int64_t, int64_t, bool>, int> bound_var_;
  uint64_t stamp_ = 0;
  // Created on first use: most components never need Z3.
  std::unique_ptr<z3::context> z3ctx_;
  std::unique_ptr<z3::solver> z3s_;
  std::vector<z3::expr> zt_, zb_;
};

}  // namespace

std::optional<std::string> continuous_sat_unsupported(const ConstraintSystem& sys, const std::vector<uint32_t>& pairs,
                                                      bool relax_covers) {
  for (uint32_t ci : pairs) {
    const CollisionConstraint& c = sys.constraints[ci];
    if (c.rel.size() <= 2) continue;
    if (c.rel.size() > kMaxGapCouplings)
      return "a pair of more than " + std::to_string(kMaxGapCouplings) + " couplings";
    if (c.num_forms > 1 && !relax_covers && !forms_never_both_nonpositive(c))
      return "a pair of three or more couplings with several forms";
  }
  return std::nullopt;
}

ContinuousSatOutcome solve_component_sat(const ConstraintSystem& sys, const std::vector<CouplingId>& couplings,
                                         const std::vector<uint32_t>& pairs, const ComponentFaces& faces,
                                         FreeOffsetsCache& cache, SearchBudget& budget, SolveStats& stats,
                                         ContinuousSatOptions options) {
  Engine engine(sys, couplings, pairs, faces, cache, budget, stats);
  engine.z3_for_linear = options.z3_for_linear;
  engine.relax_covers = options.relax_covers;
  engine.difference_logic = options.difference_logic || options.proof != nullptr;
  engine.proof_ = options.proof;
  return engine.run();
}

}  // namespace gridlock
