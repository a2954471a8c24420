// A forward RUP check of a clausal proof over numbered variables (DIMACS
// literals), the propositional half of a continuous NO certificate (kind
// bounds). Clauses are added as axioms (each justified elsewhere) or as
// lemmas that must be RUP: making every literal of the lemma false and
// unit-propagating over the clauses so far ends in a conflict. Deletions
// are never needed (a forward check only gets stricter without them).
// Two watched literals per clause, as in MiniSat; the root assignment is
// kept between checks.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace gridlock {

class ClauseProof {
 public:
  // Variables 1..num_vars.
  explicit ClauseProof(uint32_t num_vars);

  // Adds a clause without checking it. Literals must be within
  // +-[1, num_vars]. O(size) plus root propagation.
  void add_axiom(const std::vector<int>& clause);

  // True iff clause is RUP with respect to the clauses so far (then it is
  // added). O(total size of the clauses) per check in the worst case.
  bool add_lemma(const std::vector<int>& clause);

  // True once the clauses are refuted by unit propagation at the root (the
  // empty clause is RUP).
  bool refuted() const { return refuted_; }

 private:
  size_t index(int lit) const { return 2 * static_cast<size_t>(lit > 0 ? lit : -lit) + (lit < 0 ? 1 : 0); }
  int8_t value(int lit) const;  // 1 true, -1 false, 0 unset
  void assign(int lit);
  // Propagates from trail position head_; false on a conflict.
  bool propagate();
  void attach(uint32_t c);
  void undo(size_t to);

  std::vector<std::vector<int>> clauses_;
  std::vector<std::vector<uint32_t>> watches_;  // per literal index: clauses watching it
  std::vector<int8_t> values_;                  // per variable
  std::vector<int> trail_;
  size_t head_ = 0;
  bool refuted_ = false;
};

}  // namespace gridlock
