// The gap system as inequalities over precedence literals, shared by the two
// engines that reason on them (solver/search_sat.cpp encodes them as
// clauses, solver/search_precedence.cpp propagates them as weighted sums).
//
// A gap system holds along an order iff every form stays <= 0 right after
// each narrower t (positive coefficient) of each gap c:
//   base_c + coef_t + sum over u in c, u before t, of coef_u <= 0.
// Writing a widener w (coef_w < 0) through "t before w" = not "w before t"
// makes every weight positive:
//   sum_{narrowers u != t} coef_u [u before t] + sum_{wideners w} |coef_w| [t before w]
//     <= -base_c - coef_t + sum_w |coef_w|  =: bound.
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "common/assert.hpp"
#include "solver/internal/constraints.hpp"

namespace gridlock {

struct PrecedenceTerm {
  CouplingId first, second;  // the literal "first before second"
  int64_t weight;            // > 0
};

// Calls f(terms, bound) once per narrower of c, unless c can never go
// negative (base + all narrowers <= 0: no inequality). Returns false as soon
// as f does. Requires c.num_forms == 1. O(|c.rel|^2).
template <class F>
bool for_each_gap_inequality(const CollisionConstraint& c, std::vector<PrecedenceTerm>& terms, F&& f) {
  GRIDLOCK_ASSERT(c.num_forms == 1, "for_each_gap_inequality needs a gap constraint (one form)");
  int64_t narrow = 0, widen = 0;
  for (size_t j = 0; j < c.rel.size(); ++j) {
    const int64_t a = c.coef_of(j)[0];
    (a > 0 ? narrow : widen) += a > 0 ? a : -a;
  }
  if (c.base[0] + narrow <= 0) return true;  // never negative
  for (size_t jt = 0; jt < c.rel.size(); ++jt) {
    const int64_t at = c.coef_of(jt)[0];
    if (at <= 0) continue;
    const CouplingId t = c.rel[jt];
    terms.clear();
    for (size_t j = 0; j < c.rel.size(); ++j) {
      if (j == jt) continue;
      const int64_t a = c.coef_of(j)[0];
      if (a > 0) terms.push_back({c.rel[j], t, a});
      else terms.push_back({t, c.rel[j], -a});
    }
    if (!f(terms, -c.base[0] - at + widen)) return false;
  }
  return true;
}

// Relations every solution has, from one gap alone: for a narrower t of c
// with need = base + coef_t > 0 (a lower bound: other narrowers before t only
// add), a widener w without which the other wideners cannot supply need must
// come before t. Appends (w, t) to out. Requires c.num_forms == 1. O(|c.rel|^2).
inline void gap_forced_relations(const CollisionConstraint& c, std::vector<std::pair<CouplingId, CouplingId>>& out) {
  GRIDLOCK_ASSERT(c.num_forms == 1, "gap_forced_relations needs a gap constraint (one form)");
  int64_t widen = 0;
  for (size_t j = 0; j < c.rel.size(); ++j) widen += std::max<int64_t>(-c.coef_of(j)[0], 0);
  for (size_t jt = 0; jt < c.rel.size(); ++jt) {
    const int64_t need = c.base[0] + c.coef_of(jt)[0];
    if (c.coef_of(jt)[0] <= 0 || need <= 0) continue;
    for (size_t j = 0; j < c.rel.size(); ++j) {
      const int64_t a = c.coef_of(j)[0];
      if (a < 0 && widen + a < need) out.push_back({c.rel[j], c.rel[jt]});
    }
  }
}

}  // namespace gridlock
