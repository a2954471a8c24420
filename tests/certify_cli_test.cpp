// gridlock certify and solve --certificate end to end (the real binary on
// real files): every kind of certificate written and accepted (exit 20,
// "s NO", "c certificate checked"); broken ones refused with exit 1 and the
// reason; YES instances get no certificate; verify and gen-instances use it.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "bench/bench_families.hpp"
#include "collide/adversarial.hpp"
#include "lattice/grid_format.hpp"
#include "support/cli.hpp"
#include "support/instance_io.hpp"

namespace gridlock {
namespace {

using test::run_gridlock;

// (1,0) expands into (2,0), which sits beside it unjoined: NO in both models.
const char* const kPush =
    "p grid 6 5 1 0\nn 0 0\nn 1 0\nn 0 1\nn 1 1\nn 2 1\nn 2 0\n"
    "e 0 0 1 0\ne 0 0 0 1\ne 0 1 1 1\ne 1 1 2 1\ne 2 1 2 0\no a expand 0 0 +x\n";
// An expansion on one side of a square: a breaks the cycle.
const char* const kSquare =
    "p grid 4 4 1 0\nn 0 0\nn 1 0\nn 0 1\nn 1 1\ne 0 0 1 0\ne 0 0 0 1\ne 1 0 1 1\ne 0 1 1 1\no a expand 0 0 +x\n";

// (2,0) rides coupling Q diagonally past (0,0), corner to corner: x overlap
// needs Q past 1/2, y overlap Q before 1/2. No schedule collides, and only
// the sum of those two forms shows it (an r line).
const char* const kDiagonal =
    "p grid 17 16 4 1\nn 0 0\nn -1 0\nn -2 0\nn -3 0\nn -4 0\nn -4 1\nn -4 2\nn -4 3\nn -3 3\n"
    "n -2 3\nn -1 3\nn 0 3\nn 1 3\nn 2 3\nn 2 2\nn 2 1\nn 2 0\ne 0 0 -1 0\ne -1 0 -2 0\n"
    "e -2 0 -3 0\ne -3 0 -4 0\ne -4 0 -4 1\ne -4 1 -4 2\ne -4 2 -4 3\ne -4 3 -3 3\n"
    "e -3 3 -2 3\ne -2 3 -1 3\ne -1 3 0 3\ne 0 3 1 3\ne 1 3 2 3\ne 2 3 2 2\ne 2 2 2 1\n"
    "e 2 1 2 0\no e1 expand 0 0 -x\no e2 expand -2 0 -x\no e3 expand -4 0 +y\n"
    "o e4 expand -4 2 +y\nq Q e1 e2 e3 e4\n";

void expect_certified(const std::string& grid, const std::string& cert, const std::string& model,
                      const std::string& kind) {
  const auto s = run_gridlock({"solve", grid, "--model", model, "--certificate", cert});
  ASSERT_EQ(s.exit_code, 20) << s.out << s.err;
  EXPECT_NE(s.out.find("certificate written to"), std::string::npos);
  EXPECT_NE(test::read_file(cert).find(kind), std::string::npos) << test::read_file(cert);
  const auto c = run_gridlock({"certify", grid, cert, "--model", model});
  EXPECT_EQ(c.exit_code, 20) << c.out << c.err;
  EXPECT_NE(c.out.find("s NO"), std::string::npos);
  EXPECT_NE(c.out.find("c certificate checked"), std::string::npos);
}

TEST(CertifyCli, EveryKindWrittenAndChecked) {
  const std::string d = test::temp_dir();
  const std::string push = test::write_file(d + "/push.grid", kPush),
                    square = test::write_file(d + "/sq.grid", kSquare);
  expect_certified(push, d + "/push.cert", "discrete", "gaps");
  expect_certified(push, d + "/push.ccert", "continuous", "final-gap 1,0 2,0");
  expect_certified(square, d + "/sq.cert", "discrete", "breaker a");
  expect_certified(square, d + "/sq.ccert", "continuous", "final-cycle");
}

TEST(CertifyCli, CompiledUnsatFormula) {
  const std::string d = test::temp_dir();
  // (x1 or x2) and (x1 or -x2) and (-x1 or x2) and (-x1 or -x2): unsatisfiable.
  test::write_file(d + "/f.cnf", "p cnf 2 4\n1 2 0\n1 -2 0\n-1 2 0\n-1 -2 0\n");
  ASSERT_EQ(run_gridlock({"compile", d + "/f.cnf", "-o", d + "/f.grid"}).exit_code, 0);
  expect_certified(d + "/f.grid", d + "/f.cert", "discrete", "gaps");
  // Its certificate is refused for another instance.
  test::write_file(d + "/g.cnf", "p cnf 2 3\n1 2 0\n1 -2 0\n-1 2 0\n");
  ASSERT_EQ(run_gridlock({"compile", d + "/g.cnf", "-o", d + "/g.grid"}).exit_code, 0);
  const auto other = run_gridlock({"certify", d + "/g.grid", d + "/f.cert"});
  EXPECT_EQ(other.exit_code, 1);
  EXPECT_NE(other.err.find("certificate for another instance"), std::string::npos) << other.err;
  // The satisfiable one gets no certificate (and leaves no file).
  const auto yes = run_gridlock({"solve", d + "/g.grid", "--certificate", d + "/g.cert"});
  EXPECT_EQ(yes.exit_code, 10);
  EXPECT_FALSE(std::filesystem::exists(d + "/g.cert"));
}

TEST(CertifyCli, BrokenCertificatesRefusedWithTheReason) {
  const std::string d = test::temp_dir();
  const std::string push = test::write_file(d + "/push.grid", kPush),
                    square = test::write_file(d + "/sq.grid", kSquare);
  ASSERT_EQ(run_gridlock({"solve", push, "--certificate", d + "/p.cert"}).exit_code, 20);
  const std::string good = test::read_file(d + "/p.cert");
  struct Case {
    std::string grid, text, model, reason;
  };
  const std::string head = good.substr(0, good.find("gaps"));
  const Case cases[] = {
      {push, head, "discrete", "no evidence"},
      {push, head + "gaps\n", "discrete", "does not end with the empty clause"},
      {push, head + "gaps\nl a<zz\nl\n", "discrete", "line 5: unknown coupling 'zz'"},
      {push, head + "gaps\nl a<a\nl\n", "discrete", "orders a coupling before itself"},
      {push, head + "final-gap 0,0 1,0\n", "discrete", "does not prove NO in the discrete model"},
      {push, "p gridlock-no-certificate 1 continuous\n" + head.substr(head.find("couplings")) + "final-gap 0,0 1,0\n",
       "continuous", "not negative"},
      {push, good, "continuous", "a discrete certificate, checked as continuous"},
      {square, head + "breaker a 0,0 1,0\n", "discrete", "sums to zero around this walk"},
      {square, head + "breaker a 0,0 1,1\n", "discrete", "are not joined by an edge"},
      {push, "", "discrete", "no 'p gridlock-no-certificate 1 MODEL' line"},
  };
  int i = 0;
  for (const Case& c : cases) {
    const std::string f = test::write_file(d + "/bad" + std::to_string(i++), c.text);
    const auto r = run_gridlock({"certify", c.grid, f, "--model", c.model});
    EXPECT_EQ(r.exit_code, 1) << c.text;
    // A reason "line N: what" is reported as FILE:N: certificate rejected: what; others as FILE: ...
    EXPECT_EQ(r.err.rfind("gridlock: error: " + f, 0), 0U) << r.err;
    EXPECT_NE(r.err.find("certificate rejected: "), std::string::npos) << r.err;
    std::string want = c.reason;
    if (c.reason.rfind("line ", 0) == 0) {
      const size_t colon = c.reason.find(": ");
      want = f + ":" + c.reason.substr(5, colon - 5) + ": certificate rejected: " + c.reason.substr(colon + 2);
    }
    EXPECT_NE(r.err.find(want), std::string::npos) << "want '" << want << "' in " << r.err;
  }
}

// gridlock collide --certificate: written with a NO, checked by certify in
// both models; a changed multiplier, a foreign instance and a YES refused.
TEST(CertifyCli, CollideCertificateEndToEnd) {
  const std::string d = test::temp_dir();
  // The arc sweep of 8 runs: no cut over (0, 1), but cuts over slabs of
  // it: the slabs kind, accepted in both models.
  std::ostringstream arc_text;
  write_instance(arc_text, arc_sweep_instance(8, 3));
  const std::string arc = test::write_file(d + "/arc.grid", arc_text.str()), arc_cert = d + "/arc.cert";
  ASSERT_EQ(run_gridlock({"collide", arc, "--certificate", arc_cert}).exit_code, 20);
  EXPECT_EQ(test::read_file(arc_cert).rfind("p gridlock-collide-no-certificate 1 continuous kept-order slabs\n", 0),
            0U);
  for (const char* model : {"continuous", "discrete"})
    EXPECT_EQ(run_gridlock({"certify", arc, arc_cert, "--model", model}).exit_code, 20) << model;
  // The diagonal hook with its operations in two couplings: every pair,
  // one of them ruled out by a combination of two forms.
  std::string two = kDiagonal;
  two.replace(two.find("p grid 17 16 4 1"), 16, "p grid 17 16 4 2");
  two.replace(two.find("q Q e1 e2 e3 e4"), 15, "q Q e1 e3\nq R e2 e4");
  const std::string diag = test::write_file(d + "/diag.grid", two), cert = d + "/diag.cert";
  const auto w = run_gridlock({"collide", diag, "--certificate", cert});
  ASSERT_EQ(w.exit_code, 20) << w.out << w.err;
  EXPECT_NE(w.out.find("1 with multipliers"), std::string::npos) << w.out;
  const std::string text = test::read_file(cert);
  EXPECT_EQ(text.rfind("p gridlock-collide-no-certificate 1 continuous\n", 0), 0U) << text;
  EXPECT_NE(text.find("r 0,0 2,0 1 0 1 0 0 0 0 0\n"), std::string::npos) << text;
  for (const char* model : {"continuous", "discrete"}) {
    const auto c = run_gridlock({"certify", diag, cert, "--model", model});
    EXPECT_EQ(c.exit_code, 20) << c.out << c.err;
    EXPECT_NE(c.out.find("s NO"), std::string::npos);
    EXPECT_NE(c.out.find("c certificate checked"), std::string::npos);
    EXPECT_NE(c.out.find("no schedule collides"), std::string::npos) << c.out;
  }
  std::string bad = text;
  bad.replace(bad.find("r 0,0 2,0 1 0 1"), 15, "r 0,0 2,0 1 0 0");
  const std::string badf = test::write_file(d + "/bad.cert", bad);
  const auto b = run_gridlock({"certify", diag, badf});
  EXPECT_EQ(b.exit_code, 1);
  EXPECT_NE(b.err.find(badf + ":3: certificate rejected: the combination of the forms is positive"), std::string::npos)
      << b.err;
  // '#' lines are comments; a p line after the couplings line is named
  // by the collide reader, not taken for a solve certificate.
  const std::string noted = test::write_file(d + "/noted.cert", "# checked by hand\n" + text);
  EXPECT_EQ(run_gridlock({"certify", diag, noted}).exit_code, 20);
  const size_t p_end = text.find('\n') + 1, q_end = text.find('\n', p_end) + 1;
  const std::string swapped = test::write_file(
      d + "/swapped.cert", text.substr(p_end, q_end - p_end) + text.substr(0, p_end) + text.substr(q_end));
  const auto sw = run_gridlock({"certify", diag, swapped});
  EXPECT_EQ(sw.exit_code, 1);
  EXPECT_NE(sw.err.find(swapped + ":1: certificate rejected: expected 'p gridlock-collide-no-certificate 1 "
                                  "continuous' first"),
            std::string::npos)
      << sw.err;
  const std::string push = test::write_file(d + "/push.grid", kPush);
  const auto other = run_gridlock({"certify", push, cert});
  EXPECT_EQ(other.exit_code, 1);
  EXPECT_NE(other.err.find("certificate for another instance"), std::string::npos) << other.err;
  // A YES (a breaks the square's cycle) writes nothing.
  const std::string square = test::write_file(d + "/sq.grid", kSquare);
  EXPECT_EQ(run_gridlock({"collide", square, "--certificate", d + "/sq.cert"}).exit_code, 10);
  EXPECT_FALSE(std::filesystem::exists(d + "/sq.cert"));
}

// One axis: collide writes the one-axis kind (only the row groups' pairs),
// certify checks it and says so; the one-axis p line is refused on an
// instance whose operations use both axes, and on a YES (kPush) the
// certificate of the same shape with its expansion moved (a NO) is refused
// at the row group pair that meets.
TEST(CertifyCli, CollideOneAxisCertificateEndToEnd) {
  const std::string d = test::temp_dir();
  const std::string row = test::write_file(d + "/row.grid", test::expansion_row_grid(41, 3)), cert = d + "/row.cert";
  const auto w = run_gridlock({"collide", row, "--certificate", cert, "--json"});
  ASSERT_EQ(w.exit_code, 20) << w.out << w.err;
  EXPECT_NE(w.out.find("\"certificate_kind\":\"one-axis\""), std::string::npos) << w.out;
  // 41 units and 20 inserted nodes: 40 pairs of neighbour units, and each
  // inserted node with the two units around it.
  EXPECT_NE(w.out.find("80 pairs of regions (one axis: the row groups' pairs)"), std::string::npos) << w.out;
  const std::string text = test::read_file(cert);
  EXPECT_EQ(text.rfind("p gridlock-collide-no-certificate 1 continuous one-axis\n", 0), 0U) << text;
  for (const char* model : {"continuous", "discrete"}) {
    const auto c = run_gridlock({"certify", row, cert, "--model", model});
    EXPECT_EQ(c.exit_code, 20) << c.out << c.err;
    EXPECT_NE(c.out.find("one axis, 80 pairs in row groups"), std::string::npos) << c.out;
    EXPECT_NE(c.out.find("c certificate checked"), std::string::npos) << c.out;
  }
  const std::string diag = test::write_file(d + "/diag.grid", kDiagonal), dcert = d + "/diag.cert";
  ASSERT_EQ(run_gridlock({"collide", diag, "--certificate", dcert}).exit_code, 20);
  std::string both = test::read_file(dcert);
  both = "p gridlock-collide-no-certificate 1 continuous one-axis" + both.substr(both.find('\n'));
  const std::string bothf = test::write_file(d + "/both.cert", both);
  const auto b = run_gridlock({"certify", diag, bothf});
  EXPECT_EQ(b.exit_code, 1);
  EXPECT_NE(b.err.find(bothf + ":1: certificate rejected: one-axis, but the operations move along both x and y"),
            std::string::npos)
      << b.err;
  std::string moved = kPush;
  moved.replace(moved.find("o a expand 0 0"), 14, "o a expand 1 1");
  const std::string no = test::write_file(d + "/moved.grid", moved), ncert = d + "/moved.cert";
  ASSERT_EQ(run_gridlock({"collide", no, "--certificate", ncert}).exit_code, 20);
  const std::string push = test::write_file(d + "/push.grid", kPush);
  ASSERT_EQ(run_gridlock({"collide", push}).exit_code, 10);
  const auto y = run_gridlock({"certify", push, ncert});
  EXPECT_EQ(y.exit_code, 1);
  EXPECT_NE(y.err.find("node (1,0) and node (2,0) have no r line, and no single form rules them out (a pair of one "
                       "row group)"),
            std::string::npos)
      << y.err;
}

// One coupling whose x faces keep their order (the mixed comb): collide
// writes the kept-order kind (only the fixed-axis sweep's pairs), certify
// checks it with its own sweep and says so; the y word is refused (the
// teeth's y faces change order), and so is the word on an instance of
// several couplings.
TEST(CertifyCli, CollideKeptOrderCertificateEndToEnd) {
  const std::string d = test::temp_dir();
  std::ostringstream grid;
  write_instance(grid, bench::comb(64, 3, 64, bench::CombOps::Mixed, 0, 7));
  const std::string comb = test::write_file(d + "/comb.grid", grid.str()), cert = d + "/comb.cert";
  const auto w = run_gridlock({"collide", comb, "--certificate", cert, "--json"});
  ASSERT_EQ(w.exit_code, 20) << w.out << w.err;
  EXPECT_NE(w.out.find("\"algorithm\":\"single-coupling-fixed-axis\""), std::string::npos) << w.out;
  EXPECT_NE(w.out.find("\"certificate_kind\":\"kept-order\""), std::string::npos) << w.out;
  EXPECT_NE(w.out.find("(one coupling, the x order kept: the sweep's pairs)"), std::string::npos) << w.out;
  const std::string text = test::read_file(cert);
  EXPECT_EQ(text.rfind("p gridlock-collide-no-certificate 1 continuous kept-order x\n", 0), 0U) << text;
  for (const char* model : {"continuous", "discrete"}) {
    const auto c = run_gridlock({"certify", comb, cert, "--model", model, "--json"});
    EXPECT_EQ(c.exit_code, 20) << c.out << c.err;
    EXPECT_NE(c.out.find("one coupling, the x order kept, "), std::string::npos) << c.out;
    EXPECT_NE(c.out.find("\"kept_axis\":\"x\""), std::string::npos) << c.out;
    EXPECT_NE(c.out.find("\"certificate checked\""), std::string::npos) << c.out;
  }
  std::string other = text;
  other.replace(other.find("kept-order x"), 12, "kept-order y");
  const std::string otherf = test::write_file(d + "/other.cert", other);
  const auto o = run_gridlock({"certify", comb, otherf});
  EXPECT_EQ(o.exit_code, 1);
  EXPECT_NE(o.err.find(otherf + ":1: certificate rejected: kept-order y, but the y faces of "), std::string::npos)
      << o.err;
  const std::string row = test::write_file(d + "/row.grid", test::expansion_row_grid(41, 3)), rcert = d + "/row.cert";
  ASSERT_EQ(run_gridlock({"collide", row, "--certificate", rcert}).exit_code, 20);
  std::string several = test::read_file(rcert);
  several.replace(several.find("one-axis"), 8, "kept-order x");
  const std::string severalf = test::write_file(d + "/several.cert", several);
  const auto v = run_gridlock({"certify", row, severalf});
  EXPECT_EQ(v.exit_code, 1);
  EXPECT_NE(v.err.find(severalf + ":1: certificate rejected: kept-order, but the instance has "), std::string::npos)
      << v.err;
}

// The lidded comb (bench_families.hpp): neither axis keeps its order,
// but cuts split it into groups that do. collide writes `kept-order
// separated` with every group's sweep pairs; certify cuts the groups
// itself and accepts it in both models. The word is refused at line 1 on
// the diagonal sweep, which no cut separates, and `kept-order x` on the
// comb, whose x order the lid changes.
TEST(CertifyCli, CollideSeparatedCertificateEndToEnd) {
  const std::string d = test::temp_dir();
  std::ostringstream grid;
  write_instance(grid, bench::comb(256, 3, 256, bench::CombOps::Mixed, 0, 7, true));
  const std::string comb = test::write_file(d + "/lidded.grid", grid.str()), cert = d + "/lidded.cert";
  const auto w = run_gridlock({"collide", comb, "--certificate", cert, "--json"});
  ASSERT_EQ(w.exit_code, 20) << w.out << w.err;
  EXPECT_NE(w.out.find("\"algorithm\":\"single-coupling-separated\""), std::string::npos) << w.out;
  EXPECT_NE(w.out.find("\"certificate_kind\":\"kept-order\""), std::string::npos) << w.out;
  EXPECT_NE(w.out.find("(one coupling, separated groups each keeping an order: their sweeps' pairs)"), std::string::npos)
      << w.out;
  const std::string text = test::read_file(cert);
  EXPECT_EQ(text.rfind("p gridlock-collide-no-certificate 1 continuous kept-order separated\n", 0), 0U) << text;
  for (const char* model : {"continuous", "discrete"}) {
    const auto c = run_gridlock({"certify", comb, cert, "--model", model, "--json"});
    EXPECT_EQ(c.exit_code, 20) << c.out << c.err;
    EXPECT_NE(c.out.find("one coupling, separated groups each keeping an order, "), std::string::npos) << c.out;
    EXPECT_NE(c.out.find("\"kept_axis\":\"separated\""), std::string::npos) << c.out;
  }
  std::string one = text;
  one.replace(one.find("kept-order separated"), 20, "kept-order x");
  const std::string onef = test::write_file(d + "/one.cert", one);
  const auto o = run_gridlock({"certify", comb, onef});
  EXPECT_EQ(o.exit_code, 1);
  EXPECT_NE(o.err.find(onef + ":1: certificate rejected: kept-order x, but the x faces of "), std::string::npos)
      << o.err;
  std::ostringstream diag;
  write_instance(diag, arc_sweep_instance(8, 3));  // no cut over (0, 1): the slabs kind
  const std::string diagonal = test::write_file(d + "/diagonal.grid", diag.str()), dcert = d + "/diagonal.cert";
  ASSERT_EQ(run_gridlock({"collide", diagonal, "--certificate", dcert}).exit_code, 20);
  std::string forged = test::read_file(dcert);
  const size_t end = forged.find('\n');
  forged.replace(0, end, "p gridlock-collide-no-certificate 1 continuous kept-order separated");
  const std::string forgedf = test::write_file(d + "/forged.cert", forged);
  const auto f = run_gridlock({"certify", diagonal, forgedf});
  EXPECT_EQ(f.exit_code, 1);
  EXPECT_NE(f.err.find(forgedf + ":1: certificate rejected: kept-order separated, but the group of "), std::string::npos)
      << f.err;
  EXPECT_NE(f.err.find("keeps neither order and no cut along x, y, x + y, x - y or across its motion separates it"),
            std::string::npos)
      << f.err;
}

TEST(CertifyCli, VerifyAndGenInstancesUseIt) {
  const std::string d = test::temp_dir();
  test::write_file(d + "/f.cnf", "p cnf 2 4\n1 2 0\n1 -2 0\n-1 2 0\n-1 -2 0\n");
  const auto v = run_gridlock({"verify", d + "/f.cnf"});
  EXPECT_EQ(v.exit_code, 0) << v.out << v.err;
  EXPECT_NE(v.out.find("1 NO certificates checked, 0 missing or rejected"), std::string::npos) << v.out;
  const auto g = run_gridlock(
      {"gen-instances", "-o", d + "/set", "--threshold", "0", "--lsat", "0", "--formula", d + "/f.cnf"});
  ASSERT_EQ(g.exit_code, 0) << g.out << g.err;
  const std::string manifest = test::read_file(d + "/set/manifest.json");
  EXPECT_NE(manifest.find("\"file\": \"given-f.nocert\""), std::string::npos) << manifest;
  const auto c = run_gridlock({"certify", d + "/set/given-f.grid", d + "/set/given-f.nocert"});
  EXPECT_EQ(c.exit_code, 20) << c.err;
}

}  // namespace
}  // namespace gridlock
