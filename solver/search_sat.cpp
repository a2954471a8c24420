// SAT back end for gap systems. Why the encoding is exact: docs/solver.md,
// "Engine sat".
//
// A gap system (every constraint one form) holds along an order iff every
// prefix state keeps every form <= 0, and a form only grows when a narrower
// (positive coefficient) runs, so it suffices to look right after each
// narrower t of each gap c:
//   base_c + coef_t + sum over u in c, u != t, u before t of coef_u <= 0.
// With literals B(a, b) = "a before b" this is a pseudo-Boolean constraint;
// writing wideners w (coef_w < 0) through B(t, w) = not B(w, t) makes every
// weight positive:
//   sum_{narrowers u} coef_u B(u, t) + sum_{wideners w} |coef_w| B(t, w)
//     <= -base_c - coef_t + sum_w |coef_w|  =: K,
// encoded by a weighted sequential counter. Only the relative order of
// couplings that share a gap matters, so any topological order of an acyclic
// orientation of those pairs satisfies the system; cyclic orientations are
// excluded lazily by the order layer (solver/internal/order_sat.hpp).
#include <stdexcept>

#include "common/assert.hpp"
#include "solver/internal/gap_inequalities.hpp"
#include "solver/internal/order_sat.hpp"
#include "solver/internal/search.hpp"

namespace gridlock {

SearchOutcome search_sat(const ConstraintSystem& sys, SearchBudget& budget, SolveStats& st) {
  SearchOutcome out;
  for (const CollisionConstraint& c : sys.constraints) {
    GRIDLOCK_REQUIRE(c.num_forms == 1, "the SAT engine needs one form per constraint");
    if (c.base[0] > 0) {  // overlapping from the start: the first step of c collides
      out.status = Verdict::No;
      ++st.refuted;
      return out;
    }
  }
  OrderSat os(sys.num_couplings, budget, st);
  // CaDiCaL's "lucky" phases try a few fixed assignments (all false, all
  // true, forward, backward) by full propagation before the search. On
  // compiled formulas they cost about half of CaDiCaL's solve instructions
  // (2.4 % of the 3..6-variable fuzz campaign's total) and the search
  // without them is no dearer (on 16-variable formulas too). Another
  // model may be found; the verdict is the same.
  os.set_solver_option("lucky", 0);
  std::vector<std::pair<CouplingId, CouplingId>> forced;
  for (size_t ci = 0; ci < sys.constraints.size(); ++ci) {
    if ((ci & 255) == 0) budget.check(st);
    if (!encode_gap_constraint(sys.constraints[ci], os)) {
      out.status = Verdict::No;
      return out;
    }
    gap_forced_relations(sys.constraints[ci], forced);
  }
  if (!os.add_order_clauses(forced)) {
    out.status = Verdict::No;
    return out;
  }
  return os.solve([&](const std::vector<CouplingId>& order) {
    if (replay_order(sys, order).failed_step != order.size())
      throw std::logic_error("SAT engine: an acyclic model whose order the constraints reject");
    return true;
  });
}

}  // namespace gridlock
