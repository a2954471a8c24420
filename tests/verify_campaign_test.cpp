// The campaign library (verify/campaign.hpp, verify/instance_set.hpp): the
// loops behind fuzz, verify and gen-instances, called directly. The command
// line's JSON must report what the library's tally says; shards add up to
// the whole; a stop request ends a campaign with a partial tally.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>

#include "cnf/dimacs.hpp"
#include "common/limits.hpp"
#include "support/cli.hpp"
#include "verify/campaign.hpp"
#include "verify/instance_set.hpp"

namespace gridlock {
namespace {

using nlohmann::json;

const std::string kExamples = std::string(GRIDLOCK_SOURCE_DIR) + "/examples/formulas/";

FuzzCampaign small_fuzz(uint64_t seed, uint64_t count) {
  FuzzCampaign c;
  c.formulas.seed = seed;
  c.formulas.min_vars = 3;
  c.formulas.max_vars = 4;
  c.verify.solve_seconds = 10;
  c.verify.max_states = 2'000'000;
  c.first = 0;
  c.last = count;
  return c;
}

// A stop request the test itself makes (what SIGINT does in the command
// line), cleared again whatever happens.
struct StopRequest {
  void request() { stop_signal().store(2); }
  ~StopRequest() { stop_signal().store(0); }
};

TEST(FuzzCampaign, TallyEqualsTheCommandLinesJson) {
  FuzzCampaign c = small_fuzz(5, 24);
  const FuzzTally t = run_fuzz_campaign(c);
  EXPECT_EQ(t.formulas, 24u);
  EXPECT_EQ(t.sat + t.unsat, 24u);  // CaDiCaL decides every small formula
  EXPECT_GT(t.sat, 0u);
  EXPECT_GT(t.unsat, 0u);
  EXPECT_EQ(t.disagreements, 0u);
  EXPECT_FALSE(t.interrupted);
  const std::string dir = test::temp_dir();
  auto r = test::run_gridlock(
      {"fuzz", "--seed", "5", "--count", "24", "--min-vars", "3", "--max-vars", "4", "--json", "--out", dir});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["formulas"].get<uint64_t>(), t.formulas);
  EXPECT_EQ(j["sat"].get<uint64_t>(), t.sat);
  EXPECT_EQ(j["unsat"].get<uint64_t>(), t.unsat);
  EXPECT_EQ(j["unknown"].get<uint64_t>(), t.unknown);
  EXPECT_EQ(j["certificates_checked"].get<uint64_t>(), t.certificates);
  EXPECT_EQ(j["disagreements"].get<uint64_t>(), t.disagreements);
}

TEST(FuzzCampaign, ShardsAddUpToTheWhole) {
  const FuzzTally whole = run_fuzz_campaign(small_fuzz(9, 15));
  FuzzTally sum;
  for (uint64_t k = 0; k < 3; ++k) {
    FuzzCampaign c = small_fuzz(9, 15);
    c.first = k;
    c.step = 3;
    std::vector<uint64_t> seen;
    FuzzEvents ev;
    ev.progress = [&](const FuzzTally& t) { seen.push_back(t.formulas); };
    const FuzzTally t = run_fuzz_campaign(c, ev);
    EXPECT_EQ(t.formulas, 5u);
    EXPECT_EQ(seen, (std::vector<uint64_t>{1, 2, 3, 4, 5}));  // one progress report per formula
    sum.formulas += t.formulas;
    sum.sat += t.sat;
    sum.unsat += t.unsat;
    sum.certificates += t.certificates;
  }
  EXPECT_EQ(sum.formulas, whole.formulas);
  EXPECT_EQ(sum.sat, whole.sat);
  EXPECT_EQ(sum.unsat, whole.unsat);
  EXPECT_EQ(sum.certificates, whole.certificates);
}

TEST(FuzzCampaign, ABrokenGadgetGivesOneShrunkFinding) {
  FuzzCampaign c = small_fuzz(1, 200);
  c.formulas.max_vars = 6;
  c.verify.mutation = Mutation::ClauseLoose;
  std::vector<uint64_t> disagreeing;
  std::vector<std::string> shrunk_problems;
  FuzzEvents ev;
  ev.disagreement = [&](uint64_t i, const VerifyResult& r) {
    EXPECT_FALSE(r.agree);
    disagreeing.push_back(i);
  };
  ev.finding = [&](const FuzzFinding& f, const VerifyResult& shrunk) {
    EXPECT_FALSE(shrunk.agree);  // the shrunk formula still disagrees
    EXPECT_EQ(f.problem, shrunk.problem);
    shrunk_problems.push_back(f.problem);
  };
  const FuzzTally t = run_fuzz_campaign(c, ev);
  ASSERT_EQ(t.disagreements, 1u);  // no keep_going: the first disagreement ends it
  ASSERT_EQ(t.findings.size(), 1u);
  ASSERT_EQ(disagreeing.size(), 1u);
  EXPECT_EQ(t.findings[0].index, disagreeing[0]);
  EXPECT_EQ(t.formulas, disagreeing[0] + 1);
  EXPECT_EQ(shrunk_problems.size(), 1u);
  EXPECT_LE(t.findings[0].shrunk.clauses.size(), t.findings[0].original.clauses.size());
  EXPECT_EQ(to_dimacs(t.findings[0].original), to_dimacs(fuzz_formula(c.formulas, t.findings[0].index)));
}

TEST(FuzzCampaign, AStopRequestReturnsAPartialTally) {
  FuzzCampaign c = small_fuzz(3, 1000);
  StopRequest stop;
  FuzzEvents ev;
  ev.progress = [&](const FuzzTally& t) {
    if (t.formulas == 4) stop.request();
  };
  const FuzzTally t = run_fuzz_campaign(c, ev);
  EXPECT_TRUE(t.interrupted);
  EXPECT_EQ(t.formulas, 4u);
  EXPECT_EQ(t.sat + t.unsat + 0u, 4u);
}

std::vector<Formula> example_formulas(const std::vector<std::string>& names) {
  std::vector<Formula> out;
  for (const auto& n : names) {
    Formula f;
    EXPECT_FALSE(read_dimacs_file(n, f)) << n;
    out.push_back(f);
  }
  return out;
}

TEST(VerifyCampaign, TallyEqualsTheCommandLinesJsonAndShardsSplitTheInputs) {
  const std::vector<std::string> names = {kExamples + "tiny-sat.cnf", kExamples + "tiny-unsat.cnf",
                                          kExamples + "lsat-sat.cnf"};
  const std::vector<Formula> formulas = example_formulas(names);
  VerifyCampaign c;
  std::vector<size_t> checked;
  VerifyEvents ev;
  ev.start = [&](size_t i) { checked.push_back(i); };
  ev.result = [&](size_t, const VerifyResult& r, FormulaStatus s) {
    EXPECT_TRUE(r.agree);
    EXPECT_EQ(s, FormulaStatus::Agree);
  };
  const VerifyTally t = run_verify_campaign(formulas, names, c, ev);
  EXPECT_EQ(checked, (std::vector<size_t>{0, 1, 2}));
  EXPECT_EQ(t.formulas, 3u);
  EXPECT_EQ(t.sat, 2u);
  EXPECT_EQ(t.unsat, 1u);
  EXPECT_EQ(t.agree, 3u);
  auto r = test::run_gridlock({"verify", names[0], names[1], names[2], "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json s = json::parse(r.out)["summary"];
  EXPECT_EQ(s["formulas"].get<size_t>(), t.formulas);
  EXPECT_EQ(s["sat"].get<size_t>(), t.sat);
  EXPECT_EQ(s["unsat"].get<size_t>(), t.unsat);
  EXPECT_EQ(s["agree"].get<size_t>(), t.agree);
  EXPECT_EQ(s["certificates_checked"].get<size_t>(), t.certificates);

  c.shard = {1, 2};
  checked.clear();
  const VerifyTally odd = run_verify_campaign(formulas, names, c, ev);
  EXPECT_EQ(checked, (std::vector<size_t>{1}));
  EXPECT_EQ(odd.formulas, 1u);
  EXPECT_EQ(odd.unsat, 1u);
}

TEST(VerifyCampaign, ADisagreementWritesItsReproducer) {
  const std::vector<std::string> names = {kExamples + "tiny-unsat.cnf"};
  VerifyCampaign c;
  c.verify.mutation = Mutation::ClauseLoose;
  c.reproducers = test::temp_dir();
  std::string problem;
  VerifyEvents ev;
  ev.result = [&](size_t, const VerifyResult& r, FormulaStatus s) {
    EXPECT_EQ(s, FormulaStatus::Disagree);
    problem = r.problem;
  };
  const VerifyTally t = run_verify_campaign(example_formulas(names), names, c, ev);
  EXPECT_EQ(t.disagree, 1u);
  const std::string dir = c.reproducers + "/tiny-unsat";
  EXPECT_NE(problem.find("(reproducer: " + dir + ")"), std::string::npos) << problem;
  EXPECT_TRUE(std::filesystem::exists(dir + "/formula.cnf"));
}

TEST(VerifyCampaign, AStopRequestAfterOneFormulaEndsTheRun) {
  const std::vector<std::string> names = {kExamples + "tiny-sat.cnf", kExamples + "tiny-unsat.cnf"};
  StopRequest stop;
  VerifyEvents ev;
  ev.result = [&](size_t, const VerifyResult&, FormulaStatus) { stop.request(); };
  const VerifyTally t = run_verify_campaign(example_formulas(names), names, VerifyCampaign{}, ev);
  EXPECT_TRUE(t.interrupted);
  EXPECT_EQ(t.formulas, 1u);  // the first one finished, then the stop
}

TEST(InstanceSet, FilesComeInASafeOrderAndEveryYesHasItsWitness) {
  InstanceSetPlan plan;
  plan.seed = 4;
  plan.vars = 5;
  plan.threshold = 3;
  plan.lsat = 2;
  plan.models = {TimeModel::Discrete, TimeModel::Continuous};
  std::vector<std::string> order;
  std::map<std::string, std::string> files;
  InstanceSetEvents ev;
  ev.write = [&](const std::string& file, const std::string& text) {
    order.push_back(file);
    files[file] = text;
  };
  const InstanceSetTally t = make_instance_set(plan, ev);
  EXPECT_EQ(t.yes + t.no, 5);
  EXPECT_EQ(t.instances.size(), 10u);  // two models per formula
  for (const SetInstance& e : t.instances) {
    SCOPED_TRACE(e.name);
    auto at = [&](const std::string& f) { return std::find(order.begin(), order.end(), f) - order.begin(); };
    ASSERT_TRUE(files.count(e.instance_file));
    EXPECT_LT(at(e.formula_file), at(e.instance_file));  // the formula before its instance
    EXPECT_EQ(e.yes, !e.certificate_file.empty());
    if (e.yes) {
      EXPECT_LT(at(e.certificate_file), at(e.instance_file));  // the witness too
    }
    EXPECT_NE(files[e.instance_file].find(e.yes ? "answer: YES" : "answer: NO"), std::string::npos);
  }
  // The same set, sharded in two, has the same instances between its shards.
  size_t sharded = 0;
  for (uint64_t k = 0; k < 2; ++k) {
    plan.shard = {k, 2};
    InstanceSetEvents quiet;
    quiet.write = [](const std::string&, const std::string&) {};
    for (const SetInstance& e : make_instance_set(plan, quiet).instances) {
      EXPECT_EQ(e.index % 2, k);
      ++sharded;
    }
  }
  EXPECT_EQ(sharded, t.instances.size());
}

}  // namespace
}  // namespace gridlock
