// The continuous solver's learning engine on compiled random 3-SAT
// (docs/performance.md, "Continuous learning engine"): uniform random 3-SAT
// at ratio 4.26 (n = 3: 13 clauses), through reduce_to_lsat, compiled with
// --model continuous; the same formula under
//  - sat: solve_continuous, the default (cheap tests, the discrete order,
//    then the learning engine);
//  - z3: the same with ContinuousEngine::Z3 (the Z3-only path it replaces);
//  - discrete: solve_discrete on the formula's discrete reduction (what the
//    issue's "within 10x" goal compares with);
//  - cadical: CaDiCaL on the source formula (the answer every path must give).
// One iteration each: a solve takes seconds. Arguments: n, seed.
#include <benchmark/benchmark.h>

#include "cnf/generate.hpp"
#include "cnf/sat_solver.hpp"
#include "reductions/compile.hpp"
#include "reductions/to_lsat.hpp"
#include "solver/continuous.hpp"
#include "solver/solve.hpp"

namespace gridlock {
namespace {

Formula lsat_formula(const benchmark::State& state) {
  KSatParams p;
  p.n = static_cast<int>(state.range(0));
  p.m = clauses_for_ratio(p.n, 4.26);
  p.seed = static_cast<uint64_t>(state.range(1));
  return reduce_to_lsat(random_ksat(p)).output();
}

Verdict expected(const benchmark::State& state) {
  KSatParams p;
  p.n = static_cast<int>(state.range(0));
  p.m = clauses_for_ratio(p.n, 4.26);
  p.seed = static_cast<uint64_t>(state.range(1));
  return solve_sat(random_ksat(p)).status;
}

void run_continuous(benchmark::State& state, ContinuousEngine engine) {
  const CompiledFormula c = compile_formula(lsat_formula(state), Mutation::None, ReductionModel::Continuous);
  SolveOptions opt;
  opt.seconds = 120;
  ContinuousResult r;
  for (auto _ : state) r = solve_continuous(c.instance, opt, engine);
  if (r.status != expected(state)) state.SkipWithError("no answer or not CaDiCaL's");
  state.counters["couplings"] = static_cast<double>(c.stats.couplings);
  state.counters["rounds"] = static_cast<double>(r.stats.decisions);
  state.counters["learned"] = static_cast<double>(r.stats.propagations);
  state.counters["yes"] = r.status == Verdict::Yes ? 1 : 0;
}

void BM_ContinuousSat(benchmark::State& state) { run_continuous(state, ContinuousEngine::Auto); }
void BM_ContinuousZ3(benchmark::State& state) { run_continuous(state, ContinuousEngine::Z3); }

void BM_DiscreteSameFormula(benchmark::State& state) {
  const CompiledFormula c = compile_formula(lsat_formula(state));
  SolveOptions opt;
  opt.seconds = 120;
  SolveResult r;
  for (auto _ : state) r = solve_discrete(c.instance, opt);
  if (r.status != expected(state)) state.SkipWithError("no answer or not CaDiCaL's");
  state.counters["couplings"] = static_cast<double>(c.stats.couplings);
}

void BM_CadicalSource(benchmark::State& state) {
  KSatParams p;
  p.n = static_cast<int>(state.range(0));
  p.m = clauses_for_ratio(p.n, 4.26);
  p.seed = static_cast<uint64_t>(state.range(1));
  const Formula f = random_ksat(p);
  for (auto _ : state) benchmark::DoNotOptimize(solve_sat(f).status);
}

#define GRIDLOCK_SIZES ArgsProduct({{3}, {1, 2, 3, 4}})->Iterations(1)->Unit(benchmark::kMillisecond)
BENCHMARK(BM_ContinuousSat)->GRIDLOCK_SIZES;
BENCHMARK(BM_ContinuousZ3)->GRIDLOCK_SIZES;
BENCHMARK(BM_DiscreteSameFormula)->GRIDLOCK_SIZES;
BENCHMARK(BM_CadicalSource)->ArgsProduct({{3}, {1, 2, 3, 4}})->Unit(benchmark::kMicrosecond);
#undef GRIDLOCK_SIZES

}  // namespace
}  // namespace gridlock
BENCHMARK_MAIN();
