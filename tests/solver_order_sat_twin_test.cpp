// Twin of the order layer's shortcuts (solver/internal/order_sat.hpp):
// a unit not sent again when it repeats, and the forced closure skipping
// partners without forced successors, against reference mode (every unit
// sent, every pair of partners tried). CaDiCaL must end in the same state,
// so the engine's whole run must be the same: verdict, order, solve calls,
// conflicts and cycle clauses, on thousands of random gap systems and on
// compiled random 3-SAT formulas (the fuzz campaign's systems).
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

#include "cnf/generate.hpp"
#include "reductions/compile.hpp"
#include "reductions/to_lsat.hpp"
#include "solver/internal/constraints.hpp"
#include "solver/internal/gap_inequalities.hpp"
#include "solver/internal/order_sat.hpp"
#include "solver/internal/search.hpp"
#include "support/random_gap_system.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

struct Run {
  SearchOutcome out;
  SolveStats st;
  size_t skipped = 0;
};

// search_sat's steps (solver/search_sat.cpp), in reference mode or not.
Run run(const ConstraintSystem& sys, bool reference) {
  Run r;
  SolveOptions o;
  SearchBudget budget(o);
  OrderSat os(sys.num_couplings, budget, r.st);
  os.set_reference(reference);
  os.set_solver_option("lucky", 0);
  std::vector<std::pair<CouplingId, CouplingId>> forced;
  for (const CollisionConstraint& c : sys.constraints) {
    if (c.base[0] > 0 || !encode_gap_constraint(c, os)) return r;  // No before any solve
    gap_forced_relations(c, forced);
  }
  if (!os.add_order_clauses(forced)) return r;
  r.out = os.solve([&](const std::vector<CouplingId>& order) {
    if (replay_order(sys, order).failed_step != order.size())
      throw std::logic_error("an acyclic model whose order the constraints reject");
    return true;
  });
  r.skipped = os.skipped_units();
  return r;
}

// Returns the number of units the shortcut skipped.
size_t expect_twins(const ConstraintSystem& sys, const std::string& what) {
  const Run a = run(sys, false), b = run(sys, true);
  EXPECT_EQ(a.out.status, b.out.status) << what;
  EXPECT_EQ(a.out.order, b.out.order) << what;
  EXPECT_EQ(a.st.decisions, b.st.decisions) << what;
  EXPECT_EQ(a.st.refuted, b.st.refuted) << what;
  EXPECT_EQ(a.st.propagations, b.st.propagations) << what;
  EXPECT_EQ(b.skipped, 0U) << what;
  return a.skipped;
}

TEST(OrderSatTwin, ShortcutsAgreeWithReferenceOnRandomGapSystems) {
  const uint64_t seed = test::base_seed(2480);
  Rng rng(seed);
  const int count = test::scaled(3000);
  size_t with_skips = 0;
  for (int i = 0; i < count; ++i) {
    const auto k = static_cast<size_t>(rng.between(2, 24));
    // Gaps over 2..6 couplings, up to 2k of them: many forced relations and
    // repeated units.
    const auto gaps = static_cast<int64_t>(2 * k);
    const ConstraintSystem s = test::random_gap_system(rng, k, {.max_gaps = gaps, .max_size = 6});
    if (expect_twins(s, "seed " + std::to_string(seed) + " case " + std::to_string(i)) > 0) ++with_skips;
    if (HasFailure()) return;
  }
  EXPECT_GT(with_skips, static_cast<size_t>(count / 10));  // the shortcut must be exercised
}

TEST(OrderSatTwin, ShortcutsAgreeWithReferenceOnCompiledFormulas) {
  const uint64_t seed = test::base_seed(2481);
  const int count = test::scaled(300);
  size_t with_skips = 0;
  for (int i = 0; i < count; ++i) {
    const uint64_t s = derive_seed(seed, static_cast<uint64_t>(i));
    Rng rng(s);
    const int n = static_cast<int>(rng.between(3, 6));
    const Formula f = random_ksat({n, static_cast<int>(rng.between(1, int64_t{5} * n)), 3, s});
    const Instance inst = compile_formula(reduce_to_lsat(f).output()).instance;
    const PreparedInstance prep(inst);
    if (expect_twins(build_gap_constraints(prep), "seed " + std::to_string(seed) + " formula " + std::to_string(i)) > 0)
      ++with_skips;
    if (HasFailure()) return;
  }
  EXPECT_GT(with_skips, static_cast<size_t>(count / 2));
}

}  // namespace
}  // namespace gridlock
