// Fuzzer throughput (docs/performance.md, "Fuzzing throughput"): formulas per
// second through Verifier::verify (CaDiCaL, to-lsat, compile, the exact solver
// with its simulator replay, the gap checker, the two certificate runs) for
// each kind of `gridlock fuzz` and each variable count, one core. The same
// campaign formulas as `gridlock fuzz --seed 1 --min-vars V --max-vars V
// --kinds KIND`, cycling over the first 64. For comparison, BM_CadicalOnly
// answers the same formulas with CaDiCaL alone (what one would run without
// checking the reduction).
#include <benchmark/benchmark.h>

#include "cnf/sat_solver.hpp"
#include "verify/fuzz.hpp"
#include "verify/verify.hpp"

namespace gridlock {
namespace {

constexpr uint64_t kFormulas = 64;

std::vector<Formula> campaign(FuzzKind kind, int vars) {
  FuzzParams p;
  p.seed = 1;
  p.min_vars = p.max_vars = vars;
  p.kinds = {kind};
  std::vector<Formula> out;
  for (uint64_t i = 0; i < kFormulas; ++i) out.push_back(fuzz_formula(p, i));
  return out;
}

void BM_Fuzz(benchmark::State& state) {
  const auto kind = static_cast<FuzzKind>(state.range(0));
  const auto formulas = campaign(kind, static_cast<int>(state.range(1)));
  VerifyOptions opt;
  opt.solve_seconds = 10;
  opt.max_states = 2'000'000;
  uint64_t i = 0, disagreements = 0;
  Verifier verifier;  // as a campaign loop runs it: work arrays kept from formula to formula
  for (auto _ : state) {
    VerifyResult r = verifier.verify(formulas[i++ % kFormulas], "bench", opt);
    disagreements += !r.agree;
    benchmark::DoNotOptimize(r.agree);
  }
  state.SetLabel(fuzz_kind_name(kind));
  state.counters["formulas_per_s"] = benchmark::Counter(1, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["disagreements"] = static_cast<double>(disagreements);
}

void BM_CadicalOnly(benchmark::State& state) {
  const auto kind = static_cast<FuzzKind>(state.range(0));
  const auto formulas = campaign(kind, static_cast<int>(state.range(1)));
  uint64_t i = 0;
  for (auto _ : state) {
    SatResult r = solve_sat(formulas[i++ % kFormulas]);
    benchmark::DoNotOptimize(r.status);
  }
  state.SetLabel(fuzz_kind_name(kind));
  state.counters["formulas_per_s"] = benchmark::Counter(1, benchmark::Counter::kIsIterationInvariantRate);
}

void kinds_and_sizes(benchmark::internal::Benchmark* b) {
  for (auto kind : {FuzzKind::Ksat, FuzzKind::Lsat, FuzzKind::Planted})
    for (int v : {3, 4, 5, 6}) b->Args({static_cast<int64_t>(kind), v});
}

BENCHMARK(BM_Fuzz)->Apply(kinds_and_sizes)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CadicalOnly)->Apply(kinds_and_sizes)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace gridlock

BENCHMARK_MAIN();
