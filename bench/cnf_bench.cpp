// Formula layer costs (docs/formulas.md): the DIMACS reader, the LSAT check,
// to-lsat, and CaDiCaL on the input and on its LSAT<=3 image, on the SATLIB
// sample (uf50-218 satisfiable, uuf50-218 unsatisfiable), plus to-lsat on
// large random 3-SAT at the threshold ratio 4.26 to show linear scaling.
#include <benchmark/benchmark.h>

#include <string>

#include "cnf/dimacs.hpp"
#include "cnf/generate.hpp"
#include "cnf/lsat.hpp"
#include "cnf/sat_solver.hpp"
#include "reductions/to_lsat.hpp"

namespace gridlock {
namespace {

Formula satlib(const std::string& set, int index) {
  std::string path = std::string(GRIDLOCK_DATA_DIR) + "/satlib/" + set + "-218/" + set + "-0" + std::to_string(index) +
                     ".cnf";
  Formula f;
  if (auto e = read_dimacs_file(path, f)) throw std::runtime_error(e->str());
  return f;
}

void BM_ReadDimacs(benchmark::State& state) {
  const std::string text = to_dimacs(
      random_ksat({static_cast<int>(state.range(0)), clauses_for_ratio(static_cast<int>(state.range(0)), 4.26), 3, 1}));
  for (auto _ : state) {
    Formula f;
    benchmark::DoNotOptimize(read_dimacs_string(text, "bench.cnf", f));
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * text.size()));
}
BENCHMARK(BM_ReadDimacs)->Arg(1000)->Arg(100000);

void BM_ToLsatRandom(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const Formula f = random_ksat({n, clauses_for_ratio(n, 4.26), 3, 2});
  for (auto _ : state) benchmark::DoNotOptimize(reduce_to_lsat(f));
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * f.clauses.size()));
  state.SetComplexityN(static_cast<int64_t>(f.clauses.size()));
}
BENCHMARK(BM_ToLsatRandom)->RangeMultiplier(10)->Range(1000, 1000000)->Complexity(benchmark::oN);

void BM_CheckLsat(benchmark::State& state) {
  const Formula out = reduce_to_lsat(random_ksat({static_cast<int>(state.range(0)),
                                                  clauses_for_ratio(static_cast<int>(state.range(0)), 4.26), 3, 3}))
                          .output();
  for (auto _ : state) benchmark::DoNotOptimize(is_lsat(out, LsatForm::AtMost3));
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * out.clauses.size()));
}
BENCHMARK(BM_CheckLsat)->Arg(10000)->Arg(100000);

// CaDiCaL on SATLIB formula `index` of a set, directly (arg 1 = 0) or after
// to-lsat (arg 1 = 1): what the reduction costs the solver.
void BM_CadicalSatlib(benchmark::State& state, const char* set) {
  const Formula in = satlib(set, static_cast<int>(state.range(0)));
  const Formula f = state.range(1) ? reduce_to_lsat(in).output() : in;
  for (auto _ : state) benchmark::DoNotOptimize(solve_sat(f));
  state.SetLabel(summary(f));
}
BENCHMARK_CAPTURE(BM_CadicalSatlib, uf50, "uf50")->Args({1, 0})->Args({1, 1})->Args({2, 0})->Args({2, 1});
BENCHMARK_CAPTURE(BM_CadicalSatlib, uuf50, "uuf50")->Args({1, 0})->Args({1, 1})->Args({2, 0})->Args({2, 1});

}  // namespace
}  // namespace gridlock

BENCHMARK_MAIN();
