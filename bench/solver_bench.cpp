// Solver benchmarks (docs/performance.md, "Solvers").
//  - gaps: the linear-time continuous checker on horizontal combs of 10^4 to
//    10^7 nodes; time per node should stay flat.
//  - solve vs naive: the exact discrete solver against the all-permutations
//    search (the tests' reference) on random instances with k couplings.
//  - sat: the precedence search on the constraint system of the paper's
//    gadgets for a CNF formula, written directly (no geometry): order chain
//    y_1 < .. < y_n < z_1 < .. < z_n < u_1 < .. < u_m, variable gadgets and
//    clause gadgets, couplings x_i:T, x_i:F, y_i, z_i, u_h. Runs the SATLIB
//    samples in tests/data/satlib (through to-lsat).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>
#include <numeric>

#include "cnf/dimacs.hpp"
#include "lattice/random_instance.hpp"
#include "lattice/simulate.hpp"
#include "reductions/to_lsat.hpp"
#include "solver/gaps.hpp"
#include "solver/internal/search.hpp"
#include "solver/solve.hpp"

namespace gridlock {
namespace {

// A horizontal comb: rows of width W stacked in a column joined at x = 0;
// every other node of each row expands toward +x, a few grow -x at row ends.
Instance horizontal_comb(int64_t n) {
  const int64_t W = 1000;
  const int64_t rows = std::max<int64_t>(1, n / W);
  InstanceBuilder b;
  for (int64_t y = 0; y < rows; ++y)
    for (int64_t x = 0; x < W; ++x) b.add_node({x, 2 * y});
  for (int64_t y = 0; y + 1 < rows; ++y) b.add_node({0, 2 * y + 1});
  for (int64_t y = 0; y < rows; ++y) {
    for (int64_t x = 0; x + 1 < W; ++x) b.add_edge({x, 2 * y}, {x + 1, 2 * y});
    if (y + 1 < rows) b.add_edge({0, 2 * y}, {0, 2 * y + 1}), b.add_edge({0, 2 * y + 1}, {0, 2 * y + 2});
  }
  int64_t id = 0;
  for (int64_t y = 0; y < rows; ++y)
    for (int64_t x = 1; x + 1 < W; x += 2) b.add_op("e" + std::to_string(id++), OpKind::Expand, {x, 2 * y}, Dir::PosX);
  Instance inst;
  if (auto e = b.finish(inst)) throw std::runtime_error(e->message);
  return inst;
}

void BM_Gaps(benchmark::State& state) {
  Instance inst = horizontal_comb(state.range(0));
  for (auto _ : state) {
    GapVerdict v = check_gaps(inst);
    benchmark::DoNotOptimize(v.collision_free);
  }
  const double n = static_cast<double>(inst.num_nodes());
  state.counters["nodes"] = n;
  state.counters["nodes_per_s"] = benchmark::Counter(n, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_Gaps)->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->Arg(10'000'000)->Unit(benchmark::kMillisecond);

// --- solve vs naive ------------------------------------------------------

Instance random_k(uint32_t k, bool horizontal, uint64_t seed) {
  RandomInstanceParams p;
  p.nodes = 4 * k + 4;
  p.ops = k;
  p.max_coupling = 1;
  p.horizontal_only = horizontal;
  return random_instance(p, seed);
}

bool naive(const Instance& inst, uint64_t& tried) {
  std::vector<CouplingId> order(inst.couplings().size());
  std::iota(order.begin(), order.end(), 0);
  Simulator sim(inst);
  do {
    ++tried;
    if (!sim.run_order(order).collision) return true;
  } while (std::next_permutation(order.begin(), order.end()));
  return false;
}

void BM_SolveRandom(benchmark::State& state) {
  const auto k = static_cast<uint32_t>(state.range(0));
  const bool horizontal = state.range(1) != 0;
  uint64_t states = 0, runs = 0;
  for (auto _ : state) {
    for (uint64_t seed = 1; seed <= 20; ++seed) {
      SolveResult r = solve_discrete(random_k(k, horizontal, seed));
      states += r.stats.states;
      ++runs;
    }
  }
  state.counters["states_per_instance"] = static_cast<double>(states) / static_cast<double>(runs);
}
BENCHMARK(BM_SolveRandom)->ArgsProduct({{4, 6, 8, 10, 20, 40}, {0, 1}})->Unit(benchmark::kMillisecond);

void BM_NaiveRandom(benchmark::State& state) {
  const auto k = static_cast<uint32_t>(state.range(0));
  const bool horizontal = state.range(1) != 0;
  uint64_t tried = 0, runs = 0;
  for (auto _ : state) {
    for (uint64_t seed = 1; seed <= 20; ++seed) {
      naive(random_k(k, horizontal, seed), tried);
      ++runs;
    }
  }
  state.counters["orders_per_instance"] = static_cast<double>(tried) / static_cast<double>(runs);
}
BENCHMARK(BM_NaiveRandom)->ArgsProduct({{4, 6, 8}, {0, 1}})->Unit(benchmark::kMillisecond);

// --- the gadget system of a formula, without geometry -----------------------

struct GadgetSystem {
  ConstraintSystem sys;
};

// One single-form constraint: base + sum coef * [coupling done] <= 0.
void add_form(ConstraintSystem& s, int64_t base, std::vector<std::pair<CouplingId, int64_t>> terms) {
  std::sort(terms.begin(), terms.end());
  CollisionConstraint c;
  c.num_forms = 1;
  c.base = {base};
  std::vector<int64_t> coef;
  for (auto& [q, v] : terms) {
    if (!c.rel.empty() && c.rel.back() == q) {
      coef.back() += v;
      continue;
    }
    c.rel.push_back(q);
    coef.push_back(v);
  }
  c.set_coef(coef);
  s.constraints.push_back(std::move(c));
}

ConstraintSystem gadget_system(const Formula& f) {
  const auto n = static_cast<CouplingId>(f.num_vars), m = static_cast<CouplingId>(f.clauses.size());
  // Couplings: T_i = i, F_i = n + i, y_i = 2n + i, z_i = 3n + i, u_h = 4n + h.
  auto T = [&](CouplingId i) { return i; };
  auto F = [&](CouplingId i) { return n + i; };
  auto Y = [&](CouplingId i) { return 2 * n + i; };
  auto Z = [&](CouplingId i) { return 3 * n + i; };
  auto U = [&](CouplingId h) { return 4 * n + h; };
  ConstraintSystem s;
  s.kind = ConstraintKind::Gaps;
  s.num_couplings = 4 * n + m;
  std::vector<CouplingId> chain;
  for (CouplingId i = 0; i < n; ++i) chain.push_back(Y(i));
  for (CouplingId i = 0; i < n; ++i) chain.push_back(Z(i));
  for (CouplingId h = 0; h < m; ++h) chain.push_back(U(h));
  for (size_t i = 0; i + 1 < chain.size(); ++i) add_form(s, 0, {{chain[i + 1], 1}, {chain[i], -1}});  // a < b
  for (CouplingId i = 0; i < n; ++i) {
    add_form(s, -1, {{T(i), 1}, {F(i), 1}, {Z(i), -1}});  // not both values before z_i
    add_form(s, 0, {{Y(i), 1}, {T(i), -1}, {F(i), -1}});  // some value before y_i
  }
  for (CouplingId h = 0; h < m; ++h) {
    std::vector<std::pair<CouplingId, int64_t>> t{{U(h), -1}};
    // The clause operation of literal l runs with the coupling that makes l false.
    for (int l : f.clauses[h])
      t.push_back({l > 0 ? F(static_cast<CouplingId>(l - 1)) : T(static_cast<CouplingId>(-l - 1)), 1});
    add_form(s, -static_cast<int64_t>(f.clauses[h].size()) + 1, t);
  }
  s.index();
  return s;
}

std::vector<std::string> satlib_files(const std::string& set) {
  std::vector<std::string> files;
  std::string dir = std::string(GRIDLOCK_DATA_DIR) + "/satlib/" + set;
  if (!std::filesystem::is_directory(dir)) return files;
  for (auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".cnf") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

// Every sample of a SATLIB set through to-lsat and the gadget system; reports
// the slowest sample and the total.
void BM_GadgetSystemSatlib(benchmark::State& state, const std::string& set, bool expect_sat) {
  std::vector<ConstraintSystem> systems;
  for (const std::string& path : satlib_files(set)) {
    Formula f;
    if (read_dimacs_file(path, f)) continue;
    systems.push_back(gadget_system(reduce_to_lsat(f).output()));
  }
  if (systems.empty()) {
    state.SkipWithError("no SATLIB samples");
    return;
  }
  double worst = 0;
  uint64_t states = 0, wrong = 0, unknown = 0, decisions = 0, props = 0;
  for (auto _ : state) {
    for (const ConstraintSystem& s : systems) {
      SolveOptions o;
      o.seconds = 60;
      SearchBudget budget(o);
      SolveStats st;
      SearchOutcome out;
      try {
        out = search_precedence(s, budget, st);
      } catch (const SearchBudget::LimitReached&) {
        ++unknown;
      }
      worst = std::max(worst, budget.elapsed());
      states += st.states;
      decisions += st.decisions;
      props += st.propagations;
      if (out.status != Verdict::Unknown && (out.status == Verdict::Yes) != expect_sat) ++wrong;
    }
  }
  state.counters["samples"] = static_cast<double>(systems.size());
  state.counters["worst_s"] = worst;
  state.counters["states_per_sample"] = static_cast<double>(states) /
                                        static_cast<double>(systems.size() * state.iterations());
  state.counters["wrong"] = static_cast<double>(wrong);
  state.counters["couplings"] = static_cast<double>(systems[0].num_couplings);
  state.counters["constraints"] = static_cast<double>(systems[0].constraints.size());
  state.counters["decisions_per_sample"] = static_cast<double>(decisions) / static_cast<double>(systems.size());
  state.counters["orderings_per_sample"] = static_cast<double>(props) / static_cast<double>(systems.size());
  state.counters["unknown"] = static_cast<double>(unknown);
}
BENCHMARK_CAPTURE(BM_GadgetSystemSatlib, uf20_91, std::string("uf20-91"), true)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_GadgetSystemSatlib, uf50_218, std::string("uf50-218"), true)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_GadgetSystemSatlib, uuf50_218, std::string("uuf50-218"), false)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gridlock

BENCHMARK_MAIN();
