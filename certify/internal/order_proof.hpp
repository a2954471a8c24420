// The proof check of a "gaps" certificate: unit propagation over order
// literals ("a before b"), forward, as in a RUP checker for DRAT proofs
// (drat-trim's forward mode, without deletions).
//
// Variables: one per unordered pair {a, b} named anywhere (inequality or
// lemma); its two literals are a<b and b<a, so antisymmetry and totality on
// the pair are built in. What propagation knows, all true in every total
// order that keeps every gap >= 0:
//   - the gap inequalities, sum weight * [lit] <= bound: a literal heavier
//     than the slack left is false; a negative slack is a conflict;
//   - transitivity on triangles of variables: a<b and b<c give a<c;
//   - the order closure: the relations true at the root before any lemma
//     (after propagating the two rules above), transitively closed through
//     any coupling: a cycle is a conflict; a pair it orders is a unit; for a
//     coupling x and two others c1, c2 with c1 before c2 in it, "x<c1 implies
//     x<c2" when both pairs are variables;
//   - the lemmas accepted so far (clauses, watched by two literals).
// A lemma 'o' is accepted if its literals, as edges a -> b, contain a
// directed cycle (no total order has them all). A lemma 'l' is accepted if
// making every literal of it false and propagating gives a conflict. The
// proof holds once the empty clause is accepted.
#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "certify/internal/certificate_text.hpp"
#include "certify/internal/geometry.hpp"

namespace gridlock {

class OrderProof {
 public:
  // k couplings; every pair any inequality or lemma names gets a variable.
  OrderProof(size_t k, const std::vector<GapInequality>& inequalities, const std::vector<CertificateLemma>& lemmas);

  // Propagates at the root, then adds the order closure. False when that
  // already conflicts (the instance is refuted without lemmas).
  bool start();
  // Checks one lemma and, if accepted, adds it. Returns the reason it is
  // not accepted, or an empty string.
  std::string check(const CertificateLemma& lemma);
  // Adds a clause the caller has justified (kind pairs: an x line) without a check.
  void add_axiom(const CertificateLemma& lemma);
  bool refuted() const { return refuted_; }
  uint64_t axioms() const { return axioms_; }

 private:
  using Lit = uint32_t;  // 2v: lo(v) < hi(v); 2v + 1: hi(v) < lo(v)
  static Lit neg(Lit l) { return l ^ 1; }
  uint32_t var_of(CouplingId a, CouplingId b);
  Lit lit(OrderLiteral l) const;
  Lit find_lit(CouplingId a, CouplingId b) const;  // kNoLit if no variable
  CouplingId from(Lit l) const { return (l & 1) ? hi_[l >> 1] : lo_[l >> 1]; }
  CouplingId to(Lit l) const { return (l & 1) ? lo_[l >> 1] : hi_[l >> 1]; }
  bool is_true(Lit l) const { return value_[l >> 1] == static_cast<int8_t>(l & 1); }
  bool is_false(Lit l) const { return value_[l >> 1] == static_cast<int8_t>((l & 1) ^ 1); }
  bool is_free(Lit l) const { return value_[l >> 1] < 0; }

  void assign(Lit l);
  bool imply(Lit l);  // false on a conflict
  void undo(size_t trail_size);
  bool propagate();
  bool propagate_triangles(Lit p);
  bool propagate_clauses(Lit p);
  bool propagate_inequalities(Lit p);
  bool add_clause(const std::vector<Lit>& c);  // at the root; false on a conflict
  bool add_closure();

  static constexpr Lit kNoLit = UINT32_MAX;
  size_t k_;
  std::unordered_map<uint64_t, uint32_t> index_;                        // (lo << 32 | hi) -> variable
  std::vector<CouplingId> lo_, hi_;                                     // per variable
  std::vector<std::vector<std::pair<CouplingId, uint32_t>>> partners_;  // per coupling: (other, variable)
  std::vector<int8_t> value_;                                           // per variable: -1 free, 0, 1
  std::vector<Lit> trail_;
  size_t qhead_ = 0;
  // Inequalities: literals by weight, heaviest first; running sums of the true ones.
  struct Ineq {
    int64_t bound;
    std::vector<std::pair<Lit, int64_t>> terms;
  };
  std::vector<Ineq> ineqs_;
  std::vector<int64_t> ineq_sum_;
  std::vector<std::vector<std::pair<uint32_t, int64_t>>> occ_;  // per literal: (inequality, weight)
  std::vector<std::vector<Lit>> clauses_;
  std::vector<std::vector<uint32_t>> watches_;  // per literal: clauses watching it
  bool refuted_ = false;
  uint64_t axioms_ = 0;
};

}  // namespace gridlock
