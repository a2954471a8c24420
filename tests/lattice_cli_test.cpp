// End to end: the real `gridlock` binary on real files.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/cli.hpp"

namespace gridlock {
namespace {

using test::run_gridlock;

const std::string kExamples = std::string(GRIDLOCK_SOURCE_DIR) + "/examples/instances/";

TEST(CheckCommand, DiscreteYesAndNoWithExitCodes) {
  auto yes = run_gridlock({"check", kExamples + "model-case2-order-gadget.grid", "--order", "a b"});
  EXPECT_EQ(yes.exit_code, 10) << yes.err;
  EXPECT_NE(yes.out.find("\ns YES\n"), std::string::npos) << yes.out;
  auto no = run_gridlock({"check", kExamples + "model-case2-order-gadget.grid", "--order", "b a"});
  EXPECT_EQ(no.exit_code, 20);
  EXPECT_NE(no.out.find("c node collision at time 0 between node (0,1) and node (1,1)"), std::string::npos) << no.out;
  EXPECT_NE(no.out.find("c moving then: b"), std::string::npos);
}

TEST(CheckCommand, ContinuousTimesAndJson) {
  std::string dir = test::temp_dir();
  test::write_file(dir + "/t", "c both at once\na 0\nb 1/3\n");
  auto r = run_gridlock({"check", kExamples + "model-case2-order-gadget.grid", "--times", dir + "/t", "--json"});
  EXPECT_EQ(r.exit_code, 10) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "YES");
  EXPECT_EQ(j["model"], "continuous");
  test::write_file(dir + "/t2", "g1 0\ng2 1/2\n");
  auto c = run_gridlock({"check", kExamples + "model-case1-two-growths.grid", "--times", dir + "/t2", "--json"});
  EXPECT_EQ(c.exit_code, 20);
  auto jc = nlohmann::json::parse(c.out);
  EXPECT_EQ(jc["collision"]["kind"], "node");
  // g1 has grown to width 1/2 when g2 starts; they meet when the widths sum to 1: at 3/4.
  EXPECT_EQ(jc["collision"]["time"], "3/4");
}

TEST(CheckCommand, OrderFileReadsSolverOutputAndSvgIsWritten) {
  std::string dir = test::temp_dir();
  test::write_file(dir + "/order", "c from a solver\ns YES\nv b\nv a\n");
  auto r = run_gridlock(
      {"check", kExamples + "model-case2-order-gadget.grid", "--order-file", dir + "/order", "--svg", dir + "/c.svg"});
  EXPECT_EQ(r.exit_code, 20) << r.err;
  std::string svg = test::read_file(dir + "/c.svg");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("#ff9896"), std::string::npos) << "colliding nodes are marked";
}

TEST(CheckCommand, ErrorsNameFileAndLineAndExitOne) {
  std::string dir = test::temp_dir();
  test::write_file(dir + "/bad.grid", "p grid 2 0 0 0\nn 0 0\nn 0 0\n");
  auto r = run_gridlock({"check", dir + "/bad.grid", "--order", ""});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "gridlock: error: " + dir + "/bad.grid:3: two nodes in cell (0,0)\n");
  auto missing = run_gridlock({"check", kExamples + "model-case2-order-gadget.grid", "--order", "a"});
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_EQ(missing.err, "gridlock: error: --order: the order leaves out coupling 'b'\n");
  test::write_file(dir + "/t", "a 0\nb 1/0\n");
  auto badtime = run_gridlock({"check", kExamples + "model-case2-order-gadget.grid", "--times", dir + "/t"});
  EXPECT_EQ(badtime.exit_code, 1);
  EXPECT_EQ(badtime.err, "gridlock: error: " + dir + "/t:2: bad time '1/0' (an integer or a fraction a/b)\n");
  auto usage = run_gridlock({"check", kExamples + "model-case2-order-gadget.grid"});
  EXPECT_EQ(usage.exit_code, 1);
  auto unknown = run_gridlock({"frobnicate"});
  EXPECT_EQ(unknown.exit_code, 1);
  EXPECT_EQ(unknown.err, "gridlock: error: unknown subcommand 'frobnicate' (see 'gridlock --help')\n");
}

TEST(CheckCommand, StdinInstance) {
  auto r = run_gridlock({"check", "-", "--order", "Q"}, test::read_file(kExamples + "model-case3-block.grid"));
  EXPECT_EQ(r.exit_code, 10) << r.err;
}

TEST(RenderCommand, SvgAsciiTikz) {
  std::string dir = test::temp_dir();
  auto r = run_gridlock({"render", kExamples + "model-case2-order-gadget.grid", "-o", dir + "/o.svg"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::string svg = test::read_file(dir + "/o.svg");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find(">a</text>"), std::string::npos) << "operations are labelled";
  auto a = run_gridlock({"render", kExamples + "model-case2-order-gadget.grid", "--ascii"});
  EXPECT_EQ(a.exit_code, 0);
  EXPECT_EQ(a.out.substr(0, a.out.find("anchor")), "o o-oEo\n|     |\n@Eo-o-o\n");
  auto t = run_gridlock({"render", kExamples + "model-case2-order-gadget.grid", "--tikz"});
  EXPECT_NE(t.out.find("\\begin{tikzpicture}"), std::string::npos);
  auto help = run_gridlock({"--help"});
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("check"), std::string::npos);
}

}  // namespace
}  // namespace gridlock
