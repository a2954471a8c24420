// Simulator scaling (docs/performance.md): how time grows with the number of
// nodes n and of couplings k. Families are collision-free, so every interval
// is simulated (a collision would end the run early):
//   comb: a spine of length L along x with a tooth of height H on every spine
//   node (n = L (H + 1)); k singleton expansions, run in a random order.
//   - spine: expansions on spine edges (+x): each moves the smaller side,
//     about a quarter of the shape on average: O(n) per step.
//   - teeth: expansions inside teeth (+y): each moves part of one tooth:
//     O(H) per step, whatever n is.
//   - all at once: every spine expansion coupled into one continuous run.
#include <benchmark/benchmark.h>

#include <string>

#include "bench_families.hpp"
#include "common/random.hpp"
#include "lattice/random_instance.hpp"
#include "lattice/simulate.hpp"

namespace gridlock {
namespace {

void run(benchmark::State& state, bool teeth, bool at_once) {
  const int64_t n = state.range(0), k = state.range(1);
  const int64_t H = teeth ? 9 : 3, L = n / (H + 1);
  Instance inst = bench::comb(L, H, k, teeth ? bench::CombOps::Teeth : bench::CombOps::Spine, at_once ? 0 : 1, 42);
  if (static_cast<int64_t>(inst.ops().size()) < k) {
    state.SkipWithError("k too large for n");
    return;
  }
  Simulator sim(inst);
  std::vector<CouplingId> order(inst.couplings().size());
  Rng rng(7);
  for (CouplingId q = 0; q < order.size(); ++q) order[q] = q;
  rng.shuffle(order);
  Schedule sched = schedule_from_order(order);
  SimStats stats;
  for (auto _ : state) {
    SimResult r = sim.run(sched);
    if (r.collision) state.SkipWithError("unexpected collision");
    stats = r.stats;
    benchmark::DoNotOptimize(r);
  }
  state.counters["nodes"] = static_cast<double>(inst.num_nodes());
  state.counters["couplings"] = static_cast<double>(inst.couplings().size());
  state.counters["moved_per_interval"] = static_cast<double>(stats.moved_regions) /
                                         static_cast<double>(std::max<uint64_t>(stats.intervals, 1));
  state.counters["ns_per_moved_region"] = benchmark::Counter(
      static_cast<double>(stats.moved_regions),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_CombSpine(benchmark::State& s) { run(s, false, false); }
void BM_CombTeeth(benchmark::State& s) { run(s, true, false); }
void BM_AllAtOnce(benchmark::State& s) { run(s, false, true); }

// n from 10^3 to 10^6; k from 10^2 to 10^4 (spine runs with n k <= 10^9 only:
// they move O(n) regions per step by design).
BENCHMARK(BM_CombSpine)
    ->Args({1000, 100})
    ->Args({10000, 100})
    ->Args({10000, 1000})
    ->Args({100000, 100})
    ->Args({100000, 1000})
    ->Args({100000, 10000})
    ->Args({1000000, 100})
    ->Args({1000000, 1000})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CombTeeth)
    ->Args({1000, 100})
    ->Args({10000, 100})
    ->Args({10000, 1000})
    ->Args({100000, 100})
    ->Args({100000, 1000})
    ->Args({100000, 10000})
    ->Args({1000000, 100})
    ->Args({1000000, 1000})
    ->Args({1000000, 10000})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_AllAtOnce)
    ->Args({1000, 50})
    ->Args({2000, 100})
    ->Args({4000, 200})
    ->Args({8000, 400})
    ->Args({16000, 800})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gridlock

BENCHMARK_MAIN();
