// The .grid reader and writer: round trips, and one test per class of bad
// input with the exact message (docs/grid-format.md lists them all).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "lattice/grid_format.hpp"
#include "lattice/random_instance.hpp"
#include "lattice/schedule.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

std::string error_of(const std::string& text) {
  Instance inst;
  std::istringstream in(text);
  auto err = read_instance(in, "bad.grid", inst);
  return err ? err->str() : "no error";
}

std::string written(const Instance& inst) {
  std::ostringstream out;
  write_instance(out, inst);
  return out.str();
}

const std::string kHead = "p grid 3 2 1 0\nn 0 0\nn 1 0\nn 2 0\ne 0 0 1 0\ne 1 0 2 0\n";

TEST(GridFormat, RoundTripRandomInstances) {
  const int cases = test::scaled(500);
  for (int i = 0; i < cases; ++i) {
    RandomInstanceParams p;
    p.nodes = 1 + static_cast<uint32_t>(i % 30);
    p.ops = static_cast<uint32_t>(i % 7);
    p.max_coupling = 1 + static_cast<uint32_t>(i % 3);
    p.extra_edge_percent = i % 2 ? 30 : 0;
    Instance inst = random_instance(p, static_cast<uint64_t>(i));
    std::string once = written(inst);
    Instance back;
    std::istringstream in(once);
    auto err = read_instance(in, "round.grid", back);
    ASSERT_FALSE(err) << err->str() << "\n" << once;
    EXPECT_EQ(written(back), once) << "seed " << i;
    EXPECT_EQ(back.num_nodes(), inst.num_nodes());
    EXPECT_EQ(back.couplings().size(), inst.couplings().size());
  }
}

TEST(GridFormat, AcceptsCommentsBlankLinesCrLfAndImplicitCouplings) {
  Instance inst;
  std::istringstream in(
      "c hello\r\n\r\n# also a comment\np grid 2 1 1 0\nn 0 0\n  n 1 0\ne 0 0 1 0\t\n"
      "c mid\no a expand 0 0 +x\na 1 0\n");
  auto err = read_instance(in, "ok.grid", inst);
  ASSERT_FALSE(err) << err->str();
  ASSERT_EQ(inst.couplings().size(), 1u);
  EXPECT_EQ(inst.couplings()[0].name, "a");
  EXPECT_EQ(inst.node_label(inst.anchor()), "(1,0)");
}

struct BadCase {
  const char* what;
  std::string text;
  std::string message;
};

TEST(GridFormat, RejectsEachBadInputClassWithItsMessage) {
  const std::vector<BadCase> cases = {
      {"two nodes in one cell", "p grid 2 0 0 0\nn 0 0\nn 0 0\n", "bad.grid:3: two nodes in cell (0,0)"},
      {"edge between non-adjacent cells", "p grid 2 1 0 0\nn 0 0\nn 2 0\ne 0 0 2 0\n",
       "bad.grid:4: edge between non-adjacent cells (0,0) and (2,0)"},
      {"edge to a missing node", "p grid 1 1 0 0\nn 0 0\ne 0 0 1 0\n", "bad.grid:3: edge end (1,0) holds no node"},
      {"edge given twice", "p grid 2 2 0 0\nn 0 0\nn 1 0\ne 0 0 1 0\ne 1 0 0 0\n",
       "bad.grid:5: edge between (1,0) and (0,0) given twice"},
      {"operation on a missing node", kHead + "o a expand 5 5 +x\n",
       "bad.grid:7: operation 'a' on cell (5,5), which holds no node"},
      {"expansion on a non-edge", "p grid 2 1 1 0\nn 0 0\nn 0 1\ne 0 0 0 1\no a expand 0 0 +x\n",
       "bad.grid:5: expand 'a' needs an edge from (0,0) to (1,0), and there is none"},
      {"contraction on a non-edge", "p grid 2 1 1 0\nn 0 0\nn 0 1\ne 0 0 0 1\no a contract 0 0 -y\n",
       "bad.grid:5: contract 'a' needs an edge from (0,0) to (0,-1), and there is none"},
      {"growth into a joined neighbour", kHead + "o g grow 0 0 +x\n",
       "bad.grid:7: growth 'g' into (1,0), which holds a node joined to (0,0) by an edge (use expand)"},
      {"bad direction", kHead + "o a expand 0 0 up\n", "bad.grid:7: bad direction 'up' (one of +x, -x, +y, -y)"},
      {"direction without sign", kHead + "o a expand 0 0 x\n", "bad.grid:7: bad direction 'x' (one of +x, -x, +y, -y)"},
      {"direction y without sign", kHead + "o a grow 0 0 y\n", "bad.grid:7: bad direction 'y' (one of +x, -x, +y, -y)"},
      {"bad kind", kHead + "o a push 0 0 +x\n", "bad.grid:7: unknown operation kind 'push' (expand, grow or contract)"},
      {"node in two operations",
       "p grid 3 2 2 0\nn 0 0\nn 1 0\nn 2 0\ne 0 0 1 0\ne 1 0 2 0\no a expand 0 0 +x\n"
       "o b expand 1 0 +x\n",
       "bad.grid:8: node (1,0) already takes part in operation 'a'"},
      {"operation defined twice",
       "p grid 3 2 2 0\nn 0 0\nn 1 0\nn 2 0\ne 0 0 1 0\ne 1 0 2 0\no a grow 0 0 -x\n"
       "o a grow 2 0 +x\n",
       "bad.grid:8: operation 'a' defined twice"},
      {"unknown name in a coupling",
       "p grid 3 2 1 1\nn 0 0\nn 1 0\nn 2 0\ne 0 0 1 0\ne 1 0 2 0\no a expand 0 0 +x\n"
       "q Q a zz\n",
       "bad.grid:8: unknown operation 'zz' in coupling 'Q'"},
      {"operation in two couplings",
       "p grid 3 2 1 2\nn 0 0\nn 1 0\nn 2 0\ne 0 0 1 0\ne 1 0 2 0\no a expand 0 0 +x\n"
       "q Q a\nq R a\n",
       "bad.grid:9: operation 'a' is already in coupling 'Q'"},
      {"singleton name taken",
       "p grid 3 2 2 1\nn 0 0\nn 1 0\nn 2 0\ne 0 0 1 0\ne 1 0 2 0\no a expand 0 0 +x\n"
       "o b grow 2 0 +x\nq b a\n",
       "bad.grid:9: operation 'b' is in no coupling, and its singleton coupling's name is taken"},
      {"disconnected shape", "p grid 3 1 0 0\nn 0 0\nn 1 0\nn 5 5\ne 0 0 1 0\n",
       "bad.grid:4: the shape is not connected: node (5,5) cannot be reached from node (0,0)"},
      {"coordinate out of range", "p grid 1 0 0 0\nn 0 1000000001\n",
       "bad.grid:2: coordinate out of range: '1000000001' (allowed -1000000000 to 1000000000)"},
      {"number overflowing 64 bits", "p grid 1 0 0 0\nn 0 99999999999999999999999\n",
       "bad.grid:2: coordinate out of range: '99999999999999999999999' (allowed -1000000000 to 1000000000)"},
      {"count out of range", "p grid 999999999999 0 0 0\n",
       "bad.grid:1: count out of range: '999999999999' (allowed 0 to 67108864)"},
      {"not an integer", "p grid 1 0 0 0\nn 0 x1\n", "bad.grid:2: expected an integer coordinate, got 'x1'"},
      {"missing header", "n 0 0\n",
       "bad.grid:1: missing header 'p grid NODES EDGES OPS COUPLINGS' before the first n line"},
      {"empty input", "", "bad.grid:1: empty input: no 'p grid' header"},
      {"truncated input", "p grid 3 2 0 0\nn 0 0\nn 1 0\n",
       "bad.grid:3: unexpected end of input: the header promises 3 nodes, the file gives 2 (truncated?)"},
      {"more than the header", "p grid 1 0 0 0\nn 0 0\nn 1 0\n", "bad.grid:3: more nodes than the header's 1"},
      {"binary input", std::string("p grid 1 0 0 0\nn 0 \0 0\n", 22),
       "bad.grid:2: binary input: byte 0x00 at column 5"},
      {"binary high byte", "p grid 1 0 0 0\nn 0 \xff\n",
       "bad.grid:2: binary input: byte 0xff at column 5 (UTF-8 is read in comments only)"},
      {"byte-order mark", "\xef\xbb\xbfp grid 1 0 0 0\nn 0 0\n",
       "bad.grid:1: binary input: byte 0xef at column 1 (a UTF-8 byte-order mark: save the file without one)"},
      {"wrong field count", "p grid 1 0 0 0\nn 0 0 0\n", "bad.grid:2: expected 'n X Y', got 3 fields"},
      {"unknown line type", "p grid 1 0 0 0\nz 0 0\n", "bad.grid:2: unknown line type 'z'"},
      {"second header", "p grid 1 0 0 0\np grid 1 0 0 0\n", "bad.grid:2: second header line"},
      {"bad name", kHead + "o -a expand 0 0 +x\n", "bad.grid:7: bad operation name '-a'"},
      {"anchor on no node", "p grid 1 0 0 0\nn 0 0\na 3 3\n", "bad.grid:3: anchor (3,3) holds no node"},
      {"no nodes", "p grid 0 0 0 0\n", "bad.grid:1: the shape has no nodes"},
  };
  for (const auto& c : cases) EXPECT_EQ(error_of(c.text), c.message) << c.what;
}

// The reader's line rules one by one (header line, item lines, the counts
// against the header at each item and at the end), each with its line number.
TEST(GridFormat, LineRulesNameTheLineThatBreaksThem) {
  const std::string two = "p grid 2 1 0 0\nn 0 0\nn 1 0\ne 0 0 1 0\n";
  const std::vector<BadCase> cases = {
      {"header not 'p grid'", "p cnf 1 0 0 0\n", "bad.grid:1: header must start 'p grid', got 'p cnf'"},
      {"header field count", "c note\np grid 1 0 0\n",
       "bad.grid:2: expected 'p grid NODES EDGES OPS COUPLINGS', got 4 fields"},
      {"line type of two letters", "p grid 1 0 0 0\nnn 0 0\n", "bad.grid:2: unknown line type 'nn'"},
      {"more edges than the header", "p grid 2 0 0 0\nn 0 0\nn 1 0\ne 0 0 1 0\n",
       "bad.grid:4: more edges than the header's 0"},
      {"more operations than the header", two + "o a expand 0 0 +x\n",
       "bad.grid:5: more operations than the header's 0"},
      {"more couplings than the header", "p grid 2 1 1 0\nn 0 0\nn 1 0\ne 0 0 1 0\no a expand 0 0 +x\nq Q a\n",
       "bad.grid:6: more couplings than the header's 0"},
      {"coupling without operations", "p grid 2 1 1 1\nn 0 0\nn 1 0\ne 0 0 1 0\no a expand 0 0 +x\nq Q\n",
       "bad.grid:6: expected 'q NAME OP...' with at least one operation"},
      {"second anchor", "p grid 2 1 0 0\nn 0 0\nn 1 0\ne 0 0 1 0\na 0 0\n\na 1 0\n",
       "bad.grid:7: second anchor line (the first is line 5)"},
      {"operation field count", two + "o a expand 0 0\n",
       "bad.grid:5: expected 'o NAME expand|grow|contract X Y DIR', got 4 fields"},
      {"truncated couplings", "p grid 2 1 1 1\nn 0 0\nn 1 0\ne 0 0 1 0\no a expand 0 0 +x\n",
       "bad.grid:5: unexpected end of input: the header promises 1 couplings, the file gives 0 (truncated?)"},
  };
  for (const auto& c : cases) EXPECT_EQ(error_of(c.text), c.message) << c.what;
}

TEST(GridFormat, OverlongLineIsReportedNotCrashed) {
  std::string text = "p grid 1 0 0 0\nc " + std::string(2 << 20, 'x') + "\n";
  EXPECT_EQ(error_of(text), "bad.grid:2: line longer than 1048576 bytes");
}

// A coupling of 10^5 operations is a q line longer than 1 MiB; what
// write_instance writes must read back (the bound grows with the header's
// operations), while a runaway line is still refused.
TEST(GridFormat, OneCouplingLongerThanAMebibyteReadsBack) {
  // A row of 34 000 nodes, the edges (2i, 2i+1) expanding, all in one
  // coupling; names of 64 bytes make the q line 1.1 MB.
  const int n = 17000;
  auto name = [](int i) {
    std::string s = std::to_string(i);
    return std::string(64 - s.size(), 'o') + s;
  };
  std::ostringstream text;
  text << "p grid " << 2 * n << ' ' << 2 * n - 1 << ' ' << n << " 1\n";
  for (int i = 0; i < 2 * n; ++i) text << "n " << i << " 0\n";
  for (int i = 0; i + 1 < 2 * n; ++i) text << "e " << i << " 0 " << i + 1 << " 0\n";
  for (int i = 0; i < n; ++i) text << "o " << name(i) << " expand " << 2 * i << " 0 +x\n";
  text << "q Q";
  for (int i = 0; i < n; ++i) text << ' ' << name(i);
  text << '\n';
  Instance inst;
  std::istringstream first(text.str());
  auto first_err = read_instance(first, "long.grid", inst);
  ASSERT_FALSE(first_err) << first_err->str();
  ASSERT_EQ(inst.couplings().size(), 1u);
  const std::string once = written(inst);
  const size_t q = once.find("\nq ");
  ASSERT_NE(q, std::string::npos);
  ASSERT_GT(once.find('\n', q + 1) - q, size_t{1} << 20) << "the q line must be longer than 1 MiB";
  Instance back;
  std::istringstream in(once);
  auto err = read_instance(in, "long.grid", back);
  ASSERT_FALSE(err) << err->str();
  EXPECT_EQ(back.couplings()[0].ops.size(), inst.couplings()[0].ops.size());
  EXPECT_EQ(written(back), once);
  // The bound is 1 MiB plus 65 bytes per declared operation.
  EXPECT_EQ(error_of("p grid 1 0 2 0\nc " + std::string((1 << 20) + 200, 'x') + "\n"),
            "bad.grid:2: line longer than 1048706 bytes");
}

TEST(GridFormat, MissingFileIsADiagnostic) {
  Instance inst;
  auto err = read_instance_file("/nonexistent/x.grid", inst);
  ASSERT_TRUE(err);
  EXPECT_EQ(err->str(), "/nonexistent/x.grid: cannot open file");
}

// docs/model.md worked case 4, its operations named c and g (valid names
// that are also the comment and status words of schedule files).
Instance case4_named(const std::string& first, const std::string& second) {
  const std::string text =
      "p grid 6 5 2 0\nn 0 0\nn 1 0\nn 2 0\nn 0 1\nn 1 1\nn 2 1\ne 0 0 1 0\ne 0 0 0 1\n"
      "e 0 1 1 1\ne 1 1 2 1\ne 2 1 2 0\no " +
      first + " contract 0 0 +x\no " + second + " grow 2 0 -x\n";
  Instance inst;
  std::istringstream in(text);
  EXPECT_FALSE(read_instance(in, "case4.grid", inst));
  return inst;
}

std::string schedule_file(const std::string& text) {
  std::string path = ::testing::TempDir() + "/gridlock_schedule_" +
                     ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".txt";
  std::ofstream(path) << text;
  return path;
}

std::string names_in(const Instance& inst, const std::vector<CouplingId>& order) {
  std::string s;
  for (CouplingId q : order) s += (s.empty() ? "" : " ") + inst.couplings()[q].name;
  return s;
}

TEST(ScheduleFiles, CouplingsNamedCAndSAreDataNotCommentsInOrders) {
  const Instance inst = case4_named("c", "s");
  std::vector<CouplingId> order;
  auto err = read_order_file(inst, schedule_file("c a comment about the order\nc s\n"), order);
  ASSERT_FALSE(err) << err->str();
  EXPECT_EQ(names_in(inst, order), "c s");
  err = read_order_file(inst, schedule_file("s YES\nv s c\n"), order);  // solve's own output
  ASSERT_FALSE(err) << err->str();
  EXPECT_EQ(names_in(inst, order), "s c");
  err = read_order_file(inst, schedule_file("s\nc\n"), order);  // one name per line
  ASSERT_FALSE(err) << err->str();
  EXPECT_EQ(names_in(inst, order), "s c");
}

// With a coupling named v, a plain line "v c" is the order v, c (the
// instance's names win), while solve's "v v c" still reads as v, c.
TEST(ScheduleFiles, CouplingNamedVKeepsItsPlaceInPlainOrders) {
  const Instance inst = case4_named("v", "c");
  std::vector<CouplingId> order;
  for (const auto& [text, want] : std::vector<std::pair<std::string, std::string>>{{"v c\n", "v c"},
                                                                                   {"c v\n", "c v"},
                                                                                   {"c a comment\nv c\n", "v c"},
                                                                                   {"s YES\nv v c\n", "v c"},
                                                                                   {"v c v\n", "c v"},
                                                                                   {"v v\nv c\n", "v c"},
                                                                                   {"v\nc\n", "v c"}}) {
    auto err = read_order_file(inst, schedule_file(text), order);
    ASSERT_FALSE(err) << text << ": " << err->str();
    EXPECT_EQ(names_in(inst, order), want) << text;
  }
  auto err = read_order_file(inst, schedule_file("v c\nv\n"), order);
  ASSERT_TRUE(err);
  EXPECT_NE(err->str().find("leaves out coupling 'v'"), std::string::npos) << err->str();
}

TEST(ScheduleFiles, CouplingNamedCGetsItsTimeInTimesFiles) {
  const Instance inst = case4_named("c", "g");
  Schedule s;
  auto err = read_times_file(inst, schedule_file("c start times\nc 0\ng 1/2\n"), s);
  ASSERT_FALSE(err) << err->str();
  EXPECT_EQ(s.start[inst.find_coupling("c")], Rational(0));
  EXPECT_EQ(s.start[inst.find_coupling("g")], Rational(1, 2));
  // Without a coupling named c, "c 0" stays a comment.
  const Instance other = case4_named("a", "g");
  err = read_times_file(other, schedule_file("c 0\na 0\ng 0\n"), s);
  EXPECT_FALSE(err);
  err = read_times_file(other, schedule_file("c 0\ng 0\n"), s);
  ASSERT_TRUE(err);
  EXPECT_NE(err->str().find("no start time for coupling 'a'"), std::string::npos) << err->str();
  EXPECT_EQ(err->str().find("other 'c' lines are comments"), std::string::npos) << err->str();
  // "c 0.5" is no entry (0.5 is not a time), so it is a comment: the
  // error for the missing time says how c's entry reads.
  err = read_times_file(inst, schedule_file("c 0.5\ng 0\n"), s);
  ASSERT_TRUE(err);
  EXPECT_NE(err->str().find("no start time for coupling 'c' (a line 'c TIME' is its entry only with TIME an integer"),
            std::string::npos)
      << err->str();
}

}  // namespace
}  // namespace gridlock
