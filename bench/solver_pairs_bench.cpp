// The exact discrete solver on general instances (every operation kind,
// vertical ones too) against a general solver on a direct encoding, in the
// same run (docs/performance.md, "General instances: engine pairs").
//
// Families:
//  - cont-uf20, cont-uf50, cont-uuf50: SATLIB formulas (tests/data/satlib)
//    through to-lsat and compile --model continuous (one vertical expansion
//    per separation gadget), solved in discrete time; the answer must be the
//    formula's (CaDiCaL on the source);
//  - tree-K, cycles-K, sparse-K, dense-K: `gridlock random --family F
//    --couplings K` (max coupling 3, every kind), seeds 1, 2, ...; the
//    answers of the engines that decide must agree;
//  - planted-F-100: the same with --planted (YES by construction).
// Engines: pairs (solve_discrete with the pairs engine; the default, auto,
// picks it for these instances), states (the states engine), z3 (Z3's C++
// API on a direct encoding of the pair constraints, z3_pair_system below;
// time includes building the constraints and the encoding).
// Environment: GRIDLOCK_BENCH_ENGINES (default pairs,z3), GRIDLOCK_BENCH_SAMPLES
// (per family, default 10), GRIDLOCK_BENCH_TIMEOUT (seconds per run, default
// 10), GRIDLOCK_BENCH_FAMILIES (comma list, default all), GRIDLOCK_BENCH_CSV
// (append one line per sample and engine).
#include <benchmark/benchmark.h>
#include <z3++.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>

#include "cnf/dimacs.hpp"
#include "cnf/sat_solver.hpp"
#include "lattice/motion.hpp"
#include "lattice/random_instance.hpp"
#include "reductions/compile.hpp"
#include "reductions/to_lsat.hpp"
#include "solver/internal/constraints.hpp"
#include "solver/planted.hpp"
#include "solver/solve.hpp"

namespace gridlock {
namespace {

using Clock = std::chrono::steady_clock;

struct Sample {
  std::string name;
  int expect = 0;  // 10 / 20 when the answer is known (SATLIB), else 0
  Instance inst;
};

std::string env_or(const char* name, const std::string& dflt) {
  const char* v = std::getenv(name);
  return v ? std::string(v) : dflt;
}
double timeout_s() { return std::atof(env_or("GRIDLOCK_BENCH_TIMEOUT", "10").c_str()); }
size_t samples_wanted() { return static_cast<size_t>(std::atol(env_or("GRIDLOCK_BENCH_SAMPLES", "10").c_str())); }
bool listed(const char* var, const std::string& dflt, const std::string& item) {
  const std::string list = "," + env_or(var, dflt) + ",";
  return list == ",all," || list.find("," + item + ",") != std::string::npos;
}

std::vector<Sample> satlib_continuous(const std::string& set) {
  std::vector<std::string> files;
  const std::string dir = std::string(GRIDLOCK_DATA_DIR) + "/satlib/" + set;
  if (std::filesystem::is_directory(dir))
    for (auto& e : std::filesystem::directory_iterator(dir))
      if (e.path().extension() == ".cnf") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  if (files.size() > samples_wanted()) files.resize(samples_wanted());
  std::vector<Sample> out;
  for (const std::string& path : files) {
    Formula f;
    if (read_dimacs_file(path, f)) continue;
    Sample s;
    s.name = std::filesystem::path(path).stem().string();
    s.expect = solve_sat(f).status == Verdict::Yes ? 10 : 20;
    s.inst = compile_formula(reduce_to_lsat(f).output(), Mutation::None, TimeModel::Continuous).instance;
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<Sample> random_family(ShapeFamily fam, uint32_t k, bool planted) {
  std::vector<Sample> out;
  RandomFamilyParams f;
  f.family = fam;
  f.couplings = k;
  for (uint64_t seed = 1; seed <= samples_wanted(); ++seed) {
    Sample s;
    s.name = std::string(planted ? "planted-" : "") + shape_family_name(fam) + "-k" + std::to_string(k) + "-s" +
             std::to_string(seed);
    if (planted) {
      s.inst = planted_family_instance(f, seed).instance;
      s.expect = 10;
    } else {
      s.inst = random_family_instance(f, seed);
    }
    out.push_back(std::move(s));
  }
  return out;
}

// 10 / 20 / 0 as the exit codes.
int code_of(Verdict v) { return v == Verdict::Yes ? 10 : v == Verdict::No ? 20 : 0; }

// Z3 on a direct encoding of the pair constraints: an integer position per
// coupling, all distinct; for every constraint and every coupling c in it,
// the state values s_i = base_i + sum_{q != c} coef_{q,i} ite(pos_q < pos_c,
// 1, 0) must not satisfy step_collides' condition, which with the constant
// coefficients c_i of c is linear: all of s_i > 0 (c_i = 0 or c_i < 0),
// s_i + c_i > 0 (c_i > 0), and s_j c_i + s_i |c_j| > 0 for c_i > 0 > c_j
// (the lower end of the open interval below the upper end).
int z3_pair_system(const ConstraintSystem& sys, double seconds) {
  z3::context ctx;
  z3::solver s(ctx);
  z3::params prm(ctx);
  prm.set("timeout", static_cast<unsigned>(seconds * 1000));
  s.set(prm);
  z3::expr_vector pos(ctx);
  const auto k = static_cast<int>(sys.num_couplings);
  for (int q = 0; q < k; ++q) {
    pos.push_back(ctx.int_const(("p" + std::to_string(q)).c_str()));
    s.add(pos[q] >= 0 && pos[q] < k);
  }
  if (k > 1) s.add(z3::distinct(pos));
  for (const CollisionConstraint& c : sys.constraints)
    for (size_t jc = 0; jc < c.rel.size(); ++jc) {
      const int64_t* cc = c.coef_of(jc);
      const z3::expr pc = pos[static_cast<int>(c.rel[jc])];
      std::vector<z3::expr> sv;
      for (uint32_t i = 0; i < c.num_forms; ++i) {
        z3::expr sum = ctx.int_val(c.base[i]);
        for (size_t j = 0; j < c.rel.size(); ++j)
          if (j != jc && c.coef_of(j)[i] != 0)
            sum = sum + z3::ite(pos[static_cast<int>(c.rel[j])] < pc, ctx.int_val(c.coef_of(j)[i]), ctx.int_val(0));
        sv.push_back(sum);
      }
      z3::expr_vector all(ctx);
      for (uint32_t i = 0; i < c.num_forms; ++i) {
        all.push_back(cc[i] > 0 ? sv[i] + ctx.int_val(cc[i]) > 0 : sv[i] > 0);
        if (cc[i] <= 0) continue;
        for (uint32_t j = 0; j < c.num_forms; ++j)
          if (cc[j] < 0) all.push_back(sv[j] * ctx.int_val(cc[i]) + sv[i] * ctx.int_val(-cc[j]) > 0);
      }
      s.add(!z3::mk_and(all));
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
  int code = 0;
  std::string how;  // engine that answered ("cycle" when no search ran)
};

Run run_engine(const std::string& e, const Sample& smp, double limit) {
  Run r;
  const auto t0 = Clock::now();
  const double c0 = cpu_now();
  if (e == "z3") {
    const PreparedInstance prep(smp.inst);
    bool breaks = false;
    for (CouplingId q = 0; q < smp.inst.couplings().size(); ++q) breaks = breaks || prep.faces.coupling_breaks_cycle[q];
    if (breaks) {  // the peer gets the same up-front cycle test (no constraints describe such an instance)
      r.code = 20;
      r.how = "cycle";
    } else {
      r.code = z3_pair_system(smp.inst.horizontal_only() ? build_gap_constraints(prep) : build_pair_constraints(prep),
                              limit);
      r.how = "z3";
    }
  } else {
    SolveOptions o;
    o.seconds = limit;
    o.engine = e == "states" ? SolveOptions::Engine::States : SolveOptions::Engine::Auto;
    const SolveResult res = solve_discrete(smp.inst, o);
    r.code = code_of(res.status);
    r.how = res.stats.engine;
  }
  r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  r.cpu = cpu_now() - c0;
  return r;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

void bench_family(benchmark::State& state, const std::string& family, const std::vector<Sample>& samples) {
  const std::vector<std::string> engines = {"pairs", "states", "z3"};
  const double limit = timeout_s();
  std::map<std::string, std::vector<Run>> runs;
  for (auto _ : state)
    for (const Sample& smp : samples)
      for (const std::string& e : engines)
        if (listed("GRIDLOCK_BENCH_ENGINES", "pairs,z3", e)) runs[e].push_back(run_engine(e, smp, limit));
  uint64_t disagree = 0, yes = 0, no = 0, by_cycle = 0;
  for (size_t i = 0; i < samples.size(); ++i) {
    int answer = samples[i].expect;
    for (auto& [e, rs] : runs) {
      const Run& r = rs[i];
      if (const char* csv = std::getenv("GRIDLOCK_BENCH_CSV")) {
        std::ofstream out(csv, std::ios::app);
        out << family << ',' << samples[i].name << ',' << samples[i].inst.couplings().size() << ',' << e << ',' << r.how
            << ',' << r.seconds << ',' << r.cpu << ',' << r.code << '\n';
      }
      if (r.code == 0) continue;
      if (answer != 0 && answer != r.code) ++disagree;
      answer = r.code;
    }
    (answer == 10 ? yes : answer == 20 ? no : disagree) += answer == 0 ? 0 : 1;
    if (!runs.empty() && runs.begin()->second[i].how == "cycle") ++by_cycle;
  }
  if (disagree > 0) state.SkipWithError("engines disagree (or differ from the formula)");
  for (auto& [e, rs] : runs) {
    std::vector<double> t;
    double worst = 0;
    uint64_t unknown = 0;
    for (const Run& r : rs) {
      t.push_back(r.cpu);
      worst = std::max(worst, r.cpu);
      unknown += r.code == 0;
    }
    state.counters[e + "_median_cpu_s"] = median(t);
    state.counters[e + "_max_cpu_s"] = worst;
    state.counters[e + "_unknown"] = static_cast<double>(unknown);
  }
  double couplings = 0;
  for (const Sample& s : samples) couplings += static_cast<double>(s.inst.couplings().size());
  state.counters["couplings"] = samples.empty() ? 0 : couplings / static_cast<double>(samples.size());
  state.counters["samples"] = static_cast<double>(samples.size());
  state.counters["yes"] = static_cast<double>(yes);
  state.counters["no"] = static_cast<double>(no);
  state.counters["no_by_cycle"] = static_cast<double>(by_cycle);
}

void register_all() {
  for (const char* set : {"uf20-91", "uf50-218", "uuf50-218"}) {
    const std::string family = std::string("cont-") + set;
    if (!listed("GRIDLOCK_BENCH_FAMILIES", "all", family)) continue;
    benchmark::RegisterBenchmark(
        family.c_str(), [family, set](benchmark::State& st) { bench_family(st, family, satlib_continuous(set)); })
        ->Iterations(1)
        ->Unit(benchmark::kSecond);
  }
  for (ShapeFamily fam : {ShapeFamily::Tree, ShapeFamily::Cycles, ShapeFamily::Sparse, ShapeFamily::Dense})
    for (uint32_t k : {100U, 300U, 1000U})
      for (bool planted : {false, true}) {
        const std::string family = std::string(planted ? "planted-" : "") + shape_family_name(fam) + "-" +
                                   std::to_string(k);
        // Planting builds the pair constraints of an instance 2-4 times
        // larger: seconds at 300 couplings, minutes at 1000 (docs/performance.md).
        if ((planted && k > 100) || !listed("GRIDLOCK_BENCH_FAMILIES", "all", family)) continue;
        benchmark::RegisterBenchmark(family.c_str(),
                                     [family, fam, k, planted](benchmark::State& st) {
                                       bench_family(st, family, random_family(fam, k, planted));
                                     })
            ->Iterations(1)
            ->Unit(benchmark::kSecond);
      }
}

}  // namespace
}  // namespace gridlock

int main(int argc, char** argv) {
  gridlock::register_all();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
