// NO certificates of kind pairs (instances with vertical operations,
// docs/certificates.md): every NO the pairs engine gives on thousands of
// small seeded random instances is certified and accepted (labels from the
// all-orders reference); mutations of the certificate (a clause dropped, a
// literal turned round, a wrong reason, the proof truncated, another
// instance) are rejected, and each rejection names its line and what
// failed; YES instances get none and a forged one is refused; the real
// binary end to end. Seeds: GRIDLOCK_TEST_SEED replays one.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "certify/certify.hpp"
#include "cnf/brute_force.hpp"
#include "cnf/generate.hpp"
#include "lattice/random_instance.hpp"
#include "reductions/compile.hpp"
#include "reductions/to_lsat.hpp"
#include "solver/no_certificate.hpp"
#include "support/cli.hpp"
#include "support/general_params.hpp"
#include "support/reference_solver.hpp"
#include "support/test_scale.hpp"
#include "support/text_lines.hpp"

namespace gridlock {
namespace {

using test::join_lines;
using test::lines_of;

// Small instances with operations in all four directions (at most 6
// couplings, so that the all-orders reference labels them).
RandomInstanceParams general_params(uint64_t seed) { return test::general_params(seed, 6, 5); }

struct Counts {
  int no = 0, yes = 0, breakers = 0, pairs = 0, with_o = 0, mutations = 0, rejected = 0, drops = 0, drops_rejected = 0;
};

// The index of the first line of the kind (its first word), or 0.
size_t first_line(const std::vector<std::string>& ls, char kind) {
  for (size_t i = 4; i < ls.size(); ++i)
    if (ls[i][0] == kind && ls[i].size() > 2) return i;
  return 0;
}

// "x R1 R2 RUN": an x line without its literals.
std::string x_head(const std::string& line) {
  size_t pos = 0;
  for (int w = 0; w < 4 && pos != std::string::npos; ++w) pos = line.find(' ', pos + 1);
  return line.substr(0, pos);
}

// ls[i] with the literal at word w (counted from 0) turned round: a<b -> b<a.
std::string turned(const std::string& line, size_t w) {
  std::vector<std::string> words;
  for (size_t pos = 0; pos <= line.size();) {
    const size_t end = std::min(line.find(' ', pos), line.size());
    if (end > pos) words.push_back(line.substr(pos, end - pos));
    pos = end + 1;
  }
  if (w >= words.size()) return line;
  const size_t lt = words[w].find('<');
  if (lt == std::string::npos) return line;
  words[w] = words[w].substr(lt + 1) + "<" + words[w].substr(0, lt);
  std::string s;
  for (const auto& x : words) s += (s.empty() ? "" : " ") + x;
  return s;
}

void check_mutations(const Instance& inst, const std::string& cert, const Instance& other, uint64_t seed, Counts& n) {
  const std::vector<std::string> ls = lines_of(cert);
  auto expect_rejected = [&](const std::vector<std::string>& m, const std::string& what, const std::string& words) {
    ++n.mutations;
    const CertifyResult r = certify(inst, join_lines(m), "discrete");
    EXPECT_FALSE(r.proved) << "seed " << seed << ": " << what << " accepted\n" << join_lines(m);
    if (!r.proved) ++n.rejected;
    EXPECT_NE(r.reason.find(words), std::string::npos) << "seed " << seed << ": " << what << ": " << r.reason;
  };
  // Truncated: the empty clause dropped.
  std::vector<std::string> m(ls.begin(), ls.end() - 1);
  expect_rejected(m, "no empty clause", "does not end with the empty clause");
  // Every clause with a reason (x and o lines) dropped, one at a time:
  // rejected naming a line, or still a proof (propagation re-derives it).
  for (size_t i = 4; i + 1 < ls.size(); ++i) {
    if (ls[i][0] != 'x' && ls[i][0] != 'o') continue;
    m = ls;
    m.erase(m.begin() + static_cast<long>(i));
    const CertifyResult r = certify(inst, join_lines(m), "discrete");
    ++n.drops;
    if (r.proved) continue;
    ++n.drops_rejected;
    EXPECT_EQ(r.reason.rfind("line ", 0), 0u) << "seed " << seed << ": " << r.reason;
  }
  // A wrong reason: an x line's runner's first literal turned round (the
  // pattern it then excludes need not collide), or its regions swapped
  // for a pair of two far nodes.
  if (const size_t i = first_line(ls, 'x')) {
    m = ls;
    m[i] = turned(ls[i], 4);
    const CertifyResult r = certify(inst, join_lines(m), "discrete");
    ++n.mutations;
    if (!r.proved) {
      ++n.rejected;
      EXPECT_EQ(r.reason.rfind("line ", 0), 0u) << r.reason;
    }
    // Its literals dropped: the claim "the runner always collides" (the
    // engine frees every literal it can, so this pattern set does not).
    if (ls[i].find('<') != std::string::npos) {
      m = ls;
      m[i] = x_head(ls[i]);
      expect_rejected(m, "x line without literals", "line " + std::to_string(i + 1) + ": the step of ");
    }
    m = ls;
    m[i] = "x " + std::to_string(inst.cells()[0].x) + "," + std::to_string(inst.cells()[0].y) + " +nosuch" +
           ls[i].substr(ls[i].find(' ', ls[i].find(' ', 2) + 1));
    expect_rejected(m, "unknown region", "line " + std::to_string(i + 1) + ": unknown operation 'nosuch'");
  }
  // Cycle lines (the engine's lazy cycle clauses; rare on small
  // instances): a literal of the certificate and its reverse is a 2-cycle
  // and keeps the proof; the literal alone is no cycle.
  if (const size_t i = first_line(ls, 'x'); i != 0 && ls[i].find('<') != std::string::npos) {
    const size_t lt = ls[i].find('<'), start = ls[i].rfind(' ', lt) + 1, end = ls[i].find(' ', lt);
    const std::string a = ls[i].substr(start, lt - start), b = ls[i].substr(lt + 1, end - lt - 1);
    m = ls;
    m.insert(m.end() - 1, "o " + a + "<" + b + " " + b + "<" + a);
    const CertifyResult r = certify(inst, join_lines(m), "discrete");
    EXPECT_TRUE(r.proved) << "seed " << seed << ": a 2-cycle refused: " << r.reason;
    m = ls;
    m.insert(m.end() - 1, "o " + a + "<" + b);
    expect_rejected(m, "o line without a cycle",
                    "line " + std::to_string(m.size() - 1) + ": the literals of this o line contain no cycle");
  }
  // A lemma turned round (changed order): rejected as not implied, or still a proof.
  for (size_t i = 4; i + 1 < ls.size(); ++i) {
    if (ls[i][0] != 'l' || ls[i].size() < 3) continue;
    m = ls;
    m[i] = turned(ls[i], 1);
    const CertifyResult r = certify(inst, join_lines(m), "discrete");
    ++n.mutations;
    if (!r.proved) {
      ++n.rejected;
      EXPECT_NE(r.reason.find("not implied"), std::string::npos) << r.reason;
    }
    break;
  }
  ++n.mutations;
  if (!certify(other, cert, "discrete").proved) ++n.rejected;
  else ADD_FAILURE() << "seed " << seed << ": accepted for another instance";
}

void check_one(uint64_t seed, const Instance& other, Counts& n) {
  const Instance inst = random_instance(general_params(seed), seed);
  if (inst.horizontal_only() || inst.couplings().size() > 7) return;
  const bool yes = test::reference_solve(inst).has_value();
  const PreparedInstance prep(inst);
  const CertifiedSolve cs = solve_discrete_certified(prep, {});
  ASSERT_EQ(cs.result.status, yes ? Verdict::Yes : Verdict::No) << "seed " << seed;
  if (yes) {
    ++n.yes;
    EXPECT_TRUE(cs.certificate.empty());
    const std::string forged = "p gridlock-no-certificate 1 discrete\n" + couplings_line(inst) + "pairs\nl\n";
    EXPECT_FALSE(certify(inst, forged, "discrete").proved) << "seed " << seed;
    return;
  }
  ++n.no;
  ASSERT_FALSE(cs.certificate.empty()) << "seed " << seed << ": " << cs.why_none;
  const CertifyResult r = certify(inst, cs.certificate, "discrete");
  EXPECT_TRUE(r.proved) << "seed " << seed << ": " << r.reason << "\n" << cs.certificate;
  if (r.kind == "breaker") ++n.breakers;
  if (r.kind != "pairs") return;
  ++n.pairs;
  n.with_o += cs.certificate.find("\no ") != std::string::npos;
  check_mutations(inst, cs.certificate, other, seed, n);
}

TEST(CertifyPairs, RandomGeneralInstances) {
  const uint64_t base = test::base_seed(8400);
  const int count = test::scaled(6000);
  const Instance other = random_instance(general_params(base + 99999), base + 99999);
  Counts n;
  for (int i = 0; i < count; ++i) check_one(base + static_cast<uint64_t>(i), other, n);
  std::printf(
      "certify pairs: %d NO (%d breaker, %d pairs, %d with o lines), %d YES; %d of %d mutations rejected; %d of %d "
      "clause drops rejected\n",
      n.no, n.breakers, n.pairs, n.with_o, n.yes, n.rejected, n.mutations, n.drops_rejected, n.drops);
  EXPECT_GT(n.pairs, count / 6);  // about 1/5 of the instances (1 291 of 6 000 at scale 1)
  EXPECT_GT(n.yes, count / 6);
  EXPECT_GT(n.drops_rejected, 0);
}

// Random 3-SAT formulas through the continuous reduction, decided in
// discrete time: an instance with vertical operations (the separation
// gadget) that is NO iff the formula is unsatisfiable (labels by
// exhaustive search). Every NO certified with kind pairs and accepted.
TEST(CertifyPairs, CompiledContinuousReductionInDiscreteTime) {
  const uint64_t base = test::base_seed(8500);
  int no = 0;
  const int formulas = test::scaled(40);
  for (int i = 0; i < formulas; ++i) {
    const uint64_t seed = base + static_cast<uint64_t>(i);
    const int vars = 5 + static_cast<int>(seed % 4);
    const Formula f = random_ksat({vars, vars * 5, 3, seed});
    const bool sat = exhaustive_sat(f).status == Verdict::Yes;
    const Instance inst = compile_formula(reduce_to_lsat(f).output(), Mutation::None, TimeModel::Continuous).instance;
    ASSERT_FALSE(inst.horizontal_only());
    const PreparedInstance prep(inst);
    const CertifiedSolve cs = solve_discrete_certified(prep, {});
    ASSERT_EQ(cs.result.status, sat ? Verdict::Yes : Verdict::No) << "seed " << seed;
    if (sat) continue;
    ++no;
    const CertifyResult r = certify(inst, cs.certificate, "discrete");
    EXPECT_TRUE(r.proved) << "seed " << seed << ": " << r.reason;
    EXPECT_EQ(r.kind, "pairs") << "seed " << seed;
  }
  std::printf("compiled (continuous reduction, discrete time): %d NO certified\n", no);
  EXPECT_GE(no, formulas / 8);  // 14 of 40 at scale 1
}

// The real binary: a random tree instance with vertical operations (NO,
// decided by the pairs engine) certified and checked; a broken copy refused
// with FILE:LINE and the reason.
TEST(CertifyPairs, CommandLineEndToEnd) {
  using test::run_gridlock;
  const std::string d = test::temp_dir();
  const std::string grid = d + "/tree.grid", cert = d + "/tree.nocert", bad = d + "/bad.nocert";
  ASSERT_EQ(run_gridlock({"random", "--family", "tree", "--couplings", "20", "--seed", "1", "-o", grid}).exit_code, 0);
  const auto s = run_gridlock({"solve", grid, "--certificate", cert});
  ASSERT_EQ(s.exit_code, 20) << s.out << s.err;
  const std::string text = test::read_file(cert);
  ASSERT_NE(text.find("\npairs\n"), std::string::npos) << text;
  const auto c = run_gridlock({"certify", grid, cert});
  EXPECT_EQ(c.exit_code, 20) << c.out << c.err;
  EXPECT_NE(c.out.find("s NO"), std::string::npos);
  EXPECT_NE(c.out.find("c certificate checked"), std::string::npos);
  // The first x line's clause turned into "the runner always collides".
  std::vector<std::string> ls = lines_of(text);
  const size_t i = first_line(ls, 'x');
  ASSERT_NE(i, 0u);
  ls[i] = x_head(ls[i]);
  test::write_file(bad, join_lines(ls));
  const auto b = run_gridlock({"certify", grid, bad});
  EXPECT_EQ(b.exit_code, 1) << b.out << b.err;
  EXPECT_NE(b.err.find("bad.nocert:" + std::to_string(i + 1) + ": certificate rejected: the step of "),
            std::string::npos)
      << b.err;
  // Truncated: the empty clause gone.
  ls = lines_of(text);
  ls.pop_back();
  test::write_file(bad, join_lines(ls));
  const auto t = run_gridlock({"certify", grid, bad});
  EXPECT_EQ(t.exit_code, 1);
  EXPECT_NE(t.err.find("does not end with the empty clause"), std::string::npos) << t.err;
}

}  // namespace
}  // namespace gridlock
