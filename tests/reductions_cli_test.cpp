// `gridlock compile` and `gridlock lift` end to end: the real binary on real
// files, every certificate read back by another subcommand (check, cnf solve).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "lattice/grid_format.hpp"
#include "support/cli.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

using test::run_gridlock;

const std::string kExamples = GRIDLOCK_SOURCE_DIR "/examples/formulas/";
const std::string kSatlib = GRIDLOCK_DATA_DIR "/satlib/";

TEST(CompileCli, WritesAReadableInstanceAndPicture) {
  std::string dir = test::temp_dir();
  auto r = run_gridlock({"compile", kExamples + "tiny-sat.cnf", "-o", dir + "/i.grid", "--svg", dir + "/i.svg"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("c instance: 198 nodes, 197 edges, 38 operations"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("nodes 43n+5L+15m-11 = 198"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("largest coupling: x1:F with 3 operations"), std::string::npos) << r.out;
  Instance inst;
  ASSERT_FALSE(read_instance_file(dir + "/i.grid", inst));
  EXPECT_EQ(inst.num_nodes(), 198u);
  EXPECT_NE(test::read_file(dir + "/i.svg").find("<svg"), std::string::npos);
  // Standard output: the instance itself, its sizes as comments.
  auto s = run_gridlock({"compile", kExamples + "tiny-sat.cnf"});
  ASSERT_EQ(s.exit_code, 0);
  EXPECT_EQ(s.out.rfind("c ", 0), 0u);
  EXPECT_NE(s.out.find("\np grid 198 197 38 15\n"), std::string::npos);
}

TEST(CompileCli, JsonAndOversizeReport) {
  std::string dir = test::temp_dir();
  std::string f = test::write_file(dir + "/f.cnf", "p cnf 2 3\n1 2 0\n1 -2 0\n1 0\n");
  auto r = run_gridlock({"compile", f, "-o", dir + "/i.grid", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["max_coupling"], 4);
  ASSERT_EQ(j["oversize"].size(), 1u);
  EXPECT_EQ(j["oversize"][0], "literal x1 occurs 3 times: coupling x1:F has 4 operations");
}

TEST(CompileCli, Errors) {
  std::string dir = test::temp_dir();
  std::string f = test::write_file(dir + "/e.cnf", "p cnf 2 2\n1 2 0\n0\n");
  auto r = run_gridlock({"compile", f, "-o", dir + "/i.grid"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "gridlock: error: " + f +
                       ":3: clause 2 is empty; the reduction needs at least one literal per clause ('gridlock cnf "
                       "to-lsat' gives an equivalent formula without it)\n");
  // lift compiles the formula as it is too; verify goes through to-lsat.
  std::string model = test::write_file(dir + "/m.txt", "v 1 2 0\n");
  r = run_gridlock({"lift", f, "--model", model});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err.rfind("gridlock: error: " + f + ":3: clause 2 is empty", 0), 0u) << r.err;
  r = run_gridlock({"verify", f});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::string g = test::write_file(dir + "/g.cnf", "p cnf 2 1\n1 3 0\n");
  r = run_gridlock({"compile", g});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err.rfind("gridlock: error: " + g + ":2: ", 0), 0u) << r.err;
  r = run_gridlock({"compile", dir + "/missing.cnf"});
  EXPECT_EQ(r.exit_code, 1);
  r = run_gridlock({"compile", f, "--break-gadget", "nonsense"});
  EXPECT_EQ(r.exit_code, 1);
}

// Model -> schedule (checked by lift's simulator and again by `check`) and
// schedule -> model (checked against the formula and by `cnf solve`'s reader).
TEST(LiftCli, CertificatesBothWaysThroughOtherSubcommands) {
  std::string dir = test::temp_dir();
  for (const std::string& f : {kExamples + "tiny-sat.cnf", kExamples + "lsat-sat.cnf"}) {
    SCOPED_TRACE(f);
    auto solved = run_gridlock({"cnf", "solve", f});
    ASSERT_EQ(solved.exit_code, 10);
    std::string model = test::write_file(dir + "/model.txt", solved.out);
    auto lifted = run_gridlock({"lift", f, "--model", model});
    ASSERT_EQ(lifted.exit_code, 10) << lifted.out << lifted.err;
    std::string sched = test::write_file(dir + "/sched.txt", lifted.out);
    ASSERT_EQ(run_gridlock({"compile", f, "-o", dir + "/i.grid"}).exit_code, 0);
    auto checked = run_gridlock({"check", dir + "/i.grid", "--order-file", sched});
    EXPECT_EQ(checked.exit_code, 10) << checked.out;
    auto back = run_gridlock({"lift", f, "--schedule", sched});
    EXPECT_EQ(back.exit_code, 10) << back.out;
    EXPECT_NE(back.out.find("c the lifted assignment satisfies the formula"), std::string::npos);
  }
}

// The continuous reduction: compile --model continuous prints its sizes;
// model -> start times (lift's simulator, then `check --times` on the
// compiled instance) -> model; the continuous solver's times lift back too;
// a falsifying model collides.
TEST(LiftCli, ContinuousCertificatesBothWays) {
  std::string dir = test::temp_dir();
  const std::string f = kExamples + "tiny-sat.cnf";
  auto comp = run_gridlock({"compile", f, "--model", "continuous", "-o", dir + "/c.grid", "--json"});
  ASSERT_EQ(comp.exit_code, 0) << comp.err;
  auto j = nlohmann::json::parse(comp.out);
  EXPECT_EQ(j["model"], "continuous");
  EXPECT_EQ(j["vertical_operations"], 1);
  EXPECT_EQ(j["nodes"], 43 * 3 + 5 * 7 + 15 * 3 - 9);
  auto text = run_gridlock({"compile", f, "--model", "continuous", "-o", dir + "/c2.grid"});
  EXPECT_NE(text.out.find("c size formulas (n=3, m=3, L=7): nodes 43n+5L+15m-9 = 200"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("c gadgets: 3 variable, 3 clause, 7 order, 1 separation"), std::string::npos);
  std::string model = test::write_file(dir + "/model.txt", run_gridlock({"cnf", "solve", f}).out);
  auto lifted = run_gridlock({"lift", f, "--continuous", "--model", model});
  ASSERT_EQ(lifted.exit_code, 10) << lifted.out << lifted.err;
  std::string times = test::write_file(dir + "/times.txt", lifted.out);
  EXPECT_EQ(run_gridlock({"check", dir + "/c.grid", "--times", times}).exit_code, 10);
  // Everything at time 0 collides on the continuous instance (the separation).
  std::string zero;
  for (const char* q :
       {"x1:T", "x1:F", "x2:T", "x2:F", "x3:T", "x3:F", "y1", "y2", "y3", "z1", "z2", "z3", "u1", "u2", "u3"})
    zero += std::string(q) + " 0\n";
  EXPECT_EQ(run_gridlock({"check", dir + "/c.grid", "--times", test::write_file(dir + "/zero.txt", zero)}).exit_code,
            20);
  auto back = run_gridlock({"lift", f, "--times", times});
  EXPECT_EQ(back.exit_code, 10) << back.out;
  EXPECT_NE(back.out.find("c the lifted assignment satisfies the formula"), std::string::npos);
  auto solved = run_gridlock({"solve", dir + "/c.grid", "--model", "continuous"});
  ASSERT_EQ(solved.exit_code, 10) << solved.out;
  auto back2 = run_gridlock({"lift", f, "--times", test::write_file(dir + "/solver.txt", solved.out)});
  EXPECT_EQ(back2.exit_code, 10) << back2.out;
  auto bad = run_gridlock(
      {"lift", f, "--continuous", "--model", test::write_file(dir + "/bad.txt", "s SATISFIABLE\nv -1 -2 -3 0\n")});
  EXPECT_EQ(bad.exit_code, 20) << bad.out;
  auto err = run_gridlock({"lift", f, "--continuous", "--schedule", times});
  EXPECT_EQ(err.err, "gridlock: error: --schedule is a discrete order; use --times for the continuous instance\n");
}

TEST(LiftCli, BadModelCollidesAndBadScheduleIsRefused) {
  std::string dir = test::temp_dir();
  std::string f = kExamples + "tiny-sat.cnf";  // (1 2 3)(-2 3)(1 -3)
  std::string bad = test::write_file(dir + "/bad.txt", "s SATISFIABLE\nv 1 2 -3 0\n");
  auto r = run_gridlock({"lift", f, "--model", bad});
  EXPECT_EQ(r.exit_code, 20);
  EXPECT_NE(r.out.find("c the model falsifies clause 2: expect a collision"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("node collision"), std::string::npos) << r.out;
  // y1 before x1 is set: the variable gadget's y gap collides.
  std::string sched = test::write_file(dir + "/s.txt", "y1 x1:T x2:T x3:T y2 y3 z1 z2 z3 u1 u2 u3 x1:F x2:F x3:F\n");
  r = run_gridlock({"lift", f, "--schedule", sched});
  EXPECT_EQ(r.exit_code, 20);
  EXPECT_NE(r.out.find("c simulator: the schedule collides"), std::string::npos) << r.out;
  std::string junk = test::write_file(dir + "/j.txt", "s SATISFIABLE\nv 1 x 0\n");
  r = run_gridlock({"lift", f, "--model", junk});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "gridlock: error: " + junk + ":2: 'x' is not a literal\n");
  std::string far = test::write_file(dir + "/far.txt", "s SATISFIABLE\nv 1 -2\nv 9 0\n");
  r = run_gridlock({"lift", f, "--model", far});
  EXPECT_EQ(r.err, "gridlock: error: " + far + ":3: literal 9 beyond the formula's 3 variables\n");
}

TEST(LiftCli, EverySatlibUf20SampleLiftsThroughToLsat) {
  // End to end: compile every uf20-91 sample through
  // to-lsat; its lifted witness is accepted by the simulator.
  std::string dir = test::temp_dir();
  int done = 0;
  for (int i = 1; i <= 100 && done < test::scaled(100); i += (test::scaled(100) < 100 ? 7 : 1)) {
    std::string f = kSatlib + "uf20-91/uf20-0" + std::to_string(i) + ".cnf";
    std::string lsat = dir + "/l.cnf";
    ASSERT_EQ(run_gridlock({"cnf", "to-lsat", f, "-o", lsat}).exit_code, 0);
    auto solved = run_gridlock({"cnf", "solve", lsat});
    ASSERT_EQ(solved.exit_code, 10) << f;
    std::string model = test::write_file(dir + "/m.txt", solved.out);
    auto lifted = run_gridlock({"lift", lsat, "--model", model});
    ASSERT_EQ(lifted.exit_code, 10) << f << lifted.out;
    ++done;
  }
  EXPECT_GT(done, 0);
}

}  // namespace
}  // namespace gridlock
