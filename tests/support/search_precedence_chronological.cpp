// Chronological precedence search for gap systems (the twin of the learning
// engine in solver/search_precedence.cpp; used by tests and bench only, so it
// lives here, not in the library). Why each rule keeps the answer exact:
// docs/solver.md, "Chronological precedence search".
//
// In a gap system a state S is valid iff every form v_c(S) <= 0 (no gap is
// negative), and a step from a valid state collides iff the state after it
// is invalid. A coupling with a positive coefficient in c narrows that gap
// (a "narrower" of c), one with a negative coefficient widens it.
//
// The search keeps, besides the state, a strict partial order "a before b"
// on the couplings not yet done, transitively closed (bit matrices). Every
// relation in it holds in every solution that extends the current state and
// respects the decisions taken on the way. Propagation derives new
// relations from the constraints:
//   for a narrower t of c, need(t) = v_c(S) + coef_t + the coefficients of
//   the narrowers known to come before t. If need(t) > 0, the wideners done
//   before t must supply at least need(t). Wideners known to come after t
//   cannot help; if the others cannot supply need(t), the state is dead; a
//   widener without which they cannot supply it must come before t.
// A coupling q is performed ("safe") when it can run now, no coupling not
// done must come before it, and for every live gap it narrows every widener
// not done must come after it anyway: then moving q to the front of any
// solution gives a solution. Otherwise the search branches on a requirement
// (one of the wideners of a gap must come before t: one branch per widener)
// or, when every requirement is met by known relations, on the order of a
// runnable coupling and one widener of a gap it narrows.
#include <algorithm>
#include <stdexcept>

#include "common/assert.hpp"
#include "support/search_precedence_chronological.hpp"

namespace gridlock {
namespace {

class PrecedenceSearch {
 public:
  PrecedenceSearch(const ConstraintSystem& sys, SearchBudget& budget, SolveStats& st)
      : sys_(sys), budget_(budget), st_(st), k_(sys.num_couplings), words_((k_ + 63) / 64) {
    const size_t nc = sys.constraints.size();
    val_.resize(nc);
    terms_.resize(nc);
    for (size_t c = 0; c < nc; ++c) {
      const CollisionConstraint& cc = sys.constraints[c];
      GRIDLOCK_REQUIRE(cc.num_forms == 1, "precedence search needs one form per constraint");
      val_[c] = cc.base[0];
      for (size_t j = 0; j < cc.rel.size(); ++j) terms_[c].push_back({cc.rel[j], cc.coef_of(j)[0]});
    }
    undone_.assign(words_, 0);
    for (CouplingId q = 0; q < k_; ++q) undone_[q >> 6] |= uint64_t{1} << (q & 63);
    succ_.assign(k_ * words_, 0);
    pred_.assign(k_ * words_, 0);
    pos_rem_.assign(nc, 0);
    dirty_.assign(nc, 1);
    for (size_t c = 0; c < nc; ++c) dirty_list_.push_back(static_cast<uint32_t>(nc - 1 - c));
    for (size_t c = 0; c < nc; ++c)
      for (auto& t : terms_[c]) pos_rem_[c] += std::max<int64_t>(t.coef, 0);
  }

  SearchOutcome run() {
    SearchOutcome out;
    for (size_t c = 0; c < val_.size(); ++c)
      if (val_[c] > 0) {  // overlapping from the start: the first coupling of c collides
        out.status = Verdict::No;
        ++st_.refuted;
        return out;
      }
    out.status = node() ? Verdict::Yes : Verdict::No;
    if (out.status == Verdict::Yes) out.order = path_;
    return out;
  }

 private:
  struct Term {
    CouplingId q;
    int64_t coef;
  };

  bool undone(CouplingId q) const { return (undone_[q >> 6] >> (q & 63)) & 1; }
  uint64_t* succ(CouplingId q) { return succ_.data() + q * words_; }
  uint64_t* pred(CouplingId q) { return pred_.data() + q * words_; }
  bool before(CouplingId a, CouplingId b) const {  // a must come before b
    return (succ_[a * words_ + (b >> 6)] >> (b & 63)) & 1;
  }
  bool live(size_t c) const { return val_[c] + pos_rem_[c] > 0; }

  // Posts a before b and closes transitively. False if b before a is known.
  bool add_before(CouplingId a, CouplingId b) {
    if (before(b, a) || a == b) return false;
    if (before(a, b)) return true;
    ++st_.propagations;
    // Everything up to a (and a) comes before everything from b (and b).
    std::vector<uint64_t>& up = scratch_up_;
    std::vector<uint64_t>& down = scratch_down_;
    up.assign(pred(a), pred(a) + words_);
    down.assign(succ(b), succ(b) + words_);
    up[a >> 6] |= uint64_t{1} << (a & 63);
    down[b >> 6] |= uint64_t{1} << (b & 63);
    nz_up_.clear();
    nz_down_.clear();
    for (size_t w = 0; w < words_; ++w) {
      up[w] &= undone_[w];
      down[w] &= undone_[w];
      if (up[w]) nz_up_.push_back(static_cast<uint32_t>(w));
      if (down[w]) nz_down_.push_back(static_cast<uint32_t>(w));
    }
    // A row that already holds b (resp. a) already holds all of down (up),
    // by transitivity: skip it.
    for (uint32_t w : nz_up_)
      for (uint64_t bits = up[w]; bits; bits &= bits - 1) {
        auto x = static_cast<CouplingId>(w * 64 + __builtin_ctzll(bits));
        budget_.poll();
        if (!before(x, b)) or_row(succ_, x, down, nz_down_);
      }
    for (uint32_t w : nz_down_)
      for (uint64_t bits = down[w]; bits; bits &= bits - 1) {
        auto y = static_cast<CouplingId>(w * 64 + __builtin_ctzll(bits));
        budget_.poll();
        if (!((pred_[y * words_ + (a >> 6)] >> (a & 63)) & 1)) or_row(pred_, y, up, nz_up_);
      }
    return true;
  }

  // row q of matrix m |= bits (only the words listed in nz are non-zero),
  // remembering every changed word on the trail.
  void or_row(std::vector<uint64_t>& m, CouplingId q, const std::vector<uint64_t>& bits,
              const std::vector<uint32_t>& nz) {
    uint64_t* row = m.data() + q * words_;
    const uint64_t tag = &m == &succ_ ? 0 : uint64_t{1} << 63;
    bool changed = false;
    for (uint32_t x : nz) {
      uint64_t nv = row[x] | bits[x];
      if (nv == row[x]) continue;
      if (open_decisions_ > 0) trail_.push_back({tag | (q * words_ + x), row[x]});
      row[x] = nv;
      changed = true;
    }
    // Propagation reads only "before" (succ rows), done flags and values.
    if (changed && tag == 0) mark(q);
  }

  // The gaps of q must be looked at again by propagate().
  void mark(CouplingId q) {
    for (auto [c, j] : sys_.of_coupling[q]) {
      if (!dirty_[c]) dirty_[c] = 1, dirty_list_.push_back(static_cast<uint32_t>(c));
    }
  }

  void perform(CouplingId q) {
    for (auto [c, j] : sys_.of_coupling[q]) {
      int64_t coef = sys_.constraints[c].coef_of(j)[0];
      val_[c] += coef;
      pos_rem_[c] -= std::max<int64_t>(coef, 0);
    }
    undone_[q >> 6] &= ~(uint64_t{1} << (q & 63));
    path_.push_back(q);
    mark(q);
  }
  void unperform() {
    CouplingId q = path_.back();
    path_.pop_back();
    for (auto [c, j] : sys_.of_coupling[q]) {
      int64_t coef = sys_.constraints[c].coef_of(j)[0];
      val_[c] -= coef;
      pos_rem_[c] += std::max<int64_t>(coef, 0);
    }
    undone_[q >> 6] |= uint64_t{1} << (q & 63);
  }

  // need(t) in c (see the file comment).
  int64_t need(size_t c, CouplingId t, int64_t coef_t) const {
    int64_t n = val_[c] + coef_t;
    for (const Term& u : terms_[c])
      if (u.q != t && u.coef > 0 && undone(u.q) && before(u.q, t)) n += u.coef;
    return n;
  }

  // Derives relations to a fixpoint. False on a dead end. Only the gaps
  // marked since the last fixpoint are looked at (a gap's conclusions change
  // only when its value, its couplings' done flags or their relations do);
  // a dead end may leave marks behind, which only costs a second look.
  bool propagate() {
    while (!dirty_list_.empty()) {
      budget_.poll();
      const uint32_t c = dirty_list_.back();
      dirty_list_.pop_back();
      dirty_[c] = 0;
      if (!live(c)) continue;
      for (const Term& t : terms_[c]) {
        if (t.coef <= 0 || !undone(t.q)) continue;
        int64_t n = need(c, t.q, t.coef);
        if (n <= 0) continue;
        int64_t avail = 0;
        for (const Term& w : terms_[c])
          if (w.coef < 0 && undone(w.q) && !before(t.q, w.q)) avail -= w.coef;
        if (avail < n) return false;
        for (const Term& w : terms_[c])
          if (w.coef < 0 && undone(w.q) && !before(t.q, w.q) && avail + w.coef < n && !before(w.q, t.q))
            if (!add_before(w.q, t.q)) return false;
      }
    }
    return true;
  }

  bool has_undone_pred(CouplingId q) {
    const uint64_t* p = pred(q);
    for (size_t w = 0; w < words_; ++w)
      if (p[w] & undone_[w]) return true;
    return false;
  }
  bool runnable(CouplingId q) const {
    for (auto [c, j] : sys_.of_coupling[q])
      if (val_[c] + sys_.constraints[c].coef_of(j)[0] > 0) return false;
    return true;
  }
  // For a runnable q with no pending predecessor: a widener that blocks the
  // exchange argument (kNone if q is safe).
  CouplingId unsafe_widener(CouplingId q) const {
    for (auto [c, j] : sys_.of_coupling[q]) {
      if (sys_.constraints[c].coef_of(j)[0] <= 0 || !live(c)) continue;
      for (const Term& w : terms_[c])
        if (w.coef < 0 && undone(w.q) && !before(q, w.q)) return w.q;
    }
    return kNone;
  }

  struct Snapshot {
    size_t trail, path;
  };
  void save(Snapshot& s) const {
    s.trail = trail_.size();
    s.path = path_.size();
  }
  void restore(const Snapshot& s) {
    while (path_.size() > s.path) unperform();
    while (trail_.size() > s.trail) {
      auto [key, old] = trail_.back();
      trail_.pop_back();
      ((key >> 63) ? pred_ : succ_)[key & ~(uint64_t{1} << 63)] = old;
    }
  }

  // A branching: the orderings to try, one per branch.
  struct Branch {
    std::vector<std::pair<CouplingId, CouplingId>> edges;  // each: first before second
  };

  // How much performing w now would tighten the live gaps it narrows:
  // a gap left with no slack weighs most (like a clause left with one
  // literal). Guides the choice of branch only, never its outcome.
  uint64_t harm(CouplingId w) const {
    uint64_t h = 0;
    for (auto [c, j] : sys_.of_coupling[w]) {
      int64_t coef = sys_.constraints[c].coef_of(j)[0];
      if (coef <= 0 || !live(c)) continue;
      int64_t slack = -(val_[c] + coef);
      h += slack <= 0 ? 16 : slack == 1 ? 4 : 1;
    }
    return h;
  }

  bool choose_branch(Branch& br) {
    // Requirements: a narrower t of a live gap that needs more widening
    // than the wideners known to precede it give. Fewest options first,
    // then the most tightly constrained options; the least harmful first.
    size_t best = SIZE_MAX;
    uint64_t best_score = 0;
    std::vector<CouplingId> opts;
    std::vector<std::pair<uint64_t, CouplingId>> scored;
    for (size_t c = 0; c < terms_.size(); ++c) {
      budget_.poll();
      if (!live(c)) continue;
      for (const Term& t : terms_[c]) {
        if (t.coef <= 0 || !undone(t.q)) continue;
        int64_t n = need(c, t.q, t.coef);
        if (n <= 0) continue;
        int64_t have = 0;
        opts.clear();
        for (const Term& w : terms_[c]) {
          if (w.coef >= 0 || !undone(w.q) || before(t.q, w.q)) continue;
          if (before(w.q, t.q)) have -= w.coef;
          else opts.push_back(w.q);
        }
        if (have >= n || opts.size() > best) continue;
        uint64_t prod = 1, sum = 0;
        scored.clear();
        for (CouplingId w : opts) {
          uint64_t h = harm(w);
          scored.push_back({h, w});
          prod *= h + 1;
          sum += h;
        }
        uint64_t score = prod * 64 + sum;
        if (opts.size() == best && score <= best_score) continue;
        best = opts.size();
        best_score = score;
        std::stable_sort(scored.begin(), scored.end());
        br.edges.clear();
        for (auto [h, w] : scored) br.edges.push_back({w, t.q});
      }
    }
    if (!br.edges.empty()) return true;
    // Every requirement is met: order a runnable source and a widener.
    for (CouplingId q = 0; q < k_; ++q) {
      budget_.poll();
      if (!undone(q) || has_undone_pred(q) || !runnable(q)) continue;
      CouplingId w = unsafe_widener(q);
      if (w == kNone) continue;
      br.edges = {{q, w}, {w, q}};
      return true;
    }
    return false;
  }

  bool node() {
    for (;;) {
      budget_.tick(st_);
      if (!propagate()) {
        ++st_.refuted;
        return false;
      }
      if (path_.size() == k_) return true;
      // Every safe coupling, in one sweep (each is re-checked at the state
      // the previous ones left).
      bool moved = false;
      for (CouplingId q = 0; q < k_; ++q) {
        budget_.poll();
        if (undone(q) && runnable(q) && unsafe_widener(q) == kNone && !has_undone_pred(q)) {
          ++st_.safe_moves;
          perform(q);
          moved = true;
        }
      }
      if (!moved) break;
    }
    Branch br;
    if (!choose_branch(br)) {
      // No requirement open and no runnable source: impossible in a
      // consistent state (docs/solver.md). Never answer NO on a bug.
      throw std::logic_error("precedence search: no branching in an open state");
    }
    ++st_.decisions;
    Snapshot snap;
    save(snap);
    ++open_decisions_;
    for (auto [a, b] : br.edges) {
      if (add_before(a, b) && node()) return true;
      restore(snap);
    }
    --open_decisions_;
    ++st_.refuted;
    return false;
  }

  const ConstraintSystem& sys_;
  SearchBudget& budget_;
  SolveStats& st_;
  size_t k_, words_;
  std::vector<int64_t> val_, pos_rem_;
  std::vector<std::vector<Term>> terms_;
  std::vector<uint64_t> undone_, succ_, pred_;
  std::vector<CouplingId> path_;
  std::vector<std::pair<uint64_t, uint64_t>> trail_;  // (matrix tag | word index, old value)
  std::vector<uint64_t> scratch_up_, scratch_down_;
  std::vector<uint32_t> nz_up_, nz_down_;
  size_t open_decisions_ = 0;  // no trail is needed below the first decision
  std::vector<char> dirty_;    // per gap: in dirty_list_, to be propagated
  std::vector<uint32_t> dirty_list_;
};

}  // namespace

SearchOutcome search_precedence_chronological(const ConstraintSystem& sys, SearchBudget& budget, SolveStats& st) {
  PrecedenceSearch s(sys, budget, st);
  return s.run();
}

}  // namespace gridlock
