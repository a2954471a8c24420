// The exact discrete solver's engines on compiled 3-SAT formulas, against
// what a user would otherwise pick, in the same run (docs/performance.md,
// "Solvers: engines on compiled formulas").
//
// Each formula goes through to-lsat and compile (the paper's reduction) to a
// horizontal-only lattice instance; per sample and engine the time of
// solve_discrete (constraints, search, and the simulator's check of a YES)
// is measured, and the answer is checked against CaDiCaL on the source
// formula. Twins in the same run:
//  - z3: a general SMT solver (Z3's C++ API) on a direct encoding of the
//    same gap system (z3_gap_system below); time includes building the gap
//    system and the encoding;
//  - cadical: CaDiCaL on the source formula.
// Families: the SATLIB samples (tests/data/satlib) and random 3-SAT at the
// threshold with 75 and 100 variables (the first 20 satisfiable and 20
// unsatisfiable formulas of seeds 1, 2, ...; m = 325 and 430 as SATLIB's
// uf75-325 and uf100-430).
//
// Engines: sat (CaDiCaL on the gap system), precedence (the learning
// precedence engine), chrono (the chronological precedence engine, the
// "before" of issue 15; search only, on the gap system), z3, cadical.
// Environment: GRIDLOCK_BENCH_ENGINES (comma list of sat, precedence, chrono,
// z3, cadical; default sat,precedence,z3,cadical), GRIDLOCK_BENCH_SAMPLES (per family,
// default all), GRIDLOCK_BENCH_TIMEOUT (seconds per run, default 60),
// GRIDLOCK_BENCH_CSV (append one line per sample and engine to this file).
#include <benchmark/benchmark.h>
#include <z3++.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "cnf/dimacs.hpp"
#include "cnf/generate.hpp"
#include "cnf/sat_solver.hpp"
#include "lattice/motion.hpp"
#include "reductions/compile.hpp"
#include "reductions/to_lsat.hpp"
#include "solver/internal/constraints.hpp"
#include "solver/internal/search.hpp"
#include "solver/solve.hpp"
#include "support/search_precedence_chronological.hpp"

namespace gridlock {
namespace {

using Clock = std::chrono::steady_clock;

struct Sample {
  std::string name;
  Formula source;
  bool sat = false;  // CaDiCaL on the source
  Instance inst;
};

std::string env_or(const char* name, const std::string& dflt) {
  const char* v = std::getenv(name);
  return v ? std::string(v) : dflt;
}
double timeout_s() { return std::atof(env_or("GRIDLOCK_BENCH_TIMEOUT", "60").c_str()); }
bool engine_on(const std::string& e) {
  const std::string list = "," + env_or("GRIDLOCK_BENCH_ENGINES", "sat,precedence,z3,cadical") + ",";
  return list.find("," + e + ",") != std::string::npos;
}

Sample make_sample(const std::string& name, Formula f) {
  Sample s;
  s.name = name;
  s.sat = solve_sat(f).status == Verdict::Yes;
  s.inst = compile_formula(reduce_to_lsat(f).output()).instance;
  s.source = std::move(f);
  return s;
}

std::vector<Sample> satlib(const std::string& set) {
  std::vector<std::string> files;
  const std::string dir = std::string(GRIDLOCK_DATA_DIR) + "/satlib/" + set;
  if (std::filesystem::is_directory(dir))
    for (auto& e : std::filesystem::directory_iterator(dir))
      if (e.path().extension() == ".cnf") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  const size_t limit = static_cast<size_t>(std::atol(env_or("GRIDLOCK_BENCH_SAMPLES", "0").c_str()));
  if (limit > 0 && files.size() > limit) files.resize(limit);
  std::vector<Sample> out;
  for (const std::string& path : files) {
    Formula f;
    if (read_dimacs_file(path, f)) continue;
    out.push_back(make_sample(std::filesystem::path(path).stem().string(), std::move(f)));
  }
  return out;
}

// The first `each` satisfiable and `each` unsatisfiable formulas of seeds 1, 2, ...
std::vector<Sample> random_threshold(int n, int m, size_t each) {
  const size_t limit = static_cast<size_t>(std::atol(env_or("GRIDLOCK_BENCH_SAMPLES", "0").c_str()));
  if (limit > 0) each = std::min(each, (limit + 1) / 2);
  std::vector<Sample> out;
  size_t sat = 0, unsat = 0;
  for (uint64_t seed = 1; sat < each || unsat < each; ++seed) {
    KSatParams p;
    p.n = n;
    p.m = m;
    p.seed = seed;
    Formula f = random_ksat(p);
    const bool is_sat = solve_sat(f).status == Verdict::Yes;
    if ((is_sat && sat >= each) || (!is_sat && unsat >= each)) continue;
    (is_sat ? sat : unsat) += 1;
    out.push_back(make_sample("n" + std::to_string(n) + "-seed" + std::to_string(seed), std::move(f)));
  }
  return out;
}

// Z3 on a direct encoding of the gap system. 10 = sat, 20 = unsat, 0 = unknown.
// Integer positions; for two couplings that share a gap a Boolean o = "the
// first before the second", o -> pos_a < pos_b and not o -> pos_b < pos_a
// (difference constraints; ties between couplings that share no gap can be
// broken either way); for every narrower t of every gap
//   base + coef_t + sum_{u != t} coef_u * ite(pos_u < pos_t, 1, 0) <= 0.
// (Z3's native pseudo-Boolean constraints over the order literals were
// slower and overran the timeout.)
int z3_gap_system(const ConstraintSystem& sys, double seconds) {
  z3::context ctx;
  z3::solver s(ctx);
  z3::params prm(ctx);
  prm.set("timeout", static_cast<unsigned>(seconds * 1000));
  s.set(prm);
  z3::expr_vector pos(ctx);
  for (size_t q = 0; q < sys.num_couplings; ++q) pos.push_back(ctx.int_const(("p" + std::to_string(q)).c_str()));
  std::map<std::pair<CouplingId, CouplingId>, z3::expr> order;
  auto before = [&](CouplingId a, CouplingId b) -> z3::expr {
    const CouplingId lo = std::min(a, b), hi = std::max(a, b);
    auto it = order.find({lo, hi});
    if (it == order.end()) {
      z3::expr o = ctx.bool_const(("o" + std::to_string(lo) + "_" + std::to_string(hi)).c_str());
      const z3::expr pl = pos[static_cast<int>(lo)], ph = pos[static_cast<int>(hi)];
      s.add(z3::implies(o, pl < ph));
      s.add(z3::implies(!o, ph < pl));
      it = order.emplace(std::make_pair(lo, hi), o).first;
    }
    return a == lo ? it->second : !it->second;
  };
  for (const CollisionConstraint& c : sys.constraints) {
    if (c.base[0] > 0) return 20;
    for (size_t jt = 0; jt < c.rel.size(); ++jt) {
      const int64_t at = c.coef_of(jt)[0];
      if (at <= 0) continue;
      const CouplingId t = c.rel[jt];
      z3::expr sum = ctx.int_val(c.base[0] + at);
      for (size_t j = 0; j < c.rel.size(); ++j) {
        if (j == jt) continue;
        before(c.rel[j], t);  // keeps the two positions apart
        sum = sum + z3::ite(pos[static_cast<int>(c.rel[j])] < pos[static_cast<int>(t)], ctx.int_val(c.coef_of(j)[0]),
                            ctx.int_val(0));
      }
      s.add(sum <= 0);
    }
  }
  switch (s.check()) {
    case z3::sat: return 10;
    case z3::unsat: return 20;
    default: return 0;
  }
}

double cpu_now() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

struct Run {
  double seconds = 0, cpu = 0;
  uint64_t decisions = 0;
  int code = 0;  // 10, 20, 0
};

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// Runs the chronological precedence engine (search only) on smp's gap
// system; fills r's code and decisions.
void run_chrono(const Sample& smp, double limit, Run& r) {
  const ConstraintSystem sys = build_gap_constraints(smp.inst, SpanningTree::build(smp.inst));
  SolveOptions o;
  o.seconds = limit;
  SearchBudget budget(o);
  SolveStats st;
  try {
    const SearchOutcome out = search_precedence_chronological(sys, budget, st);
    r.code = out.status == Verdict::Yes ? 10 : 20;
  } catch (const SearchBudget::LimitReached&) {
    r.code = 0;
  }
  r.decisions = st.decisions;
}

// One timed run of engine e on smp (wall and CPU time, decisions, answer).
Run run_engine(const std::string& e, const Sample& smp, double limit) {
  Run r;
  const auto t0 = Clock::now();
  const double c0 = cpu_now();
  if (e == "sat" || e == "precedence") {
    SolveOptions o;
    o.seconds = limit;
    o.engine = e == "sat" ? SolveOptions::Engine::Sat : SolveOptions::Engine::Precedence;
    SolveResult res = solve_discrete(smp.inst, o);
    r.decisions = res.stats.decisions;
    r.code = exit_code(res.status);
  } else if (e == "chrono") {
    run_chrono(smp, limit, r);
  } else if (e == "z3") {
    const ConstraintSystem sys = build_gap_constraints(smp.inst, SpanningTree::build(smp.inst));
    r.code = z3_gap_system(sys, limit);
  } else {
    SatLimits lim;
    lim.seconds = limit;
    SatResult sr = solve_sat(smp.source, lim);
    r.code = sr.status == Verdict::Yes ? 10 : sr.status == Verdict::No ? 20 : 0;
  }
  r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  r.cpu = cpu_now() - c0;
  return r;
}

// Appends one CSV line for run r to GRIDLOCK_BENCH_CSV, if set.
void append_csv(const std::string& family, const Sample& smp, const std::string& e, const Run& r) {
  if (const char* csv = std::getenv("GRIDLOCK_BENCH_CSV")) {
    std::ofstream out(csv, std::ios::app);
    out << family << ',' << smp.name << ',' << (smp.sat ? "SAT" : "UNSAT") << ',' << e << ',' << r.seconds << ','
        << r.cpu << ',' << r.decisions << ',' << r.code << '\n';
  }
}

// Sets engine e's counters (times, wrong and unknown answers, decisions)
// from its runs rs, run i being on samples[i % samples.size()].
void report_engine(benchmark::State& state, const std::string& e, const std::vector<Run>& rs,
                   const std::vector<Sample>& samples) {
  std::vector<double> t, cpu;
  double total = 0, worst = 0;
  uint64_t dec = 0, wrong = 0, unknown = 0;
  for (size_t i = 0; i < rs.size(); ++i) {
    const Sample& smp = samples[i % samples.size()];
    t.push_back(rs[i].seconds);
    cpu.push_back(rs[i].cpu);
    total += rs[i].seconds;
    worst = std::max(worst, rs[i].seconds);
    dec += rs[i].decisions;
    if (rs[i].code == 0) ++unknown;
    else if ((rs[i].code == 10) != smp.sat) ++wrong;
  }
  state.counters[e + "_median_s"] = median(t);
  state.counters[e + "_max_s"] = worst;
  state.counters[e + "_cpu_median_s"] = median(cpu);
  state.counters[e + "_cpu_max_s"] = *std::max_element(cpu.begin(), cpu.end());
  state.counters[e + "_wrong"] = static_cast<double>(wrong);
  state.counters[e + "_unknown"] = static_cast<double>(unknown);
  if (dec > 0) {
    state.counters[e + "_decisions"] = static_cast<double>(dec) / static_cast<double>(rs.size());
    state.counters[e + "_ms_per_decision"] = 1000 * total / static_cast<double>(dec);
  }
}

// Sets the counter of the worst per-sample time ratio of engine a over
// engine b (same sample, same run), if both ran.
void report_worst_ratio(benchmark::State& state, const std::map<std::string, std::vector<Run>>& runs,
                        const std::string& a, const std::string& b) {
  if (!runs.count(a) || !runs.count(b)) return;
  const std::vector<Run>& ra = runs.at(a);
  const std::vector<Run>& rb = runs.at(b);
  double worst = 0;
  for (size_t i = 0; i < ra.size(); ++i) worst = std::max(worst, ra[i].seconds / std::max(rb[i].seconds, 1e-9));
  state.counters[a + "_over_" + b + "_max"] = worst;
}

void run_family(benchmark::State& state, const std::string& family, const std::vector<Sample>& samples) {
  if (samples.empty()) {
    state.SkipWithError("no samples");
    return;
  }
  const std::vector<std::string> engines = {"sat", "precedence", "chrono", "z3", "cadical"};
  std::map<std::string, std::vector<Run>> runs;
  const double limit = timeout_s();
  for (auto _ : state) {
    for (const Sample& smp : samples) {
      for (const std::string& e : engines) {
        if (!engine_on(e)) continue;
        const Run r = run_engine(e, smp, limit);
        runs[e].push_back(r);
        append_csv(family, smp, e, r);
      }
    }
  }
  state.counters["samples"] = static_cast<double>(samples.size());
  state.counters["couplings"] = static_cast<double>(samples[0].inst.couplings().size());
  for (auto& [e, rs] : runs) report_engine(state, e, rs, samples);
  // Worst per-sample ratio of the default engine against Z3 (same sample,
  // same run), and of the learning engine against Z3, CaDiCaL and the sat
  // engine.
  report_worst_ratio(state, runs, "sat", "z3");
  report_worst_ratio(state, runs, "precedence", "z3");
  report_worst_ratio(state, runs, "precedence", "sat");
  report_worst_ratio(state, runs, "precedence", "cadical");
}

void BM_Satlib(benchmark::State& state, const std::string& set) { run_family(state, set, satlib(set)); }
void BM_Random3Sat(benchmark::State& state, int n, int m) {
  run_family(state, "n" + std::to_string(n) + "-m" + std::to_string(m), random_threshold(n, m, 20));
}

BENCHMARK_CAPTURE(BM_Satlib, uf20_91, std::string("uf20-91"))->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(BM_Satlib, uf50_218, std::string("uf50-218"))->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(BM_Satlib, uuf50_218, std::string("uuf50-218"))->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(BM_Random3Sat, n75_m325, 75, 325)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(BM_Random3Sat, n100_m430, 100, 430)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
}  // namespace gridlock

BENCHMARK_MAIN();
