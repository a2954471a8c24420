// Colliding Schedule scaling (docs/performance.md, docs/collide.md).
//
// Families where the answer is NO, so every algorithm runs to the end (a
// YES stops at the first colliding pair):
//   comb: a spine of length L along x with a tooth of height H on every
//   spine node; expansions only (they push teeth apart: teeth slide along
//   each other, touching, never overlapping). path: H = 0, a straight row.
//   random: seeded random trees with 3 operations (YES or NO, as drawn).
// Couplings: expansions grouped into couplings of `c` operations each.
//   axis: spine expansions only (+x; every net is horizontal)
//   mixed: spine (+x) and tooth (+y) expansions (nets of many directions)
//
// Default runs are short; larger sizes:  --benchmark_filter=Tree/ etc. with
// the Args below (see docs/performance.md for the commands used).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>

#include "bench_families.hpp"
#include "certify/certify.hpp"
#include "collide/adversarial.hpp"
#include "collide/collide.hpp"
#include "collide/collide_certificate.hpp"
#include "collide/internal/collide_pairs.hpp"
#include "collide/internal/collide_tree.hpp"
#include "collide/single_coupling.hpp"
#include "lattice/prepared.hpp"
#include "lattice/random_instance.hpp"
#include "lattice/simulate.hpp"

namespace gridlock {
namespace {

Instance family(const std::string& name, int64_t n) {
  if (name == "path") return bench::comb(n, 0, n / 4, bench::CombOps::Spine, 1, 42);
  if (name == "comb") return bench::comb(n / 4, 3, n / 8, bench::CombOps::Spine, 1, 42);
  RandomInstanceParams p;
  p.nodes = static_cast<uint32_t>(n);
  p.ops = 3;
  return random_instance(p, 42);
}

void tree_bench(benchmark::State& state, const std::string& fam, bool pairwise) {
  Instance inst = family(fam, state.range(0));
  Simulator sim(inst);
  bool yes = false;
  for (auto _ : state) {
    auto r = pairwise ? tree_collision_pairwise(inst, sim.tree(), sim.regions())
                      : tree_collision(inst, sim.tree(), sim.regions());
    yes = r.has_value();
    benchmark::DoNotOptimize(r);
  }
  state.counters["n"] = static_cast<double>(inst.num_nodes());
  state.counters["yes"] = yes;
}

void coupled_bench(benchmark::State& state, bool mixed, TimeModel model) {
  const int64_t n = state.range(0), c = state.range(1);
  Instance inst = mixed ? bench::comb(n / 4, 3, n / 4, bench::CombOps::Mixed, c, 7)
                        : bench::comb(n, 0, n / 4, bench::CombOps::Spine, c, 7);
  bool yes = false;
  CollideResult r;
  for (auto _ : state) {
    r = find_collision(inst, model, CollideMethod::Pairwise);
    yes = r.collides;
  }
  state.counters["n"] = static_cast<double>(inst.num_nodes());
  state.counters["yes"] = yes;
  state.counters["full_tests"] = static_cast<double>(r.stats.full_tests);
}

// Adversarial serpentines (collide/adversarial.hpp): a square serpentine of
// about n nodes, couplings of range(1) operations (0: sqrt of the number of
// operations), Mixed or Columns grouping, seed 1. NO instances: every pair
// is examined. The pairwise method itself (pairwise_collision, as
// find_collision's Pairwise step calls it), continuous with the incremental
// supports or the per-pair rebuild (the method before them), or discrete.
// The coupling size range(1) asks for on a serpentine of range(0) nodes:
// -3 means couplings of about n^(1/3) operations, which makes the distinct
// net directions on a path (D) largest: about n^(2/3).
int64_t serpentine_coupling_size(const benchmark::State& state) {
  return state.range(1) == -3 ? std::llround(std::cbrt(static_cast<double>(state.range(0)))) : state.range(1);
}

void serpentine_bench(benchmark::State& state, SerpentineCouplings how, TimeModel model, ZonotopeTest ztest) {
  const int64_t c = serpentine_coupling_size(state);
  SerpentineParams p = how == SerpentineCouplings::Fan
                           ? fan_serpentine(state.range(0))
                           : square_serpentine(state.range(0), static_cast<uint32_t>(c), how);
  Instance inst = serpentine_instance(p, 1);
  Simulator sim(inst);
  bool yes = false;
  PairwiseStats st;
  for (auto _ : state) {
    auto r = pairwise_collision(inst, sim.tree(), sim.regions(), model, &st, nullptr, ztest);
    yes = r.has_value();
    benchmark::DoNotOptimize(r);
  }
  state.counters["n"] = static_cast<double>(inst.num_nodes());
  state.counters["couplings"] = static_cast<double>(inst.couplings().size());
  double grouped = 0;  // couplings of more than one operation (Fan: the directions (a, b) with a + b >= 2)
  for (const auto& q : inst.couplings()) grouped += q.ops.size() > 1 ? 1 : 0;
  state.counters["grouped"] = grouped;
  state.counters["yes"] = yes;
  state.counters["pairs"] = static_cast<double>(st.pairs);
  state.counters["full_tests"] = static_cast<double>(st.full_tests);
}

// One coupling (docs/performance.md, "One coupling"): every operation in
// one coupling, NO, so every method runs to the end. range(1) picks the
// method: 0 find_collision Auto (the space-time cell sweep; on one axis
// the row neighbours' test; when no two faces change order, the one-moment
// NO), 1 the pairwise zonotope method, 2 the exact
// simulator running the one schedule (what Auto did before the sweep), 3
// the sweep's all-pairs twin, 4 the sweep with every item in memory at
// once (one band: its memory before the column bands), 5 the sweep as
// Auto runs it (column bands), whatever the axes, 6 motion classes
// whatever their cost (after the cuts), 7 time slabs.
// Counters: items (M) and tests (T) of the sweep, candidate pairs of the
// simulator's broad phase.
void single_coupling_bench(benchmark::State& state, const Instance& inst) {
  const int64_t how = state.range(1);
  Simulator sim(inst);
  bool yes = false;
  SingleCouplingStats st;
  SimStats ss;
  std::string algorithm;
  for (auto _ : state) {
    if (how == 0 || how == 1) {
      CollideResult r = find_collision(inst, TimeModel::Continuous,
                                       how == 1 ? CollideMethod::Pairwise : CollideMethod::Auto);
      if (how == 0 && r.algorithm.rfind("single-coupling", 0) != 0) state.SkipWithError("not a single-coupling step");
      algorithm = r.algorithm;
      yes = r.collides;
      st.items = r.stats.cell_items, st.tests = r.stats.pair_tests;
    } else if (how == 4 || how == 5) {
      yes = single_coupling_sweep(inst, sim.tree(), sim.regions(), &st, nullptr,
                                  how == 4 ? UINT64_MAX : kSingleCouplingBandItems)
                .collides;
    } else if (how == 6) {
      const std::optional<MotionClassAnswer> c = single_coupling_motion_classes(inst, sim.tree(), sim.regions(),
                                                                                nullptr, false, true);
      if (!c) return state.SkipWithError("motion classes declined");
      yes = c->answer.collides;
      state.counters["classes"] = static_cast<double>(c->classes);
    } else if (how == 7) {
      const std::optional<TimeSlabAnswer> ts = single_coupling_time_slabs(inst, sim.tree(), sim.regions());
      if (!ts) return state.SkipWithError("time slabs declined");
      yes = ts->answer.collides;
    } else if (how == 2) {
      SimResult run = sim.run_order({0});
      yes = run.collision.has_value(), ss = run.stats;
    } else {
      yes = single_coupling_pairwise(inst, sim.tree(), sim.regions()).has_value();
    }
  }
  if (how == 0 && algorithm == "single-coupling")
    (void)single_coupling_sweep(inst, sim.tree(), sim.regions(), &st);  // the counters
  if (how == 0 && (algorithm == "single-coupling-fixed-axis" || algorithm == "single-coupling-separated"))
    if (const std::optional<FixedAxisAnswer> f = single_coupling_fixed_axis(inst, sim.tree(), sim.regions())) {
      state.counters["sweeps"] = static_cast<double>(f->sweeps), st.tests = f->tests;  // sweeps run, exact tests
      state.counters["groups"] = static_cast<double>(f->groups);
    }
  if (how == 0 && algorithm == "single-coupling-motion-classes")
    if (const std::optional<MotionClassAnswer> c = single_coupling_motion_classes(inst, sim.tree(), sim.regions())) {
      state.counters["sweeps"] = static_cast<double>(c->sweeps);
      state.counters["classes"] = static_cast<double>(c->classes);
      state.counters["class_pairs"] = static_cast<double>(c->class_pairs);
      state.counters["queries"] = static_cast<double>(c->queries);
      state.counters["groups"] = static_cast<double>(c->groups);
    }
  if ((how == 0 && algorithm == "single-coupling-time-slabs") || how == 7)
    if (const std::optional<TimeSlabAnswer> ts = single_coupling_time_slabs(inst, sim.tree(), sim.regions())) {
      state.counters["sweeps"] = static_cast<double>(ts->sweeps), st.tests = ts->tests;
      state.counters["groups"] = static_cast<double>(ts->groups);
      state.counters["slabs"] = static_cast<double>(ts->slabs);
      state.counters["finest"] = static_cast<double>(ts->finest);
      state.counters["work"] = static_cast<double>(ts->work);
    }
  if (!algorithm.empty()) state.SetLabel(algorithm);
  state.counters["n"] = static_cast<double>(inst.num_nodes());
  state.counters["yes"] = yes;
  state.counters["items"] = static_cast<double>(st.items);
  state.counters["tests"] = static_cast<double>(st.tests);
  state.counters["motion"] = static_cast<double>(st.motion);
  state.counters["max_active"] = static_cast<double>(st.max_active);
  state.counters["bands"] = static_cast<double>(st.bands);
  state.counters["peak_items"] = static_cast<double>(st.peak_items);
  state.counters["sim_pairs"] = static_cast<double>(ss.candidate_pairs);
}

// The mixed serpentine of n nodes with every operation in one coupling.
void BM_SerpentineSingleCoupling(benchmark::State& state) {
  SerpentineParams p = square_serpentine(state.range(0), 1u << 30, SerpentineCouplings::Mixed);
  single_coupling_bench(state, serpentine_instance(p, 1));
}

// The mixed comb (n/4 expansions, spine and teeth, all in one coupling).
void BM_CombSingleCoupling(benchmark::State& state) {
  single_coupling_bench(state, bench::comb(state.range(0) / 4, 3, state.range(0) / 4, bench::CombOps::Mixed, 0, 7));
}

// The mixed comb under a lid (bench_families.hpp, comb with lid = true;
// n/4 spine nodes, teeth of height 3, n/4 expansions, about 3n/2 nodes):
// NO, total motion Theta(n^2), and the faces of both axes change order.
// Auto cuts it into separated groups (the lid's row above, its column to
// the left, the comb keeping its x order) and sweeps each; range(1) = 5
// is the cell sweep it took before, 2 the simulation.
void BM_LiddedCombSingleCoupling(benchmark::State& state) {
  single_coupling_bench(state,
                        bench::comb(state.range(0) / 4, 3, state.range(0) / 4, bench::CombOps::Mixed, 0, 7, true));
}

// The stalactite comb of about n nodes (bench_families.hpp): NO, total
// motion Theta(n^2), both axes changing order and no cut between the
// teeth and the stalactites they pass over (0, 1): Auto cuts it over two
// time slabs (range(1) = 0: apart along y before t = 1/2, along x
// after); 6 is its six motion classes (Auto before the slabs), 5 the cell
// sweep (Auto before the classes), 2 the simulation.
void BM_StalactiteCombSingleCoupling(benchmark::State& state) {
  single_coupling_bench(state, bench::stalactite_comb(state.range(0) / 24));
}

// The stalactite comb with its middle stalactite reaching into the teeth's
// path (bench_families.hpp, hit): YES at t = floor(L / 2) / k. Auto finds
// a pair in the time slabs' first half and bisects for the first moment
// (range(1) = 0); 6 motion classes, 5 the cell sweep, 2 the simulation.
void BM_StalactiteHitSingleCoupling(benchmark::State& state) {
  single_coupling_bench(state, bench::stalactite_comb(state.range(0) / 24, false, true));
}

// The stalactite comb whose pairs of teeth each move at their own speed
// (bench_families.hpp, own_speeds): NO, about L / 2 kinds of motion among
// the teeth (k of order n). Auto cuts it over two time slabs as the plain
// comb (range(1) = 0); 6 is motion classes (Auto before the slabs,
// quadratic here), 5 the cell sweep, 2 the simulation.
void BM_OwnSpeedStalactiteCombSingleCoupling(benchmark::State& state) {
  single_coupling_bench(state, bench::stalactite_comb(state.range(0) / 24, true));
}

// The awning comb of about n nodes (bench_families.hpp): both axes, x
// faces keeping their order, total motion Theta(n^2), YES at t = 2/3.
// Auto sweeps along x and bisects for the first moment.
void BM_AwningCombSingleCoupling(benchmark::State& state) {
  single_coupling_bench(state, bench::awning_comb(state.range(0) / 9, 7));
}

// The spine comb: teeth of height 3 on a spine of n / 4 nodes, n / 4
// spine expansions (+x only) in one coupling: one axis, total motion
// Theta(n^2) (the teeth slide along each other, touching).
void BM_SpineCombSingleCoupling(benchmark::State& state) {
  single_coupling_bench(state, bench::comb(state.range(0) / 4, 3, state.range(0) / 4, bench::CombOps::Spine, 0, 7));
}

// The hook (bench_families.hpp): one axis, YES, total motion Theta(n^2);
// Auto names the first collision and checks it at one moment, the
// simulation (range(1) = 2) is what confirmed the witness before.
void BM_HookSingleCoupling(benchmark::State& state) {
  single_coupling_bench(state, bench::hook((state.range(0) - 3) / 2));
}

// One axis, couplings of 3 (NO: expansions only push apart). range(1): 0
// a row of n nodes, 1 a square comb (spine and teeth of about sqrt(n)
// nodes), whose row neighbours are 2h + 1 tree edges apart at height h;
// n / 4 expansions on the spine (+x). range(2): 0 Auto (the group pairs,
// ends walked in Mo's order), 1 Pairwise (every pair: what Auto ran before).
// Family 2: the hook (bench_families.hpp) with couplings of 3, a YES.
// (one_axis_family builds them; BM_OneAxisCertificate uses 0 and 1.)
Instance one_axis_family(int64_t n, int64_t family) {
  const int64_t side = std::llround(std::sqrt(static_cast<double>(n)));
  return family == 0   ? bench::comb(n, 0, n / 4, bench::CombOps::Spine, 3, 7)
         : family == 1 ? bench::comb(side, side - 1, side / 2, bench::CombOps::Spine, 3, 7)
                       : bench::hook((n - 3) / 2, 3);
}

void BM_OneAxisCouplings(benchmark::State& state) {
  const Instance inst = one_axis_family(state.range(0), state.range(1));
  CollideResult r;
  for (auto _ : state)
    r = find_collision(inst, TimeModel::Continuous,
                       state.range(2) == 0 ? CollideMethod::Auto : CollideMethod::Pairwise);
  state.SetLabel(r.algorithm);
  state.counters["n"] = static_cast<double>(inst.num_nodes());
  state.counters["yes"] = r.collides;
  state.counters["pairs"] = static_cast<double>(r.stats.pairs);
  state.counters["full_tests"] = static_cast<double>(r.stats.full_tests);
}

// collide's NO certificate on BM_OneAxisCouplings' NO families (range(1):
// 0 the row, 1 the square comb) and on the mixed comb of
// BM_CombSingleCoupling (2: one coupling, both axes, the x order kept)
// and the lidded comb of BM_LiddedCombSingleCoupling (3: separated groups).
// range(2): 0 the kind Auto writes (one-axis: the row groups' pairs;
// kept-order: the fixed-axis sweep's pairs), 1 every pair (what these NOs
// got before). range(3): 0 times writing it, 1 checking it (certify, the
// certificate written once outside the loop).
void BM_OneAxisCertificate(benchmark::State& state) {
  const Instance inst = state.range(1) >= 2 ? bench::comb(state.range(0) / 4, 3, state.range(0) / 4,
                                                          bench::CombOps::Mixed, 0, 7, state.range(1) == 3)
                                            : one_axis_family(state.range(0), state.range(1));
  const bool every_pair = state.range(2) == 1;
  CollideCertificate cert = collide_no_certificate(inst, nullptr, false, {}, every_pair);
  if (cert.text.empty()) state.SkipWithError("no certificate");
  CertifyResult r;
  for (auto _ : state) {
    if (state.range(3) == 0) cert = collide_no_certificate(inst, nullptr, false, {}, every_pair);
    else r = certify(inst, cert.text, "continuous");
  }
  if (state.range(3) == 1 && !r.proved) state.SkipWithError(("refused: " + r.reason).c_str());
  state.counters["n"] = static_cast<double>(inst.num_nodes());
  state.counters["pairs"] = static_cast<double>(cert.pairs);
  state.counters["lines"] = static_cast<double>(cert.lines);
  state.counters["bytes"] = static_cast<double>(cert.text.size());
}
BENCHMARK(BM_OneAxisCertificate)
    ->ArgsProduct({{1024, 4096, 16384}, {0, 1, 2, 3}, {0, 1}, {0, 1}})
    ->Unit(benchmark::kMillisecond);

// The diagonal sweep (collide/adversarial.hpp): quadratic candidate pairs
// for the simulator, total motion O(n^{3/2}).
void BM_DiagonalSingleCoupling(benchmark::State& state) {
  single_coupling_bench(state, diagonal_sweep_of_size(state.range(0)));
}

// The diagonal sweep with its post (collide/adversarial.hpp): the same
// motion, a YES at t = 1 - 1/K. Auto (range(1) = 0) names the first
// collision from the sweep and checks it at one moment; the simulation
// (2) is what confirmed a sweep's YES before, on top of the sweep.
void BM_DiagonalHitSingleCoupling(benchmark::State& state) {
  single_coupling_bench(state, diagonal_sweep_of_size(state.range(0), true));
}

// The band sweep of slope p = range(2) (collide/adversarial.hpp): a
// staircase carried along (p, 1) past a static band, total motion
// Theta(n^2); Auto cuts it across the motion (docs/collide.md, "Separated
// groups").
void BM_BandSingleCoupling(benchmark::State& state) {
  single_coupling_bench(state, band_sweep_of_size(state.range(0), static_cast<uint32_t>(state.range(2))));
}

// The arc sweep (collide/adversarial.hpp): cells moving away from the
// anchor in Theta(sqrt n) directions beside a static copy, total motion
// Theta(n^2), no cut: Auto's worst case today (the cell sweep).
void BM_ArcSingleCoupling(benchmark::State& state) { single_coupling_bench(state, arc_sweep_of_size(state.range(0))); }

// The discrete answer as `collide --model discrete` gives it, on the mixed
// serpentine (docs/performance.md, "The discrete answer by the continuous
// decider"). range(1): coupling size as in serpentine_bench (3, 0: sqrt
// of the operations, -3: cube root); range(2): 0 Auto (the continuous pair
// tests decide; a YES's witness by subset sums from the nodes the continuous
// pair's faces follow), 1 Pairwise (subset sums on every pair: the discrete decider
// on its own); range(3): contract_percent (0: NO, every pair examined;
// > 0: most instances collide, the witness search runs).
void BM_DiscreteAnswerSerpentine(benchmark::State& state) {
  const int64_t n = state.range(0), c = serpentine_coupling_size(state);
  SerpentineParams p = square_serpentine(n, static_cast<uint32_t>(c), SerpentineCouplings::Mixed);
  p.contract_percent = static_cast<uint32_t>(state.range(3));
  const Instance inst = serpentine_instance(p, 1);
  const PreparedInstance prep(inst);
  CollideResult r;
  for (auto _ : state)
    r = find_collision(prep, TimeModel::Discrete, state.range(2) == 0 ? CollideMethod::Auto : CollideMethod::Pairwise);
  state.SetLabel(r.algorithm);
  state.counters["n"] = static_cast<double>(inst.num_nodes());
  state.counters["yes"] = r.collides;
  state.counters["pairs"] = static_cast<double>(r.stats.pairs);
  state.counters["full_tests"] = static_cast<double>(r.stats.full_tests);
  state.counters["fallbacks"] = static_cast<double>(r.stats.witness_fallbacks);
}

void BM_TreeCentroidPath(benchmark::State& s) { tree_bench(s, "path", false); }
void BM_TreeCentroidComb(benchmark::State& s) { tree_bench(s, "comb", false); }
void BM_TreeCentroidRandom(benchmark::State& s) { tree_bench(s, "random", false); }
void BM_TreePairwisePath(benchmark::State& s) { tree_bench(s, "path", true); }
void BM_TreePairwiseComb(benchmark::State& s) { tree_bench(s, "comb", true); }
void BM_TreePairwiseRandom(benchmark::State& s) { tree_bench(s, "random", true); }
void BM_ZonotopeAxis(benchmark::State& s) { coupled_bench(s, false, TimeModel::Continuous); }
void BM_ZonotopeMixed(benchmark::State& s) { coupled_bench(s, true, TimeModel::Continuous); }
void BM_SubsetSumAxis(benchmark::State& s) { coupled_bench(s, false, TimeModel::Discrete); }
void BM_SubsetSumMixed(benchmark::State& s) { coupled_bench(s, true, TimeModel::Discrete); }
void BM_SerpentineZonotopeMixed(benchmark::State& s) {
  serpentine_bench(s, SerpentineCouplings::Mixed, TimeModel::Continuous, ZonotopeTest::Incremental);
}
void BM_SerpentineZonotopeColumns(benchmark::State& s) {
  serpentine_bench(s, SerpentineCouplings::Columns, TimeModel::Continuous, ZonotopeTest::Incremental);
}
// The fan serpentine (collide/adversarial.hpp): D = Theta(n^{2/3}) distinct
// directions; range(1) is unused (0).
void BM_FanZonotope(benchmark::State& s) {
  serpentine_bench(s, SerpentineCouplings::Fan, TimeModel::Continuous, ZonotopeTest::Incremental);
}
void BM_FanAngleTree(benchmark::State& s) {
  serpentine_bench(s, SerpentineCouplings::Fan, TimeModel::Continuous, ZonotopeTest::AngleTree);
}
void BM_FanPerPair(benchmark::State& s) {
  serpentine_bench(s, SerpentineCouplings::Fan, TimeModel::Continuous, ZonotopeTest::PerPair);
}
void BM_SerpentinePerPairMixed(benchmark::State& s) {
  serpentine_bench(s, SerpentineCouplings::Mixed, TimeModel::Continuous, ZonotopeTest::PerPair);
}
void BM_SerpentinePerPairColumns(benchmark::State& s) {
  serpentine_bench(s, SerpentineCouplings::Columns, TimeModel::Continuous, ZonotopeTest::PerPair);
}
void BM_SerpentineAngleTreeMixed(benchmark::State& s) {
  serpentine_bench(s, SerpentineCouplings::Mixed, TimeModel::Continuous, ZonotopeTest::AngleTree);
}
void BM_SerpentineAngleTreeColumns(benchmark::State& s) {
  serpentine_bench(s, SerpentineCouplings::Columns, TimeModel::Continuous, ZonotopeTest::AngleTree);
}
void BM_SerpentineSubsetSumMixed(benchmark::State& s) {
  serpentine_bench(s, SerpentineCouplings::Mixed, TimeModel::Discrete, ZonotopeTest::Incremental);
}
// The discrete method before the distinct-vector refinement (the twin).
void BM_SerpentinePerVectorMixed(benchmark::State& s) {
  serpentine_bench(s, SerpentineCouplings::Mixed, TimeModel::Discrete, ZonotopeTest::PerPair);
}

#define TREE_SIZES ->RangeMultiplier(10)->Range(1000, 100000)->Unit(benchmark::kMillisecond)
#define PAIR_SIZES ->RangeMultiplier(2)->Range(1000, 8000)->Unit(benchmark::kMillisecond)
BENCHMARK(BM_TreeCentroidPath) TREE_SIZES;
BENCHMARK(BM_TreeCentroidComb) TREE_SIZES;
BENCHMARK(BM_TreeCentroidRandom) TREE_SIZES;
BENCHMARK(BM_TreePairwisePath) PAIR_SIZES;
BENCHMARK(BM_TreePairwiseComb) PAIR_SIZES;
BENCHMARK(BM_TreePairwiseRandom) PAIR_SIZES;
BENCHMARK(BM_ZonotopeAxis)->ArgsProduct({{250, 500, 1000}, {3}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ZonotopeMixed)->ArgsProduct({{250, 500, 1000}, {3}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SubsetSumAxis)->ArgsProduct({{100, 200, 400}, {3}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SubsetSumMixed)->ArgsProduct({{100, 200, 400}, {3}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SerpentineZonotopeMixed)->ArgsProduct({{64, 144, 256}, {3, 0, -3}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SerpentineZonotopeColumns)->ArgsProduct({{64, 144, 256}, {3}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SerpentinePerPairMixed)->ArgsProduct({{64, 144, 256}, {3, 0}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SerpentinePerPairColumns)->ArgsProduct({{64, 144, 256}, {3}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SerpentineAngleTreeMixed)->ArgsProduct({{64, 144, 256}, {3, 0, -3}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SerpentineAngleTreeColumns)->ArgsProduct({{64, 144, 256}, {3}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FanZonotope)->ArgsProduct({{256, 576}, {0}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FanAngleTree)->ArgsProduct({{256, 576}, {0}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FanPerPair)->ArgsProduct({{256}, {0}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SerpentineSingleCoupling)->ArgsProduct({{1024, 4096, 16384}, {0, 2, 5}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SerpentineSingleCoupling)->ArgsProduct({{256, 1024}, {1}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CombSingleCoupling)->ArgsProduct({{1024, 4096, 16384}, {0, 5}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CombSingleCoupling)->ArgsProduct({{1024, 4096}, {1, 2}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LiddedCombSingleCoupling)->ArgsProduct({{1024, 4096, 16384}, {0, 5}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LiddedCombSingleCoupling)->ArgsProduct({{1024, 4096}, {2}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StalactiteCombSingleCoupling)
    ->ArgsProduct({{1536, 6144, 24576, 98304}, {0}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StalactiteCombSingleCoupling)->ArgsProduct({{1536, 6144}, {2, 5}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StalactiteCombSingleCoupling)->ArgsProduct({{1536, 6144, 24576}, {6, 7}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StalactiteHitSingleCoupling)->ArgsProduct({{1536, 6144, 24576, 98304}, {0}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StalactiteHitSingleCoupling)->ArgsProduct({{1536, 6144}, {2, 5}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StalactiteHitSingleCoupling)->ArgsProduct({{1536, 6144, 24576}, {6}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OwnSpeedStalactiteCombSingleCoupling)
    ->ArgsProduct({{1536, 6144, 24576, 98304}, {0}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OwnSpeedStalactiteCombSingleCoupling)
    ->ArgsProduct({{1536, 3072, 6144}, {2, 5, 6, 7}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_AwningCombSingleCoupling)->ArgsProduct({{1024, 4096, 16384}, {0, 2, 5}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SpineCombSingleCoupling)->ArgsProduct({{1024, 4096, 16384}, {0, 5}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SpineCombSingleCoupling)->ArgsProduct({{1024, 4096}, {2}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HookSingleCoupling)->ArgsProduct({{1027, 4099, 16387}, {0}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HookSingleCoupling)->ArgsProduct({{1027, 4099}, {2}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OneAxisCouplings)->ArgsProduct({{1024, 4096, 16384}, {0, 1, 2}, {0}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OneAxisCouplings)->ArgsProduct({{1024, 4096}, {0, 1, 2}, {1}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DiagonalSingleCoupling)->ArgsProduct({{1024, 4096, 16384}, {0, 2, 5}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DiagonalSingleCoupling)->ArgsProduct({{1024}, {1, 3}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DiagonalHitSingleCoupling)->ArgsProduct({{1024, 4096, 16384}, {0, 2, 5}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BandSingleCoupling)->ArgsProduct({{1024, 4096, 16384}, {0, 5}, {1, 2, 3}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BandSingleCoupling)->ArgsProduct({{1024, 4096}, {2}, {1, 2, 3}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ArcSingleCoupling)->ArgsProduct({{1024, 4096}, {0, 2, 5}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SerpentineSubsetSumMixed)->ArgsProduct({{36, 64, 100}, {3, 0}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SerpentinePerVectorMixed)->ArgsProduct({{36, 64, 100}, {3, 0}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DiscreteAnswerSerpentine)
    ->ArgsProduct({{64, 144, 256}, {3, 0}, {0, 1}, {0, 30}})
    ->Unit(benchmark::kMillisecond);

// GRIDLOCK_BENCH_LARGE=1 adds the large sizes of docs/performance.md
// (centroid up to 10^6 nodes, all-pairs and coupling methods until ~60 s).
void register_large_serpentines();
void register_large_fans();
void register_large_discrete_answers();
void register_large_one_axis();
void register_large_cut_families();

void register_large() {
  for (int64_t n : {300000, 1000000}) {
    benchmark::RegisterBenchmark("BM_TreeCentroidPath", BM_TreeCentroidPath)->Arg(n)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("BM_TreeCentroidComb", BM_TreeCentroidComb)->Arg(n)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("BM_TreeCentroidRandom", BM_TreeCentroidRandom)->Arg(n)->Unit(benchmark::kMillisecond);
  }
  for (int64_t n : {16000, 32000}) {
    benchmark::RegisterBenchmark("BM_TreePairwisePath", BM_TreePairwisePath)
        ->Arg(n)
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond);
  }
  for (int64_t n : {2000, 4000, 8000, 16000}) {
    benchmark::RegisterBenchmark("BM_ZonotopeAxis", BM_ZonotopeAxis)
        ->Args({n, 3})
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("BM_ZonotopeMixed", BM_ZonotopeMixed)
        ->Args({n, 3})
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond);
  }
  for (int64_t n : {800, 1600, 3200, 6400}) {
    benchmark::RegisterBenchmark("BM_SubsetSumAxis", BM_SubsetSumAxis)
        ->Args({n, 3})
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("BM_SubsetSumMixed", BM_SubsetSumMixed)
        ->Args({n, 3})
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond);
  }
  register_large_serpentines();
  register_large_discrete_answers();
  register_large_one_axis();
  register_large_cut_families();
  register_large_fans();
}

// The fan serpentines' large sizes (docs/performance.md, issue 25).
void register_large_fans() {
  for (int64_t n : {1024, 1600, 2304, 3136, 4096})
    for (auto* f : {BM_FanZonotope, BM_FanAngleTree})
      benchmark::RegisterBenchmark(f == BM_FanZonotope ? "BM_FanZonotope" : "BM_FanAngleTree", f)
          ->Args({n, 0})
          ->Iterations(1)
          ->Unit(benchmark::kMillisecond);
}

// The discrete answer's large sizes (docs/performance.md, "The discrete
// answer by the continuous decider").
void register_large_discrete_answers() {
  // The discrete answer: Auto (continuous decision) 400 .. 4 096, Pairwise
  // (subset sums on every pair) at 400, its 60 s size.
  for (int64_t n : {400, 576, 1024, 2304, 4096})
    for (int64_t c : {3, 0})
      benchmark::RegisterBenchmark("BM_DiscreteAnswerSerpentine", BM_DiscreteAnswerSerpentine)
          ->Args({n, c, 0, 0})
          ->Iterations(1)
          ->Unit(benchmark::kMillisecond);
  for (int64_t c : {3, 0})
    benchmark::RegisterBenchmark("BM_DiscreteAnswerSerpentine", BM_DiscreteAnswerSerpentine)
        ->Args({400, c, 1, 0})
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond);
}

// The band sweeps, cut across the motion, and the arc sweep, which no cut
// separates (the cell sweep, quadratic).
void register_large_cut_families() {
  for (int64_t n : {65536, 262144, 1048576})
    for (int64_t p : {1, 2, 3})
      benchmark::RegisterBenchmark("BM_BandSingleCoupling", BM_BandSingleCoupling)
          ->Args({n, 0, p})
          ->Iterations(1)
          ->Unit(benchmark::kMillisecond);
  for (int64_t n : {16384, 32768})
    benchmark::RegisterBenchmark("BM_ArcSingleCoupling", BM_ArcSingleCoupling)
        ->Args({n, 0})
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond);
}

// One coupling on one axis: the spine comb's large sizes.
void register_large_one_axis() {
  // One axis keeping its order: one sweep along it (the mixed comb's
  // 16 384 and 65 536 are with the large serpentines).
  for (int64_t n : {65536, 262144, 1048576}) {
    if (n > 65536)
      benchmark::RegisterBenchmark("BM_CombSingleCoupling", BM_CombSingleCoupling)
          ->Args({n, 0})
          ->Iterations(1)
          ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("BM_AwningCombSingleCoupling", BM_AwningCombSingleCoupling)
        ->Args({n, 0})
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond);
  }
  for (int64_t n : {65536, 262144, 1048576})  // separated groups, each keeping an order
    benchmark::RegisterBenchmark("BM_LiddedCombSingleCoupling", BM_LiddedCombSingleCoupling)
        ->Args({n, 0})
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond);
  for (int64_t n : {393216, 1572864}) {  // one piece no cut separates over (0, 1): time slabs
    benchmark::RegisterBenchmark("BM_StalactiteCombSingleCoupling", BM_StalactiteCombSingleCoupling)
        ->Args({n, 0})
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("BM_OwnSpeedStalactiteCombSingleCoupling", BM_OwnSpeedStalactiteCombSingleCoupling)
        ->Args({n, 0})
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::RegisterBenchmark("BM_StalactiteCombSingleCoupling", BM_StalactiteCombSingleCoupling)
      ->Args({24576, 5})  // the cell sweep, for the ratio
      ->Iterations(1)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("BM_AwningCombSingleCoupling", BM_AwningCombSingleCoupling)
      ->Args({65536, 5})  // the cell sweep, for the ratio
      ->Iterations(1)
      ->Unit(benchmark::kMillisecond);
  for (int64_t n : {65536, 262144, 1048576})  // one axis: the row neighbours' test
    benchmark::RegisterBenchmark("BM_SpineCombSingleCoupling", BM_SpineCombSingleCoupling)
        ->Args({n, 0})
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("BM_SpineCombSingleCoupling", BM_SpineCombSingleCoupling)
      ->Args({65536, 5})  // the sweep: about 2 minutes
      ->Iterations(1)
      ->Unit(benchmark::kMillisecond);
  for (int64_t n : {65539, 262147, 1048579})  // a YES named and checked at one moment
    benchmark::RegisterBenchmark("BM_HookSingleCoupling", BM_HookSingleCoupling)
        ->Args({n, 0})
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond);
  for (int64_t n : {65536, 262144, 1048576})  // one axis, couplings of 3: the group pairs
    for (int64_t family : {0, 1, 2})
      benchmark::RegisterBenchmark("BM_OneAxisCouplings", BM_OneAxisCouplings)
          ->Args({n, family, 0})
          ->Iterations(1)
          ->Unit(benchmark::kMillisecond);
  for (int64_t n : {65536, 262144, 1048576})  // the one-axis and kept-order certificates: written, checked
    for (int64_t family : {0, 1, 2, 3})
      for (int64_t stage : {0, 1})
        benchmark::RegisterBenchmark("BM_OneAxisCertificate", BM_OneAxisCertificate)
            ->Args({n, family, 0, stage})
            ->Iterations(1)
            ->Unit(benchmark::kMillisecond);
  for (int64_t family : {0, 1, 2})  // every pair: up to a minute at 16 384
    benchmark::RegisterBenchmark("BM_OneAxisCouplings", BM_OneAxisCouplings)
        ->Args({16384, family, 1})
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond);
  for (int64_t n : {32768, 65536, 131072, 262144})  // the diagonal sweep's YES: named, and simulated
    for (int64_t how : {0, 2})
      benchmark::RegisterBenchmark("BM_DiagonalHitSingleCoupling", BM_DiagonalHitSingleCoupling)
          ->Args({n, how})
          ->Iterations(1)
          ->Unit(benchmark::kMillisecond);
  for (int64_t n : {16387, 65539})  // the simulation that confirmed it before: minutes at 65 539
    benchmark::RegisterBenchmark("BM_HookSingleCoupling", BM_HookSingleCoupling)
        ->Args({n, 2})
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond);
}

// The serpentines' large sizes (docs/performance.md, issue 25).
void register_large_serpentines() {
  for (int64_t n : {576, 1024, 1600, 2304, 4096}) {
    for (int64_t c : {3, 0, -3})
      benchmark::RegisterBenchmark("BM_SerpentineZonotopeMixed", BM_SerpentineZonotopeMixed)
          ->Args({n, c})
          ->Iterations(1)
          ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("BM_SerpentineZonotopeColumns", BM_SerpentineZonotopeColumns)
        ->Args({n, 3})
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond);
  }
  for (int64_t c : {0, -3})  // the angle tree at n = 6 400: about the 60 s limit
    benchmark::RegisterBenchmark("BM_SerpentineAngleTreeMixed", BM_SerpentineAngleTreeMixed)
        ->Args({6400, c})
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond);
  for (int64_t n : {576, 1024, 1600, 2304, 4096}) {  // the angle tree, same sizes
    for (int64_t c : {3, 0, -3})
      benchmark::RegisterBenchmark("BM_SerpentineAngleTreeMixed", BM_SerpentineAngleTreeMixed)
          ->Args({n, c})
          ->Iterations(1)
          ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("BM_SerpentineAngleTreeColumns", BM_SerpentineAngleTreeColumns)
        ->Args({n, 3})
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond);
  }
  // n = 6 400 with couplings of 3 (mixed and axis): about the 60 s limit.
  benchmark::RegisterBenchmark("BM_SerpentineZonotopeMixed", BM_SerpentineZonotopeMixed)
      ->Args({6400, 3})
      ->Iterations(1)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("BM_SerpentineZonotopeColumns", BM_SerpentineZonotopeColumns)
      ->Args({6400, 3})
      ->Iterations(1)
      ->Unit(benchmark::kMillisecond);
  for (int64_t n : {576, 1024, 1600}) {  // the per-pair rebuild: n^3, 1600 takes ~20 s each
    for (int64_t c : {3, 0})
      benchmark::RegisterBenchmark("BM_SerpentinePerPairMixed", BM_SerpentinePerPairMixed)
          ->Args({n, c})
          ->Iterations(1)
          ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("BM_SerpentinePerPairColumns", BM_SerpentinePerPairColumns)
        ->Args({n, 3})
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond);
  }
  for (int64_t n : {16384, 65536})
    for (int64_t how : {0, 1, 2, 4})
      benchmark::RegisterBenchmark("BM_CombSingleCoupling", BM_CombSingleCoupling)
          ->Args({n, how})
          ->Iterations(1)
          ->Unit(benchmark::kMillisecond);
  for (int64_t n : {32768, 65536, 131072})
    for (int64_t how : {0, 2, 5})
      benchmark::RegisterBenchmark("BM_SerpentineSingleCoupling", BM_SerpentineSingleCoupling)
          ->Args({n, how})
          ->Iterations(1)
          ->Unit(benchmark::kMillisecond);
  for (int64_t n : {32768, 65536, 131072, 262144})
    for (int64_t how : {0, 2, 5})  // Auto, the simulation, the bare cell sweep (Auto's attempts before it)
      benchmark::RegisterBenchmark("BM_DiagonalSingleCoupling", BM_DiagonalSingleCoupling)
          ->Args({n, how})
          ->Iterations(1)
          ->Unit(benchmark::kMillisecond);
  for (int64_t n : {144, 196, 256, 400, 576})
    for (int64_t c : {3, 0})
      benchmark::RegisterBenchmark("BM_SerpentineSubsetSumMixed", BM_SerpentineSubsetSumMixed)
          ->Args({n, c})
          ->Iterations(1)
          ->Unit(benchmark::kMillisecond);
  for (int64_t n : {144, 196})  // the twin: 66 s at n = 256 with couplings of 3
    for (int64_t c : {3, 0})
      benchmark::RegisterBenchmark("BM_SerpentinePerVectorMixed", BM_SerpentinePerVectorMixed)
          ->Args({n, c})
          ->Iterations(1)
          ->Unit(benchmark::kMillisecond);
}

}  // namespace
}  // namespace gridlock

int main(int argc, char** argv) {
  const char* large = std::getenv("GRIDLOCK_BENCH_LARGE");
  if (large && std::string(large) == "1") gridlock::register_large();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
