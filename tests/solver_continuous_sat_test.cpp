// The learning engine of the continuous solver (solver/internal/continuous_sat.hpp)
// against the Z3 encoding and the quantified-Z3 twin on seeded random
// instances (every cheap shortcut off, so the engine meets every component
// it supports), and on compiled formulas against CaDiCaL through the real
// command line.
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>

#include "cnf/generate.hpp"
#include "cnf/sat_solver.hpp"
#include "lattice/grid_format.hpp"
#include "lattice/random_instance.hpp"
#include "lattice/simulate.hpp"
#include "reductions/compile.hpp"
#include "reductions/to_lsat.hpp"
#include "solver/continuous.hpp"
#include "support/cli.hpp"
#include "support/reference_continuous.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

std::string text_of(const Instance& inst) {
  std::ostringstream out;
  write_instance(out, inst);
  return out.str();
}

struct Family {
  const char* name;
  RandomInstanceParams p;
};

// Non-horizontal families with couplings of up to three operations (gaps of
// three or more couplings need several couplings in one row).
std::vector<Family> sat_families() {
  std::vector<Family> f;
  RandomInstanceParams p;
  p.nodes = 7, p.ops = 4, p.max_coupling = 2;
  f.push_back({"couplings", p});
  p = {};
  p.nodes = 8, p.ops = 5, p.max_coupling = 1;
  f.push_back({"five-couplings", p});
  p = {};
  p.nodes = 6, p.ops = 4, p.max_coupling = 1, p.allow_grow = false;
  f.push_back({"edge-ops", p});
  p = {};
  p.nodes = 6, p.ops = 4, p.max_coupling = 2, p.allow_contract = false, p.spread = 2;
  f.push_back({"growths-spread", p});
  p = {};
  p.nodes = 7, p.ops = 5, p.max_coupling = 1, p.path_shape = true;
  f.push_back({"paths", p});
  p = {};
  p.nodes = 9, p.ops = 6, p.max_coupling = 3, p.spread = 2;
  f.push_back({"six-ops", p});
  p = {};
  p.nodes = 14, p.ops = 9, p.max_coupling = 3, p.spread = 1;
  f.push_back({"nine-ops-dense", p});
  return f;
}

void expect_collision_free(const Instance& inst, const ContinuousResult& r, const std::string& what) {
  ASSERT_EQ(r.schedule.start.size(), inst.couplings().size()) << what;
  ASSERT_FALSE(check_schedule_bounds(inst, r.schedule)) << what;
  Simulator sim(inst);
  EXPECT_FALSE(sim.run(r.schedule).collision) << what;
}

// engine: SatNoShortcuts (the lazy loop) or DlNoShortcuts (Z3's difference
// logic); reports "sat" or "dl" in stats.engine.
void agrees_with_z3_and_twin(ContinuousEngine engine, const std::string& name) {
  const uint64_t seed0 = test::base_seed(20261125);
  const int per_family = test::scaled(300);
  int yes = 0, no = 0, by_sat = 0, twin_checked = 0;
  uint64_t z3_calls = 0;
  for (const Family& fam : sat_families()) {
    for (int i = 0; i < per_family; ++i) {
      const uint64_t seed = seed0 + static_cast<uint64_t>(i);
      Instance inst = random_instance(fam.p, seed);
      if (inst.horizontal_only()) continue;
      const std::string what = std::string(fam.name) + " seed " + std::to_string(seed) +
                               " (GRIDLOCK_TEST_SEED replays)\n" + text_of(inst);
      ContinuousResult s = solve_continuous_general(inst, {}, PairEncoding::Auto, engine);
      ContinuousResult z = solve_continuous_general(inst, {}, PairEncoding::Auto, ContinuousEngine::Z3);
      ASSERT_NE(s.status, Verdict::Unknown) << what;
      ASSERT_EQ(s.status, z.status) << what;
      if (s.stats.engine == name) ++by_sat;
      z3_calls += s.stats.memo_hits;
      if (s.status == Verdict::Yes) {
        expect_collision_free(inst, s, what);
        ++yes;
      } else {
        ++no;
      }
      if (inst.couplings().size() <= 5 && i % 4 == 0) {
        std::optional<bool> ref = test::reference_continuous(inst, nullptr, 20000);
        if (ref) {
          ASSERT_EQ(s.status == Verdict::Yes, *ref) << "twin: " << what;
          ++twin_checked;
        }
      }
    }
  }
  EXPECT_GT(yes, per_family / 4);
  EXPECT_GT(no, per_family / 4);
  EXPECT_GT(by_sat, per_family);  // the engine itself answered, not only its fallback
  std::printf("%s engine: %d YES, %d NO, %d decided by the engine (%llu Z3 calls), %d also against the twin\n",
              name.c_str(), yes, no, by_sat, static_cast<unsigned long long>(z3_calls), twin_checked);
}

TEST(ContinuousSat, LazyLoopAgreesWithZ3AndTwin) { agrees_with_z3_and_twin(ContinuousEngine::SatNoShortcuts, "sat"); }

// With every shortcut off, a model with an active linear rule escalates to
// Z3 on everything (QF_LRA): stats.memo_hits counts the Z3 calls (1 or 2).
TEST(ContinuousSat, DifferenceLogicAgreesWithZ3AndTwin) {
  agrees_with_z3_and_twin(ContinuousEngine::DlNoShortcuts, "dl");
}

// The default (shortcuts, then the engine) answers as the Z3 path does.
TEST(ContinuousSat, DefaultAgreesWithZ3) {
  const uint64_t seed0 = test::base_seed(20261126);
  const int per_family = test::scaled(150);
  for (const Family& fam : sat_families()) {
    for (int i = 0; i < per_family; ++i) {
      const uint64_t seed = seed0 + static_cast<uint64_t>(i);
      Instance inst = random_instance(fam.p, seed);
      ContinuousResult a = solve_continuous(inst);
      ContinuousResult z = solve_continuous_general(inst, {}, PairEncoding::Auto, ContinuousEngine::Z3);
      ASSERT_EQ(a.status, z.status) << fam.name << " seed " << seed << "\n" << text_of(inst);
    }
  }
}

// A timeout or a node limit gives Unknown and no schedule, never a wrong
// answer (both searches: the lazy loop and Z3's difference logic).
TEST(ContinuousSat, LimitsGiveUnknown) {
  const uint64_t seed0 = test::base_seed(20261127);
  for (ContinuousEngine engine : {ContinuousEngine::SatNoShortcuts, ContinuousEngine::DlNoShortcuts}) {
    int limited = 0;
    for (int i = 0; i < test::scaled(120); ++i) {
      Instance inst = random_instance(sat_families()[5].p, seed0 + static_cast<uint64_t>(i));
      ContinuousResult full = solve_continuous_general(inst, {}, PairEncoding::Auto, engine);
      SolveOptions o;
      o.max_states = 1;
      ContinuousResult lim = solve_continuous_general(inst, o, PairEncoding::Auto, engine);
      if (lim.status == Verdict::Unknown) {
        ++limited;
        EXPECT_TRUE(lim.schedule.start.empty());
      } else {
        EXPECT_EQ(lim.status, full.status);
      }
    }
    EXPECT_GE(limited, 1);
  }
}

// A compiled unsatisfiable formula that needs thousands of Z3 conflicts:
// --timeout and a node limit stop Z3 (a watcher thread interrupts it).
TEST(ContinuousSat, DifferenceLogicHonoursTimeAndNodes) {
  KSatParams p;
  p.n = 15, p.m = 64, p.k = 3, p.seed = 1;
  while (solve_sat(random_ksat(p)).status != Verdict::No) ++p.seed;
  const Formula f = random_ksat(p);
  const CompiledFormula c = compile_formula(reduce_to_lsat(f).output(), Mutation::None, TimeModel::Continuous);
  SolveOptions o;
  // 0.2 s: the whole solve took 10-20 s once and about 2.5 s on the
  // hosts of 2026-12 (a limit of 2 s was then no longer reached).
  o.seconds = 0.2;
  ContinuousResult r = solve_continuous(c.instance, o);
  EXPECT_EQ(r.status, Verdict::Unknown);
  EXPECT_LT(r.stats.seconds, 10.0);  // not a speed assertion: the limit is honoured, not how fast
  o = {};
  o.max_states = 50;
  r = solve_continuous(c.instance, o);
  EXPECT_EQ(r.status, Verdict::Unknown);
  EXPECT_LE(r.stats.refuted, 60u);
}

// Compiled formulas in-process, every shortcut off (SatNoShortcuts: the
// engine decides the whole instance, and a model with an active linear rule
// would go to Z3): the answer equals CaDiCaL's on the source formula. (No
// model of these formulas, nor of the random families above, has had an
// active linear rule so far: the Z3 conjunction check is counted, not
// asserted.)
TEST(ContinuousSat, CompiledFormulasWithoutShortcutsMatchCadical) {
  uint64_t z3_calls = 0;
  const int formulas = test::scaled(4);
  for (int s = 1; s <= formulas; ++s) {
    KSatParams p;
    p.n = 3, p.m = 4 + s % 3, p.k = 3, p.seed = 20261125 + static_cast<uint64_t>(s);
    const Formula f = random_ksat(p);
    const CompiledFormula c = compile_formula(reduce_to_lsat(f).output(), Mutation::None, TimeModel::Continuous);
    for (ContinuousEngine engine : {ContinuousEngine::SatNoShortcuts, ContinuousEngine::DlNoShortcuts}) {
      ContinuousResult r = solve_continuous_general(c.instance, {}, PairEncoding::Auto, engine);
      EXPECT_EQ(r.status, solve_sat(f).status) << "seed " << p.seed;
      if (r.status == Verdict::Yes) expect_collision_free(c.instance, r, "seed " + std::to_string(p.seed));
      z3_calls += r.stats.memo_hits;
    }
  }
  std::printf("Z3 calls: %llu\n", static_cast<unsigned long long>(z3_calls));
}

// Unsatisfiable and satisfiable formulas of 4 to 7 variables at the
// threshold, every shortcut off: Z3's difference logic decides each
// compiled instance (the lazy loop does not reach these sizes) and the
// answer equals CaDiCaL's.
TEST(ContinuousSat, DifferenceLogicDecidesLargerCompiledFormulas) {
  const int formulas = test::scaled(8);
  int unsat = 0;
  for (int s = 0; s < formulas; ++s) {
    KSatParams p;
    p.n = 4 + s % 4, p.k = 3, p.seed = 20261130 + static_cast<uint64_t>(s);
    p.m = (p.n * 426 + 50) / 100;
    const Formula f = random_ksat(p);
    const CompiledFormula c = compile_formula(reduce_to_lsat(f).output(), Mutation::None, TimeModel::Continuous);
    ContinuousResult r = solve_continuous_general(c.instance, {}, PairEncoding::Auto, ContinuousEngine::DlNoShortcuts);
    const Verdict expected = solve_sat(f).status;
    EXPECT_EQ(r.status, expected) << "n " << p.n << " seed " << p.seed;
    if (r.status == Verdict::Yes) expect_collision_free(c.instance, r, "seed " + std::to_string(p.seed));
    unsat += expected == Verdict::No;
  }
  std::printf("%d of %d unsatisfiable\n", unsat, formulas);
}

// Compiled 3-SAT formulas (through to-lsat, continuous reduction): the
// continuous answer through the real binary equals CaDiCaL's on the source.
TEST(ContinuousSat, CompiledFormulasMatchCadical) {
  const std::string dir = test::temp_dir();
  const int formulas = test::scaled(3);
  for (int s = 1; s <= formulas; ++s) {
    const std::string seed = std::to_string(20261125 + s);
    const std::string stem = dir + "/f" + seed;  // NOLINT(performance-inefficient-string-concatenation)
    const std::string cnf = stem + ".cnf", lsat = stem + ".l.cnf", grid = stem + ".grid";
    ASSERT_EQ(test::run_gridlock({"cnf", "gen", "ksat", "--n", "3", "--m", "10", "--seed", seed, "-o", cnf}).exit_code,
              0);
    ASSERT_EQ(test::run_gridlock({"cnf", "to-lsat", cnf, "-o", lsat}).exit_code, 0);
    ASSERT_EQ(test::run_gridlock({"compile", lsat, "--model", "continuous", "-o", grid}).exit_code, 0);
    const int expected = test::run_gridlock({"cnf", "solve", cnf}).exit_code;
    for (const char* engine : {"sat", "dl"}) {
      auto got = test::run_gridlock({"solve", grid, "--model", "continuous", "--engine", engine});
      EXPECT_EQ(got.exit_code, expected) << "seed " << seed << "\n" << got.out;
      if (expected == 20) {
        EXPECT_NE(got.out.find(std::string("c engine ") + engine), std::string::npos) << got.out;
      }
    }
  }
}

}  // namespace
}  // namespace gridlock
