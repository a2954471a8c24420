// `gridlock verify`, `gridlock fuzz` and `gridlock gen-instances` end to end:
// the real binary on real files. The bundled examples agree; a deliberately
// broken gadget is caught, reproduced and shrunk; campaigns are deterministic
// and shard exactly; every label of a generated set is confirmed by other
// subcommands.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "support/cli.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

using test::run_gridlock;
namespace fs = std::filesystem;

const std::string kExamples = GRIDLOCK_SOURCE_DIR "/examples/formulas";
const std::string kSatlib = GRIDLOCK_DATA_DIR "/satlib/";

TEST(VerifyCli, BundledExamplesAgreeWithEveryCertificateChecked) {
  std::string dir = test::temp_dir();
  auto r = run_gridlock({"verify", kExamples, "--json", "--pictures", dir + "/pics", "--reproducers", dir + "/rep"});
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["summary"]["disagree"], 0);
  EXPECT_EQ(j["summary"]["unknown"], 0);
  for (const auto& row : j["formulas"]) {
    SCOPED_TRACE(row["formula"].get<std::string>());
    EXPECT_EQ(row["status"], "agree");
    EXPECT_EQ(row["discrete"], row["sat"]);
    EXPECT_EQ(row["continuous"], "YES");  // continuous time is easy
    EXPECT_LE(row["max_coupling"], 3);
    // SAT: model schedule, solver schedule, all-at-once; UNSAT: all-at-once
    // and the solver's NO certificate (certify/).
    EXPECT_EQ(row["witnesses_checked"], row["sat"] == "YES" ? 3 : 2);
    EXPECT_EQ(row["no_certificate"], row["sat"] == "YES" ? "none" : "checked");
  }
  EXPECT_TRUE(fs::exists(dir + "/pics/tiny-sat-witness.svg"));
  EXPECT_TRUE(fs::exists(dir + "/pics/tiny-unsat-collision.svg"));
  EXPECT_FALSE(fs::exists(dir + "/rep"));
}

TEST(VerifyCli, TableAndSummary) {
  auto r = run_gridlock({"verify", kExamples + "/tiny-sat.cnf", kExamples + "/tiny-unsat.cnf"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("summary: 2 formulas (1 SAT, 1 UNSAT): 2 agree, 0 unknown (solver limit), 0 disagree; "
                       "5 certificates checked (1 NO certificates checked, 0 missing or rejected)"),
            std::string::npos)
      << r.out;
}

TEST(VerifyCli, SatlibSamplesAgree) {
  // A spread of uf20-91 (the full folder is the README's acceptance run,
  // docs/verify.md) plus a formula read from standard input.
  std::vector<std::string> args = {"verify", "--json"};
  for (int i = 1; i <= 100; i += 100 / test::scaled(4))
    args.push_back(kSatlib + "uf20-91/uf20-0" + std::to_string(i) + ".cnf");
  args.push_back("-");
  auto r = run_gridlock(args, "p cnf 2 2\n1 2 0\n-1 0\n");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["summary"]["agree"], args.size() - 2);
}

TEST(VerifyCli, BrokenGadgetIsCaughtWithAReproducer) {
  std::string dir = test::temp_dir();
  auto r = run_gridlock(
      {"verify", kExamples + "/tiny-unsat.cnf", "--reproducers", dir, "--break-gadget", "clause-loose"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("DISAGREE: exact solver says YES, CaDiCaL says UNSAT"), std::string::npos) << r.out;
  EXPECT_EQ(r.err, "gridlock: error: verify: 1 disagreement; reproducers in " + dir + "\n");
  for (const char* f :
       {"formula.cnf", "lsat.cnf", "instance.grid", "sat-schedule.txt", "solver-schedule.txt", "README.txt", "run.sh"})
    EXPECT_TRUE(fs::exists(dir + "/tiny-unsat/" + f)) << f;
  EXPECT_NE(test::read_file(dir + "/tiny-unsat/run.sh").find("verify formula.cnf --break-gadget clause-loose"),
            std::string::npos);
  // The reproducer replays: the solver's schedule is collision-free on the broken instance.
  auto c = run_gridlock(
      {"check", dir + "/tiny-unsat/instance.grid", "--order-file", dir + "/tiny-unsat/solver-schedule.txt"});
  EXPECT_EQ(c.exit_code, 10) << c.out;
}

TEST(VerifyCli, BadInput) {
  std::string dir = test::temp_dir();
  auto r = run_gridlock({"verify", dir + "/none.cnf"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "gridlock: error: " + dir + "/none.cnf: cannot open file\n");
  r = run_gridlock({"verify", dir});
  EXPECT_EQ(r.err, "gridlock: error: " + dir + ": folder holds no .cnf file\n");
  std::string bad = test::write_file(dir + "/bad.cnf", "p cnf 2 1\n1 x 0\n");
  r = run_gridlock({"verify", kExamples + "/tiny-sat.cnf", bad});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err.rfind("gridlock: error: " + bad + ":2: ", 0), 0u) << r.err;
  EXPECT_EQ(r.out, "");  // nothing is checked before every file has been read
  r = run_gridlock({"verify"});
  EXPECT_EQ(r.err, "gridlock: error: missing argument INPUTS (see 'gridlock verify --help')\n");
  r = run_gridlock({"gen-instances"});
  EXPECT_EQ(r.err, "gridlock: error: missing option --out (see 'gridlock gen-instances --help')\n");
  r = run_gridlock({"cnf", "solve"});
  EXPECT_EQ(r.err, "gridlock: error: missing argument FILE (see 'gridlock cnf solve --help')\n");
}

nlohmann::json fuzz(const std::vector<std::string>& extra) {
  std::vector<std::string> args = {"fuzz", "--json"};
  args.insert(args.end(), extra.begin(), extra.end());
  auto r = run_gridlock(args);
  EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.err;
  return nlohmann::json::parse(r.out);
}

TEST(FuzzCli, CampaignAgreesIsDeterministicAndShardsExactly) {
  const std::string n = std::to_string(test::scaled(60));
  auto all = fuzz({"--seed", "3", "--count", n});
  EXPECT_EQ(all["status"], "AGREE");
  EXPECT_EQ(all["formulas"].get<int>(), std::stoi(n));
  EXPECT_GT(all["sat"].get<int>(), 0);
  EXPECT_GT(all["unsat"].get<int>(), 0);
  auto again = fuzz({"--seed", "3", "--count", n});
  EXPECT_EQ(again["sat"], all["sat"]);
  EXPECT_EQ(again["unsat"], all["unsat"]);
  auto a = fuzz({"--seed", "3", "--count", n, "--shard", "0/2"});
  auto b = fuzz({"--seed", "3", "--count", n, "--shard", "1/2"});
  EXPECT_EQ(a["formulas"].get<int>() + b["formulas"].get<int>(), all["formulas"].get<int>());
  EXPECT_EQ(a["sat"].get<int>() + b["sat"].get<int>(), all["sat"].get<int>());
}

// The fuzzer's self-test: with a deliberately broken gadget it must find a
// disagreement, shrink it to a tiny formula and save a replayable folder.
TEST(FuzzCli, FindsAndShrinksABrokenGadget) {
  for (const char* m : {"clause-loose", "clause-tight", "variable-loose-y", "order-loose", "order-drop-release"}) {
    SCOPED_TRACE(m);
    std::string dir = test::temp_dir();
    auto j = fuzz({"--seed", "1", "--count", "200", "--out", dir, "--break-gadget", m});
    ASSERT_EQ(j["status"], "DISAGREE");
    ASSERT_EQ(j["findings"].size(), 1u);
    const auto& f = j["findings"][0];
    EXPECT_LE(f["shrunk_clauses"].get<int>(), 4) << f["dimacs"];
    EXPECT_LE(f["shrunk_variables"].get<int>(), 3) << f["dimacs"];
    const std::string folder = f["folder"];
    EXPECT_TRUE(fs::exists(folder + "/formula.cnf"));
    EXPECT_TRUE(fs::exists(folder + "/original.cnf"));
    // The saved formula still disagrees under the same broken gadget, and
    // agrees with the real gadgets.
    auto bad = run_gridlock({"verify", folder + "/formula.cnf", "--break-gadget", m, "--reproducers", dir + "/r"});
    EXPECT_EQ(bad.exit_code, 1) << bad.out;
    auto good = run_gridlock({"verify", folder + "/formula.cnf"});
    EXPECT_EQ(good.exit_code, 0) << good.out;
  }
}

TEST(FuzzCli, ReplayAndErrors) {
  auto one = fuzz({"--seed", "9", "--index", "17"});
  EXPECT_EQ(one["formulas"], 1);
  auto r = run_gridlock({"fuzz", "--shard", "2/2"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "gridlock: error: --shard: want K/N with 0 <= K < N, not '2/2'\n");
  r = run_gridlock({"fuzz", "--kinds", "foo"});
  EXPECT_EQ(r.err, "gridlock: error: --kinds: unknown kind 'foo' (ksat, lsat, planted, mix)\n");
}

// gen-instances: every label confirmed independently. YES: the saved schedule
// through `gridlock check`; NO: `gridlock cnf solve` on the saved source
// formula; both: `gridlock verify` on the saved formula agrees.
TEST(GenInstancesCli, LabelsAreConfirmedByOtherSubcommands) {
  std::string dir = test::temp_dir();
  auto r = run_gridlock({"gen-instances", "-o", dir, "--vars", "6", "--threshold", "3", "--lsat", "2", "--seed", "4",
                         "--formula", kExamples + "/tiny-unsat.cnf"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto m = nlohmann::json::parse(test::read_file(dir + "/manifest.json"));
  ASSERT_EQ(m["instances"].size(), 6u);
  int yes = 0, no = 0;
  std::vector<std::string> formulas = {"verify", "--json"};
  for (const auto& e : m["instances"]) {
    const std::string name = e["name"];
    SCOPED_TRACE(name);
    ASSERT_TRUE(fs::exists(dir + "/" + e["instance"].get<std::string>()));
    formulas.push_back(dir + "/" + e["formula"].get<std::string>());
    if (e["answer"] == "YES") {
      ++yes;
      auto c = run_gridlock({"check", dir + "/" + e["instance"].get<std::string>(), "--order-file",
                             dir + "/" + e["certificate"]["file"].get<std::string>()});
      EXPECT_EQ(c.exit_code, 10) << c.out;
    } else {
      ++no;
      EXPECT_EQ(run_gridlock({"cnf", "solve", dir + "/" + e["formula"].get<std::string>()}).exit_code, 20);
    }
  }
  EXPECT_EQ(m["yes"], yes);
  EXPECT_EQ(m["no"], no);
  EXPECT_GE(no, 1);  // tiny-unsat
  auto v = run_gridlock(formulas);
  ASSERT_EQ(v.exit_code, 0) << v.out;
  auto j = nlohmann::json::parse(v.out);
  for (size_t i = 0; i < m["instances"].size(); ++i)
    EXPECT_EQ(j["formulas"][i]["discrete"], m["instances"][i]["answer"]);
}

TEST(GenInstancesCli, YesNoMix) {
  std::string dir = test::temp_dir();
  auto r = run_gridlock(
      {"gen-instances", "-o", dir, "--vars", "5", "--threshold", "4", "--lsat", "0", "--yes", "2", "--no", "2"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto m = nlohmann::json::parse(test::read_file(dir + "/manifest.json"));
  EXPECT_EQ(m["yes"], 2);
  EXPECT_EQ(m["no"], 2);
}

}  // namespace
}  // namespace gridlock

// The continuous reduction end to end (docs/verify.md): the bundled small
// examples agree with CaDiCaL under the exact continuous solver, every
// certificate checked; the broken separation gadget is caught and shrunk.
namespace gridlock {
namespace {

TEST(VerifyContinuousCli, BundledExamplesAgree) {
  // Compiled as they are (--direct): through to-lsat tiny-sat becomes 47
  // couplings, beyond what the continuous solver decides in seconds.
  std::vector<std::string> args = {"verify", "--model", "both", "--direct", "--json", "--timeout", "120"};
  for (const char* f : {"tiny-sat.cnf", "tiny-unsat.cnf"}) args.push_back(kExamples + "/" + f);
  auto r = run_gridlock(args);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["model"], "both");
  ASSERT_EQ(j["formulas"].size(), 2u);
  EXPECT_EQ(j["formulas"][0]["continuous_solver"], "YES");
  EXPECT_EQ(j["formulas"][1]["continuous_solver"], "NO");
  // tiny-sat: CaDiCaL's model and both solvers' schedules, each in both
  // models where it applies: 3 discrete + 2 continuous certificates.
  EXPECT_EQ(j["formulas"][0]["witnesses_checked"], 5);
  EXPECT_EQ(j["summary"]["agree"], 2);
}

TEST(VerifyContinuousCli, LooseSeparationIsCaughtWithAReproducer) {
  std::string dir = test::temp_dir();
  auto r = run_gridlock({"verify", kExamples + "/tiny-unsat.cnf", "--model", "continuous", "--direct", "--reproducers",
                         dir, "--break-gadget", "separation-loose"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("DISAGREE: exact continuous solver says YES, CaDiCaL says UNSAT"), std::string::npos) << r.out;
  for (const char* f : {"formula.cnf", "instance-continuous.grid", "solver-times.txt", "README.txt", "run.sh"})
    EXPECT_TRUE(fs::exists(dir + "/tiny-unsat/" + f)) << f;
  EXPECT_NE(test::read_file(dir + "/tiny-unsat/run.sh")
                .find("verify formula.cnf --model continuous --break-gadget separation-loose --direct"),
            std::string::npos);
  // The reproducer replays: the solver's start times are collision-free on the broken instance...
  auto c = run_gridlock(
      {"check", dir + "/tiny-unsat/instance-continuous.grid", "--times", dir + "/tiny-unsat/solver-times.txt"});
  EXPECT_EQ(c.exit_code, 10) << c.out;
  // ...and the real gadget says NO.
  auto good = run_gridlock({"verify", kExamples + "/tiny-unsat.cnf", "--model", "continuous", "--direct"});
  EXPECT_EQ(good.exit_code, 0) << good.out;
  r = run_gridlock({"verify", kExamples + "/tiny-unsat.cnf", "--model", "sometimes"});
  EXPECT_EQ(r.err, "gridlock: error: --model must be discrete, continuous or both, not 'sometimes'\n");
}

TEST(FuzzContinuousCli, FindsAndShrinksABrokenSeparationGadget) {
  std::string dir = test::temp_dir();
  auto r = run_gridlock({"fuzz", "--json", "--model", "continuous", "--seed", "1", "--count", "50", "--min-vars", "2",
                         "--max-vars", "4", "--out", dir, "--break-gadget", "separation-loose"});
  ASSERT_EQ(r.exit_code, 1) << r.out << r.err;
  auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["status"], "DISAGREE");
  ASSERT_EQ(j["findings"].size(), 1u);
  const auto& f = j["findings"][0];
  EXPECT_LE(f["shrunk_clauses"].get<int>(), 2) << f["dimacs"];
  EXPECT_LE(f["shrunk_variables"].get<int>(), 2) << f["dimacs"];
  EXPECT_NE(f["replay"].get<std::string>().find("--model continuous"), std::string::npos);
  const std::string folder = f["folder"];
  // Still disagrees with the broken gadget, agrees with the real one.
  auto bad = run_gridlock({"verify", folder + "/formula.cnf", "--model", "continuous", "--break-gadget",
                           "separation-loose", "--reproducers", dir + "/r"});
  EXPECT_EQ(bad.exit_code, 1) << bad.out;
  auto good = run_gridlock({"verify", folder + "/formula.cnf", "--model", "continuous"});
  EXPECT_EQ(good.exit_code, 0) << good.out;
}

}  // namespace
}  // namespace gridlock

namespace gridlock {
namespace {

// gen-instances --model both: every continuous YES label is confirmed by its
// start times through `gridlock check --times`, every NO by `cnf solve` and
// by the exact continuous solver (manifest "solver_check", and again here
// through `solve --model continuous`); the continuous instance differs from
// the discrete one by the separation gadget.
TEST(GenInstancesContinuousCli, LabelsAreConfirmed) {
  std::string dir = test::temp_dir();
  auto r = run_gridlock({"gen-instances", "-o", dir, "--model", "both", "--vars", "5", "--threshold", "3", "--lsat",
                         "1", "--seed", "4", "--formula", kExamples + "/tiny-unsat.cnf"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto m = nlohmann::json::parse(test::read_file(dir + "/manifest.json"));
  EXPECT_EQ(m["model"], "both");
  ASSERT_EQ(m["instances"].size(), 10u);  // 5 formulas, 2 models
  int continuous = 0, continuous_no = 0;
  for (const auto& e : m["instances"]) {
    const std::string name = e["name"];
    SCOPED_TRACE(name);
    const std::string inst = dir + "/" + e["instance"].get<std::string>();
    ASSERT_TRUE(fs::exists(inst));
    if (e["model"] != "continuous") continue;
    ++continuous;
    EXPECT_NE(test::read_file(inst).find(" +y"), std::string::npos);  // the separation gadget's lift
    if (e["answer"] == "YES") {
      auto c = run_gridlock({"check", inst, "--times", dir + "/" + e["certificate"]["file"].get<std::string>()});
      EXPECT_EQ(c.exit_code, 10) << c.out;
    } else {
      EXPECT_EQ(run_gridlock({"cnf", "solve", dir + "/" + e["formula"].get<std::string>()}).exit_code, 20);
      EXPECT_EQ(e["solver_check"]["answer"], "NO") << e.dump();
      EXPECT_EQ(run_gridlock({"solve", inst, "--model", "continuous"}).exit_code, 20);
      ++continuous_no;
    }
  }
  EXPECT_EQ(continuous, 5);
  EXPECT_GE(continuous_no, 1);
}

// A reproducer folder that cannot be created (a file stands where the
// finding's folder goes) is an I/O error naming that folder: the row says
// the reproducer was NOT written and why, the last line is a normal error
// naming the folder, and nothing says "internal" (docs/errors.md keeps that
// for bugs). The same for fuzz's finding folder.
TEST(VerifyCli, UncreatableReproducerFolderIsAnErrorNamingIt) {
  const std::string dir = test::temp_dir();
  const std::string rep = dir + "/rep";
  fs::create_directories(rep);
  test::write_file(rep + "/tiny-unsat", "a file, not a folder\n");
  auto r = run_gridlock(
      {"verify", kExamples + "/tiny-unsat.cnf", "--break-gadget", "clause-loose", "--reproducers", rep});
  EXPECT_EQ(r.exit_code, 1);
  const std::string why = rep + "/tiny-unsat: cannot create folder: Not a directory";
  EXPECT_NE(r.out.find("(reproducer NOT written: " + why + ")"), std::string::npos) << r.out;
  EXPECT_EQ(r.err.substr(r.err.rfind("gridlock: error: ")), "gridlock: error: " + why + "\n") << r.err;
  EXPECT_EQ(r.err.find("internal"), std::string::npos) << r.err;

  const std::string out = dir + "/fz";
  fs::create_directories(out);
  test::write_file(out + "/seed7-formula0", "a file, not a folder\n");
  r = run_gridlock({"fuzz", "--break-gadget", "clause-loose", "--count", "3", "--seed", "7", "--out", out});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err.substr(r.err.rfind("gridlock: error: ")),
            "gridlock: error: " + out + "/seed7-formula0: cannot create folder: Not a directory\n")
      << r.err;
  EXPECT_EQ(r.err.find("internal"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace gridlock
