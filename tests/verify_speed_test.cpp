// The reusable Verifier (verify/verify.hpp) against its twin, a fresh
// verify_formula per formula: one Verifier running formula after formula
// (its simulator rebound from instance to instance) must give exactly the
// same result, field by field, for every kind of fuzz formula and model, and
// when a broken gadget makes the checks disagree.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "support/test_scale.hpp"
#include "verify/fuzz.hpp"
#include "verify/verify.hpp"

namespace gridlock {
namespace {

const char* check_name(Check c) { return c == Check::None ? "none" : c == Check::Valid ? "valid" : "INVALID"; }

// Everything verify decides about a formula (not the timings).
std::string summary(const VerifyResult& r) {
  std::ostringstream o;
  o << r.name << " reduced " << r.reduced << " lsat " << r.lsat.num_vars << "/" << r.lsat.clauses.size() << " nodes "
    << r.nodes << " ops " << r.ops << " couplings " << r.couplings << " max " << r.max_coupling << " cnodes "
    << r.cnodes << " | sat " << verdict_name(r.sat) << " discrete " << verdict_name(r.discrete) << " gaps "
    << verdict_name(r.continuous) << " csolver " << verdict_name(r.continuous_solver) << " | witnesses "
    << check_name(r.sat_witness) << " " << check_name(r.solver_witness) << " " << check_name(r.gaps_witness) << " "
    << check_name(r.csat_witness) << " " << check_name(r.csolver_witness) << " | ran " << r.ran_discrete
    << r.ran_continuous << " states " << r.solver_states << " | agree " << r.agree << " " << r.problem << " |";
  for (const auto& v : {r.sat_schedule, r.solver_schedule, r.csat_times, r.csolver_times}) {
    for (const auto& x : v) o << " " << x;
    o << " /";
  }
  return o.str();
}

// Runs formulas 0 .. count-1 of the campaign (seed, 1 .. max_vars variables,
// kinds) through a fresh verify_formula and one reused Verifier; returns how
// many disagreed.
int same_results(uint64_t seed, int max_vars, std::vector<FuzzKind> kinds, VerifyOptions opt, int count) {
  FuzzParams p;
  p.seed = test::base_seed(seed);
  p.min_vars = 1;
  p.max_vars = max_vars;
  p.kinds = std::move(kinds);
  opt.max_states = 20'000;  // a deterministic limit (UNKNOWN alike on both sides), no time limit
  opt.solve_seconds = 0;
  Verifier verifier;
  int disagreements = 0;
  for (int i = 0; i < count; ++i) {
    const auto index = static_cast<uint64_t>(i);
    SCOPED_TRACE("campaign seed " + std::to_string(p.seed) + ", formula " + std::to_string(index) +
                 " (replay: gridlock fuzz --seed " + std::to_string(p.seed) + " --index " + std::to_string(index) +
                 " --min-vars 1 --max-vars " + std::to_string(max_vars) + ")");
    const Formula f = fuzz_formula(p, index);
    const VerifyResult fresh = verify_formula(f, "f", opt);
    const VerifyResult reused = verifier.verify(f, "f", opt);
    EXPECT_EQ(summary(reused), summary(fresh));
    if (::testing::Test::HasFailure()) break;
    disagreements += !fresh.agree;
  }
  return disagreements;
}

const std::vector<FuzzKind> kAllKinds = {FuzzKind::Ksat, FuzzKind::Lsat, FuzzKind::Planted};

VerifyOptions with_model(TimeModels m, bool direct = false, Mutation mutation = Mutation::None) {
  VerifyOptions opt;
  opt.models = m;
  opt.direct = direct;
  opt.mutation = mutation;
  return opt;
}

TEST(Verifier, ReusedVerifierMatchesFreshVerifyFormula) {
  EXPECT_EQ(same_results(15, 6, kAllKinds, VerifyOptions{}, test::scaled(300)), 0);
  EXPECT_EQ(same_results(18, 6, kAllKinds, with_model(TimeModels::only(TimeModel::Discrete), true), test::scaled(60)),
            0);
}

// The exact continuous solver is the slow part: fewer, smaller formulas.
TEST(Verifier, ContinuousAndBothModelsMatch) {
  EXPECT_EQ(same_results(16, 3, kAllKinds, with_model(TimeModels::only(TimeModel::Continuous)), test::scaled(10)), 0);
  EXPECT_EQ(same_results(19, 3, kAllKinds, with_model(TimeModels::both()), test::scaled(10)), 0);
}

// With a broken gadget the checks disagree on some formulas: the reused
// Verifier must report the same disagreements.
TEST(Verifier, BrokenGadgetDisagreementsMatch) {
  const VerifyOptions broken = with_model(TimeModels::only(TimeModel::Discrete), false, Mutation::ClauseTight);
  EXPECT_GT(same_results(17, 6, {FuzzKind::Ksat, FuzzKind::Planted}, broken, test::scaled(60)), 0);
}

}  // namespace
}  // namespace gridlock
