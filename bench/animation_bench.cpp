// The viewer's data (docs/animate.md, docs/performance.md): build_animation
// against what it costs anyway, one run of the simulator on the same
// schedule, measured side by side. Family: the comb of simulate_bench with k
// singleton expansions on the spine (a chain of k nested parts: the deepest
// part tree) or inside the teeth, run in a random order.
#include <benchmark/benchmark.h>

#include "bench_families.hpp"
#include "common/random.hpp"
#include "lattice/animation.hpp"
#include "lattice/random_instance.hpp"
#include "lattice/simulate.hpp"

namespace gridlock {
namespace {

Schedule random_order(const Instance& inst) {
  std::vector<CouplingId> order(inst.couplings().size());
  Rng rng(7);
  for (CouplingId q = 0; q < order.size(); ++q) order[q] = q;
  rng.shuffle(order);
  return schedule_from_order(order);
}

void run(benchmark::State& state, bool spine, bool animation) {
  const int64_t n = state.range(0), k = state.range(1), H = 9, L = n / (H + 1);
  Instance inst = bench::comb(L, H, k, spine ? bench::CombOps::Spine : bench::CombOps::Teeth, 1, 42);
  Schedule sched = random_order(inst);
  size_t keys = 0;
  for (auto _ : state) {
    if (animation) {
      Animation a = build_animation(inst, sched);
      keys = a.keyframes();
      benchmark::DoNotOptimize(a);
    } else {
      Simulator sim(inst);
      SimResult r = sim.run(sched);
      benchmark::DoNotOptimize(r);
    }
  }
  state.counters["nodes"] = static_cast<double>(inst.num_nodes());
  if (animation) state.counters["keyframes"] = static_cast<double>(keys);
}

void BM_AnimationSpine(benchmark::State& s) { run(s, true, true); }
void BM_SimulatorSpine(benchmark::State& s) { run(s, true, false); }
void BM_AnimationTeeth(benchmark::State& s) { run(s, false, true); }
void BM_SimulatorTeeth(benchmark::State& s) { run(s, false, false); }

// Spine runs move O(n) regions per step by design (n k <= 10^8 here).
#define SPINE ->Args({10000, 100})->Args({100000, 100})->Args({100000, 1000})->Unit(benchmark::kMillisecond)
#define TEETH ->Args({10000, 100})->Args({100000, 1000})->Args({1000000, 1000})->Unit(benchmark::kMillisecond)
BENCHMARK(BM_AnimationSpine) SPINE;
BENCHMARK(BM_SimulatorSpine) SPINE;
BENCHMARK(BM_AnimationTeeth) TEETH;
BENCHMARK(BM_SimulatorTeeth) TEETH;

}  // namespace
}  // namespace gridlock

BENCHMARK_MAIN();
