// The learning precedence engine (solver/search_precedence.cpp) against its
// twins: every permutation, the chronological precedence engine and the SAT
// engine on random gap systems and on the gap systems of random horizontal
// instances; every nogood it learns is checked to hold in every
// collision-free order there; on the SATLIB samples compiled through to-lsat
// it agrees with CaDiCaL on the source formula.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "cnf/dimacs.hpp"
#include "cnf/generate.hpp"
#include "cnf/sat_solver.hpp"
#include "common/random.hpp"
#include "lattice/prepared.hpp"
#include "lattice/random_instance.hpp"
#include "reductions/compile.hpp"
#include "reductions/to_lsat.hpp"
#include "solver/internal/search.hpp"
#include "solver/solve.hpp"
#include "support/cnf_testing.hpp"
#include "support/random_gap_system.hpp"
#include "support/search_precedence_chronological.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

using Status = Verdict;
using Edges = std::vector<std::pair<CouplingId, CouplingId>>;

// A random gap system unlike solver_sat_test's: more gaps (up to 10), heavier
// coefficients ([-4, 4] \ {0}), gaps over few couplings more often (so pairs
// recur across gaps and cycles through several gaps arise).
ConstraintSystem random_system(Rng& rng, size_t k) {
  return test::random_gap_system(rng, k, {.max_gaps = 10, .sometimes_three = true, .min_base = -5, .max_coef = 4});
}

// Every collision-free order (positions: pos[q] of each), by all permutations.
std::vector<std::vector<size_t>> all_solutions(const ConstraintSystem& s) {
  std::vector<std::vector<size_t>> out;
  std::vector<CouplingId> order(s.num_couplings);
  std::iota(order.begin(), order.end(), 0);
  do {
    if (replay_order(s, order).failed_step != order.size()) continue;
    std::vector<size_t> pos(order.size());
    for (size_t i = 0; i < order.size(); ++i) pos[order[i]] = i;
    out.push_back(std::move(pos));
  } while (std::next_permutation(order.begin(), order.end()));
  return out;
}

bool satisfies(const std::vector<size_t>& pos, const Edges& nogood) {
  return std::any_of(nogood.begin(), nogood.end(), [&](auto e) { return pos[e.first] < pos[e.second]; });
}

struct Learned {
  std::vector<Edges> nogoods;
  PrecedenceHooks hooks;
  Learned() {
    hooks.on_learned = [this](const Edges& e) { nogoods.push_back(e); };
  }
};

SearchOutcome run_learning(const ConstraintSystem& s, Learned* learned = nullptr) {
  SolveOptions o;
  SearchBudget budget(o);
  SolveStats st;
  return search_precedence(s, budget, st, learned ? &learned->hooks : nullptr);
}

struct Tally {
  int yes = 0, no = 0;
  size_t nogoods = 0;
};

// One system: the learning engine against all permutations, its twins, and
// its own nogoods. where: what to print on a failure (family, seed, case).
void cross_check(const ConstraintSystem& s, const std::string& where, Tally& t) {
  const auto sols = all_solutions(s);
  Learned learned;
  const SearchOutcome out = run_learning(s, &learned);
  ASSERT_EQ(out.status == Status::Yes, !sols.empty()) << where;
  if (out.status == Status::Yes) {
    ASSERT_EQ(out.order.size(), s.num_couplings) << where;
    EXPECT_EQ(replay_order(s, out.order).failed_step, s.num_couplings) << where;
  }
  SolveOptions o;
  SearchBudget budget(o);
  SolveStats st;
  EXPECT_EQ(search_precedence_chronological(s, budget, st).status, out.status) << where << " (chronological)";
  EXPECT_EQ(search_sat(s, budget, st).status, out.status) << where << " (sat)";
  for (const Edges& ng : learned.nogoods) {
    ASSERT_FALSE(ng.empty()) << where;
    for (const auto& pos : sols) ASSERT_TRUE(satisfies(pos, ng)) << where << ": a learned nogood is not implied";
  }
  t.nogoods += learned.nogoods.size();
  (sols.empty() ? t.no : t.yes) += 1;
}

TEST(LearnEngine, RandomGapSystemsAgreeAndNogoodsAreImplied) {
  const uint64_t seed = test::base_seed(7300);
  Rng rng(seed);
  const int count = test::scaled(2000);
  Tally t;
  for (int i = 0; i < count; ++i) {
    const auto k = static_cast<size_t>(rng.between(2, 7));
    cross_check(random_system(rng, k), "seed " + std::to_string(seed) + " case " + std::to_string(i), t);
    if (::testing::Test::HasFatalFailure()) return;
  }
  // Both answers, and learning itself, must be exercised.
  EXPECT_GT(t.yes, count / 10);
  EXPECT_GT(t.no, count / 10);
  EXPECT_GT(t.nogoods, static_cast<size_t>(count / 100));
  std::printf("[ learn-gap-systems ] %d systems: %d YES, %d NO, %zu nogoods checked (seed %llu)\n", count, t.yes, t.no,
              t.nogoods, static_cast<unsigned long long>(seed));
}

// Tight systems: gaps over 2..4 of 8 couplings whose bases are the lowest a
// hidden random order survives (in half of the systems one raised by 1,
// so that the hidden order fails there): near the YES/NO boundary, so that the search
// goes past level 0 and learns (40320 orders each for the reference).
ConstraintSystem tight_system(Rng& rng, size_t k, size_t gaps) {
  std::vector<CouplingId> hidden(k);
  std::iota(hidden.begin(), hidden.end(), 0);
  rng.shuffle(hidden);
  std::vector<size_t> pos(k);
  for (size_t i = 0; i < k; ++i) pos[hidden[i]] = i;
  ConstraintSystem s = random_system(rng, k);
  s.constraints.clear();
  const bool raise = rng.coin();
  for (size_t g = 0; g < gaps; ++g) {
    CollisionConstraint c = random_system(rng, k).constraints[0];
    std::vector<size_t> by_pos(c.rel.size());
    std::iota(by_pos.begin(), by_pos.end(), 0);
    std::sort(by_pos.begin(), by_pos.end(), [&](size_t x, size_t y) { return pos[c.rel[x]] < pos[c.rel[y]]; });
    int64_t sum = 0, peak = 0;
    for (size_t j : by_pos) {
      sum += c.coef_of(j)[0];
      if (c.coef_of(j)[0] > 0) peak = std::max(peak, sum);
    }
    c.base = {-peak + (g == 0 && raise ? 1 : 0)};
    s.constraints.push_back(std::move(c));
  }
  s.index();
  return s;
}

TEST(LearnEngine, TightSystemsLearnImpliedNogoods) {
  const uint64_t seed = test::base_seed(7400);
  Rng rng(seed);
  const int count = test::scaled(100);
  Tally t;
  for (int i = 0; i < count; ++i) {
    cross_check(tight_system(rng, 8, 6 + rng.below(10)), "seed " + std::to_string(seed) + " case " + std::to_string(i),
                t);
    if (::testing::Test::HasFatalFailure()) return;
  }
  EXPECT_GT(t.yes, count / 10);
  EXPECT_GT(t.no, count / 10);
  EXPECT_GT(t.nogoods, 0u);  // about one a system at full scale
  std::printf("[ learn-tight ] %d systems: %d YES, %d NO, %zu nogoods checked (seed %llu)\n", count, t.yes, t.no,
              t.nogoods, static_cast<unsigned long long>(seed));
}

// Gap systems of random horizontal instances (those no coupling of which
// breaks a cycle; at most 7 couplings).
TEST(LearnEngine, RandomHorizontalInstances) {
  const uint64_t base = test::base_seed(410000);
  const int count = test::scaled(1500);
  Tally t;
  for (int i = 0; i < count; ++i) {
    const uint64_t seed = base + static_cast<uint64_t>(i);
    Rng draw(derive_seed(seed, 1));
    RandomInstanceParams p;
    p.nodes = 4 + static_cast<uint32_t>(draw.below(12));
    p.ops = 3 + static_cast<uint32_t>(draw.below(5));
    p.max_coupling = 1 + static_cast<uint32_t>(draw.below(3));
    p.extra_edge_percent = static_cast<uint32_t>(draw.below(2) * 30);
    p.horizontal_only = true;
    const Instance inst = random_instance(p, seed);
    if (inst.couplings().size() > 7 || inst.couplings().size() < 2) continue;
    const PreparedInstance prep(inst);
    const auto& breaks = prep.faces.coupling_breaks_cycle;
    if (std::find(breaks.begin(), breaks.end(), true) != breaks.end()) continue;
    cross_check(build_gap_constraints(prep), "instance seed " + std::to_string(seed), t);
    if (::testing::Test::HasFatalFailure()) return;
  }
  EXPECT_GT(t.yes, 0);
  EXPECT_GT(t.no, 0);
  std::printf("[ learn-horizontal ] %d instances: %d YES, %d NO, %zu nogoods checked (seeds %llu..)\n", t.yes + t.no,
              t.yes, t.no, t.nogoods, static_cast<unsigned long long>(base));
}

// The gap "a before b": a widens by 1 what b narrows by 1, base 0.
CollisionConstraint before_gap(CouplingId a, CouplingId b) {
  CollisionConstraint c;
  c.num_forms = 1;
  c.base = {0};
  c.rel = {std::min(a, b), std::max(a, b)};
  c.set_coef(a < b ? std::vector<int64_t>{-1, 1} : std::vector<int64_t>{1, -1});
  return c;
}

// A ring of n such gaps (i before i + 1, and n - 1 before 0) is NO only
// through a cycle of n literals, which the search finds only when all are
// set; open (the last gap left out) it is YES in exactly one order.
TEST(LearnEngine, RingOfGapsIsOneLongCycle) {
  for (CouplingId n : {2u, 3u, 10u, 300u})
    for (bool closed : {false, true}) {
      ConstraintSystem s;
      s.kind = ConstraintKind::Gaps;
      s.num_couplings = n;
      for (CouplingId i = 0; i + 1 < n; ++i) s.constraints.push_back(before_gap(i, i + 1));
      if (closed) s.constraints.push_back(before_gap(n - 1, 0));
      s.index();
      const SearchOutcome out = run_learning(s);
      ASSERT_EQ(out.status, closed ? Status::No : Status::Yes) << n;
      std::vector<CouplingId> expect(closed ? 0 : n);
      std::iota(expect.begin(), expect.end(), 0);
      EXPECT_EQ(out.order, expect) << n;
    }
}

// The node budget stops the search itself (LimitReached, counted in
// decisions and conflicts); the clock stops solve_discrete in time.
TEST(LearnEngine, LimitsStopTheSearch) {
  Formula f;
  ASSERT_FALSE(read_dimacs_file(GRIDLOCK_DATA_DIR "/satlib/uuf50-218/uuf50-02.cnf", f));
  const Instance inst = compile_formula(reduce_to_lsat(f).output()).instance;
  const PreparedInstance prep(inst);  // keeps a reference to inst
  const ConstraintSystem sys = build_gap_constraints(prep);
  SolveOptions o;
  o.max_states = 5;
  SearchBudget budget(o);
  SolveStats st;
  EXPECT_THROW(search_precedence(sys, budget, st), SearchBudget::LimitReached);
  EXPECT_EQ(st.states, 6u);
  SolveOptions timed;
  timed.engine = SolveOptions::Engine::Precedence;
  timed.seconds = 0.02;
  const SolveResult r = solve_discrete(prep, timed);
  EXPECT_EQ(r.status, Status::Unknown);
  EXPECT_LT(r.stats.seconds, 0.02 * 1.1 + 0.05);
}

// Every SATLIB sample of one folder through to-lsat and compile: the
// learning engine agrees with CaDiCaL on the source formula and the label
// (a YES order passed the simulator inside solve_discrete). On every tenth
// satisfiable sample every learned nogood also holds in the SAT engine's
// witness order (an independent solution). A spread subset under a scale < 1.
void satlib_folder(const std::string& folder) {
  std::vector<test::SatlibFile> files;
  for (const auto& file : test::satlib_files())
    if (file.path.find("/" + folder + "/") != std::string::npos) files.push_back(file);
  ASSERT_EQ(files.size(), 100u) << folder;
  const auto want = static_cast<size_t>(test::scaled(100));
  size_t checked = 0, witnessed = 0, nogoods = 0;
  for (size_t i = 0; i < files.size(); ++i) {
    if (want < files.size() && (i * want) % files.size() >= want) continue;
    Formula f;
    ASSERT_FALSE(read_dimacs_file(files[i].path, f)) << files[i].path;
    const bool sat = solve_sat(f).status == Verdict::Yes;
    ASSERT_EQ(sat, files[i].sat) << files[i].path;
    const Instance inst = compile_formula(reduce_to_lsat(f).output()).instance;
    const PreparedInstance prep(inst);
    SolveOptions o;
    o.engine = SolveOptions::Engine::Precedence;
    const SolveResult r = solve_discrete(prep, o);
    ASSERT_EQ(r.stats.engine, "precedence");
    ASSERT_NE(r.status, Status::Unknown) << files[i].path;
    ASSERT_EQ(r.status == Status::Yes, sat) << files[i].path;
    ++checked;
    if (!sat || i % 10 != 0) continue;
    const ConstraintSystem sys = build_gap_constraints(prep);
    Learned learned;
    SearchBudget budget(o);
    SolveStats st;
    ASSERT_EQ(search_precedence(sys, budget, st, &learned.hooks).status, Status::Yes) << files[i].path;
    const SearchOutcome witness = search_sat(sys, budget, st);
    std::vector<size_t> pos(sys.num_couplings);
    for (size_t p = 0; p < witness.order.size(); ++p) pos[witness.order[p]] = p;
    for (const Edges& ng : learned.nogoods) ASSERT_TRUE(satisfies(pos, ng)) << files[i].path;
    nogoods += learned.nogoods.size();
    ++witnessed;
  }
  std::printf("[ learn-satlib ] %s: %zu samples agree with CaDiCaL; %zu nogoods of %zu SAT samples hold in a witness\n",
              folder.c_str(), checked, nogoods, witnessed);
}

TEST(LearnEngine, SatlibUf20AgreesWithCadical) { satlib_folder("uf20-91"); }
TEST(LearnEngine, SatlibUf50AgreesWithCadical) { satlib_folder("uf50-218"); }
TEST(LearnEngine, SatlibUuf50AgreesWithCadical) { satlib_folder("uuf50-218"); }

// Random 3-SAT at the threshold with 100 variables (seeds 4, NO, and 6, YES,
// of `cnf gen ksat --n 100 --m 430`: 3 300 and 5 700 conflicts, so that the
// deletion of learned nogoods, which starts at 2 000 live ones, runs): the
// learning engine agrees with CaDiCaL on the source formula.
TEST(LearnEngine, Random100AgreesWithCadicalThroughDeletion) {
  const std::vector<uint64_t> seeds = {4, 6};
  const auto want = static_cast<size_t>(test::scaled(2));
  for (size_t i = 0; i < seeds.size() && i < want; ++i) {
    KSatParams p;
    p.n = 100;
    p.m = 430;
    p.seed = seeds[i];
    const Formula f = random_ksat(p);
    const bool sat = solve_sat(f).status == Verdict::Yes;
    const Instance inst = compile_formula(reduce_to_lsat(f).output()).instance;
    SolveOptions o;
    o.engine = SolveOptions::Engine::Precedence;
    const SolveResult r = solve_discrete(inst, o);
    ASSERT_NE(r.status, Status::Unknown) << "seed " << seeds[i];
    EXPECT_EQ(r.status == Status::Yes, sat) << "seed " << seeds[i];
    EXPECT_GT(r.stats.refuted, 2000u) << "seed " << seeds[i] << ": deletion never ran";
  }
}

}  // namespace
}  // namespace gridlock
