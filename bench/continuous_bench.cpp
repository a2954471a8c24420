// Continuous solver benchmarks (docs/performance.md, "Continuous solver").
//  - chain: separation chains (bench_families.hpp), the shape of the
//    continuous reduction's gadgets, n + 1 couplings of 2 operations (or 3
//    with rows), one component that Z3 must order: growth with n;
//  - random: random instances of every operation kind with k couplings
//    (tree shapes with a few cycles): growth with k;
//  - twin: the same inputs through the tests' twin (one quantified Z3
//    formula on the region geometry, what a user would otherwise write), for
//    the ratio, on the sizes it can reach.
#include <benchmark/benchmark.h>

#include "bench/bench_families.hpp"
#include "lattice/random_instance.hpp"
#include "solver/continuous.hpp"
#include "support/reference_continuous.hpp"

namespace gridlock {
namespace {

void report(benchmark::State& state, const Instance& inst, const ContinuousResult& r) {
  state.counters["couplings"] = static_cast<double>(inst.couplings().size());
  state.counters["constraints"] = static_cast<double>(r.stats.constraints);
  state.counters["z3_components"] = static_cast<double>(r.stats.states);
  state.counters["yes"] = r.status == Verdict::Yes ? 1 : 0;
}

void BM_ContinuousChain(benchmark::State& state) {
  Instance inst = bench::separation_chain(state.range(0), state.range(1) != 0);
  ContinuousResult r;
  for (auto _ : state) {
    r = solve_continuous(inst);
    if (r.status != Verdict::Yes) state.SkipWithError("chain must be YES");
  }
  report(state, inst, r);
}
BENCHMARK(BM_ContinuousChain)
    ->ArgsProduct({{1, 2, 4, 8, 16, 64, 256, 1024, 4096}, {0}})
    ->ArgsProduct({{4, 16, 64, 256, 1024}, {1}})
    ->Unit(benchmark::kMillisecond);

void BM_TwinChain(benchmark::State& state) {
  Instance inst = bench::separation_chain(state.range(0), state.range(1) != 0);
  for (auto _ : state) {
    auto r = test::reference_continuous(inst);
    if (!r || !*r) state.SkipWithError("twin must say YES");
  }
  state.counters["couplings"] = static_cast<double>(inst.couplings().size());
}
BENCHMARK(BM_TwinChain)->ArgsProduct({{1, 2, 4, 8}, {0}})->Unit(benchmark::kMillisecond);

// k couplings: 4k nodes (sparse trees), k single operations; 20 seeds per
// iteration (the mean per instance is time / 20).
std::vector<Instance> random_set(int64_t k) {
  std::vector<Instance> v;
  RandomInstanceParams p;
  p.nodes = static_cast<uint32_t>(4 * k);
  p.ops = static_cast<uint32_t>(k);
  p.max_coupling = 1;
  p.spread = 2;
  for (uint64_t s = 0; s < 20; ++s) v.push_back(random_instance(p, 1000 + s));
  return v;
}

void BM_ContinuousRandom(benchmark::State& state) {
  std::vector<Instance> set = random_set(state.range(0));
  int yes = 0, z3 = 0;
  for (auto _ : state) {
    yes = z3 = 0;
    for (const Instance& inst : set) {
      ContinuousResult r = solve_continuous(inst);
      yes += r.status == Verdict::Yes;
      z3 += r.stats.states > 0;
    }
  }
  state.counters["instances"] = static_cast<double>(set.size());
  state.counters["yes"] = yes;
  state.counters["used_z3"] = z3;
}
BENCHMARK(BM_ContinuousRandom)->Arg(3)->Arg(5)->Arg(10)->Arg(20)->Arg(40)->Arg(80)->Unit(benchmark::kMillisecond);

void BM_TwinRandom(benchmark::State& state) {
  std::vector<Instance> set = random_set(state.range(0));
  for (auto _ : state)
    for (const Instance& inst : set) benchmark::DoNotOptimize(test::reference_continuous(inst));
  state.counters["instances"] = static_cast<double>(set.size());
}
BENCHMARK(BM_TwinRandom)->Arg(3)->Arg(5)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gridlock
BENCHMARK_MAIN();
