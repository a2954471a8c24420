// Precedence search for gap systems (one form per constraint). Why each rule
// keeps the answer exact: docs/solver.md, "Precedence search".
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

#include "solver/search.hpp"

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
      if (cc.num_forms != 1) throw std::invalid_argument("precedence search needs one form per constraint");
      val_[c] = cc.base[0];
      for (size_t j = 0; j < cc.rel.size(); ++j) terms_[c].push_back({cc.rel[j], cc.coef_of(j)[0]});
    }
    undone_.assign(words_, 0);
    for (CouplingId q = 0; q < k_; ++q) undone_[q >> 6] |= uint64_t{1} << (q & 63);
    succ_.assign(k_ * words_, 0);
    pred_.assign(k_ * words_, 0);
    pos_rem_.assign(nc, 0);
    for (size_t c = 0; c < nc; ++c)
      for (auto& t : terms_[c]) pos_rem_[c] += std::max<int64_t>(t.coef, 0);
  }

  SearchOutcome run() {
    SearchOutcome out;
    for (size_t c = 0; c < val_.size(); ++c)
      if (val_[c] > 0) {  // overlapping from the start: the first coupling of c collides
        out.status = SolveResult::Status::No;
        ++st_.refuted;
        return out;
      }
    out.status = node() ? SolveResult::Status::Yes : SolveResult::Status::No;
    if (out.status == SolveResult::Status::Yes) out.order = path_;
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
    std::vector<uint64_t> up(pred(a), pred(a) + words_), down(succ(b), succ(b) + words_);
    up[a >> 6] |= uint64_t{1} << (a & 63);
    down[b >> 6] |= uint64_t{1} << (b & 63);
    for (size_t w = 0; w < words_; ++w) {
      up[w] &= undone_[w];
      down[w] &= undone_[w];
    }
    for (size_t w = 0; w < words_; ++w)
      for (uint64_t bits = up[w]; bits; bits &= bits - 1) {
        uint64_t* s = succ(static_cast<CouplingId>(w * 64 + __builtin_ctzll(bits)));
        for (size_t x = 0; x < words_; ++x) s[x] |= down[x];
      }
    for (size_t w = 0; w < words_; ++w)
      for (uint64_t bits = down[w]; bits; bits &= bits - 1) {
        uint64_t* p = pred(static_cast<CouplingId>(w * 64 + __builtin_ctzll(bits)));
        for (size_t x = 0; x < words_; ++x) p[x] |= up[x];
      }
    return true;
  }

  void perform(CouplingId q) {
    for (auto [c, j] : sys_.of_coupling[q]) {
      int64_t coef = sys_.constraints[c].coef_of(j)[0];
      val_[c] += coef;
      pos_rem_[c] -= std::max<int64_t>(coef, 0);
    }
    undone_[q >> 6] &= ~(uint64_t{1} << (q & 63));
    path_.push_back(q);
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

  // Derives relations to a fixpoint. False on a dead end.
  bool propagate() {
    for (bool changed = true; changed;) {
      changed = false;
      for (size_t c = 0; c < terms_.size(); ++c) {
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
            if (w.coef < 0 && undone(w.q) && !before(t.q, w.q) && avail + w.coef < n && !before(w.q, t.q)) {
              if (!add_before(w.q, t.q)) return false;
              changed = true;
            }
        }
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
    std::vector<uint64_t> succ, pred;
    size_t path;
  };
  void save(Snapshot& s) {
    s.succ = succ_;
    s.pred = pred_;
    s.path = path_.size();
  }
  void restore(const Snapshot& s) {
    while (path_.size() > s.path) unperform();
    succ_ = s.succ;
    pred_ = s.pred;
  }

  // A branching: the orderings to try, one per branch.
  struct Branch {
    std::vector<std::pair<CouplingId, CouplingId>> edges;  // each: first before second
  };

  bool choose_branch(Branch& br) {
    // Requirements: a narrower t of a live gap that needs more widening
    // than the wideners known to precede it give. Fewest options first.
    size_t best = SIZE_MAX;
    for (size_t c = 0; c < terms_.size(); ++c) {
      if (!live(c)) continue;
      for (const Term& t : terms_[c]) {
        if (t.coef <= 0 || !undone(t.q)) continue;
        int64_t n = need(c, t.q, t.coef);
        if (n <= 0) continue;
        int64_t have = 0;
        std::vector<CouplingId> opts;
        for (const Term& w : terms_[c]) {
          if (w.coef >= 0 || !undone(w.q) || before(t.q, w.q)) continue;
          if (before(w.q, t.q)) have -= w.coef;
          else opts.push_back(w.q);
        }
        if (have >= n || opts.size() >= best) continue;
        best = opts.size();
        br.edges.clear();
        for (CouplingId w : opts) br.edges.push_back({w, t.q});
        if (best <= 2) return true;
      }
    }
    if (!br.edges.empty()) return true;
    // Every requirement is met: order a runnable source and a widener.
    for (CouplingId q = 0; q < k_; ++q) {
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
      CouplingId move = kNone;
      for (CouplingId q = 0; q < k_ && move == kNone; ++q)
        if (undone(q) && !has_undone_pred(q) && runnable(q) && unsafe_widener(q) == kNone) move = q;
      if (move == kNone) break;
      ++st_.safe_moves;
      perform(move);
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
    for (auto [a, b] : br.edges) {
      if (add_before(a, b) && node()) return true;
      restore(snap);
    }
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
};

}  // namespace

SearchOutcome search_precedence(const ConstraintSystem& sys, SearchBudget& budget, SolveStats& st) {
  PrecedenceSearch s(sys, budget, st);
  return s.run();
}

}  // namespace gridlock
