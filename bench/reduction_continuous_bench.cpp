// The continuous reduction under the exact continuous solver (docs/
// performance.md, "Continuous reduction"): how far continuous verification
// scales with the formula.
//  - family: the implication chain (x1)(~x1 v x2)(~x2 v x3)...(~x_{n-1} v x_n),
//    satisfiable, and the same with (~x_n) added, unsatisfiable: LSAT<=3,
//    n variables, 4n + m couplings, compiled with --model continuous;
//  - continuous: solve_continuous on it (what `verify --model continuous`
//    spends per formula);
//  - discrete: solve_discrete on the discrete reduction of the same formula,
//    for the ratio (the other model's question on the same formula).
// One iteration each: a single solve takes seconds.
#include <benchmark/benchmark.h>

#include "cnf/formula.hpp"
#include "reductions/compile.hpp"
#include "solver/continuous.hpp"
#include "solver/solve.hpp"

namespace gridlock {
namespace {

Formula chain(int n, bool unsat) {
  Formula f;
  f.num_vars = n;
  f.clauses.push_back({1});
  for (int i = 1; i < n; ++i) f.clauses.push_back({-i, i + 1});
  if (unsat) f.clauses.push_back({-n});
  return f;
}

void BM_ContinuousReduction(benchmark::State& state) {
  const Formula f = chain(static_cast<int>(state.range(0)), state.range(1) != 0);
  const CompiledFormula c = compile_formula(f, Mutation::None, TimeModel::Continuous);
  ContinuousResult r;
  for (auto _ : state) r = solve_continuous(c.instance);
  const bool want_yes = state.range(1) == 0;
  if (r.status != (want_yes ? Verdict::Yes : Verdict::No)) state.SkipWithError("wrong or no answer");
  state.counters["couplings"] = static_cast<double>(c.stats.couplings);
  state.counters["nodes"] = static_cast<double>(c.stats.nodes);
  state.counters["z3_conflicts"] = static_cast<double>(r.stats.refuted);
}
BENCHMARK(BM_ContinuousReduction)->ArgsProduct({{1, 2, 3, 4}, {0, 1}})->Iterations(1)->Unit(benchmark::kMillisecond);

void BM_DiscreteReduction(benchmark::State& state) {
  const Formula f = chain(static_cast<int>(state.range(0)), state.range(1) != 0);
  const CompiledFormula c = compile_formula(f);
  SolveResult r;
  for (auto _ : state) r = solve_discrete(c.instance);
  const bool want_yes = state.range(1) == 0;
  if (r.status != (want_yes ? Verdict::Yes : Verdict::No)) state.SkipWithError("wrong or no answer");
  state.counters["couplings"] = static_cast<double>(c.stats.couplings);
  state.counters["states"] = static_cast<double>(r.stats.states);
}
BENCHMARK(BM_DiscreteReduction)->ArgsProduct({{1, 2, 3, 4}, {0, 1}})->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gridlock
BENCHMARK_MAIN();
