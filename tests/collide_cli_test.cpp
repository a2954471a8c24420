// End to end: `gridlock collide` through the real binary, its witnesses read
// back by `gridlock check`, and bad input.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include <nlohmann/json.hpp>

#include "bench/bench_families.hpp"
#include "collide/adversarial.hpp"
#include "lattice/grid_format.hpp"
#include "support/cli.hpp"
#include "support/instance_io.hpp"

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
  EXPECT_EQ(j["algorithm"], "single-coupling-one-axis");
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

// With couplings, the discrete answer comes from the continuous pair tests
// (docs/collide.md, "the models agree") and a YES's order from subset sums
// near the continuous pair; `--method pairwise` is the subset-sum decider
// on every pair. Both answers agree, the YES order is read back by `check`,
// and the NO certificate is accepted by `certify`.
TEST(CollideCommand, DiscreteAnswerFromTheContinuousTests) {
  const std::string dir = test::temp_dir();
  const std::string yes = kExamples + "tiny-sat.grid";
  auto r = run_gridlock({"collide", yes, "--model", "discrete"});
  ASSERT_EQ(r.exit_code, 10) << r.err;
  EXPECT_NE(r.out.find("c algorithm: one-axis-groups+subset-sum"), std::string::npos) << r.out;
  test::write_file(dir + "/w", r.out);
  auto c = run_gridlock({"check", yes, "--order-file", dir + "/w"});
  EXPECT_EQ(c.exit_code, 20) << c.out << c.err;
  auto p = run_gridlock({"collide", yes, "--model", "discrete", "--method", "pairwise"});
  EXPECT_EQ(p.exit_code, 10) << p.err;
  EXPECT_NE(p.out.find("c algorithm: pairwise-subset-sum"), std::string::npos) << p.out;

  // A row pushed apart by expansions (two couplings, one of two): NO.
  test::write_file(dir + "/row.grid",
                   "p grid 6 5 3 2\nn 0 0\nn 1 0\nn 2 0\nn 3 0\nn 4 0\nn 5 0\n"
                   "e 0 0 1 0\ne 1 0 2 0\ne 2 0 3 0\ne 3 0 4 0\ne 4 0 5 0\n"
                   "o a expand 0 0 +x\no b expand 2 0 +x\no c expand 4 0 +x\nq P a b\nq Q c\n");
  auto n = run_gridlock({"collide", dir + "/row.grid", "--model", "discrete", "--certificate", dir + "/no.cert"});
  ASSERT_EQ(n.exit_code, 20) << n.out << n.err;
  EXPECT_NE(n.out.find("c algorithm: one-axis-groups ("), std::string::npos) << n.out;
  EXPECT_NE(n.out.find("the discrete answer is the continuous one"), std::string::npos) << n.out;
  auto np = run_gridlock({"collide", dir + "/row.grid", "--model", "discrete", "--method", "pairwise"});
  EXPECT_EQ(np.exit_code, 20) << np.out << np.err;
  auto cert = run_gridlock({"certify", dir + "/row.grid", dir + "/no.cert"});
  EXPECT_EQ(cert.exit_code, 20) << cert.out << cert.err;
}

// A one-coupling YES that names its first collision (the instance's .grid
// text): in both models
// `collide` reports `algorithm`, the collision at `time` (`first`: the
// rest of its line) and the moment it was checked at, and `check` runs the
// full simulation on the witness and must find the same collision.
void expect_named_first_collision(const std::string& grid_text, const std::string& algorithm, const std::string& time,
                                  const std::string& first, const std::string& checked_at) {
  const std::string dir = test::temp_dir(), grid = dir + "/i.grid";
  test::write_file(grid, grid_text);
  const std::string collision = "node collision at time " + time + " between " + first;
  const std::string algorithm_line = "c algorithm: " + algorithm + " (";
  const std::string checked_line = "c checked in the simulator's configuration at time " + checked_at +
                                   ": they overlap";
  for (const char* model : {"continuous", "discrete"}) {
    auto r = run_gridlock({"collide", grid, "--model", model});
    ASSERT_EQ(r.exit_code, 10) << r.out << r.err;
    EXPECT_NE(r.out.find(algorithm_line), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("c first " + collision), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(checked_line), std::string::npos) << r.out;
    test::write_file(dir + "/w", r.out);
    auto c = run_gridlock({"check", grid, std::string(model) == "discrete" ? "--order-file" : "--times", dir + "/w"});
    EXPECT_EQ(c.exit_code, 20) << c.out << c.err;
    EXPECT_NE(c.out.find(collision), std::string::npos) << c.out;
  }
  auto j = nlohmann::json::parse(run_gridlock({"collide", grid, "--json"}).out);
  EXPECT_EQ(j["status"], "YES");
  EXPECT_EQ(j["checked_at"], checked_at);
  EXPECT_EQ(j["collision"]["time"], time);
}

// One coupling, one axis: the answer names the first collision itself
// (worked case 1 with both growths in one coupling: [1, 1 + t] meets
// [2 - t, 2] after t = 1/2).
TEST(CollideCommand, OneAxisYesNamesTheFirstCollision) {
  expect_named_first_collision(
      "p grid 5 4 2 1\nn 0 0\nn 2 0\nn 0 1\nn 1 1\nn 2 1\ne 0 0 0 1\ne 0 1 1 1\ne 1 1 2 1\n"
      "e 2 1 2 0\no g1 grow 0 0 +x\no g2 grow 2 0 -x\nq G g1 g2\n",
      "single-coupling-one-axis", "1/2", "", "3/4");
}

// One coupling on both axes whose x faces keep their order: one sweep
// along x finds the YES and bisects for its first moment. A U whose right
// side contracts (+y) pulls its top left node onto its bottom left one
// from t = 0, while an expansion (+x) moves the whole U.
TEST(CollideCommand, FixedAxisYesNamesTheFirstCollision) {
  expect_named_first_collision(
      "p grid 5 4 2 1\nn -1 0\nn 0 0\nn 1 0\nn 1 1\nn 0 1\ne -1 0 0 0\ne 0 0 1 0\ne 1 0 1 1\n"
      "e 1 1 0 1\no x expand -1 0 +x\no c contract 1 0 +y\nq Q x c\n",
      "single-coupling-fixed-axis", "0", "node (0,0) and node (0,1)", "1/2");
}

// One coupling whose faces change order on both axes: the space-time cell
// sweep names the first collision (the band sweep of slope 2 with its band
// one unit too close, K = 16: collide/adversarial.hpp; no cut along x, y or
// a diagonal, and the time slabs decline it). `check` confirms the named
// collision by simulating the printed schedule.
TEST(CollideCommand, SweepYesNamesTheFirstCollision) {
  std::ostringstream grid;
  write_instance(grid, band_sweep_instance(16, 2, 3, true));
  expect_named_first_collision(grid.str(), "single-coupling", "17/32", "node (64,30) and node (82,37)", "511/960");
}

// Time slabs name it too: the stalactite comb of 3 with its middle
// stalactite reaching into the teeth's path (bench_families.hpp), cut over
// the halves of [0, 1]; first at floor(3 / 2) / k = 1/14.
TEST(CollideCommand, TimeSlabsYesNamesTheFirstCollision) {
  std::ostringstream grid;
  write_instance(grid, bench::stalactite_comb(3, false, true));
  expect_named_first_collision(grid.str(), "single-coupling-time-slabs", "1/14", "node (2,3) and node (4,4)", "1/7");
}

// The own-speed stalactite comb's NO by time slabs, through the command
// line: its certificate is of the slabs kind (the pairs of the slabs'
// sweeps, not every pair), and certify accepts it in both models, making
// the slabs itself; the same word on the comb with a hit (YES) is refused.
TEST(CollideCommand, TimeSlabsNoHasASlabsCertificate) {
  const std::string dir = test::temp_dir();
  std::ostringstream grid, hit;
  write_instance(grid, bench::stalactite_comb(12, true));
  test::write_file(dir + "/s.grid", grid.str());
  auto r = run_gridlock({"collide", dir + "/s.grid", "--certificate", dir + "/s.cert"});
  ASSERT_EQ(r.exit_code, 20) << r.out << r.err;
  EXPECT_NE(r.out.find("c algorithm: single-coupling-time-slabs ("), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("(one coupling, groups over time slabs each keeping an order: their sweeps' pairs)"),
            std::string::npos)
      << r.out;
  const std::string cert = test::read_file(dir + "/s.cert");
  EXPECT_EQ(cert.rfind("p gridlock-collide-no-certificate 1 continuous kept-order slabs\n", 0), 0u) << cert;
  for (const char* model : {"continuous", "discrete"}) {
    auto c = run_gridlock({"certify", dir + "/s.grid", dir + "/s.cert", "--model", model});
    EXPECT_EQ(c.exit_code, 20) << c.out << c.err;
    EXPECT_NE(c.out.find("groups over time slabs each keeping an order"), std::string::npos) << c.out;
  }
  const Instance yes = bench::stalactite_comb(12, false, true);
  write_instance(hit, yes);
  test::write_file(dir + "/h.grid", hit.str());
  test::write_file(dir + "/h.cert",
                   "p gridlock-collide-no-certificate 1 continuous kept-order slabs\n" + couplings_line(yes));
  auto h = run_gridlock({"certify", dir + "/h.grid", dir + "/h.cert"});
  EXPECT_EQ(h.exit_code, 1) << h.out << h.err;
  EXPECT_NE(h.err.find("(a pair of the kept-order sweep)"), std::string::npos) << h.err;
}

// --certificate C on an answer without one: C is left as it was (a file
// there is not this answer's certificate) and a comment says so.
TEST(CollideCommand, CertificateOptionOnAYesLeavesTheFileAndSaysSo) {
  const std::string dir = test::temp_dir();
  test::write_file(dir + "/old.cert", "an earlier certificate\n");
  const std::string yes = kExamples + "model-case1-two-growths.grid";
  auto r = run_gridlock({"collide", yes, "--certificate", dir + "/old.cert"});
  ASSERT_EQ(r.exit_code, 10) << r.out << r.err;
  EXPECT_NE(r.out.find("c no certificate written: only a NO has one"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("old.cert is left as it was (not this answer's)"), std::string::npos) << r.out;
  EXPECT_EQ(test::read_file(dir + "/old.cert"), "an earlier certificate\n");
  for (const char* model : {"discrete", "continuous"}) {
    auto s = run_gridlock({"solve", kExamples + "tiny-sat.grid", "--model", model, "--certificate", dir + "/new.cert"});
    ASSERT_EQ(s.exit_code, 10) << s.out << s.err;
    EXPECT_NE(s.out.find("new.cert not created"), std::string::npos) << s.out;
    EXPECT_FALSE(std::filesystem::exists(dir + "/new.cert"));
  }
  auto d = run_gridlock({"solve", kExamples + "tiny-sat.grid", "--certificate", "-"});
  EXPECT_EQ(d.exit_code, 10) << d.out << d.err;
  EXPECT_NE(d.out.find("only a NO has one (the witness of this YES is on the 'v' lines); nothing printed"),
            std::string::npos)
      << d.out;
  // A row of 20 000 nodes with singleton expansions and a stub of two nodes
  // above its first with one vertical expansion: its NO (the tree method)
  // takes well under a second; its certificate covers every pair (the
  // operations use both axes), far more than one second, so the limit
  // comes while it is written (or, on a slow machine, before the answer).
  std::string row = test::expansion_row_grid(20000, 1);
  row.replace(0, row.find('\n'), "p grid 20002 20001 10001 10000");
  row.insert(row.find("e 0 0 1 0"), "n 0 1\nn 0 2\n");
  row.insert(row.find("o e0 "), "e 0 0 0 1\ne 0 1 0 2\no v expand 0 1 +y\n");
  test::write_file(dir + "/row.grid", row);
  auto t = run_gridlock({"collide", dir + "/row.grid", "--timeout", "1", "--certificate", dir + "/old.cert"});
  EXPECT_TRUE(t.exit_code == 20 || t.exit_code == 0) << t.out << t.err;
  EXPECT_NE(t.out.find("old.cert is left as it was (not this answer's)"), std::string::npos) << t.out;
  EXPECT_EQ(test::read_file(dir + "/old.cert"), "an earlier certificate\n");
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
