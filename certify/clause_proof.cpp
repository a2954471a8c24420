#include "certify/internal/clause_proof.hpp"

#include <algorithm>

namespace gridlock {

ClauseProof::ClauseProof(uint32_t num_vars)
    : watches_(2 * (static_cast<size_t>(num_vars) + 1)), values_(num_vars + 1, 0) {}

int8_t ClauseProof::value(int lit) const {
  const int8_t v = values_[static_cast<size_t>(lit > 0 ? lit : -lit)];
  return lit > 0 ? v : static_cast<int8_t>(-v);
}

void ClauseProof::assign(int lit) {
  values_[static_cast<size_t>(lit > 0 ? lit : -lit)] = lit > 0 ? 1 : -1;
  trail_.push_back(lit);
}

void ClauseProof::undo(size_t to) {
  while (trail_.size() > to) {
    const int lit = trail_.back();
    trail_.pop_back();
    values_[static_cast<size_t>(lit > 0 ? lit : -lit)] = 0;
  }
  head_ = std::min(head_, to);
}

// Watches the first two literals; they are the ones not false, if any.
void ClauseProof::attach(uint32_t c) {
  std::vector<int>& cl = clauses_[c];
  for (size_t w = 0; w < 2 && w < cl.size(); ++w) {
    for (size_t i = w; i < cl.size(); ++i)
      if (value(cl[i]) >= 0) {
        std::swap(cl[w], cl[i]);
        break;
      }
    watches_[index(cl[w])].push_back(c);
  }
}

bool ClauseProof::propagate() {
  while (head_ < trail_.size()) {
    const int falsified = -trail_[head_++];
    std::vector<uint32_t>& ws = watches_[index(falsified)];
    size_t keep = 0;
    bool conflict = false;
    for (size_t k = 0; k < ws.size(); ++k) {
      const uint32_t c = ws[k];
      std::vector<int>& cl = clauses_[c];
      if (conflict) {
        ws[keep++] = c;
        continue;
      }
      if (cl[0] == falsified) std::swap(cl[0], cl[1]);  // the false watch in position 1
      if (value(cl[0]) > 0) {
        ws[keep++] = c;
        continue;
      }
      size_t i = 2;
      for (; i < cl.size() && value(cl[i]) < 0; ++i) {
      }
      if (i < cl.size()) {  // a new watch
        std::swap(cl[1], cl[i]);
        watches_[index(cl[1])].push_back(c);
        continue;
      }
      ws[keep++] = c;
      if (value(cl[0]) < 0) conflict = true;
      else assign(cl[0]);
    }
    ws.resize(keep);
    if (conflict) return false;
  }
  return true;
}

void ClauseProof::add_axiom(const std::vector<int>& clause) {
  if (refuted_) return;
  std::vector<int> cl = clause;
  std::sort(cl.begin(), cl.end());
  cl.erase(std::unique(cl.begin(), cl.end()), cl.end());
  for (size_t i = 0; i + 1 < cl.size(); ++i)
    if (std::binary_search(cl.begin(), cl.end(), -cl[i])) return;  // a tautology adds nothing
  // Literals false at the root are dropped; a clause true at the root adds nothing.
  std::vector<int> open;
  for (int l : cl) {
    if (value(l) > 0) return;
    if (value(l) == 0) open.push_back(l);
  }
  if (open.empty()) return void(refuted_ = true);
  if (open.size() == 1) {
    assign(open[0]);
    if (!propagate()) refuted_ = true;
    return;
  }
  clauses_.push_back(std::move(open));
  attach(static_cast<uint32_t>(clauses_.size() - 1));
}

bool ClauseProof::add_lemma(const std::vector<int>& clause) {
  if (refuted_) return true;
  const size_t root = trail_.size();
  bool conflict = false;
  for (int l : clause) {
    if (value(l) > 0) {  // true at the root: implied
      conflict = true;
      break;
    }
    if (value(l) == 0) assign(-l);
  }
  if (!conflict) conflict = !propagate();
  undo(root);
  if (!conflict) return false;
  add_axiom(clause);
  return true;
}

}  // namespace gridlock
