// The NO-certificate checker tested as a checker (docs/certificates.md):
// every certificate the solver writes for a NO is accepted; mutations that
// break one are rejected with a reason naming what failed; no certificate
// is ever accepted for an instance that has a schedule (the all-orders
// reference decides which). Seeds: GRIDLOCK_TEST_SEED replays one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "certify/certify.hpp"
#include "cnf/brute_force.hpp"
#include "cnf/generate.hpp"
#include "lattice/random_instance.hpp"
#include "reductions/compile.hpp"
#include "reductions/to_lsat.hpp"
#include "solver/continuous.hpp"
#include "solver/no_certificate.hpp"
#include "support/reference_solver.hpp"
#include "support/test_scale.hpp"
#include "support/text_lines.hpp"

namespace gridlock {
namespace {

using test::join_lines;
using test::lines_of;

RandomInstanceParams horizontal_params(uint64_t seed) {
  RandomInstanceParams p;
  p.nodes = 6 + static_cast<uint32_t>(seed % 9);
  p.ops = 3 + static_cast<uint32_t>(seed % 5);
  p.max_coupling = 1 + static_cast<uint32_t>(seed % 3);
  p.extra_edge_percent = static_cast<uint32_t>(seed % 2) * 30;
  p.horizontal_only = true;
  p.spread = static_cast<uint32_t>(seed % 3);
  return p;
}

struct Counts {
  int no = 0, yes = 0, breakers = 0, gaps = 0, mutations = 0, rejected = 0;
};

// Mutations of a gaps certificate that must fail, each with the words its reason must contain.
void check_mutations(const Instance& inst, const std::string& cert, const Instance& other, uint64_t seed, Counts& n) {
  const std::vector<std::string> ls = lines_of(cert);
  auto expect_rejected = [&](const std::string& text, const std::string& what, const std::string& words,
                             const std::string& model = "discrete") {
    ++n.mutations;
    const CertifyResult r = certify(inst, text, model);
    EXPECT_FALSE(r.proved) << "seed " << seed << ": " << what << " accepted\n" << text;
    if (!r.proved) ++n.rejected;
    EXPECT_NE(r.reason.find(words), std::string::npos) << "seed " << seed << ": " << what << ": " << r.reason;
  };
  // The empty clause dropped.
  std::vector<std::string> m = ls;
  m.pop_back();
  expect_rejected(join_lines(m), "no empty clause", "does not end with the empty clause");
  // Every lemma dropped, when propagation alone does not refute.
  m.clear();
  for (const auto& l : ls)
    if (l[0] != 'l' && l[0] != 'o') m.push_back(l);
  m.push_back("l");
  if (!certify(inst, join_lines(m), "discrete").proved && ls.size() > 5) {
    // Each single lemma dropped in turn: rejected, or still a proof (the checker
    // propagates more than the engine did); a rejection names a line.
    for (size_t i = 4; i + 1 < ls.size(); ++i) {
      std::vector<std::string> d = ls;
      d.erase(d.begin() + static_cast<long>(i));
      const CertifyResult r = certify(inst, join_lines(d), "discrete");
      if (!r.proved) {
        EXPECT_EQ(r.reason.rfind("line ", 0), 0u) << r.reason;
      }
    }
  }
  // A literal that names no coupling; a coupling before itself.
  for (size_t i = 4; i < ls.size(); ++i) {
    const size_t lt = ls[i].find('<');
    if (lt == std::string::npos) continue;
    m = ls;
    m[i].insert(lt, "_nosuch");
    expect_rejected(join_lines(m), "unknown coupling", "unknown coupling");
    break;
  }
  // An 'o' line with one edge turned round: a simple cycle becomes acyclic.
  for (size_t i = 4; i < ls.size(); ++i) {
    if (ls[i][0] != 'o') continue;
    m = ls;
    const size_t sp = m[i].find(' ', 2), start = 2, lt = m[i].find('<');
    const std::string a = m[i].substr(start, lt - start), b = m[i].substr(lt + 1, sp - lt - 1);
    if (m[i].find(' ', sp + 1) == std::string::npos) break;  // a 2-cycle stays a cycle
    std::string flipped = "o " + b;
    flipped += "<";
    flipped += a;
    flipped += m[i].substr(sp);
    m[i] = flipped;
    expect_rejected(join_lines(m), "flipped cycle edge", "contain no cycle");
    break;
  }
  // The certificate checked against another instance.
  ++n.mutations;
  const CertifyResult r = certify(other, cert, "discrete");
  EXPECT_FALSE(r.proved) << "seed " << seed << ": accepted for another instance";
  if (!r.proved) ++n.rejected;
  // Checked as the other model.
  expect_rejected(cert, "wrong model", "checked as continuous", "continuous");
}

void check_one(uint64_t seed, const Instance& other, Counts& n) {
  const Instance inst = random_instance(horizontal_params(seed), seed);
  const bool yes = test::reference_solve(inst).has_value();
  const PreparedInstance prep(inst);
  const CertifiedSolve cs = solve_discrete_certified(prep, {});
  ASSERT_EQ(cs.result.status, yes ? Verdict::Yes : Verdict::No) << "seed " << seed;
  if (yes) {
    ++n.yes;
    EXPECT_TRUE(cs.certificate.empty());
    // Forged certificates: just the empty clause, and a breaker on every coupling.
    const std::string head = "p gridlock-no-certificate 1 discrete\n" + couplings_line(inst);
    EXPECT_FALSE(certify(inst, head + "gaps\nl\n", "discrete").proved) << "seed " << seed;
    return;
  }
  ++n.no;
  ASSERT_FALSE(cs.certificate.empty()) << "seed " << seed << ": " << cs.why_none;
  const CertifyResult r = certify(inst, cs.certificate, "discrete");
  EXPECT_TRUE(r.proved) << "seed " << seed << ": " << r.reason << "\n" << cs.certificate;
  if (r.kind == "breaker") ++n.breakers;
  if (r.kind != "gaps") return;
  ++n.gaps;
  check_mutations(inst, cs.certificate, other, seed, n);
}

TEST(CertifyChecker, RandomHorizontalInstances) {
  const uint64_t base = test::base_seed(8100);
  const int count = test::scaled(600);
  const Instance other = random_instance(horizontal_params(base + 999), base + 999);
  Counts n;
  for (int i = 0; i < count; ++i) check_one(base + static_cast<uint64_t>(i), other, n);
  std::printf("certify: %d NO (%d breaker, %d gaps), %d YES; %d of %d mutations rejected\n", n.no, n.breakers, n.gaps,
              n.yes, n.rejected, n.mutations);
  EXPECT_GT(n.gaps, 20);
  EXPECT_GT(n.yes, 20);
}

TEST(CertifyChecker, ContinuousHorizontal) {
  const uint64_t base = test::base_seed(8200);
  int no = 0;
  for (int i = 0; i < test::scaled(300); ++i) {
    const uint64_t seed = base + static_cast<uint64_t>(i);
    const Instance inst = random_instance(horizontal_params(seed), seed);
    const std::string cert = continuous_no_certificate(inst);
    const bool yes = solve_continuous(inst).status == Verdict::Yes;
    EXPECT_EQ(cert.empty(), yes) << "seed " << seed;
    if (yes) continue;
    ++no;
    const CertifyResult r = certify(inst, cert, "continuous");
    EXPECT_TRUE(r.proved) << "seed " << seed << ": " << r.reason << "\n" << cert;
    EXPECT_FALSE(certify(inst, cert, "discrete").proved);
  }
  EXPECT_GT(no, 10);
}

// The certificate's header rewritten for inst: the lemmas of another
// instance presented as this one's.
std::string rehead(const Instance& inst, const std::string& cert) {
  std::vector<std::string> ls = lines_of(cert);
  std::string line = couplings_line(inst);
  line.pop_back();  // the newline: join_lines adds it back
  for (auto& l : ls)
    if (l.rfind("couplings ", 0) == 0) l = line;
  return join_lines(ls);
}

// Compiled random 3-SAT formulas (the paper's reduction): long lemma logs.
// Labels from exhaustive search on the formula; every NO certified, each
// lemma dropped in turn (counted), the mutations of check_mutations; every
// NO certificate, re-headed, is refused for every YES instance.
TEST(CertifyChecker, CompiledFormulas) {
  const uint64_t base = test::base_seed(8300);
  const int count = test::scaled(60);
  std::vector<Instance> yes;
  std::vector<std::string> certs;
  Counts n;
  int drops = 0, drops_rejected = 0, flips = 0, flips_rejected = 0;
  const Instance other = compile_formula(reduce_to_lsat(random_ksat({6, 40, 3, base + 5000})).output()).instance;
  for (int i = 0; i < count; ++i) {
    const uint64_t seed = base + static_cast<uint64_t>(i);
    const int vars = 6 + static_cast<int>(seed % 5);
    const Formula f = random_ksat({vars, vars * 5, 3, seed});
    const bool sat = exhaustive_sat(f).status == Verdict::Yes;
    Instance inst = compile_formula(reduce_to_lsat(f).output()).instance;
    const PreparedInstance prep(inst);
    const CertifiedSolve cs = solve_discrete_certified(prep, {});
    ASSERT_EQ(cs.result.status, sat ? Verdict::Yes : Verdict::No) << "seed " << seed;
    if (sat) {
      yes.push_back(std::move(inst));
      continue;
    }
    ++n.no;
    const CertifyResult r = certify(inst, cs.certificate, "discrete");
    ASSERT_TRUE(r.proved) << "seed " << seed << ": " << r.reason;
    EXPECT_EQ(r.kind, "gaps");
    certs.push_back(cs.certificate);
    check_mutations(inst, cs.certificate, other, seed, n);
    const std::vector<std::string> ls = lines_of(cs.certificate);
    const size_t step = std::max<size_t>(1, ls.size() / 12);  // about a dozen drops per certificate
    for (size_t i2 = 4; i2 + 1 < ls.size(); i2 += step) {
      std::vector<std::string> d = ls;
      d.erase(d.begin() + static_cast<long>(i2));
      const CertifyResult rd = certify(inst, join_lines(d), "discrete");
      ++drops;
      if (rd.proved) continue;
      ++drops_rejected;
      EXPECT_EQ(rd.reason.rfind("line ", 0), 0u) << rd.reason;
    }
    // The first literal of an l line turned round (a<b -> b<a), a dozen lines
    // per certificate: rejected, naming the line, or still a proof.
    for (size_t i2 = 4; i2 + 1 < ls.size(); i2 += step) {
      const size_t lt = ls[i2].find('<'), sp = ls[i2].find(' ', lt);
      if (ls[i2][0] != 'l' || lt == std::string::npos) continue;
      std::vector<std::string> d = ls;
      const std::string a = d[i2].substr(2, lt - 2),
                        b = d[i2].substr(lt + 1, sp == std::string::npos ? sp : sp - lt - 1);
      std::string flipped = "l " + b;
      flipped += "<";
      flipped += a;
      if (sp != std::string::npos) flipped += d[i2].substr(sp);
      d[i2] = flipped;
      const CertifyResult rf = certify(inst, join_lines(d), "discrete");
      ++flips;
      if (rf.proved) continue;
      ++flips_rejected;
      EXPECT_EQ(rf.reason.rfind("line ", 0), 0u) << rf.reason;
    }
  }
  int forged = 0;
  for (const Instance& y : yes)
    for (size_t ci = 0; ci < certs.size() && ci < 8; ++ci) {
      const std::string& c = certs[ci];
      ++forged;
      EXPECT_FALSE(certify(y, rehead(y, c), "discrete").proved);
    }
  std::printf(
      "compiled: %d NO certified, %zu YES; %d of %d mutations rejected; %d of %d single-lemma drops rejected; "
      "%d of %d literal flips rejected; %d forged certificates for YES instances all refused\n",
      n.no, yes.size(), n.rejected, n.mutations, drops_rejected, drops, flips_rejected, flips, forged);
  EXPECT_GT(n.no, 5);
  EXPECT_GT(yes.size(), 3u);
  EXPECT_GT(drops_rejected, 0);
  EXPECT_GT(flips_rejected, 0);
}

// The fuzz path decides with the SAT engine and, on a NO, runs the
// precedence engine for the log on the SAT engine's gap constraints
// (solve_discrete_kept). Twin: the precedence engine deciding alone builds
// its own; the two certificates must be the same text, and accepted.
TEST(CertifyChecker, SatThenLogEngineSharesTheGapConstraints) {
  const uint64_t base = test::base_seed(8400);
  const int count = test::scaled(400);
  int gaps = 0;
  for (int i = 0; i < count; ++i) {
    const uint64_t seed = base + static_cast<uint64_t>(i);
    // Half random horizontal instances, half compiled random 3-SAT of 3-6 variables.
    const Instance inst = i % 2 == 0
                              ? random_instance(horizontal_params(seed), seed)
                              : compile_formula(reduce_to_lsat(random_ksat({3 + static_cast<int>(seed % 4),
                                                                            4 + static_cast<int>(seed % 20), 3, seed}))
                                                    .output())
                                    .instance;
    const PreparedInstance prep(inst);
    SolveOptions sat, precedence;
    sat.engine = SolveOptions::Engine::Sat;
    precedence.engine = SolveOptions::Engine::Precedence;
    const CertifiedSolve by_sat = solve_discrete_certified(prep, sat);
    const CertifiedSolve alone = solve_discrete_certified(prep, precedence);
    ASSERT_EQ(by_sat.result.status, alone.result.status) << "seed " << seed;
    EXPECT_EQ(by_sat.certificate, alone.certificate) << "seed " << seed;
    if (by_sat.result.status != Verdict::No || by_sat.result.cycle_breaker != kNone) continue;
    ++gaps;
    const CertifyResult r = certify(inst, by_sat.certificate, "discrete");
    EXPECT_TRUE(r.proved) << "seed " << seed << ": " << r.reason;
  }
  std::printf("sat then log engine: %d gaps certificates of %d instances\n", gaps, count);
  EXPECT_GT(gaps, count / 20);
}

}  // namespace
}  // namespace gridlock
