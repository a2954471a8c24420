// End to end: `gridlock solve --model continuous` through the real binary,
// its start times read back by `gridlock check --times`, exit codes, JSON,
// limits and errors.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/cli.hpp"

namespace gridlock {
namespace {

using test::run_gridlock;

const std::string kExamples = std::string(GRIDLOCK_SOURCE_DIR) + "/examples/instances/";

bool has_line(const std::string& out, const std::string& line) {
  return ("\n" + out).find("\n" + line + "\n") != std::string::npos;
}

// b grows into the cell that a's contraction empties: b must start when a
// has finished (t_b >= t_a + 1).
const char* kSeparation =
    "p grid 4 3 2 0\nn 0 0\nn 0 1\nn 1 0\nn 1 1\n"
    "e 0 0 0 1\ne 0 0 1 0\ne 1 0 1 1\n"
    "o a contract 0 0 +y\no b grow 1 1 -x\n";

// Two separation gadgets whose couplings wait for each other: P = {a0, b1},
// Q = {a1, b0} needs t_Q >= t_P + 1 and t_P >= t_Q + 1.
const char* kMutualWait =
    "p grid 9 8 4 2\nn 0 0\nn 0 1\nn 1 0\nn 1 1\nn 2 0\nn 3 0\nn 3 1\nn 4 0\nn 4 1\n"
    "e 0 0 1 0\ne 1 0 2 0\ne 2 0 3 0\ne 3 0 4 0\ne 0 0 0 1\ne 1 0 1 1\ne 3 0 3 1\ne 4 0 4 1\n"
    "o a0 contract 0 0 +y\no b0 grow 1 1 -x\no a1 contract 3 0 +y\no b1 grow 4 1 -x\n"
    "q P a0 b1\nq Q a1 b0\n";

TEST(SolveContinuousCommand, YesWitnessReadBackByCheckTimes) {
  std::string dir = test::temp_dir();
  std::string grid = test::write_file(dir + "/sep.grid", kSeparation);
  auto yes = run_gridlock({"solve", grid, "--model", "continuous"});
  ASSERT_EQ(yes.exit_code, 10) << yes.out << yes.err;
  EXPECT_TRUE(has_line(yes.out, "s YES")) << yes.out;
  EXPECT_TRUE(has_line(yes.out, "v a 0")) << yes.out;
  EXPECT_NE(yes.out.find("c start times checked by the simulator"), std::string::npos);
  test::write_file(dir + "/times", yes.out);
  auto back = run_gridlock({"check", grid, "--times", dir + "/times"});
  EXPECT_EQ(back.exit_code, 10) << back.out << back.err;
  // The discrete model gives an order for the same instance.
  auto disc = run_gridlock({"solve", grid});
  EXPECT_EQ(disc.exit_code, 10) << disc.err;
  EXPECT_TRUE(has_line(disc.out, "v a b")) << disc.out;
}

TEST(SolveContinuousCommand, ExamplesAndExitCodes) {
  auto no = run_gridlock({"solve", kExamples + "model-case1-two-growths.grid", "--model", "continuous"});
  EXPECT_EQ(no.exit_code, 20) << no.err;
  EXPECT_TRUE(has_line(no.out, "s NO")) << no.out;
  std::string dir = test::temp_dir();
  auto both = run_gridlock({"solve", kExamples + "model-case2-order-gadget.grid", "--model", "continuous"});
  EXPECT_EQ(both.exit_code, 10) << both.err;
  EXPECT_TRUE(has_line(both.out, "v a 0") && has_line(both.out, "v b 0")) << both.out;
  test::write_file(dir + "/t", both.out);
  EXPECT_EQ(run_gridlock({"check", kExamples + "model-case2-order-gadget.grid", "--times", dir + "/t"}).exit_code, 10);
  // The continuous examples: answers stated in their comments.
  auto sep = run_gridlock({"solve", kExamples + "continuous-separation.grid", "--model", "continuous"});
  EXPECT_EQ(sep.exit_code, 10) << sep.err;
  EXPECT_TRUE(has_line(sep.out, "v a 0") && has_line(sep.out, "v b 1")) << sep.out;
  auto block = run_gridlock({"solve", kExamples + "continuous-block-two-couplings.grid", "--model", "continuous"});
  EXPECT_EQ(block.exit_code, 10) << block.err;
  EXPECT_EQ(run_gridlock({"solve", kExamples + "continuous-block-two-couplings.grid"}).exit_code, 20);
}

// The block with its two expansions in separate couplings: no order works,
// starting them together does.
TEST(SolveContinuousCommand, ContinuousYesWhereDiscreteSaysNo) {
  std::string dir = test::temp_dir();
  std::string grid = test::write_file(dir + "/b.grid",
                                      "p grid 4 4 2 0\nn 0 0\nn 1 0\nn 0 1\nn 1 1\n"
                                      "e 0 0 1 0\ne 0 1 1 1\ne 0 0 0 1\ne 1 0 1 1\n"
                                      "o a expand 0 0 +x\no b expand 0 1 +x\n");
  EXPECT_EQ(run_gridlock({"solve", grid}).exit_code, 20);
  auto r = run_gridlock({"solve", grid, "--model", "continuous", "--json"});
  ASSERT_EQ(r.exit_code, 10) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "YES");
  EXPECT_EQ(j["model"], "continuous");
  ASSERT_EQ(j["witness"].size(), 2u);
  EXPECT_EQ(j["witness"][0], "a 0");
  EXPECT_EQ(j["witness"][1], "b 0");
  EXPECT_TRUE(j["stats"].contains("constraints"));
}

// The mutual wait is proved NO by the learning engine (the default) and by
// Z3 (--engine z3).
TEST(SolveContinuousCommand, NoFromZ3OnANonHorizontalInstance) {
  std::string dir = test::temp_dir();
  std::string grid = test::write_file(dir + "/n.grid", kMutualWait);
  auto r = run_gridlock({"solve", grid, "--model", "continuous", "--json"});
  ASSERT_EQ(r.exit_code, 20) << r.out << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["engine"], "dl") << r.out;
  EXPECT_EQ(j["status"], "NO");
  auto z = run_gridlock({"solve", grid, "--model", "continuous", "--engine", "z3", "--json"});
  ASSERT_EQ(z.exit_code, 20) << z.out << z.err;
  EXPECT_EQ(nlohmann::json::parse(z.out)["engine"], "z3") << z.out;
  // No order works either.
  auto disc = run_gridlock({"solve", grid});
  EXPECT_EQ(disc.exit_code, 20) << disc.out;
}

TEST(SolveContinuousCommand, BadOptionsAreErrors) {
  auto bad = run_gridlock({"solve", kExamples + "model-case1-two-growths.grid", "--model", "sometimes"});
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("gridlock: error: --model must be discrete or continuous"), std::string::npos) << bad.err;
  auto eng = run_gridlock(
      {"solve", kExamples + "model-case1-two-growths.grid", "--model", "continuous", "--engine", "states"});
  EXPECT_EQ(eng.exit_code, 1);
  EXPECT_NE(eng.err.find("--engine with --model continuous must be auto, dl, sat or z3"), std::string::npos) << eng.err;
  auto missing = run_gridlock({"solve", "/nonexistent.grid", "--model", "continuous"});
  EXPECT_EQ(missing.exit_code, 1);
}

// A limit gives s UNKNOWN and exit 0, never a wrong answer: the smallest
// timeout (a millisecond, counted from the command's start) has passed
// before Z3 answers (creating its context alone takes longer).
// The instance needs Z3 (the two gadgets wait for each other: NO).
TEST(SolveContinuousCommand, TimeoutGivesUnknown) {
  std::string dir = test::temp_dir();
  std::string wait = test::write_file(dir + "/n.grid", kMutualWait);
  auto r = run_gridlock({"solve", wait, "--model", "continuous", "--timeout", "0.001"});
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_TRUE(has_line(r.out, "s UNKNOWN")) << r.out;
  EXPECT_EQ(r.out.find("\nv "), std::string::npos) << r.out;
  std::string grid = test::write_file(dir + "/sep.grid", kSeparation);
  auto ok = run_gridlock({"solve", grid, "--model", "continuous", "--timeout", "60", "--max-states", "1000000"});
  EXPECT_EQ(ok.exit_code, 10) << ok.out << ok.err;
}

}  // namespace
}  // namespace gridlock
