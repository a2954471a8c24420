// What verify runs on a compiled random formula, for the simulator's twin
// tests: CaDiCaL's order when the formula is satisfiable (collision-free),
// a random order, every coupling at once (verify's gap witness), then the
// first schedule again.
#pragma once

#include <vector>

#include "cnf/sat_solver.hpp"
#include "common/random.hpp"
#include "gadgets/mutation.hpp"
#include "lattice/schedule.hpp"
#include "reductions/compile.hpp"
#include "support/cnf_testing.hpp"

namespace gridlock::test {

struct CompiledRuns {
  CompiledFormula compiled;
  std::vector<Schedule> runs;
};

// A formula of 1 to 6 variables and 1 to max_clauses clauses of 1 to 3
// literals from rng, compiled (a third of the time with a random mutation).
inline CompiledRuns compiled_runs(Rng& rng, int max_clauses) {
  static const std::vector<Mutation> mutations = all_mutations();
  const Formula f = random_cnf(rng, static_cast<int>(rng.between(1, 6)), static_cast<int>(rng.between(1, max_clauses)),
                               1, 3, false);
  const Mutation m = rng.below(3) == 0 ? mutations[rng.below(mutations.size())] : Mutation::None;
  CompiledRuns out{compile_formula(f, m), {}};
  const size_t k = out.compiled.instance.couplings().size();
  const SatResult sat = solve_sat(f);
  if (sat.status == Verdict::Yes)
    out.runs.push_back(schedule_from_order(schedule_from_assignment(out.compiled, sat.model)));
  std::vector<CouplingId> order(k);
  for (CouplingId q = 0; q < k; ++q) order[q] = q;
  rng.shuffle(order);
  out.runs.push_back(schedule_from_order(order));
  Schedule at_once;
  at_once.start.assign(k, Rational(0));
  out.runs.push_back(at_once);
  out.runs.push_back(out.runs.front());
  return out;
}

}  // namespace gridlock::test
