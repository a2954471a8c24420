// End to end: `gridlock collide` through the real binary, its witnesses read
// back by `gridlock check`, and bad input.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/cli.hpp"

namespace gridlock {
namespace {

using test::run_gridlock;

const std::string kExamples = std::string(GRIDLOCK_SOURCE_DIR) + "/examples/instances/";

TEST(CollideCommand, DiscreteWitnessReadBackByCheck) {
  std::string dir = test::temp_dir();
  auto r = run_gridlock({"collide", kExamples + "model-case2-order-gadget.grid", "--model", "discrete"});
  ASSERT_EQ(r.exit_code, 10) << r.err;
  EXPECT_NE(r.out.find("\ns YES\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("c checked by the simulator: node collision"), std::string::npos) << r.out;
  test::write_file(dir + "/w", r.out);
  auto c = run_gridlock({"check", kExamples + "model-case2-order-gadget.grid", "--order-file", dir + "/w"});
  EXPECT_EQ(c.exit_code, 20) << c.out << c.err;  // check: NO = not collision-free
}

TEST(CollideCommand, ContinuousWitnessReadBackByCheck) {
  std::string dir = test::temp_dir();
  auto r = run_gridlock({"collide", kExamples + "model-case1-two-growths.grid"});
  ASSERT_EQ(r.exit_code, 10) << r.err;
  EXPECT_NE(r.out.find("\nv g1 "), std::string::npos) << r.out;
  test::write_file(dir + "/w", r.out);
  auto c = run_gridlock({"check", kExamples + "model-case1-two-growths.grid", "--times", dir + "/w"});
  EXPECT_EQ(c.exit_code, 20) << c.out << c.err;
}

TEST(CollideCommand, DrawsTheCollision) {
  std::string dir = test::temp_dir();
  auto r = run_gridlock(
      {"collide", kExamples + "model-case2-order-gadget.grid", "--model", "discrete", "--svg", dir + "/c.svg"});
  ASSERT_EQ(r.exit_code, 10) << r.err;
  std::string svg = test::read_file(dir + "/c.svg");
  EXPECT_NE(svg.find("collision from time 0 (drawn at 1/2)"), std::string::npos);
  EXPECT_NE(svg.find("#ff9896"), std::string::npos) << "colliding nodes are marked";
}

TEST(CollideCommand, NoAndJson) {
  auto r = run_gridlock({"collide", kExamples + "model-case3-block.grid", "--json"});
  ASSERT_EQ(r.exit_code, 20) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "NO");
  EXPECT_EQ(j["algorithm"], "single-coupling");
  auto y = run_gridlock({"collide", kExamples + "model-case1-two-growths.grid", "--json", "--model", "discrete"});
  auto jy = nlohmann::json::parse(y.out);
  EXPECT_EQ(jy["status"], "YES");
  EXPECT_EQ(jy["collision"]["kind"], "node");
  EXPECT_EQ(jy["witness"].size(), 2u);
}

TEST(CollideCommand, MethodsAgreeOnExamples) {
  for (const char* f : {"model-case1-two-growths.grid", "model-case2-order-gadget.grid"})
    for (const char* m : {"tree", "tree-pairwise", "pairwise"}) {
      auto r = run_gridlock({"collide", kExamples + f, "--method", m});
      EXPECT_EQ(r.exit_code, 10) << f << " " << m << r.err;
    }
  auto bad = run_gridlock({"collide", kExamples + "model-case3-block.grid", "--method", "tree"});
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("gridlock: error: collide: the tree algorithm needs an instance without couplings"),
            std::string::npos)
      << bad.err;
}

TEST(CollideCommand, BadInput) {
  std::string dir = test::temp_dir();
  auto m = run_gridlock({"collide", kExamples + "model-case1-two-growths.grid", "--model", "quantum"});
  EXPECT_EQ(m.exit_code, 1);
  EXPECT_NE(m.err.find("--model must be"), std::string::npos) << m.err;
  auto missing = run_gridlock({"collide", dir + "/nope.grid"});
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find("gridlock: error:"), std::string::npos);
  test::write_file(dir + "/bad.grid", "p grid 2 1 0 0\nn 0 0\nn 0 0\ne 0 0 0 1\n");
  auto bad = run_gridlock({"collide", dir + "/bad.grid"});
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("bad.grid:3"), std::string::npos) << bad.err;
  auto none = run_gridlock({"collide"});
  EXPECT_EQ(none.exit_code, 1);
  auto stdin_run = run_gridlock({"collide", "-"}, "p grid 1 0 0 0\nn 0 0\n");
  EXPECT_EQ(stdin_run.exit_code, 20) << stdin_run.err;
}

}  // namespace
}  // namespace gridlock
