// End to end: `gridlock solve` and `gridlock gaps` through the real binary,
// their witnesses read back by `gridlock check`, and their error cases.
#include <gtest/gtest.h>

#include <sstream>

#include <nlohmann/json.hpp>

#include "lattice/grid_format.hpp"
#include "lattice/random_instance.hpp"
#include "support/cli.hpp"
#include "support/reference_solver.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

using test::run_gridlock;

const std::string kExamples = std::string(GRIDLOCK_SOURCE_DIR) + "/examples/instances/";

bool has_line(const std::string& out, const std::string& line) {
  return ("\n" + out).find("\n" + line + "\n") != std::string::npos;
}

TEST(SolveCommand, ExamplesWithExitCodesAndReadBack) {
  std::string dir = test::temp_dir();
  auto no = run_gridlock({"solve", kExamples + "model-case1-two-growths.grid"});
  EXPECT_EQ(no.exit_code, 20) << no.err;
  EXPECT_TRUE(has_line(no.out, "s NO")) << no.out;
  EXPECT_NE(no.out.find("c states "), std::string::npos);
  EXPECT_NE(no.out.find(", refuted "), std::string::npos);
  EXPECT_NE(no.out.find("c time "), std::string::npos);

  auto yes = run_gridlock({"solve", kExamples + "model-case2-order-gadget.grid"});
  EXPECT_EQ(yes.exit_code, 10) << yes.err;
  EXPECT_TRUE(has_line(yes.out, "s YES")) << yes.out;
  EXPECT_TRUE(has_line(yes.out, "v a b")) << yes.out;
  test::write_file(dir + "/order", yes.out);
  auto back = run_gridlock({"check", kExamples + "model-case2-order-gadget.grid", "--order-file", dir + "/order"});
  EXPECT_EQ(back.exit_code, 10) << back.out << back.err;

  auto block = run_gridlock({"solve", kExamples + "model-case3-block.grid", "--engine", "states"});
  EXPECT_EQ(block.exit_code, 10) << block.err;
  EXPECT_TRUE(has_line(block.out, "v Q")) << block.out;
}

TEST(SolveCommand, CycleBreakerIsNamed) {
  std::string dir = test::temp_dir();
  std::string grid = test::write_file(dir + "/b.grid",
                                      "p grid 4 4 1 0\nn 0 0\nn 1 0\nn 0 1\nn 1 1\n"
                                      "e 0 0 1 0\ne 0 1 1 1\ne 0 0 0 1\ne 1 0 1 1\no a expand 0 0 +x\n");
  auto r = run_gridlock({"solve", grid, "--json"});
  EXPECT_EQ(r.exit_code, 20) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "NO");
  EXPECT_EQ(j["engine"], "cycle");
  EXPECT_EQ(j["cycle_breaker"], "a");
}

// A random shape of hundreds of couplings that one coupling alone makes
// collide: both models name the coupling and the pair, stop building there
// (a handful of constraints, not the whole system), and write a NO
// certificate that the independent checker accepts.
TEST(SolveCommand, LoneColliderIsNamedAndCertified) {
  const std::string dir = test::temp_dir();
  const std::string grid = dir + "/tree.grid";
  ASSERT_EQ(run_gridlock({"random", "--family", "tree", "--couplings", "400", "--seed", "2", "-o", grid}).exit_code, 0);
  for (const char* model : {"discrete", "continuous"}) {
    auto r = run_gridlock({"solve", grid, "--model", model, "--json"});
    ASSERT_EQ(r.exit_code, 20) << model << r.err;
    auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["status"], "NO");
    ASSERT_TRUE(j.contains("lone_collider")) << model << r.out;
    const std::string q = j["lone_collider"]["coupling"], pair = j["lone_collider"]["pair"];
    EXPECT_FALSE(q.empty());
    EXPECT_NE(pair.find(" and "), std::string::npos) << pair;
    EXPECT_LT(j["stats"]["constraints"].get<uint64_t>(), 1000u) << model;
    auto t = run_gridlock({"solve", grid, "--model", model});
    std::string said = "c coupling " + q;
    said += " alone moves " + pair;
    said += " against each other: they collide whenever it runs";
    EXPECT_TRUE(has_line(t.out, said)) << t.out;
    const std::string cert = dir + "/" + model + ".nocert";
    ASSERT_EQ(run_gridlock({"solve", grid, "--model", model, "--certificate", cert}).exit_code, 20);
    auto c = run_gridlock({"certify", grid, cert, "--model", model});
    EXPECT_EQ(c.exit_code, 20) << model << c.out << c.err;
  }
}

TEST(SolveCommand, JsonAndLimits) {
  auto r = run_gridlock({"solve", kExamples + "model-case2-order-gadget.grid", "--json"});
  EXPECT_EQ(r.exit_code, 10);
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "YES");
  EXPECT_EQ(j["witness"], nlohmann::json::array({"a", "b"}));
  EXPECT_GE(j["stats"]["states"].get<uint64_t>(), 1u);
  EXPECT_EQ(j["engine"], "sat");  // the default for horizontal-only instances
  for (std::string e : {"precedence", "sat", "states"}) {
    auto o = run_gridlock({"solve", kExamples + "model-case2-order-gadget.grid", "--engine", e, "--json"});
    EXPECT_EQ(o.exit_code, 10) << e << o.err;
    EXPECT_EQ(nlohmann::json::parse(o.out)["witness"], nlohmann::json::array({"a", "b"})) << e;
  }
  auto u = run_gridlock(
      {"solve", kExamples + "model-case2-order-gadget.grid", "--max-states", "1", "--engine", "states"});
  EXPECT_EQ(u.exit_code, 0) << u.out << u.err;
  EXPECT_TRUE(has_line(u.out, "s UNKNOWN")) << u.out;
}

TEST(SolveCommand, Errors) {
  std::string dir = test::temp_dir();
  auto missing = run_gridlock({"solve", dir + "/nope.grid"});
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find("gridlock: error: "), std::string::npos) << missing.err;
  std::string bad = test::write_file(dir + "/bad.grid", "p grid 1 0 0 0\nn 0 0\nn 0 0\n");
  auto r = run_gridlock({"solve", bad});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("bad.grid:"), std::string::npos) << r.err;
  for (auto args : std::vector<std::vector<std::string>>{
           {"solve", kExamples + "model-case2-order-gadget.grid", "--timeout", "0"},
           {"solve", kExamples + "model-case2-order-gadget.grid", "--timeout", "-3"},
           {"solve", kExamples + "model-case2-order-gadget.grid", "--max-states", "0"},
           {"solve", kExamples + "model-case2-order-gadget.grid", "--engine", "magic"},
           {"solve"}}) {
    auto e = run_gridlock(args);
    EXPECT_EQ(e.exit_code, 1) << args.back() << ": " << e.out;
    EXPECT_NE(e.err.find("gridlock: error: "), std::string::npos) << e.err;
  }
  std::string vertical = test::write_file(dir + "/v.grid",
                                          "p grid 2 1 1 0\nn 0 0\nn 0 1\ne 0 0 0 1\no a expand 0 0 +y\n");
  for (std::string e : {"precedence", "sat"}) {
    auto pv = run_gridlock({"solve", vertical, "--engine", e});
    EXPECT_EQ(pv.exit_code, 1) << e;
    EXPECT_NE(pv.err.find("horizontal-only"), std::string::npos) << pv.err;
  }
  auto sv = run_gridlock({"solve", vertical});
  EXPECT_EQ(sv.exit_code, 10) << sv.out << sv.err;
}

TEST(GapsCommand, ExamplesAndReadBackByCheckTimes) {
  std::string dir = test::temp_dir();
  auto yes = run_gridlock({"gaps", kExamples + "model-case2-order-gadget.grid"});
  EXPECT_EQ(yes.exit_code, 10) << yes.err;
  EXPECT_TRUE(has_line(yes.out, "v a 0")) << yes.out;
  EXPECT_TRUE(has_line(yes.out, "v b 0")) << yes.out;
  test::write_file(dir + "/times", yes.out);
  auto back = run_gridlock({"check", kExamples + "model-case2-order-gadget.grid", "--times", dir + "/times"});
  EXPECT_EQ(back.exit_code, 10) << back.out << back.err;

  auto no = run_gridlock({"gaps", kExamples + "model-case1-two-growths.grid", "--json"});
  EXPECT_EQ(no.exit_code, 20) << no.err;
  auto j = nlohmann::json::parse(no.out);
  EXPECT_EQ(j["gap"]["row"], 0);
  EXPECT_EQ(j["gap"]["left"], "(0,0)");
  EXPECT_EQ(j["gap"]["right"], "(2,0)");
  EXPECT_EQ(j["gap"]["initial_size"], 1);
  EXPECT_EQ(j["gap"]["final_size"], -1);
  EXPECT_EQ(j["gap"]["narrowed_by"].size(), 2u);
  auto text = run_gridlock({"gaps", kExamples + "model-case1-two-growths.grid"});
  EXPECT_NE(text.out.find("c gap in row 0 between (0,0) and (2,0): initial size 1"), std::string::npos) << text.out;
}

TEST(GapsCommand, OpenCycleAndErrors) {
  std::string dir = test::temp_dir();
  std::string cyc = test::write_file(dir + "/c.grid",
                                     "p grid 4 4 1 0\nn 0 0\nn 1 0\nn 0 1\nn 1 1\n"
                                     "e 0 0 1 0\ne 0 1 1 1\ne 0 0 0 1\ne 1 0 1 1\no a expand 0 0 +x\n");
  auto c = run_gridlock({"gaps", cyc, "--json"});
  EXPECT_EQ(c.exit_code, 20) << c.err;
  auto j = nlohmann::json::parse(c.out);
  EXPECT_NE(j["cycle"]["mismatch"], 0);
  std::string vertical = test::write_file(dir + "/v.grid",
                                          "p grid 2 1 1 0\nn 0 0\nn 0 1\ne 0 0 0 1\no up expand 0 0 +y\n");
  auto v = run_gridlock({"gaps", vertical});
  EXPECT_EQ(v.exit_code, 1);
  EXPECT_NE(v.err.find("gridlock: error: "), std::string::npos);
  EXPECT_NE(v.err.find("'up' moves vertically"), std::string::npos) << v.err;
  auto none = run_gridlock({"gaps"});
  EXPECT_EQ(none.exit_code, 1);
}

// Random horizontal instances through both commands: the discrete answer
// matches the reference, every YES order reads back through check, and a
// discrete YES comes with a continuous YES.
TEST(SolveCommand, RandomInstancesEndToEnd) {
  std::string dir = test::temp_dir();
  const uint64_t base = test::base_seed(400);
  for (int i = 0; i < test::scaled(25); ++i) {
    uint64_t seed = base + static_cast<uint64_t>(i);
    RandomInstanceParams p;
    p.nodes = 10;
    p.ops = 5;
    p.max_coupling = 2;
    p.horizontal_only = i % 2 == 0;
    Instance inst = random_instance(p, seed);
    std::ostringstream text;
    write_instance(text, inst);
    std::string grid = test::write_file(dir + "/r" + std::to_string(i) + ".grid", text.str());
    auto s = run_gridlock({"solve", grid});
    bool want = test::reference_solve(inst).has_value();
    ASSERT_EQ(s.exit_code, want ? 10 : 20) << "seed " << seed << "\n" << s.out << s.err;
    if (want) {
      std::string order = test::write_file(grid + ".order", s.out);
      auto back = run_gridlock({"check", grid, "--order-file", order});
      EXPECT_EQ(back.exit_code, 10) << "seed " << seed << back.out;
    }
    if (p.horizontal_only) {
      auto g = run_gridlock({"gaps", grid});
      if (want) {
        EXPECT_EQ(g.exit_code, 10) << "seed " << seed;
      }
      if (g.exit_code == 10) {
        std::string times = test::write_file(grid + ".times", g.out);
        auto back = run_gridlock({"check", grid, "--times", times});
        EXPECT_EQ(back.exit_code, 10) << "seed " << seed << back.out << back.err;
      }
    }
  }
}

}  // namespace
}  // namespace gridlock
