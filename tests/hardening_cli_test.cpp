// Hardening: every limit honoured, nothing half-written, no garbage
// accepted. One test per failure class that docs/errors.md lists, each with
// the real binary on real files.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <thread>

#include "cnf/dimacs.hpp"
#include "lattice/grid_format.hpp"
#include "support/cli.hpp"

namespace gridlock {
namespace {

namespace fs = std::filesystem;
using test::run_gridlock;

const std::string kExamples = GRIDLOCK_SOURCE_DIR "/examples/formulas/";
const std::string kSatlib = GRIDLOCK_DATA_DIR "/satlib/";

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Files left in dir whose name holds ".tmp." (an atomic write cut short).
std::vector<std::string> temp_files(const std::string& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().filename().string().find(".tmp.") != std::string::npos) out.push_back(e.path().string());
  return out;
}

// 1. --timeout is honoured by both engines on a large instance ("k300":
// random 3-SAT, 300 variables at ratio 4.26, through to-lsat: about 490 000
// nodes), set-up included. Before: UNKNOWN after 30 to
// 90 s for --timeout 1. The bound asserted is deliberately loose (the
// machines are shared): it catches a limit that is ignored, not a slow one.
TEST(HardeningCli, TimeoutIsHonouredByEveryEngineOnALargeInstance) {
  std::string dir = test::temp_dir();
  ASSERT_EQ(run_gridlock({"cnf", "gen", "ksat", "--n", "300", "--ratio", "4.26", "--seed", "3", "-o", dir + "/k.cnf"})
                .exit_code,
            0);
  ASSERT_EQ(run_gridlock({"cnf", "to-lsat", dir + "/k.cnf", "-o", dir + "/l.cnf"}).exit_code, 0);
  ASSERT_EQ(run_gridlock({"compile", dir + "/l.cnf", "-o", dir + "/k300.grid"}).exit_code, 0);
  for (const char* engine : {"states", "precedence"}) {
    SCOPED_TRACE(engine);
    auto t0 = std::chrono::steady_clock::now();
    auto r = run_gridlock({"solve", dir + "/k300.grid", "--timeout", "1", "--engine", engine, "--json"});
    const double wall = seconds_since(t0);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["status"], "UNKNOWN");
    EXPECT_LT(j["stats"]["seconds"].get<double>(), 1.0 * 1.1 + 0.2);
    EXPECT_LT(wall, 10.0);
  }
}

// 2. A full disk is an error, never a success: stdout checked at exit, every
// output file checked before it is renamed into place.
TEST(HardeningCli, FullDiskIsAnErrorNeverASuccess) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  std::string dir = test::temp_dir();
  const std::string tiny = kExamples + "tiny-sat.cnf";
  ASSERT_EQ(run_gridlock({"compile", tiny, "-o", dir + "/t.grid"}).exit_code, 0);
  const std::vector<std::vector<std::string>> to_stdout = {
      {"solve", dir + "/t.grid"},
      {"solve", dir + "/t.grid", "--json"},
      {"compile", tiny},
      {"render", dir + "/t.grid"},
      {"cnf", "gen", "ksat", "--n", "5", "--m", "10"},
      {"cnf", "solve", tiny, "--json"},
  };
  for (const auto& args : to_stdout) {
    SCOPED_TRACE(args[0] + " " + args[1]);
    auto r = test::run_gridlock_stdout_to(args, "/dev/full");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "gridlock: error: <stdout>: write failed: No space left on device\n");
  }
  auto g = run_gridlock({"cnf", "gen", "ksat", "--n", "5", "--m", "10", "-o", "/dev/full"});
  EXPECT_EQ(g.exit_code, 1);
  EXPECT_EQ(g.err, "gridlock: error: /dev/full: write failed: No space left on device\n");
  EXPECT_EQ(g.out.find("c wrote"), std::string::npos) << g.out;
  auto c = run_gridlock({"compile", tiny, "-o", "/dev/full"});
  EXPECT_EQ(c.exit_code, 1);
  EXPECT_EQ(c.err, "gridlock: error: /dev/full: write failed: No space left on device\n");
}

// 3. SIGTERM during gen-instances: only whole files stay, the manifest is
// written last and lists exactly the instances in the folder. 60 variables:
// every NO instance waits for its NO certificate, which at 150 variables can
// take the solver its full minute before the first file is written.
TEST(HardeningCli, SigtermDuringGenInstancesLeavesOnlyWholeFilesAndAMatchingManifest) {
  std::string dir = test::temp_dir() + "/set";
  auto p = test::start_gridlock(
      {"gen-instances", "-o", dir, "--vars", "60", "--threshold", "200", "--lsat", "0", "--seed", "5"});
  // Wait for the first instance, then stop it mid-campaign.
  auto t0 = std::chrono::steady_clock::now();
  auto grids = [&] {
    size_t n = 0;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec)) n += e.path().extension() == ".grid";
    return n;
  };
  while (grids() == 0 && seconds_since(t0) < 60) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_GT(grids(), 0u) << "no instance written in 60 s";
  kill(p.pid, SIGTERM);
  auto r = test::finish_gridlock(p);
  ASSERT_EQ(r.exit_code, 143) << r.err;
  EXPECT_NE(r.out.find("c INTERRUPTED by signal 15"), std::string::npos) << r.out;
  EXPECT_TRUE(temp_files(dir).empty());
  auto m = nlohmann::json::parse(test::read_file(dir + "/manifest.json"));
  EXPECT_EQ(m["interrupted"], true);
  std::set<std::string> listed, present;
  for (const auto& e : m["instances"]) {
    listed.insert(e["instance"].get<std::string>());
    EXPECT_TRUE(e["seed"].is_string());
  }
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() == ".grid") present.insert(e.path().filename().string());
    if (e.path().extension() == ".grid") {
      Instance inst;
      EXPECT_FALSE(read_instance_file(e.path().string(), inst)) << e.path();
    }
    if (e.path().extension() == ".cnf") {
      Formula f;
      EXPECT_FALSE(read_dimacs_file(e.path().string(), f)) << e.path();
    }
  }
  EXPECT_EQ(listed, present);
  EXPECT_LT(listed.size(), 200u);
}

// 4. A directory as input is "is a directory", wherever a file is read.
TEST(HardeningCli, DirectoryInputIsADirectory) {
  std::string dir = test::temp_dir();
  fs::create_directories(dir + "/adir.grid");
  const std::string d = dir + "/adir.grid";
  ASSERT_EQ(run_gridlock({"compile", kExamples + "tiny-sat.cnf", "-o", dir + "/t.grid"}).exit_code, 0);
  const std::vector<std::vector<std::string>> cases = {
      {"solve", d},
      {"render", d},
      {"check", dir + "/t.grid", "--order-file", d},
      {"cnf", "solve", d},
      {"compile", d},
      {"lift", kExamples + "tiny-sat.cnf", "--model", d},
      {"render", dir + "/t.grid", "-o", d},
  };
  for (const auto& args : cases) {
    SCOPED_TRACE(args[0]);
    auto r = run_gridlock(args);
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "gridlock: error: " + d + ": is a directory, not a file\n");
  }
}

// 5. One numeric option parser: negatives, zero where meaningless, junk and
// overflow are errors that name the option.
TEST(HardeningCli, NegativeZeroAndJunkNumbersAreRejectedNamingTheOption) {
  std::string dir = test::temp_dir();
  const std::string tiny = kExamples + "tiny-sat.cnf";
  ASSERT_EQ(run_gridlock({"compile", tiny, "-o", dir + "/t.grid"}).exit_code, 0);
  const std::string g = dir + "/t.grid";
  struct Case {
    std::vector<std::string> args;
    std::string option;
  };
  const std::vector<Case> cases = {
      {{"solve", g, "--max-states", "-5"}, "--max-states"},
      {{"solve", g, "--max-states", "0"}, "--max-states"},
      {{"solve", g, "--timeout", "-1"}, "--timeout"},
      {{"solve", g, "--timeout", "0"}, "--timeout"},
      {{"solve", g, "--timeout", "nan"}, "--timeout"},
      {{"solve", g, "--timeout", "1e9999"}, "--timeout"},
      {{"fuzz", "--count", "-3"}, "--count"},
      {{"fuzz", "--count", "0"}, "--count"},
      {{"fuzz", "--time", "-1"}, "--time"},
      {{"fuzz", "--seed=-5", "--count", "1"}, "--seed"},
      {{"fuzz", "--seed", "18446744073709551616", "--count", "1"}, "--seed"},
      {{"fuzz", "--shard", "0/-1"}, "--shard"},
      {{"fuzz", "--min-vars", "0"}, "--min-vars"},
      {{"verify", "--timeout", "-1", tiny}, "--timeout"},
      {{"verify", "--max-states", "-1", tiny}, "--max-states"},
      {{"verify", "--picture-nodes", "-1", tiny}, "--picture-nodes"},
      {{"cnf", "solve", "--conflicts", "-1", tiny}, "--conflicts"},
      {{"cnf", "solve", "--time", "-1", tiny}, "--time"},
      {{"cnf", "check", "--max-violations", "-1", tiny}, "--max-violations"},
      {{"cnf", "gen", "ksat", "--n", "-5", "--m", "3"}, "--n"},
      {{"cnf", "gen", "ksat", "--n", "5", "--m", "3x"}, "--m"},
      {{"gen-instances", "-o", dir + "/gi", "--threshold", "-1"}, "--threshold"},
      {{"gen-instances", "-o", dir + "/gi", "--yes", "-2"}, "--yes"},
      {{"gen-instances", "-o", dir + "/gi", "--vars", "2"}, "--vars"},
      {{"gen-instances", "-o", dir + "/gi", "--timeout", "0"}, "--timeout"},
      {{"gadget", "clause", "-k", "-1"}, "--literals"},
  };
  for (const auto& c : cases) {
    std::string line;
    for (const auto& a : c.args) line += a + " ";
    SCOPED_TRACE(line);
    auto r = run_gridlock(c.args);
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err.rfind("gridlock: error: " + c.option + ": want ", 0), 0u) << r.err;
  }
  EXPECT_FALSE(fs::exists(dir + "/gi"));  // rejected before anything is written
  // The largest seed is accepted and kept exactly (a string in JSON).
  auto f = run_gridlock({"fuzz", "--seed", "18446744073709551615", "--count", "1", "--json"});
  ASSERT_EQ(f.exit_code, 0) << f.err;
  EXPECT_EQ(nlohmann::json::parse(f.out)["seed"], "18446744073709551615");
}

// 6. --break-gadget with a kind that does not apply is an error, never the
// sound gadget labelled broken.
TEST(HardeningCli, BreakGadgetMustBreakTheGadgetDrawn) {
  const std::vector<std::pair<std::string, std::string>> applies = {{"variable", "variable-loose-y"},
                                                                    {"clause", "clause-loose"},
                                                                    {"clause", "clause-tight"},
                                                                    {"order", "order-loose"},
                                                                    {"order", "order-drop-release"}};
  int refused = 0, drawn = 0;
  for (const std::string kind : {"variable", "clause", "order"})
    for (const std::string m :
         {"variable-loose-y", "clause-loose", "clause-tight", "order-loose", "order-drop-release"}) {
      SCOPED_TRACE(std::string(kind).append(" ").append(m));
      auto r = run_gridlock({"gadget", kind, "--break-gadget", m});
      bool ok = std::find(applies.begin(), applies.end(), std::make_pair(kind, m)) != applies.end();
      if (ok) {
        EXPECT_EQ(r.exit_code, 0) << r.err;
        EXPECT_NE(r.out.find("BROKEN GADGET (" + m + ")"), std::string::npos);
        auto strip = [](const std::string& text) {  // the instance without its comments
          std::string out, line;
          std::istringstream in(text);
          while (std::getline(in, line))
            if (line.rfind("c ", 0) != 0) out += line + "\n";
          return out;
        };
        EXPECT_NE(strip(r.out), strip(run_gridlock({"gadget", kind}).out)) << "the broken gadget is the sound one";
        ++drawn;
      } else {
        EXPECT_EQ(r.exit_code, 1);
        EXPECT_EQ(r.out, "");
        EXPECT_NE(r.err.find("--break-gadget " + m + " breaks the"), std::string::npos) << r.err;
        ++refused;
      }
    }
  // Each mutation breaks exactly one kind: 5 pairs draw a really broken
  // gadget (each differs from the sound one), the other 10 are refused.
  EXPECT_EQ(refused, 10);
  EXPECT_EQ(drawn, 5);
}

// 7. Sizes up front: a header count never drives allocation beyond what the
// file holds; a compiled instance beyond the format is refused before it is
// drawn. Each answer is immediate and names FILE:LINE.
TEST(HardeningCli, HeaderCountsAreCheckedBeforeAllocating) {
  std::string dir = test::temp_dir();
  std::string big = test::write_file(dir + "/big.cnf", "c 22 bytes of formula\np cnf 2000000000 1\n1 0\n");
  const std::string unused = "gridlock: error: " + big +
                             ":2: the header declares 2000000000 variables but no clause uses one above 1: at most "
                             "1048576 unused variables beyond the last one used are accepted\n";
  for (const std::vector<std::string>& args : {std::vector<std::string>{"cnf", "solve", big},
                                               {"compile", big, "-o", dir + "/x.grid"},
                                               {"cnf", "to-lsat", big},
                                               {"lift", big, "--model", "1"},
                                               {"verify", big}}) {
    SCOPED_TRACE(args[0] + " " + args[1]);
    auto r = run_gridlock(args);
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, unused);
  }
  std::string wide = test::write_file(dir + "/wide.cnf", "p cnf 781000 1\n1 0\n");
  auto c = run_gridlock({"compile", wide, "-o", dir + "/w.grid"});
  EXPECT_EQ(c.exit_code, 1);
  EXPECT_EQ(c.err,
            "gridlock: error: " + wide +
                ":1: the compiled instance would have 33583009 nodes (43n + 5L + 15m - 11; 33583011 in the continuous "
                "model), more than the "
                ".grid format's limit of 33554432\n");
  EXPECT_FALSE(fs::exists(dir + "/w.grid"));
  // Inside the discrete limit, 1 node over it in the continuous model (the
  // campaign's `internal:` midway): refused at reading by every command.
  std::string edge = test::write_file(dir + "/edge.cnf", "p cnf 780334 1\n1 2 3 4 5 6 7 8 9 10 11 12 13 0\n");
  for (const std::vector<std::string>& args : {std::vector<std::string>{"compile", edge, "-o", dir + "/e.grid"},
                                               {"verify", edge, "--model", "continuous"},
                                               {"verify", edge}}) {
    SCOPED_TRACE(args[0] + " " + args.back());
    auto e = run_gridlock(args);
    EXPECT_EQ(e.exit_code, 1);
    EXPECT_EQ(e.err, "gridlock: error: " + edge +
                         ":1: the compiled instance would have 33554431 nodes (43n + 5L + 15m - 11; 33554433 in the "
                         "continuous model), more than the .grid format's limit of 33554432\n");
  }
  // Just inside both limits: accepted (to-lsat passes it through).
  std::string ok = test::write_file(dir + "/ok.cnf", "p cnf 1048577 1\n1 0\n");
  EXPECT_EQ(run_gridlock({"cnf", "to-lsat", ok, "-o", dir + "/ok-l.cnf"}).exit_code, 0);
  // Out of memory names the file and the task (address space limited to
  // 400 MB for the child; the instance would need several GB). Not under
  // AddressSanitizer: its shadow memory needs far more address space than
  // that, so the child could not even start.
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "out-of-memory case skipped under AddressSanitizer (it reserves terabytes of address space)";
#endif
  std::string huge = test::write_file(dir + "/huge.cnf", "p cnf 700000 1\n1 0\n");
  struct rlimit old {};
  getrlimit(RLIMIT_AS, &old);
  struct rlimit small = old;
  small.rlim_cur = 400ull << 20;
  ASSERT_EQ(setrlimit(RLIMIT_AS, &small), 0);
  auto p = test::start_gridlock({"compile", huge, "-o", dir + "/huge.grid"});
  setrlimit(RLIMIT_AS, &old);
  auto oom = test::finish_gridlock(p);
  EXPECT_EQ(oom.exit_code, 1);
  EXPECT_EQ(oom.err, "gridlock: error: " + huge + ": out of memory while compiling the formula\n");
  EXPECT_FALSE(fs::exists(dir + "/huge.grid"));
}

// 8. Models are SAT-competition answers (or literals on the command line),
// every variable given.
TEST(HardeningCli, ModelsAreSatCompetitionAnswersOrLiterals) {
  std::string dir = test::temp_dir();
  const std::string f = kExamples + "tiny-sat.cnf";  // (1 2 3)(-2 3)(1 -3), 3 variables
  auto err_of = [&](const std::string& name, const std::string& text) {
    std::string path = test::write_file(dir + "/" + name, text);
    auto r = run_gridlock({"lift", f, "--model", path});
    EXPECT_EQ(r.exit_code, 1) << name;
    return r.err.substr(r.err.find(path) + path.size());
  };
  EXPECT_EQ(err_of("empty", ""), ":1: empty model: want 's SATISFIABLE' and 'v' lines ending in 0\n");
  EXPECT_EQ(err_of("unsat", "s UNSATISFIABLE\n"),
            ":1: the answer is not 's SATISFIABLE' but 's UNSATISFIABLE': it holds no model\n");
  EXPECT_EQ(err_of("nostatus", "v 1 -2 3 0\n"), ":1: no 's SATISFIABLE' line: not a SAT-competition answer\n");
  EXPECT_EQ(err_of("noend", "s SATISFIABLE\nv 1 -2 3\n"), ":2: the 'v' lines do not end in 0 (truncated?)\n");
  EXPECT_EQ(err_of("missing", "s SATISFIABLE\nv 1 -2 0\n"),
            ":2: variable 3 is missing: the model must give all 3 variables\n");
  EXPECT_EQ(err_of("minus0", "s SATISFIABLE\nv -0 0\n"), ":2: '-0' is not a literal (0 alone ends the model)\n");
  EXPECT_EQ(err_of("twice", "s SATISFIABLE\ns SATISFIABLE\n"), ":2: second status line (the first is line 1)\n");
  // A real answer, and the same literals on the command line.
  auto solved = run_gridlock({"cnf", "solve", f});
  ASSERT_EQ(solved.exit_code, 10);
  std::string model = test::write_file(dir + "/model", solved.out);
  EXPECT_EQ(run_gridlock({"lift", f, "--model", model}).exit_code, 10);
  EXPECT_EQ(run_gridlock({"lift", f, "--model", "1 -2 3"}).exit_code, 10);
  EXPECT_EQ(run_gridlock({"lift", f, "--model", "1 -2 3 0"}).exit_code, 10);
  EXPECT_EQ(run_gridlock({"lift", f, "--model", "1 2 -3"}).exit_code, 20);  // falsifies (-2 3)
  auto partial = run_gridlock({"lift", f, "--model", "1 -2"});
  EXPECT_EQ(partial.err, "gridlock: error: --model: variable 3 is missing: the model must give all 3 variables\n");
}

// 9. gen-instances has a per-formula --timeout (a formula not decided in time
// is skipped, noted in the output and the manifest) and finishes.
TEST(HardeningCli, GenInstancesHasAPerFormulaTimeout) {
  std::string dir = test::temp_dir() + "/set";
  auto r = run_gridlock(
      {"gen-instances", "-o", dir, "--vars", "1000", "--threshold", "1", "--lsat", "0", "--timeout", "0.5"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto m = nlohmann::json::parse(test::read_file(dir + "/manifest.json"));
  EXPECT_EQ(m["interrupted"], false);
  EXPECT_EQ(m["instances"].size() + m["skipped"].get<size_t>(), 1u);
  if (m["skipped"] == 1) {
    EXPECT_NE(r.out.find("skipped, CaDiCaL did not decide it"), std::string::npos) << r.out;
  }
}

// 10. SIGINT during fuzz and verify: a partial summary marked interrupted
// (valid JSON in --json mode), exit 130; SIGTERM: 143.
TEST(HardeningCli, SignalsDuringFuzzAndVerifyGiveAPartialSummary) {
  std::string dir = test::temp_dir();
  {
    auto p = test::start_gridlock({"fuzz", "--json", "--count", "100000000", "--out", dir + "/f"});
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
    kill(p.pid, SIGINT);
    auto r = test::finish_gridlock(p);
    EXPECT_EQ(r.exit_code, 130) << r.err;
    auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["interrupted"], true);
    EXPECT_LT(j["formulas"].get<uint64_t>(), 100000000u);
  }
  {
    auto p = test::start_gridlock({"fuzz", "--count", "100000000", "--out", dir + "/f"});
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
    kill(p.pid, SIGTERM);
    auto r = test::finish_gridlock(p);
    EXPECT_EQ(r.exit_code, 143) << r.err;
    EXPECT_NE(r.out.find("c INTERRUPTED by signal 15: partial campaign\ns AGREE\n"), std::string::npos) << r.out;
  }
  {
    auto p = test::start_gridlock({"verify", "--json", kSatlib + "uf50-218", "--reproducers", dir + "/v"});
    std::this_thread::sleep_for(std::chrono::milliseconds(2000));
    kill(p.pid, SIGINT);
    auto r = test::finish_gridlock(p);
    EXPECT_EQ(r.exit_code, 130) << r.err;
    auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["interrupted"], true);
    EXPECT_EQ(j["exit_code"], 130);
    EXPECT_LT(j["summary"]["formulas"].get<size_t>(), j["inputs"].get<size_t>());
    EXPECT_EQ(j["formulas"].size(), j["summary"]["formulas"].get<size_t>());
  }
  {
    auto p = test::start_gridlock({"verify", kSatlib + "uf50-218", "--reproducers", dir + "/v"});
    std::this_thread::sleep_for(std::chrono::milliseconds(2000));
    kill(p.pid, SIGINT);
    auto r = test::finish_gridlock(p);
    EXPECT_EQ(r.exit_code, 130) << r.err;
    EXPECT_NE(r.out.find("summary: "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("INTERRUPTED by signal 2"), std::string::npos) << r.out;
  }
}

// 11. No second anchor, no output over an input, no half set of outputs, no
// mixed benchmark sets; seeds survive JSON readers.
TEST(HardeningCli, NoSilentOverwritesOrMixedSets) {
  std::string dir = test::temp_dir();
  const std::string tiny = kExamples + "tiny-sat.cnf";
  std::string two = test::write_file(dir + "/two.grid", "p grid 1 0 0 0\nn 0 0\na 0 0\na 0 0\n");
  auto a = run_gridlock({"solve", two});
  EXPECT_EQ(a.exit_code, 1);
  EXPECT_EQ(a.err, "gridlock: error: " + two + ":4: second anchor line (the first is line 3)\n");

  ASSERT_EQ(run_gridlock({"compile", tiny, "-o", dir + "/same.grid"}).exit_code, 0);
  const std::string before = test::read_file(dir + "/same.grid");
  auto r = run_gridlock({"render", dir + "/same.grid", "-o", dir + "/same.grid"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "gridlock: error: " + dir + "/same.grid: output would overwrite the input " + dir + "/same.grid\n");
  r = run_gridlock({"render", dir + "/same.grid", "-o", dir + "/./same.grid"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(test::read_file(dir + "/same.grid"), before);
  r = run_gridlock({"cnf", "to-lsat", tiny, "-o", tiny});
  EXPECT_EQ(r.exit_code, 1);

  auto c = run_gridlock({"compile", tiny, "-o", dir + "/ok.grid", "--svg", "/proc/x.svg"});
  EXPECT_EQ(c.exit_code, 1);
  EXPECT_FALSE(fs::exists(dir + "/ok.grid"));

  std::string set = dir + "/set";
  ASSERT_EQ(run_gridlock({"gen-instances", "-o", set, "--vars", "5", "--threshold", "2", "--lsat", "0"}).exit_code, 0);
  auto again = run_gridlock({"gen-instances", "-o", set, "--vars", "5", "--threshold", "1", "--lsat", "0"});
  EXPECT_EQ(again.exit_code, 1);
  EXPECT_EQ(again.err, "gridlock: error: " + set + ": folder is not empty (give --force to replace the set in it)\n");
  auto forced = run_gridlock({"gen-instances", "-o", set, "--vars", "5", "--threshold", "1", "--lsat", "0", "--seed",
                              "18446744073709551615", "--force"});
  ASSERT_EQ(forced.exit_code, 0) << forced.err;
  auto m = nlohmann::json::parse(test::read_file(set + "/manifest.json"));
  EXPECT_EQ(m["seed"], "18446744073709551615");
  ASSERT_EQ(m["instances"].size(), 1u);
  EXPECT_TRUE(m["instances"][0]["seed"].is_string());
  size_t grids = 0;
  for (const auto& e : fs::directory_iterator(set)) grids += e.path().extension() == ".grid";
  EXPECT_EQ(grids, 1u);  // the old set's threshold-2 is gone
}

// 12. Empty files give FILE:LINE (line 1), as the docs promise.
TEST(HardeningCli, EmptyFilesGiveALineNumber) {
  std::string dir = test::temp_dir();
  std::string e = test::write_file(dir + "/empty", "");
  EXPECT_EQ(run_gridlock({"solve", e}).err, "gridlock: error: " + e + ":1: empty input: no 'p grid' header\n");
  EXPECT_EQ(run_gridlock({"cnf", "solve", e}).err, "gridlock: error: " + e + ":1: empty input: no 'p cnf' header\n");
  auto m = run_gridlock({"lift", kExamples + "tiny-sat.cnf", "--model", e});
  EXPECT_EQ(m.err, "gridlock: error: " + e + ":1: empty model: want 's SATISFIABLE' and 'v' lines ending in 0\n");
}

// ---------------------------------------------------------------- round 2
// (docs/errors.md, "Round 2"): one test per class the second adversarial
// campaign found; each failed before its fix.

// A hard link to path (the same file under another name), or "" when the
// file system refuses links.
std::string hard_link(const std::string& path, const std::string& link) {
  std::error_code ec;
  fs::create_hard_link(path, link, ec);
  return ec ? "" : link;
}

// 13. Inputs are sacred: no output over a file the command reads (compared
// by device and inode: a hard link is the same file), whatever option
// names it. Before: verify/gen-instances --json-out, animate/check over the
// schedule, merge -o over a shard all overwrote their input.
TEST(HardeningCli, NoCommandWritesOverAFileItReads) {
  std::string dir = test::temp_dir();
  const std::string f = dir + "/f.cnf";
  fs::copy_file(kExamples + "tiny-sat.cnf", f);
  const std::string before = test::read_file(f);
  auto refused = [&](const std::vector<std::string>& args, const std::string& victim) {
    auto r = run_gridlock(args);
    EXPECT_EQ(r.exit_code, 1) << args[0] << ": " << r.err;
    EXPECT_NE(r.err.find("output would overwrite the input"), std::string::npos) << args[0] << ": " << r.err;
    EXPECT_EQ(test::read_file(victim), victim == f ? before : test::read_file(victim));
  };
  refused({"verify", f, "--json-out", f}, f);
  refused({"gen-instances", "-o", dir + "/set", "--formula", f, "--threshold", "0", "--lsat", "0", "--json-out", f}, f);
  EXPECT_EQ(test::read_file(f), before);
  const std::string link = hard_link(f, dir + "/link.cnf");
  if (!link.empty()) {
    refused({"verify", f, "--json-out", link}, f);
    refused({"cnf", "to-lsat", f, "-o", link}, f);
    EXPECT_EQ(test::read_file(f), before);
  }
  // The schedule a command reads is an input too.
  ASSERT_EQ(run_gridlock({"compile", f, "-o", dir + "/t.grid"}).exit_code, 0);
  auto s = run_gridlock({"solve", dir + "/t.grid"});
  ASSERT_EQ(s.exit_code, 10) << s.err;
  const std::string sched = test::write_file(dir + "/t.schedule", s.out);
  refused({"animate", dir + "/t.grid", "--order-file", sched, "-o", sched}, sched);
  refused({"check", dir + "/t.grid", "--order-file", sched, "--svg", sched}, sched);
  EXPECT_EQ(test::read_file(sched), s.out);
  // merge -o over one of its shards.
  ASSERT_EQ(run_gridlock({"verify", f, "--shard", "0/2", "--json-out", dir + "/s0.json"}).exit_code, 0);
  ASSERT_EQ(run_gridlock({"verify", f, "--shard", "1/2", "--json-out", dir + "/s1.json"}).exit_code, 0);
  const std::string shard0 = test::read_file(dir + "/s0.json");
  refused({"merge", dir + "/s0.json", dir + "/s1.json", "-o", dir + "/s0.json"}, dir + "/s0.json");
  EXPECT_EQ(test::read_file(dir + "/s0.json"), shard0);
  EXPECT_TRUE(temp_files(dir).empty());
}

// 14. --force removes only what gridlock wrote there (its ledger and
// manifests), never an input, never a file of the user's. Before:
// `gen-instances -o . --force` deleted every .cnf and .grid in the folder,
// the input formula included.
TEST(HardeningCli, ForceRemovesOnlyWhatGridlockWrote) {
  std::string dir = test::temp_dir() + "/work";
  fs::create_directories(dir);
  const std::string f = dir + "/mine.cnf";
  fs::copy_file(kExamples + "tiny-sat.cnf", f);
  const std::string user_grid = test::write_file(dir + "/notes.grid", "c the user's own file\n");
  auto r = run_gridlock(
      {"gen-instances", "-o", dir, "--force", "--formula", f, "--threshold", "1", "--lsat", "0", "--vars", "5"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(f));
  EXPECT_TRUE(fs::exists(user_grid));
  EXPECT_TRUE(fs::exists(dir + "/given-mine.grid"));
  // Again with --force: the previous set goes, the user's files stay.
  r = run_gridlock(
      {"gen-instances", "-o", dir, "--force", "--formula", f, "--threshold", "0", "--lsat", "1", "--vars", "5"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(f));
  EXPECT_EQ(test::read_file(user_grid), "c the user's own file\n");
  EXPECT_FALSE(fs::exists(dir + "/threshold-1.grid"));
  EXPECT_TRUE(fs::exists(dir + "/lsat-1.grid"));
  // A --model continuous set leaves .times files: a later --force set of
  // another model removes them too (before: they stayed behind).
  std::string set = test::temp_dir() + "/set";
  ASSERT_EQ(run_gridlock({"gen-instances", "-o", set, "--model", "continuous", "--vars", "4", "--threshold", "0",
                          "--lsat", "3", "--seed", "2"})
                .exit_code,
            0);
  ASSERT_EQ(
      run_gridlock({"gen-instances", "-o", set, "--force", "--vars", "4", "--threshold", "1", "--lsat", "0"}).exit_code,
      0);
  auto m = nlohmann::json::parse(test::read_file(set + "/manifest.json"));
  std::set<std::string> listed = {"manifest.json", "run.json", ".gridlock-files"}, present;
  for (const auto& e : m["instances"]) {
    listed.insert(e["instance"].get<std::string>());
    listed.insert(e["formula"].get<std::string>());
    if (e["certificate"].contains("file")) listed.insert(e["certificate"]["file"].get<std::string>());
  }
  for (const auto& e : fs::directory_iterator(set)) present.insert(e.path().filename().string());
  EXPECT_EQ(present, listed);
}

// 15. Empty and root-level output paths are refused before any work.
// Before: `fuzz --out ''` wrote its reproducer under the file-system root.
TEST(HardeningCli, EmptyAndRootOutputPathsAreRefused) {
  const std::string tiny = kExamples + "tiny-sat.cnf";
  auto r = run_gridlock({"fuzz", "--out", "", "--count", "1"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "gridlock: error: --out: empty path: give a folder\n");
  r = run_gridlock({"fuzz", "--out", "/", "--count", "1"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("is the file-system root"), std::string::npos) << r.err;
  r = run_gridlock({"verify", tiny, "--reproducers", "/.."});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("is the file-system root"), std::string::npos) << r.err;
  const std::string at_root = "/gridlock-hardening-test-do-not-create.grid";
  r = run_gridlock({"compile", tiny, "-o", at_root});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("is at the file-system root"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(at_root));
  r = run_gridlock({"compile", tiny, "-o", ""});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "gridlock: error: --output: empty path: give a file\n");
}

// 16. Sets carry their identity: shards of different runs never share a
// gen-instances folder, `merge` refuses shards of different runs (verify:
// different input lists of the same length), and two inputs that would
// write the same files are refused up front. Before: the manifest labelled
// a NO instance YES, and merge listed one formula twice and dropped another.
TEST(HardeningCli, SetsOfDifferentRunsNeverMix) {
  std::string dir = test::temp_dir();
  const std::string set = dir + "/set";
  auto shard = [&](const std::string& k, const std::string& seed) {
    return run_gridlock({"gen-instances", "-o", set, "--shard", k + "/2", "--seed", seed, "--vars", "5", "--threshold",
                         "2", "--lsat", "0", "--json-out", dir + "/g" + k + "-" + seed + ".json"});
  };
  ASSERT_EQ(shard("0", "1").exit_code, 0);
  auto other = shard("1", "2");
  EXPECT_EQ(other.exit_code, 1);
  EXPECT_NE(other.err.find(set + ": holds a set of another run"), std::string::npos) << other.err;
  EXPECT_FALSE(fs::exists(set + "/manifest-shard-1-of-2.json"));
  ASSERT_EQ(shard("1", "1").exit_code, 0);
  auto m = run_gridlock({"merge", dir + "/g0-1.json", dir + "/g1-1.json"});
  ASSERT_EQ(m.exit_code, 0) << m.err;
  auto merged = nlohmann::json::parse(m.out);
  EXPECT_EQ(merged["instances"].size(), 2u);
  EXPECT_EQ(merged["run_id"].get<std::string>().size(), 16u);
  EXPECT_EQ(merged["run"]["options"]["seed"], "1");

  // verify shards of two input lists of the same length.
  const std::string a = kSatlib + "uf20-91/uf20-01.cnf", b = kSatlib + "uf20-91/uf20-02.cnf";
  const std::string c = kSatlib + "uf20-91/uf20-03.cnf";
  ASSERT_EQ(run_gridlock({"verify", a, b, c, "--shard", "0/2", "--json-out", dir + "/v0.json"}).exit_code, 0);
  ASSERT_EQ(run_gridlock({"verify", a, c, b, "--shard", "1/2", "--json-out", dir + "/v1.json"}).exit_code, 0);
  auto v = run_gridlock({"merge", dir + "/v0.json", dir + "/v1.json"});
  EXPECT_EQ(v.exit_code, 1);
  EXPECT_NE(v.err.find("\"run_id\" differs"), std::string::npos) << v.err;
  auto v0 = nlohmann::json::parse(test::read_file(dir + "/v0.json"));
  ASSERT_EQ(v0["run"]["inputs"].size(), 3u);
  EXPECT_EQ(v0["run"]["inputs"][0]["sha256"].get<std::string>().size(), 64u);

  // Two given formulas named alike would write the same given-x.* files.
  fs::create_directories(dir + "/p");
  fs::create_directories(dir + "/q");
  fs::copy_file(kExamples + "tiny-sat.cnf", dir + "/p/x.cnf");
  fs::copy_file(kExamples + "tiny-unsat.cnf", dir + "/q/x.cnf");
  auto clash = run_gridlock({"gen-instances", "-o", dir + "/clash", "--formula", dir + "/p/x.cnf", "--formula",
                             dir + "/q/x.cnf", "--threshold", "0", "--lsat", "0"});
  EXPECT_EQ(clash.exit_code, 1);
  EXPECT_NE(clash.err.find("two inputs named 'x'"), std::string::npos) << clash.err;
  EXPECT_FALSE(fs::exists(dir + "/clash"));
}

// 17. Findings survive: an output folder that cannot be made is an error
// before any work, naming the folder (never "internal:"). Before: the
// fuzzer found a counterexample, then failed with "internal:" and lost it.
// (A path below a regular file fails for every user, root included.)
TEST(HardeningCli, UnwritableOutputFoldersAreRefusedBeforeAnyWork) {
  std::string dir = test::temp_dir();
  const std::string file = test::write_file(dir + "/plain", "x\n");
  const std::string bad = file + "/sub";
  const std::vector<std::vector<std::string>> cases = {
      {"fuzz", "--break-gadget", "clause-loose", "--count", "50", "--out", bad},
      {"verify", kExamples + "tiny-sat.cnf", "--break-gadget", "clause-loose", "--reproducers", bad},
      {"verify", kExamples + "tiny-sat.cnf", "--pictures", bad},
      {"gen-instances", "-o", bad, "--threshold", "1", "--lsat", "0", "--vars", "5"},
  };
  for (const auto& args : cases) {
    SCOPED_TRACE(args[0] + " " + args.back());
    auto t0 = std::chrono::steady_clock::now();
    auto r = run_gridlock(args);
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_EQ(r.err.rfind("gridlock: error: " + bad + ": ", 0), 0u) << r.err;
    EXPECT_EQ(r.err.find("internal"), std::string::npos) << r.err;
    EXPECT_EQ(r.out.find("disagree"), std::string::npos) << r.out;  // refused before any formula was checked
    EXPECT_LT(seconds_since(t0), 5.0);
  }
}

// A row of 2k nodes with an expansion on every other edge (k expansions,
// each its own coupling): collision-free, horizontal-only; the solver finds
// an order at once, and the simulator's check of it is quadratic.
std::string expansion_row(const std::string& path, int k) {
  const int n = 2 * k;
  std::string g = "p grid " + std::to_string(n) + " " + std::to_string(n - 1) + " " + std::to_string(k) + " 0\n";
  for (int i = 0; i < n; ++i) g += "n " + std::to_string(i) + " 0\n";
  for (int i = 0; i + 1 < n; ++i) g += "e " + std::to_string(i) + " 0 " + std::to_string(i + 1) + " 0\n";
  for (int i = 0; i < k; ++i) g += "o x" + std::to_string(i) + " expand " + std::to_string(2 * i) + " 0 +x\n";
  return test::write_file(path, g);
}

// 18. One limit for everything: --timeout covers the final simulator check
// of a solution (before: `solve --timeout 5` on a 25 000-expansion row took
// 53 s), collide and check have a --timeout (before: none; 37 s at 40 000
// nodes for collide), and
// `cnf solve --time/--conflicts` bind every solver (before: dpll ignored
// both). Bounds are loose (shared machines): they catch an ignored limit.
TEST(HardeningCli, EveryDecisionCommandHonoursItsLimit) {
  std::string dir = test::temp_dir();
  const std::string row = expansion_row(dir + "/row.grid", 25000);
  auto t0 = std::chrono::steady_clock::now();
  auto r = run_gridlock({"solve", row, "--timeout", "2", "--json"});
  double wall = seconds_since(t0);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["status"], "UNKNOWN");
  EXPECT_LT(wall, 12.0);

  t0 = std::chrono::steady_clock::now();
  r = run_gridlock({"collide", row, "--model", "discrete", "--method", "pairwise", "--timeout", "1"});
  wall = seconds_since(t0);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("s UNKNOWN"), std::string::npos) << r.out;
  EXPECT_LT(wall, 10.0);
  // check: the simulator's deadline (before: no --timeout; 25 000 couplings
  // run one after another take minutes).
  std::string order;
  for (int i = 0; i < 25000; ++i) order += "x" + std::to_string(i) + " ";
  const std::string order_file = test::write_file(dir + "/row.order", order + "\n");
  t0 = std::chrono::steady_clock::now();
  r = run_gridlock({"check", row, "--order-file", order_file, "--timeout", "1", "--json"});
  wall = seconds_since(t0);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["status"], "UNKNOWN");
  EXPECT_LT(wall, 10.0);
  auto bad = run_gridlock({"collide", row, "--timeout", "0"});
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("--timeout"), std::string::npos) << bad.err;

  // dpll: a hard random formula (no learning: far beyond a second).
  ASSERT_EQ(run_gridlock({"cnf", "gen", "ksat", "--n", "250", "--ratio", "4.26", "--seed", "9", "-o", dir + "/h.cnf"})
                .exit_code,
            0);
  t0 = std::chrono::steady_clock::now();
  r = run_gridlock({"cnf", "solve", dir + "/h.cnf", "--solver", "dpll", "--time", "1"});
  wall = seconds_since(t0);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("s UNKNOWN"), std::string::npos) << r.out;
  EXPECT_LT(wall, 8.0);
  r = run_gridlock({"cnf", "solve", dir + "/h.cnf", "--solver", "dpll", "--conflicts", "5"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("s UNKNOWN"), std::string::npos) << r.out;
  auto ex = run_gridlock({"cnf", "solve", kExamples + "tiny-sat.cnf", "--solver", "exhaustive", "--conflicts", "5"});
  EXPECT_EQ(ex.exit_code, 1);
  EXPECT_EQ(ex.err, "gridlock: error: --conflicts applies to --solver cadical and dpll, not exhaustive\n");
}

// 19. One reading of the formats: UTF-8 in comments is fine in every
// reader (before: refused in .grid only), a '+' sign nowhere (before:
// accepted in .grid and times files only), messages name FILE:LINE and
// show control bytes escaped (before: raw escape sequences reached the
// terminal).
TEST(HardeningCli, ReadersAgreeOnCommentsSignsAndControlBytes) {
  std::string dir = test::temp_dir();
  const std::string grid = test::write_file(dir + "/u.grid",
                                            "c Gitter für Roboter: ✓\n# naïve\np grid 2 1 1 0\nn 0 0\nn 1 0\n"
                                            "e 0 0 1 0\no a expand 0 0 +x\n");
  auto r = run_gridlock({"solve", grid});
  EXPECT_EQ(r.exit_code, 10) << r.err;
  const std::string cnf = test::write_file(dir + "/u.cnf", "c Formel für alle ✓\np cnf 1 1\n1 0\n");
  EXPECT_EQ(run_gridlock({"cnf", "solve", cnf}).exit_code, 10);
  const std::string times = test::write_file(dir + "/u.times", "c Startzeit ✓\n# naïve\na 0\n");
  EXPECT_EQ(run_gridlock({"check", grid, "--times", times}).exit_code, 10);
  const std::string order = test::write_file(dir + "/u.order", "c Reihenfolge ✓\na\n");
  EXPECT_EQ(run_gridlock({"check", grid, "--order-file", order}).exit_code, 10);
  // UTF-8 outside a comment: refused alike, with FILE:LINE and the column.
  const std::string bad_grid = test::write_file(dir + "/b.grid", "p grid 1 0 0 0\nn 0 0 ✓\n");
  EXPECT_EQ(
      run_gridlock({"solve", bad_grid}).err,
      "gridlock: error: " + bad_grid + ":2: binary input: byte 0xe2 at column 7 (UTF-8 is read in comments only)\n");
  const std::string bad_times = test::write_file(dir + "/b.times", "a 0 ✓\n");
  EXPECT_EQ(
      run_gridlock({"check", grid, "--times", bad_times}).err,
      "gridlock: error: " + bad_times + ":1: binary input: byte 0xe2 at column 5 (UTF-8 is read in comments only)\n");
  // A UTF-8 byte-order mark (some editors write one) is named, in each reader.
  const std::string bom = "\xef\xbb\xbf";
  const std::string bom_note =
      ":1: binary input: byte 0xef at column 1 (a UTF-8 byte-order mark: save the file without one)\n";
  const std::string bom_grid = test::write_file(dir + "/bom.grid", bom + "p grid 1 0 0 0\nn 0 0\n");
  EXPECT_EQ(run_gridlock({"solve", bom_grid}).err, "gridlock: error: " + bom_grid + bom_note);
  const std::string bom_cnf = test::write_file(dir + "/bom.cnf", bom + "p cnf 1 1\n1 0\n");
  EXPECT_EQ(run_gridlock({"cnf", "solve", bom_cnf}).err, "gridlock: error: " + bom_cnf + bom_note);
  const std::string bom_times = test::write_file(dir + "/bom.times", bom + "a 0\n");
  EXPECT_EQ(run_gridlock({"check", grid, "--times", bom_times}).err, "gridlock: error: " + bom_times + bom_note);
  // Only at the very start: the same bytes later are plain non-ASCII.
  const std::string late = test::write_file(dir + "/late.cnf", "p cnf 1 1\n" + bom + "1 0\n");
  EXPECT_EQ(run_gridlock({"cnf", "solve", late}).err,
            "gridlock: error: " + late + ":2: binary input: byte 0xef at column 1 (UTF-8 is read in comments only)\n");
  // '+3' is no number anywhere.
  const std::string plus_grid = test::write_file(dir + "/p.grid", "p grid 1 0 0 0\nn +3 0\n");
  EXPECT_EQ(run_gridlock({"solve", plus_grid}).err,
            "gridlock: error: " + plus_grid + ":2: expected an integer coordinate, got '+3'\n");
  const std::string plus_times = test::write_file(dir + "/p.times", "a +3\n");
  EXPECT_EQ(run_gridlock({"check", grid, "--times", plus_times}).err,
            "gridlock: error: " + plus_times + ":1: bad time '+3' (an integer or a fraction a/b)\n");
  const std::string plus_cnf = test::write_file(dir + "/p.cnf", "p cnf 3 1\n+3 0\n");
  auto pc = run_gridlock({"cnf", "solve", plus_cnf});
  EXPECT_EQ(pc.exit_code, 1);
  EXPECT_EQ(pc.err.rfind("gridlock: error: " + plus_cnf + ":2: ", 0), 0u) << pc.err;
  // Unknown names are errors in every reader (times, order files), never skipped.
  const std::string unknown_times = test::write_file(dir + "/x.times", "s YES\nv a 0\nv zz 1\n");
  EXPECT_EQ(run_gridlock({"check", grid, "--times", unknown_times}).err,
            "gridlock: error: " + unknown_times + ":3: unknown coupling 'zz'\n");
  const std::string unknown_order = test::write_file(dir + "/x.order", "v a\nv zz\n");
  EXPECT_EQ(run_gridlock({"check", grid, "--order-file", unknown_order}).err,
            "gridlock: error: " + unknown_order + ":2: unknown coupling 'zz'\n");
  // Control bytes in what the user typed are shown escaped.
  auto c = run_gridlock({"solve", dir + "/no\x1b[2Jsuch.grid"});
  EXPECT_EQ(c.exit_code, 1);
  EXPECT_EQ(c.err.find('\x1b'), std::string::npos) << c.err;
  EXPECT_NE(c.err.find("no\\x1b[2Jsuch.grid"), std::string::npos) << c.err;
  auto o = run_gridlock({"fuzz", "--count", "7\x07"});
  EXPECT_EQ(o.exit_code, 1);
  EXPECT_EQ(o.err.find('\x07'), std::string::npos) << o.err;
}

// 20. Pictures escape what they show: TikZ labels are LaTeX text (before:
// `q_1_2` inside $...$, a LaTeX error), the SVG title is XML-escaped.
// `render --ascii` of an instance too large to draw is an error (before:
// "too large" and exit 0); options that do not apply are refused.
TEST(HardeningCli, PicturesEscapeNamesAndRefuseWhatTheyCannotDraw) {
  std::string dir = test::temp_dir();
  const std::string g = test::write_file(dir + "/t.grid",
                                         "p grid 4 3 2 0\nn 0 0\nn 1 0\nn 2 0\nn 3 0\ne 0 0 1 0\ne 1 0 2 0\n"
                                         "e 2 0 3 0\no q_1_2 expand 0 0 +x\no a~b expand 2 0 +x\n");
  auto t = run_gridlock({"render", g, "--tikz"});
  ASSERT_EQ(t.exit_code, 0) << t.err;
  EXPECT_NE(t.out.find("{q\\_1\\_2}"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("{a\\textasciitilde{}b}"), std::string::npos) << t.out;
  EXPECT_EQ(t.out.find("$q_1_2$"), std::string::npos);
  auto svg = run_gridlock({"render", g, "--title", "</text><script>alert(1)</script>"});
  ASSERT_EQ(svg.exit_code, 0) << svg.err;
  EXPECT_EQ(svg.out.find("<script>"), std::string::npos);
  EXPECT_NE(svg.out.find("&lt;/text&gt;&lt;script&gt;"), std::string::npos);
  auto ti = run_gridlock({"render", g, "--ascii", "--title", "x"});
  EXPECT_EQ(ti.exit_code, 1);
  EXPECT_EQ(ti.err, "gridlock: error: --title applies to SVG pictures only, not --ascii or --tikz\n");
  const std::string wide = expansion_row(dir + "/wide.grid", 300);
  auto a = run_gridlock({"render", wide, "--ascii"});
  EXPECT_EQ(a.exit_code, 1);
  EXPECT_EQ(a.out, "");
  EXPECT_EQ(a.err,
            "gridlock: error: " + wide + ": too large for ASCII: 600 x 1 cells (at most 401 x 401; draw it as SVG)\n");
  auto k = run_gridlock({"gadget", "order", "-k", "5"});
  EXPECT_EQ(k.exit_code, 1);
  EXPECT_EQ(k.err, "gridlock: error: --literals applies to the clause gadget only\n");
  auto at = run_gridlock({"animate", g, "--order", "q_1_2 a~b", "--timeout", "5", "-o", dir + "/v.html"});
  EXPECT_EQ(at.exit_code, 1);
  EXPECT_EQ(at.err, "gridlock: error: --timeout applies to --solve only\n");
  EXPECT_FALSE(fs::exists(dir + "/v.html"));
  auto pn = run_gridlock({"verify", kExamples + "tiny-sat.cnf", "--picture-nodes", "10"});
  EXPECT_EQ(pn.exit_code, 1);
  EXPECT_EQ(pn.err, "gridlock: error: --picture-nodes applies with --pictures only\n");
}

// 21. --break-gadget draws a broken gadget or is refused: every kind, every
// mutation, clause sizes 1 to 4. Before: 7 combinations printed "BROKEN
// GADGET" over the unchanged gadget (the separation gadget with the other
// mutations, separation-loose with the order gadget, ...).
TEST(HardeningCli, BreakGadgetNeverLabelsTheSoundGadgetBroken) {
  auto strip = [](const std::string& text) {  // the instance without its comments
    std::string out, line;
    std::istringstream in(text);
    while (std::getline(in, line))
      if (line.rfind("c ", 0) != 0) out += line + "\n";
    return out;
  };
  int drawn = 0;
  for (const std::string kind : {"variable", "clause", "order", "separation"})
    for (const std::string k : {"1", "2", "3", "4"}) {
      if (kind != "clause" && k != "3") continue;
      std::vector<std::string> base = {"gadget", kind};
      if (kind == "clause") base.insert(base.end(), {"-k", k});
      const std::string sound = strip(run_gridlock(base).out);
      ASSERT_FALSE(sound.empty());
      for (const std::string m : {"variable-loose-y", "clause-loose", "clause-tight", "order-loose",
                                  "order-drop-release", "separation-loose"}) {
        SCOPED_TRACE(std::string(kind).append(" -k ").append(k).append(" ").append(m));
        auto args = base;
        args.insert(args.end(), {"--break-gadget", m});
        auto r = run_gridlock(args);
        if (r.exit_code == 0) {
          EXPECT_NE(r.out.find("BROKEN GADGET (" + m + ")"), std::string::npos);
          EXPECT_NE(strip(r.out), sound) << "labelled broken, drawn sound";
          ++drawn;
        } else {
          EXPECT_EQ(r.exit_code, 1);
          EXPECT_EQ(r.out, "");
          EXPECT_EQ(r.err.rfind("gridlock: error: --break-gadget " + m + " ", 0), 0u) << r.err;
        }
      }
    }
  EXPECT_GE(drawn, 6);  // each mutation breaks its own gadget at least once
}

// 22. A Ctrl-C or kill during an atomic write leaves no temporary file (the
// signal is held back until the rename), with the signal disposition a
// terminal gives (default: the process ends). Before: a killed compile
// left PATH.tmp.XXXXXX files of up to 108 MB.
TEST(HardeningCli, SignalsDuringAWriteLeaveNoTemporaryFile) {
  std::string dir = test::temp_dir();
  std::string big = dir + "/big.cnf";
  {
    std::string text = "p cnf 60000 60000\n";
    for (int v = 1; v <= 60000; ++v) text += std::to_string(v) + " -" + std::to_string(v % 60000 + 1) + " 0\n";
    test::write_file(big, text);
  }
  for (int sig : {SIGINT, SIGTERM}) {
    SCOPED_TRACE(sig);
    const std::string out = dir + "/out" + std::to_string(sig);
    fs::create_directories(out);
    auto p = test::start_gridlock({"compile", big, "-o", out + "/big.grid"});
    auto t0 = std::chrono::steady_clock::now();
    bool seen = false;
    while (!seen && seconds_since(t0) < 120) {
      seen = !temp_files(out).empty();
      if (!seen) std::this_thread::sleep_for(std::chrono::microseconds(500));
      int status = 0;
      if (!seen && waitpid(p.pid, &status, WNOHANG) == p.pid) {  // finished before we saw the write
        p.pid = -1;
        break;
      }
    }
    if (p.pid < 0) {
      ADD_FAILURE() << "compile ended before its temporary file was seen";
      continue;
    }
    kill(p.pid, sig);
    auto r = test::finish_gridlock(p);
    EXPECT_TRUE(r.exit_code == 128 + sig || r.exit_code == 0) << r.exit_code << " " << r.err;
    EXPECT_TRUE(temp_files(out).empty());
  }
}

// Runs gridlock with the address space limited to `mb` MB (RLIMIT_AS, as
// `ulimit -v` does), so what does not fit fails at once instead of swapping.
test::CliResult run_gridlock_within(const std::vector<std::string>& args, uint64_t mb) {
  struct rlimit old {};
  getrlimit(RLIMIT_AS, &old);
  struct rlimit small = old;
  small.rlim_cur = mb << 20;
  EXPECT_EQ(setrlimit(RLIMIT_AS, &small), 0);
  auto p = test::start_gridlock(args);
  setrlimit(RLIMIT_AS, &old);
  return test::finish_gridlock(p);
}

// 23. Work that cannot fit in memory is refused up front, or does not blow
// up. The continuous solve of a row of k expansions all started at once
// checked its witness with S = k sub-steps whose candidate pairs piled up
// (each neighbour pair once per sub-step): 0.5 GB at k = 3000, 2 GB at
// 5000, 30 GB at the 25 000 (out of memory while gaps answered in
// 0.2 s); now each pair is kept once (14 MB at k = 3000). `cnf gen` of a
// formula beyond the memory is refused before generating (before: out of
// memory, or the machine swapping). Under a 200 MB address-space limit,
// every command on a row of 2000 answers (before: continuous solve out of
// memory).
TEST(HardeningCli, WorkThatCannotFitInMemoryIsRefusedOrBounded) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "address-space limits skipped under AddressSanitizer (it reserves terabytes of address space)";
#endif
  std::string dir = test::temp_dir();
  const std::string row = expansion_row(dir + "/row.grid", 2000);
  auto r = run_gridlock_within({"solve", row, "--model", "continuous", "--json"}, 200);
  ASSERT_EQ(r.exit_code, 10) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["status"], "YES");
  r = run_gridlock_within({"gaps", row}, 200);
  EXPECT_EQ(r.exit_code, 10) << r.err;
  r = run_gridlock_within({"solve", row, "--timeout", "2"}, 200);
  EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 10) << r.exit_code << " " << r.err;
  for (const char* model : {"discrete", "continuous"}) {
    r = run_gridlock_within({"collide", row, "--model", model}, 200);
    EXPECT_EQ(r.exit_code, 20) << model << " " << r.err;
  }
  r = run_gridlock_within({"render", row, "-o", dir + "/row.svg"}, 200);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  // The continuous final check (all 6 000 at once: about 10 s to simulate)
  // is inside --timeout: UNKNOWN, not a run to the end.
  const std::string long_row = expansion_row(dir + "/long.grid", 6000);
  const auto t0 = std::chrono::steady_clock::now();
  r = run_gridlock({"solve", long_row, "--model", "continuous", "--timeout", "1"});
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("s UNKNOWN"), std::string::npos) << r.out;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 8.0);  // ran to the end

  r = run_gridlock_within({"cnf", "gen", "lsat-le3", "--n", "1000000000", "--m", "800000000", "-o", dir + "/g.cnf"},
                          200);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err.rfind("gridlock: error: cnf gen lsat-le3: too large: a formula of 800000000 clauses and "
                        "1000000000 variables would need about ",
                        0),
            0u)
      << r.err;
  EXPECT_NE(r.err.find("MB available (address-space limit"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/g.cnf"));
  // Beyond the physical memory of any machine: refused without a limit too.
  r = run_gridlock({"cnf", "gen", "ksat", "--n", "1000", "--m", "2000000000", "--k", "100", "-o", dir + "/g.cnf"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("too large: a formula of 2000000000 clauses"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(physical memory)"), std::string::npos) << r.err;
}

// 24. "out of memory" only for a real std::bad_alloc: work refused up front
// says "too large" (not "out of memory"), a real exhaustion names the file
// and the task, and no message is "internal:". (std::length_error, a size
// beyond a container, and std::bad_array_new_length, a size that
// overflowed, are reported by main as "too large while WHAT: DETAIL";
// no input of ours reaches them: the readers bound every size first.)
TEST(HardeningCli, OutOfMemoryIsSaidOnlyWhenMemoryRanOut) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "address-space limits skipped under AddressSanitizer";
#endif
  std::string dir = test::temp_dir();
  auto r = run_gridlock_within({"cnf", "gen", "ksat", "--n", "1000000", "--m", "20000000", "-o", dir + "/g.cnf"}, 400);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err.find("out of memory"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("cnf gen ksat: too large"), std::string::npos) << r.err;
  // A real exhaustion (the compiled instance needs several GB).
  std::string huge = test::write_file(dir + "/huge.cnf", "p cnf 700000 1\n1 0\n");
  r = run_gridlock_within({"compile", huge, "-o", dir + "/huge.grid"}, 400);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "gridlock: error: " + huge + ": out of memory while compiling the formula\n");
  // Every command on an instance names it (before: collide said only "out
  // of memory"): the 25 000-expansion row under 60 MB.
  const std::string row = expansion_row(dir + "/row.grid", 25000);
  r = run_gridlock_within({"collide", row}, 60);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err.rfind("gridlock: error: " + row + ": out of memory while ", 0), 0u) << r.err;
  // The same command within reach: no stale context, no memory message.
  std::string small = test::write_file(dir + "/small.cnf", "p cnf 3 1\n1 0\n");
  r = run_gridlock_within({"compile", small, "-o", dir + "/small.grid"}, 400);
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

// 25. A reproducer that cannot be written mid-run (after the up-front check
// passed: the finding's formula.cnf is taken by a folder) is a normal error
// naming the file; the finding is printed in full on stderr, and no
// temporary file remains.
TEST(HardeningCli, AReproducerUnwritableMidRunIsAnErrorAndTheFindingIsPrinted) {
  std::string dir = test::temp_dir();
  const std::string out = dir + "/fz";
  for (int i = 0; i < 20; ++i) fs::create_directories(out + "/seed7-formula" + std::to_string(i) + "/formula.cnf");
  auto r = run_gridlock({"fuzz", "--break-gadget", "clause-loose", "--count", "20", "--seed", "7", "--out", out});
  EXPECT_EQ(r.exit_code, 1);
  const std::string blocked = out + "/seed7-formula0/formula.cnf";
  EXPECT_EQ(r.err.substr(r.err.rfind("gridlock: error: ")),
            "gridlock: error: " + blocked + ": is a directory, not a file\n");
  EXPECT_NE(r.err.find("c finding NOT saved (" + blocked + ": is a directory, not a file): formula 0: "),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("c replay: gridlock fuzz --seed 7 --index 0 "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("c   p cnf "), std::string::npos) << r.err;  // the shrunk formula, in full
  EXPECT_EQ(r.err.find("internal"), std::string::npos) << r.err;
  EXPECT_TRUE(temp_files(out + "/seed7-formula0").empty());

  const std::string rep = dir + "/rep";
  fs::create_directories(rep + "/tiny-unsat/formula.cnf");
  r = run_gridlock({"verify", kExamples + "tiny-unsat.cnf", "--break-gadget", "clause-loose", "--reproducers", rep});
  EXPECT_EQ(r.exit_code, 1);
  const std::string vblocked = rep + "/tiny-unsat/formula.cnf";
  EXPECT_NE(r.out.find("(reproducer NOT written: " + vblocked + ": is a directory, not a file)"), std::string::npos)
      << r.out;
  EXPECT_NE(r.err.find("NOT saved (" + vblocked + ": is a directory, not a file); the formula:\nc   c The smallest"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("c   -1 -2 0\n"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.substr(r.err.rfind("gridlock: error: ")),
            "gridlock: error: " + vblocked + ": is a directory, not a file\n");
  EXPECT_TRUE(temp_files(rep + "/tiny-unsat").empty());
}

}  // namespace
}  // namespace gridlock
