// `gridlock cnf` end to end: the real binary on real files. cnf solve against
// all 300 SATLIB labels (models read back from the v lines and checked),
// to-lsat piped into check and solve, gen reproducibility, errors, --json,
// --help.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cnf/dimacs.hpp"
#include "cnf/lsat.hpp"
#include "support/cli.hpp"
#include "support/cnf_testing.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

using test::run_gridlock;

// The literals of the "v" lines; the list must end with 0 (which is dropped).
std::vector<int> v_literals(const std::string& out) {
  std::vector<int> lits;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("v ", 0) != 0) continue;
    std::istringstream ls(line.substr(2));
    for (int x; ls >> x;) lits.push_back(x);
  }
  EXPECT_FALSE(lits.empty());
  if (!lits.empty()) {
    EXPECT_EQ(lits.back(), 0) << "v lines must end with 0";
    lits.pop_back();
  }
  return lits;
}

std::vector<bool> assignment(const std::vector<int>& lits, int n) {
  std::vector<bool> v(static_cast<size_t>(n) + 1, false);
  EXPECT_EQ(lits.size(), static_cast<size_t>(n));
  for (int lit : lits)
    if (var_of(lit) <= n) v[static_cast<size_t>(var_of(lit))] = lit > 0;
  return v;
}

// `count` of the files, evenly spread (all of them at GRIDLOCK_TEST_SCALE 1;
// the sanitizer run, where each process start costs ~0.1 s, takes a sample).
std::vector<test::SatlibFile> spread(const std::vector<test::SatlibFile>& files, int count) {
  std::vector<test::SatlibFile> out;
  const size_t k = std::min(files.size(), static_cast<size_t>(count));
  for (size_t i = 0; i < k; ++i) out.push_back(files[i * files.size() / k]);
  return out;
}

Formula read_text(const std::string& text) {
  Formula f;
  auto e = read_dimacs_string(text, "out.cnf", f);
  EXPECT_FALSE(e) << e->str();
  return f;
}

TEST(CnfCli, SolveAgreesWithEverySatlibLabel) {
  auto all = test::satlib_files();
  ASSERT_EQ(all.size(), 300u);
  for (const auto& file : spread(all, test::scaled(300))) {
    SCOPED_TRACE(file.path);
    auto r = run_gridlock({"cnf", "solve", file.path});
    ASSERT_EQ(r.exit_code, file.sat ? 10 : 20) << r.out << r.err;
    EXPECT_NE(r.out.find(file.sat ? "\ns SATISFIABLE\n" : "\ns UNSATISFIABLE\n"), std::string::npos) << r.out;
    if (!file.sat) {
      EXPECT_EQ(r.out.find("\nv "), std::string::npos);
      continue;
    }
    Formula f;
    ASSERT_FALSE(read_dimacs_file(file.path, f));
    EXPECT_TRUE(satisfies(f, assignment(v_literals(r.out), f.num_vars)));
  }
}

TEST(CnfCli, ToLsatPipesIntoCheckAndSolve) {
  auto files = spread(test::satlib_files(), test::scaled(30));
  ASSERT_FALSE(files.empty());
  std::string dir = test::temp_dir();
  // 30 files end to end (all 300 are checked in-process in
  // cnf_to_lsat_test.cpp): the written file is LSAT<=3 (cnf check
  // --relaxed says YES), has the same answer, and its model truncated to
  // the input's variables satisfies the input.
  for (size_t i = 0; i < files.size(); ++i) {
    SCOPED_TRACE(files[i].path);
    const std::string out = dir + "/lsat.cnf";
    auto r = run_gridlock({"cnf", "to-lsat", files[i].path, "-o", out});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out.rfind("c wrote " + out + ": ", 0), 0u) << r.out;
    auto check = run_gridlock({"cnf", "check", "--relaxed", out});
    EXPECT_EQ(check.exit_code, 10) << check.out;
    auto exact = run_gridlock({"cnf", "check", out});
    EXPECT_EQ(exact.exit_code, 20) << exact.out;  // 2-literal clauses: not exactly-3 LSAT
    auto solved = run_gridlock({"cnf", "solve", out});
    ASSERT_EQ(solved.exit_code, files[i].sat ? 10 : 20) << solved.out;
    if (files[i].sat) {
      Formula in;
      ASSERT_FALSE(read_dimacs_file(files[i].path, in));
      std::vector<int> lits = v_literals(solved.out);
      lits.resize(static_cast<size_t>(in.num_vars));  // lift_to_source: truncation
      EXPECT_TRUE(satisfies(in, assignment(lits, in.num_vars)));
    }
  }
  // Standard output and -o give the same bytes (apart from the command line).
  auto a = run_gridlock({"cnf", "to-lsat", files[0].path});
  std::string from_file = test::read_file(dir + "/lsat.cnf");
  auto b = run_gridlock({"cnf", "to-lsat", files[0].path, "-o", dir + "/again.cnf"});
  Formula fa = read_text(a.out), fb = read_text(test::read_file(dir + "/again.cnf"));
  EXPECT_EQ(fa.clauses, fb.clauses);
  EXPECT_EQ(fa.comments.at(0), "command: gridlock cnf to-lsat " + files[0].path);
  std::filesystem::remove_all(dir);
}

TEST(CnfCli, GenIsByteIdenticalAndRecordsTheCommandLine) {
  for (std::vector<std::string> args :
       {std::vector<std::string>{"cnf", "gen", "ksat", "--n", "50", "--ratio", "4.26", "--seed", "17"},
        std::vector<std::string>{"cnf", "gen", "lsat", "--n", "40", "--m", "32", "--seed", "5"},
        std::vector<std::string>{"cnf", "gen", "lsat-le3", "--n", "40", "--m", "50"},
        std::vector<std::string>{"cnf", "gen", "planted", "--n", "30", "--m", "120", "--k", "4", "--seed", "0"}}) {
    auto a = run_gridlock(args), b = run_gridlock(args);
    ASSERT_EQ(a.exit_code, 0) << a.err;
    EXPECT_EQ(a.out, b.out);
    std::string cmd = "c command: gridlock";
    for (size_t i = 0; i < args.size(); ++i) cmd += " " + args[i];
    EXPECT_EQ(a.out.substr(0, a.out.find('\n')), cmd);
    Formula f = read_text(a.out);
    if (args[2] == "lsat") {
      EXPECT_TRUE(is_lsat(f, LsatForm::Exact3));
    }
    if (args[2] == "lsat-le3") {
      EXPECT_TRUE(is_lsat(f, LsatForm::AtMost3));
    }
  }
  auto other = run_gridlock({"cnf", "gen", "ksat", "--n", "50", "--ratio", "4.26", "--seed", "18"});
  auto one = run_gridlock({"cnf", "gen", "ksat", "--n", "50", "--ratio", "4.26", "--seed", "17"});
  EXPECT_NE(read_text(other.out).clauses, read_text(one.out).clauses);
  EXPECT_EQ(read_text(one.out).clauses.size(), 213u);
  // Arguments that need quoting are quoted in the recorded command line.
  auto q = run_gridlock({"cnf", "gen", "ksat", "--n", "5", "--m", "2", "--seed", "3", "-o", "-"});
  EXPECT_EQ(q.out.substr(0, q.out.find('\n')), "c command: gridlock cnf gen ksat --n 5 --m 2 --seed 3 -o -");
}

TEST(CnfCli, CheckAnswersAndNamesTheRule) {
  std::string dir = test::temp_dir();
  auto yes = run_gridlock({"cnf", "check", GRIDLOCK_SOURCE_DIR "/examples/formulas/lsat-sat.cnf"});
  EXPECT_EQ(yes.exit_code, 10) << yes.out;
  EXPECT_NE(yes.out.find("c exactly-3 LSAT: yes\n"), std::string::npos);
  EXPECT_NE(yes.out.find("\ns YES\n"), std::string::npos);
  std::string f = test::write_file(dir + "/two.cnf", "p cnf 4 2\n1 2 3 0\n4 2 1 0\n");
  auto no = run_gridlock({"cnf", "check", f});
  EXPECT_EQ(no.exit_code, 20);
  EXPECT_NE(
      no.out.find("c exactly-3 LSAT: no: clauses 1 (1 2 3) and 2 (4 2 1) share 2 literals (1 2), not exactly 1\n"),
      std::string::npos)
      << no.out;
  EXPECT_NE(no.out.find("\ns NO\n"), std::string::npos);
  std::string short_clauses = test::write_file(dir + "/short.cnf", "p cnf 3 2\n1 2 0\n-1 3 0\n");
  EXPECT_EQ(run_gridlock({"cnf", "check", short_clauses}).exit_code, 20);
  auto relaxed = run_gridlock({"cnf", "check", "--relaxed", short_clauses});
  EXPECT_EQ(relaxed.exit_code, 10);
  EXPECT_NE(relaxed.out.find("c exactly-3 LSAT: no: clause 1 (1 2) has 2 literals, not 3\n"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(CnfCli, ErrorsAreFileLineMessage) {
  std::string dir = test::temp_dir();
  std::string bad = test::write_file(dir + "/bad.cnf", "p cnf 2 1\n1 3 0\n");
  for (const char* sub : {"check", "solve", "to-lsat"}) {
    auto r = run_gridlock({"cnf", sub, bad});
    EXPECT_EQ(r.exit_code, 1) << sub;
    EXPECT_EQ(r.err, "gridlock: error: " + bad + ":2: literal '3' out of range: the header declares 2 variables\n");
    EXPECT_EQ(r.out, "");
  }
  auto missing = run_gridlock({"cnf", "solve", dir + "/none.cnf"});
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_EQ(missing.err, "gridlock: error: " + dir + "/none.cnf: cannot open file\n");
  auto stdin_bad = run_gridlock({"cnf", "solve", "-"}, "p cnf 1 2\n1 0\n");
  EXPECT_EQ(stdin_bad.err,
            "gridlock: error: <stdin>:2: unexpected end of clauses: the header declares 2 clauses, the file gives 1\n");
  EXPECT_EQ(run_gridlock({"cnf", "solve", "--no-strict-count", "-"}, "p cnf 1 2\n1 0\n").exit_code, 10);
  auto usage = run_gridlock({"cnf", "frobnicate"});
  EXPECT_EQ(usage.exit_code, 1);
  EXPECT_EQ(usage.err,
            "gridlock: error: cnf: unknown subcommand 'frobnicate' (check, gen, to-lsat or solve; see 'gridlock cnf "
            "--help')\n");
  EXPECT_EQ(run_gridlock({"cnf"}).exit_code, 1);
  auto gen = run_gridlock({"cnf", "gen", "lsat", "--n", "10", "--m", "9"});
  EXPECT_EQ(gen.exit_code, 1);
  EXPECT_EQ(gen.err,
            "gridlock: error: cnf gen lsat: an LSAT formula with 10 variables and clauses of at least 3 literals has "
            "at most 8 clauses (got m=9)\n");
  EXPECT_EQ(run_gridlock({"cnf", "gen", "ksat", "--n", "5", "--m", "2", "--seed", "-1"}).err,
            "gridlock: error: --seed: want a seed, a whole number from 0 to 18446744073709551615, got '-1'\n");
  EXPECT_EQ(run_gridlock({"cnf", "gen", "ksat", "--n", "5"}).err,
            "gridlock: error: cnf gen: give exactly one of --m and --ratio\n");
  EXPECT_EQ(run_gridlock({"cnf", "gen", "nope", "--n", "5", "--m", "1"}).exit_code, 1);
  const std::string uf50 = std::string(GRIDLOCK_DATA_DIR) + "/satlib/uf50-218/uf50-01.cnf";
  EXPECT_EQ(run_gridlock({"cnf", "solve", "--solver", "exhaustive", uf50}).exit_code, 1);
  std::filesystem::remove_all(dir);
}

TEST(CnfCli, JsonEverywhere) {
  const std::string uf = GRIDLOCK_DATA_DIR "/satlib/uf20-91/uf20-01.cnf";
  auto solve = run_gridlock({"cnf", "solve", "--json", uf});
  EXPECT_EQ(solve.exit_code, 10);
  auto j = nlohmann::json::parse(solve.out);
  EXPECT_EQ(j["status"], "SATISFIABLE");
  EXPECT_EQ(j["exit_code"], 10);
  Formula f;
  ASSERT_FALSE(read_dimacs_file(uf, f));
  EXPECT_TRUE(satisfies(f, assignment(j["model"].get<std::vector<int>>(), 20)));
  auto check = nlohmann::json::parse(run_gridlock({"cnf", "check", "--json", uf}).out);
  EXPECT_EQ(check["status"], "NO");
  EXPECT_EQ(check["lsat"], false);
  EXPECT_EQ(check["violations"][0]["rule"], "intersects-two-clauses");
  EXPECT_EQ(check["violations"][0]["clauses"][0], 1);
  auto gen = nlohmann::json::parse(run_gridlock({"cnf", "gen", "ksat", "--n", "5", "--m", "3", "--json"}).out);
  EXPECT_EQ(gen["status"], "OK");
  EXPECT_EQ(read_text(gen["dimacs"].get<std::string>()).clauses.size(), 3u);
  auto red = nlohmann::json::parse(run_gridlock({"cnf", "to-lsat", "--json", uf}).out);
  EXPECT_EQ(red["stats"]["in_vars"], 20);
  Formula out = read_text(red["dimacs"].get<std::string>());
  EXPECT_EQ(red["stats"]["out_vars"], out.num_vars);
  EXPECT_TRUE(is_lsat(out, LsatForm::AtMost3));
}

TEST(CnfCli, HelpForEachSubcommand) {
  auto top = run_gridlock({"cnf", "--help"});
  EXPECT_EQ(top.exit_code, 0);
  EXPECT_EQ(top.out.rfind("usage: gridlock cnf SUBCOMMAND", 0), 0u);
  for (const char* sub : {"check", "gen", "to-lsat", "solve"}) {
    auto r = run_gridlock({"cnf", sub, "--help"});
    EXPECT_EQ(r.exit_code, 0) << sub;
    EXPECT_EQ(r.out.rfind(std::string("usage: gridlock cnf ") + sub, 0), 0u) << r.out;
    EXPECT_NE(r.out.find("--json"), std::string::npos) << sub;
  }
  EXPECT_NE(run_gridlock({"--help"}).out.find("  cnf "), std::string::npos);
}

TEST(CnfCli, SolveOutputHasOnlyCsvLines) {
  // CaDiCaL prints some messages by default ("c found falsified original
  // clause"); the adapter silences it, so stdout is ours alone.
  for (const char* text : {"p cnf 1 2\n1 0\n-1 0\n", "p cnf 1 1\n0\n", "p cnf 2 1\n1 -2 0\n"}) {
    auto r = run_gridlock({"cnf", "solve", "-"}, text);
    std::istringstream in(r.out);
    int status_lines = 0;
    for (std::string line; std::getline(in, line);) {
      EXPECT_TRUE(line.rfind("c ", 0) == 0 || line.rfind("s ", 0) == 0 || line.rfind("v ", 0) == 0) << line;
      status_lines += line.rfind("s ", 0) == 0;
    }
    EXPECT_EQ(status_lines, 1) << r.out;
    EXPECT_EQ(r.out.find("c found"), std::string::npos) << r.out;
  }
}

TEST(CnfCli, SolveLimitsAndOracles) {
  // Pigeonhole 10 -> 9 needs far more than 10 conflicts.
  std::string php = "p cnf 90 415\n";
  for (int i = 0; i < 10; ++i) {
    for (int j = 0; j < 9; ++j) php += std::to_string(i * 9 + j + 1) + " ";
    php += "0\n";
  }
  for (int j = 0; j < 9; ++j)
    for (int a = 0; a < 10; ++a)
      for (int b = a + 1; b < 10; ++b)
        php += std::to_string(-(a * 9 + j + 1)) + " " + std::to_string(-(b * 9 + j + 1)) + " 0\n";
  auto r = run_gridlock({"cnf", "solve", "--conflicts", "10", "-"}, php);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("\ns UNKNOWN\n"), std::string::npos);
  auto t = run_gridlock({"cnf", "solve", "--time", "0.05", "-"}, php);
  EXPECT_EQ(t.exit_code, 0);
  const std::string uf = GRIDLOCK_DATA_DIR "/satlib/uf20-91/uf20-02.cnf";
  const std::string uuf = GRIDLOCK_DATA_DIR "/satlib/uuf50-218/uuf50-02.cnf";
  for (const char* solver : {"cadical", "dpll", "exhaustive"}) {
    auto s = run_gridlock({"cnf", "solve", "--solver", solver, uf});
    EXPECT_EQ(s.exit_code, 10) << solver;
    Formula f;
    ASSERT_FALSE(read_dimacs_file(uf, f));
    EXPECT_TRUE(satisfies(f, assignment(v_literals(s.out), 20))) << solver;
  }
  EXPECT_EQ(run_gridlock({"cnf", "solve", "--solver", "dpll", uuf}).exit_code, 20);
}

}  // namespace
}  // namespace gridlock
