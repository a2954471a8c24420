// SAT back end for any constraint system (pair constraints of instances
// with vertical operations, growths and contractions in every direction).
// Why the encoding is exact: docs/solver.md, "Engine pairs".
//
// A constraint's forms depend only on S ∩ C, C = its rel (the couplings with
// a non-zero coefficient). So whether coupling c in C collides on it when it
// runs depends only on which T ⊆ C \ {c} ran before c: exactly
// step_collides(base + sum_{q in T} coef_q, coef_c). Each colliding pattern
// (c, T) is excluded by one clause over order literals,
//   OR_{q in T} not B(q, c)  OR  OR_{q in C \ T, q != c} not B(c, q),
// true in every collision-free total order, and an order satisfying every
// such clause has no colliding step (couplings outside C do not move the
// pair). Clauses cover cubes of colliding patterns: a literal is dropped when
// every pattern with either value of it collides too.
//  - one-form constraints: the sat engine's weighted counters (exact for one
//    form with base <= 0, solver/internal/gap_inequalities.hpp);
//  - up to eager_limit (8) couplings: every colliding pattern up front;
//  - larger ones: lazily, for the patterns an acyclic model's order hits.
// Transitivity, forced closure and lazy cycle clauses: solver/internal/order_sat.hpp.
#include <algorithm>
#include <stdexcept>

#include "solver/internal/gap_inequalities.hpp"
#include "solver/internal/order_sat.hpp"
#include "solver/internal/search.hpp"

namespace gridlock {
namespace {

class PairSearch {
 public:
  PairSearch(const ConstraintSystem& sys, SearchBudget& budget, SolveStats& st, size_t eager_limit,
             PairsProof* proof = nullptr)
      : sys_(sys),
        budget_(budget),
        st_(st),
        eager_limit_(eager_limit),
        os_(sys.num_couplings, budget, st),
        proof_(proof) {
    if (proof_) os_.prove_to(proof_->drat, &cycles_);
  }

  // Proof mode: the cycle clauses and the variables' pairs into proof_.
  void finish_proof() {
    for (const std::vector<int>& c : cycles_) {
      PairsProof::Axiom a;
      for (int l : c) a.lits.push_back(order_lit(l));
      proof_->axioms.push_back(std::move(a));
    }
    proof_->var_pair.assign(1, {kNone, kNone});
    for (int v = 1; v <= static_cast<int>(os_.num_pairs()); ++v) proof_->var_pair.push_back(os_.pair_of(v));
    os_.flush_proof();
  }

  SearchOutcome run() {
    SearchOutcome out;
    out.status = Verdict::No;
    for (size_t ci = 0; ci < sys_.constraints.size(); ++ci) {
      if ((ci & 63) == 0) budget_.check(st_);
      if (!encode(static_cast<uint32_t>(ci))) return out;
    }
    if (!os_.add_order_clauses(forced_)) return out;
    return os_.solve([&](const std::vector<CouplingId>& order) { return accept(order); });
  }

 private:
  // Encodes constraint ci (eagerly, or registers it as lazy). False iff it
  // alone proves that no order exists.
  bool encode(uint32_t ci) {
    const CollisionConstraint& c = sys_.constraints[ci];
    current_ = ci;
    if (c.num_forms == 1 && !proof_) {
      if (c.base[0] > 0) return false;  // overlapping from the start: the first step of c collides
      gap_forced_relations(c, forced_);
      return encode_gap_constraint(c, os_);
    }
    if (c.rel.size() > eager_limit_) {
      // Proof mode: a pair gets its variable from the first clause naming
      // it, so that every variable is named in the certificate (the
      // checker's order closure must cover the solver's).
      for (size_t a = 0; a < c.rel.size() && !proof_; ++a)
        for (size_t b = a + 1; b < c.rel.size(); ++b) os_.before(c.rel[a], c.rel[b]);
      lazy_.push_back(ci);
      return true;
    }
    for (uint32_t jc = 0; jc < c.rel.size(); ++jc)
      if (!encode_runner(c, jc)) return false;
    return true;
  }

  // Every colliding pattern of c's coupling rel[jc], covered by cubes.
  bool encode_runner(const CollisionConstraint& c, uint32_t jc) {
    const uint32_t nf = c.num_forms;
    others_.clear();
    for (uint32_t j = 0; j < c.rel.size(); ++j)
      if (j != jc) others_.push_back(j);
    const auto m = static_cast<uint32_t>(others_.size());
    const size_t n = size_t{1} << m;
    values_.assign(n * nf, 0);
    collides_.assign(n, 0);
    for (size_t mask = 0; mask < n; ++mask) {
      int64_t* s = values_.data() + mask * nf;
      if (mask == 0) {
        std::copy(c.base.begin(), c.base.end(), s);
      } else {
        const auto low = static_cast<uint32_t>(__builtin_ctzll(mask));
        const int64_t* from = values_.data() + (mask & (mask - 1)) * nf;
        const int64_t* add = c.coef_of(others_[low]);
        for (uint32_t i = 0; i < nf; ++i) s[i] = from[i] + add[i];
      }
      collides_[mask] = step_collides(s, c.coef_of(jc), nf) ? 1 : 0;
    }
    for (size_t mask = 0; mask < n; ++mask) {
      if (collides_[mask] != 1) continue;  // 2: covered by a clause already
      const size_t fixed = grow_cube(mask, m);
      if (!emit(c, jc, mask, fixed)) return false;
      for_each_in_cube(mask, fixed, m, [&](size_t p) { collides_[p] = 2; });
    }
    return true;
  }

  // Calls f on every pattern agreeing with mask on the bits of fixed.
  template <class F>
  static void for_each_in_cube(size_t mask, size_t fixed, uint32_t m, F&& f) {
    const size_t all = (size_t{1} << m) - 1;
    const size_t free_bits = all & ~fixed;
    const size_t base = mask & fixed;
    for (size_t sub = free_bits;; sub = (sub - 1) & free_bits) {
      f(base | sub);
      if (sub == 0) break;
    }
  }

  // Greedily frees bits of the cube around mask while every pattern in it
  // collides. Returns the fixed bits.
  size_t grow_cube(size_t mask, uint32_t m) {
    size_t fixed = (size_t{1} << m) - 1;
    for (uint32_t b = 0; b < m; ++b) {
      const size_t trial = fixed & ~(size_t{1} << b);
      bool all = true;
      for_each_in_cube(mask, trial, m, [&](size_t p) { all = all && collides_[p] != 0; });
      if (all) fixed = trial;
    }
    return fixed;
  }

  // The clause excluding the cube (mask, fixed) of runner rel[jc]. False iff
  // the clause is empty (the runner collides whatever runs before it).
  bool emit(const CollisionConstraint& c, uint32_t jc, size_t mask, size_t fixed) {
    const CouplingId run = c.rel[jc];
    clause_.clear();
    for (uint32_t b = 0; b < others_.size(); ++b) {
      if (((fixed >> b) & 1) == 0) continue;
      const CouplingId q = c.rel[others_[b]];
      clause_.push_back(((mask >> b) & 1) != 0 ? -os_.before(q, run) : -os_.before(run, q));
    }
    record(run);
    if (clause_.empty()) return false;
    if (clause_.size() == 1) {  // a relation every solution has: feeds the forced closure
      const size_t b = static_cast<size_t>(__builtin_ctzll(fixed));
      const CouplingId q = c.rel[others_[b]];
      forced_.push_back(((mask >> b) & 1) != 0 ? std::make_pair(run, q) : std::make_pair(q, run));
    }
    os_.add_clause(clause_);
    return true;
  }

  // Replays the lazy constraints along order; adds the clause of every
  // colliding pattern met. True iff none collides.
  bool accept(const std::vector<CouplingId>& order) {
    pos_.resize(order.size());
    for (size_t i = 0; i < order.size(); ++i) pos_[order[i]] = static_cast<uint32_t>(i);
    bool clean = true;
    std::vector<uint32_t> idx;
    std::vector<int64_t> cur;
    for (uint32_t ci : lazy_) {
      budget_.poll();
      current_ = ci;
      const CollisionConstraint& c = sys_.constraints[ci];
      idx.resize(c.rel.size());
      for (uint32_t j = 0; j < idx.size(); ++j) idx[j] = j;
      std::sort(idx.begin(), idx.end(), [&](uint32_t a, uint32_t b) { return pos_[c.rel[a]] < pos_[c.rel[b]]; });
      cur.assign(c.base.begin(), c.base.end());
      for (uint32_t h = 0; h < idx.size(); ++h) {
        const uint32_t j = idx[h];
        if (step_collides(cur.data(), c.coef_of(j), c.num_forms)) {
          add_lazy_clause(c, j);
          clean = false;
        }
        for (uint32_t i = 0; i < c.num_forms; ++i) cur[i] += c.coef_of(j)[i];
      }
    }
    if (clean && replay_order(sys_, order).failed_step != order.size())
      throw std::logic_error("pairs engine: an accepted order that the constraints reject");
    return clean;
  }

  // The clause of runner rel[j] after the couplings placed before it in
  // pos_. A literal is dropped when flipping it can only raise every form
  // (monotone: a higher state collides wherever a lower one does), so the
  // clause still excludes only colliding patterns.
  void add_lazy_clause(const CollisionConstraint& c, uint32_t j) {
    const CouplingId run = c.rel[j];
    clause_.clear();
    for (uint32_t o = 0; o < c.rel.size(); ++o) {
      if (o == j) continue;
      const CouplingId q = c.rel[o];
      const bool done = pos_[q] < pos_[run];
      bool raises = true;  // does q's presence raise (or keep) every form?
      bool lowers = true;
      for (uint32_t i = 0; i < c.num_forms; ++i) {
        raises = raises && c.coef_of(o)[i] >= 0;
        lowers = lowers && c.coef_of(o)[i] <= 0;
      }
      if ((done && lowers) || (!done && raises)) continue;
      clause_.push_back(done ? -os_.before(q, run) : -os_.before(run, q));
    }
    record(run);
    os_.add_clause(clause_);
    ++st_.propagations;
  }

  // The order literal of a variable's literal (proof mode: every variable is a pair).
  std::pair<CouplingId, CouplingId> order_lit(int l) const {
    const auto [lo, hi] = os_.pair_of(l > 0 ? l : -l);
    return l > 0 ? std::make_pair(lo, hi) : std::make_pair(hi, lo);
  }

  // Proof mode: clause_ is a pattern clause of constraint current_ with runner run.
  void record(CouplingId run) {
    if (!proof_) return;
    PairsProof::Axiom a;
    a.constraint = current_;
    a.runner = run;
    for (int l : clause_) a.lits.push_back(order_lit(l));
    proof_->axioms.push_back(std::move(a));
  }

  const ConstraintSystem& sys_;
  SearchBudget& budget_;
  SolveStats& st_;
  // Constraints of at most this many couplings get every pattern up front
  // (rel.size() * 2^(rel.size() - 1) step tests).
  size_t eager_limit_;
  OrderSat os_;
  std::vector<std::pair<CouplingId, CouplingId>> forced_;
  std::vector<uint32_t> lazy_;
  std::vector<uint32_t> others_, pos_;
  std::vector<int64_t> values_;
  std::vector<char> collides_;
  std::vector<int> clause_;
  PairsProof* proof_;
  uint32_t current_ = 0;                  // the constraint being encoded or replayed
  std::vector<std::vector<int>> cycles_;  // proof mode: OrderSat's cycle clauses
};

}  // namespace

SearchOutcome search_pairs(const ConstraintSystem& sys, SearchBudget& budget, SolveStats& st, size_t eager_limit) {
  PairSearch s(sys, budget, st, std::min<size_t>(eager_limit, 20));
  return s.run();
}

SearchOutcome search_pairs_proof(const ConstraintSystem& sys, SearchBudget& budget, SolveStats& st, PairsProof& proof) {
  PairSearch s(sys, budget, st, kPairsEagerLimit, &proof);
  SearchOutcome out = s.run();
  s.finish_proof();
  return out;
}

}  // namespace gridlock
