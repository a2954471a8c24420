// Continuous NO certificates of kind bounds (instances with vertical
// operations, docs/certificates.md "Kind bounds"): every NO the learning
// engine writes a proof for, on seeded random instances and compiled
// formulas, is accepted by the checker (labels also from the quantified Z3
// twin on the small ones); mutations of a certificate (a reason changed, a
// clause or selector dropped, a bound moved, the proof cut, another
// instance) are rejected, each naming what failed; YES instances get none
// and a forged one is refused. The checker's two parts have naive twins:
// the offsets check against the solver's own free_offsets and its exact
// per-offset test, the RUP check against propagation by repeated scans.
// Seeds: GRIDLOCK_TEST_SEED replays one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "certify/certify.hpp"
#include "certify/internal/clause_proof.hpp"
#include "certify/internal/offsets.hpp"
#include "cnf/brute_force.hpp"
#include "cnf/generate.hpp"
#include "lattice/random_instance.hpp"
#include "reductions/compile.hpp"
#include "reductions/to_lsat.hpp"
#include "solver/continuous.hpp"
#include "solver/internal/continuous_pairs.hpp"
#include "solver/internal/continuous_sat.hpp"
#include "solver/no_certificate.hpp"
#include "support/cli.hpp"
#include "support/general_params.hpp"
#include "support/reference_continuous.hpp"
#include "support/test_scale.hpp"
#include "support/text_lines.hpp"

namespace gridlock {
namespace {

using test::join_lines;
using test::lines_of;

RandomInstanceParams general_params(uint64_t seed) { return test::general_params(seed, 7, 6); }

struct Counts {
  int rich = 0;  // certificates with event or theory lines (not a lone pair that always collides)
  int no = 0, certified = 0, uncertified = 0, yes = 0, twin = 0, mutations = 0, rejected = 0, drops = 0,
      drops_rejected = 0, faces = 0, face_lines = 0, other_no = 0;
};

// The words of a line.
std::vector<std::string> words_of(const std::string& line) {
  std::vector<std::string> w;
  for (size_t pos = 0; pos <= line.size();) {
    const size_t end = std::min(line.find(' ', pos), line.size());
    if (end > pos) w.push_back(line.substr(pos, end - pos));
    pos = end + 1;
  }
  return w;
}

std::string line_of(const std::vector<std::string>& w) {
  std::string s;
  for (const auto& x : w) s += (s.empty() ? "" : " ") + x;
  return s;
}

// The index of the first line starting with "kind " that has at least
// `words` words, or 0.
size_t first_line(const std::vector<std::string>& ls, const std::string& kind, size_t words = 0) {
  for (size_t i = 4; i < ls.size(); ++i)
    if (ls[i].rfind(kind + " ", 0) == 0 && words_of(ls[i]).size() >= words) return i;
  return 0;
}

class Mutator {
 public:
  Mutator(const Instance& inst, const std::string& cert, uint64_t seed, Counts& n)
      : inst_(inst), ls_(lines_of(cert)), seed_(seed), n_(n) {}

  // m must be rejected, with `words` in the reason.
  void rejected(const std::vector<std::string>& m, const std::string& what, const std::string& words) {
    ++n_.mutations;
    const CertifyResult r = certify(inst_, join_lines(m), "continuous");
    EXPECT_FALSE(r.proved) << "seed " << seed_ << ": " << what << " accepted\n" << join_lines(m);
    if (!r.proved) ++n_.rejected;
    EXPECT_NE(r.reason.find(words), std::string::npos) << "seed " << seed_ << ": " << what << ": " << r.reason;
  }

  // m may still be a proof (the change was redundant); if rejected, the
  // reason names a line.
  void rejected_or_redundant(const std::vector<std::string>& m, const std::string& what) {
    ++n_.drops;
    const CertifyResult r = certify(inst_, join_lines(m), "continuous");
    if (r.proved) return;
    ++n_.drops_rejected;
    EXPECT_EQ(r.reason.rfind("line ", 0), 0u) << "seed " << seed_ << ": " << what << ": " << r.reason;
  }

  void run(const Instance& other) {
    std::vector<std::string> m(ls_.begin(), ls_.end() - 1);
    rejected(m, "no empty clause", "does not end with the empty clause");
    drops();
    event_line();
    interval_line();
    forms_line();
    theory_line();
    face_line();
    // Another instance: refused, unless it is NO for the same reasons (the
    // checker derives everything from the instance it is given).
    ++n_.mutations;
    if (!certify(other, join_lines(ls_), "continuous").proved) ++n_.rejected;
    else if (solve_continuous(other, SolveOptions{}).status == Verdict::No) ++n_.rejected, ++n_.other_no;
    else ADD_FAILURE() << "seed " << seed_ << ": accepted for another instance, which is not NO";
    EXPECT_FALSE(certify(inst_, join_lines(ls_), "discrete").proved);
  }

 private:
  // Every clause with a reason dropped, one at a time (at most 40).
  void drops() {
    int done = 0;
    for (size_t i = 4; i + 1 < ls_.size() && done < 40; ++i) {
      const char k = ls_[i][0];
      if (k != 'i' && k != 'e' && k != 'f' && k != 't' && k != 'w') continue;
      std::vector<std::string> m = ls_;
      m.erase(m.begin() + static_cast<long>(i));
      rejected_or_redundant(m, "line dropped");
      ++done;
    }
  }

  // An event clause without its last literal: the pattern it then claims
  // need not collide (or the clause is now stronger than the proof needs).
  void event_line() {
    const size_t i = first_line(ls_, "e", 6);
    if (i == 0) return;
    std::vector<std::string> w = words_of(ls_[i]);
    std::vector<std::string> m = ls_;
    w.pop_back();
    m[i] = line_of(w);
    rejected_or_redundant(m, "event literal dropped");
    // Its instant moved before every start: nothing moves then.
    w = words_of(ls_[i]);
    if (w[3] != "-") {
      w[3] = "-";
      m = ls_;
      m[i] = line_of(w);
      rejected_or_redundant(m, "event before every start");
    }
  }

  // An interval clause of several selectors without one of them: offsets in
  // that interval are free, so the pair does not always collide outside.
  void interval_line() {
    const size_t i = first_line(ls_, "i", 7);
    if (i == 0) return;
    std::vector<std::string> w = words_of(ls_[i]);
    w.pop_back();
    std::vector<std::string> m = ls_;
    m[i] = line_of(w);
    rejected(m, "selector dropped", "line " + std::to_string(i + 1) + ": the pair does not always collide outside");
  }

  // A forms clause without one of its guards (still valid if that form
  // can never be <= 0: the solver keeps every form that moves), and with a
  // guard of another pair.
  void forms_line() {
    const size_t i = first_line(ls_, "f", 5);
    if (i == 0) return;
    std::vector<std::string> w = words_of(ls_[i]);
    const std::string last = w.back();
    w.pop_back();
    std::vector<std::string> m = ls_;
    m[i] = line_of(w);
    rejected_or_redundant(m, "guard dropped");
    for (size_t j = i + 1; j + 1 < ls_.size(); ++j) {
      if (ls_[j].rfind("f ", 0) != 0 || words_of(ls_[j])[1] == words_of(ls_[i])[1]) continue;
      m = ls_;
      m[i] = line_of(w) + " " + words_of(ls_[j]).back();
      rejected(m, "guard of another pair", "line " + std::to_string(i + 1) + ": literal ");
      break;
    }
  }

  // A face clause: a cell of its walk dropped (no longer a closed walk of
  // edges), its last literal dropped (the coupling it placed before, with
  // or after Q is then free), its literals' signs flipped, its coupling
  // replaced by one of no face (no literal bounds it).
  void face_line() {
    size_t i = 4;  // the first face clause with literals
    while (i < ls_.size() && (ls_[i].rfind("w ", 0) != 0 || words_of(ls_[i]).back().find(',') != std::string::npos))
      ++i;
    if (i == ls_.size()) return;
    ++n_.faces;
    const std::vector<std::string> orig = words_of(ls_[i]);
    const std::string at = "line " + std::to_string(i + 1) + ": ";
    std::vector<std::string> w = orig, m = ls_;
    w.erase(w.begin() + 3);
    m[i] = line_of(w);
    rejected(m, "walk cell dropped", at);
    w = orig, m = ls_;
    w.pop_back();
    m[i] = line_of(w);
    rejected(m, "face literal dropped", at + "coupling ");
    w = orig, m = ls_;
    size_t first = 2;
    while (first < w.size() && w[first].find(',') != std::string::npos) ++first;
    for (size_t j = first; j < w.size(); ++j) w[j] = w[j][0] == '-' ? w[j].substr(1) : "-" + w[j];
    m[i] = line_of(w);
    rejected_or_redundant(m, "face literals flipped");
    const FaceNets faces = FaceNets::build(inst_);
    for (CouplingId q = 0; q < inst_.couplings().size(); ++q) {
      if (faces.coupling_breaks_cycle[q]) continue;
      w = orig, m = ls_;
      w[1] = inst_.couplings()[q].name;
      m[i] = line_of(w);
      rejected(m, "face of another coupling", at + "literal bound ");
      break;
    }
  }

  // A theory lemma with one literal fewer (the others alone are consistent,
  // as a lemma from a negative cycle uses each edge), and a bound moved far.
  void theory_line() {
    const size_t i = first_line(ls_, "t", 3);
    if (i == 0) return;
    std::vector<std::string> w = words_of(ls_[i]);
    w.pop_back();
    std::vector<std::string> m = ls_;
    m[i] = line_of(w);
    rejected_or_redundant(m, "theory literal dropped");
    // Its first two literals swapped: no longer a cycle in order.
    if (const size_t j = first_line(ls_, "t", 4); j != 0) {
      w = words_of(ls_[j]);
      std::swap(w[1], w[2]);
      m = ls_;
      m[j] = line_of(w);
      rejected(m, "theory literals swapped", "line " + std::to_string(j + 1) + ": the negated bounds are no cycle");
    }
    const size_t a = first_line(ls_, "a", 6);
    if (a == 0) return;
    w = words_of(ls_[a]);
    w[5] = "1000";
    m = ls_;
    m[a] = line_of(w);
    rejected_or_redundant(m, "bound moved");
  }

  const Instance& inst_;
  std::vector<std::string> ls_;
  uint64_t seed_;
  Counts& n_;
};

void check_one(uint64_t seed, const Instance& other, Counts& n) {
  const Instance inst = random_instance(general_params(seed), seed);
  if (inst.horizontal_only()) return;
  SolveOptions opt;
  opt.seconds = 20;
  const CertifiedContinuous cc = solve_continuous_certified(inst, opt);
  ASSERT_NE(cc.result.status, Verdict::Unknown) << "seed " << seed;
  if (cc.result.status == Verdict::Yes) {
    ++n.yes;
    EXPECT_TRUE(cc.certificate.empty());
    const std::string forged = "p gridlock-no-certificate 1 continuous\n" + couplings_line(inst) + "bounds\nl\n";
    const CertifyResult r = certify(inst, forged, "continuous");
    EXPECT_FALSE(r.proved) << "seed " << seed;
    EXPECT_NE(r.reason.find("not RUP"), std::string::npos) << r.reason;
    return;
  }
  ++n.no;
  if (cc.certificate.empty()) {
    ++n.uncertified;
    EXPECT_NE(cc.why_none.find("decided by Z3 on the clamped encoding"), std::string::npos)
        << "seed " << seed << ": " << cc.why_none;
    return;
  }
  ++n.certified;
  n.face_lines += cc.certificate.find("\nw ") != std::string::npos;
  n.rich += cc.certificate.find("\ne ") != std::string::npos || cc.certificate.find("\nt ") != std::string::npos;
  const CertifyResult r = certify(inst, cc.certificate, "continuous");
  EXPECT_TRUE(r.proved) << "seed " << seed << ": " << r.reason << "\n" << cc.certificate;
  if (inst.couplings().size() <= 4) {  // the quantified twin agrees (small instances: it is slow)
    EXPECT_EQ(test::reference_continuous(inst, nullptr, 20000), std::optional<bool>(false)) << "seed " << seed;
    ++n.twin;
  }
  if (cc.certificate.find("\nbounds\n") != std::string::npos) Mutator(inst, cc.certificate, seed, n).run(other);
}

TEST(CertifyBounds, RandomGeneralInstances) {
  const uint64_t base = test::base_seed(9100);
  const int count = test::scaled(700);
  const Instance other = random_instance(general_params(base + 99999), base + 99999);
  Counts n;
  for (int i = 0; i < count; ++i) check_one(base + static_cast<uint64_t>(i), other, n);
  std::printf(
      "certify bounds: %d NO (%d certified, %d with event or theory lines, %d with face lines, %d decided by Z3 on "
      "the clamped encoding without a proof; %d also by the twin), %d YES; %d of %d mutations rejected (%d face "
      "lines mutated); %d of %d drops rejected\n",
      n.no, n.certified, n.rich, n.face_lines, n.uncertified, n.twin, n.yes, n.rejected, n.mutations, n.faces,
      n.drops_rejected, n.drops);
  EXPECT_GE(n.certified * 10, n.no * 9);  // faces and relaxed covers: every NO of seed 9100 is certified
  EXPECT_GT(n.certified, count / 20);
  EXPECT_GT(n.yes, count / 6);
  EXPECT_GT(n.drops_rejected, 0);
}

// Random 3-SAT formulas through the continuous reduction (a tree shape with
// one vertical operation): every unsatisfiable one is certified in
// continuous time and accepted; satisfiable ones are YES.
// Shapes with many faces (`gridlock random --family cycles`): faces of more
// than kEagerFaceCouplings couplings get their clauses from the models
// (check_faces). The default engine agrees with Z3 on the clamped encoding,
// and every NO is certified and accepted.
TEST(CertifyBounds, LargeFacesAgreeWithZ3AndAreCertified) {
  const uint64_t base = test::base_seed(9500);
  const int per_size = test::scaled(20);
  int no = 0, yes = 0, large = 0;
  for (uint32_t k : {8u, 12u, 16u})
    for (int i = 0; i < per_size; ++i) {
      const uint64_t seed = base + uint64_t{k} * 1000 + static_cast<uint64_t>(i);
      RandomFamilyParams fp;
      fp.family = ShapeFamily::Cycles;
      fp.couplings = k;
      const Instance inst = random_family_instance(fp, seed);
      if (inst.horizontal_only()) continue;
      const FaceNets faces = FaceNets::build(inst);
      large += std::any_of(faces.faces.begin(), faces.faces.end(),
                           [](const FaceNets::Face& f) { return f.nets.size() > kEagerFaceCouplings; });
      SolveOptions opt;
      opt.seconds = 20;
      const CertifiedContinuous cc = solve_continuous_certified(inst, opt);
      const ContinuousResult z3 = solve_continuous(inst, opt, ContinuousEngine::Z3);
      ASSERT_NE(cc.result.status, Verdict::Unknown) << "seed " << seed << " k " << k;
      EXPECT_EQ(cc.result.status, z3.status) << "seed " << seed << " k " << k;
      if (cc.result.status == Verdict::Yes) {
        ++yes;
        continue;
      }
      ++no;
      ASSERT_FALSE(cc.certificate.empty()) << "seed " << seed << " k " << k << ": " << cc.why_none;
      const CertifyResult r = certify(inst, cc.certificate, "continuous");
      EXPECT_TRUE(r.proved) << "seed " << seed << " k " << k << ": " << r.reason;
    }
  std::printf("large faces: %d instances with a face of more than %zu couplings; %d NO certified, %d YES\n", large,
              kEagerFaceCouplings, no, yes);
  EXPECT_GT(large, per_size);
}

TEST(CertifyBounds, CompiledFormulas) {
  const uint64_t base = test::base_seed(9300);
  int no = 0;
  Counts n;
  const Instance other = compile_formula(reduce_to_lsat(random_ksat({4, 20, 3, base + 999})).output(), Mutation::None,
                                         TimeModel::Continuous)
                             .instance;
  const int formulas = test::scaled(60);
  for (int i = 0; i < formulas; ++i) {
    const uint64_t seed = base + static_cast<uint64_t>(i);
    const int vars = 3 + static_cast<int>(seed % 4);
    const Formula f = random_ksat({vars, vars * 5, 3, seed});
    const bool sat = exhaustive_sat(f).status == Verdict::Yes;
    const Instance inst = compile_formula(reduce_to_lsat(f).output(), Mutation::None, TimeModel::Continuous).instance;
    const CertifiedContinuous cc = solve_continuous_certified(inst, {});
    ASSERT_EQ(cc.result.status, sat ? Verdict::Yes : Verdict::No) << "seed " << seed;
    if (sat) continue;
    ++no;
    ASSERT_FALSE(cc.certificate.empty()) << "seed " << seed << ": " << cc.why_none;
    const CertifyResult r = certify(inst, cc.certificate, "continuous");
    EXPECT_TRUE(r.proved) << "seed " << seed << ": " << r.reason;
    EXPECT_EQ(r.kind, "bounds");
    if (no <= 3) Mutator(inst, cc.certificate, seed, n).run(other);  // the first three: every mutation
  }
  std::printf(
      "compiled (continuous reduction, continuous time): %d NO certified; %d of %d mutations rejected, %d of %d drops "
      "rejected\n",
      no, n.rejected, n.mutations, n.drops_rejected, n.drops);
  EXPECT_EQ(n.rejected, n.mutations);
  EXPECT_GE(no, formulas / 6);
}

// The offsets check against the solver's own computation (an independent
// method: candidate lines and exact 1-D tests): on random two-coupling
// pairs, the solver's free intervals pass; each interval of positive length
// dropped fails; and sampled offsets agree with pair_free_at_offset.
TEST(CertifyBounds, OffsetsAgreeWithSolver) {
  const uint64_t base = test::base_seed(9500);
  const int count = test::scaled(3000);
  int dropped = 0;
  for (int i = 0; i < count; ++i) {
    const uint64_t seed = base + static_cast<uint64_t>(i);
    std::mt19937_64 rng(seed);
    auto small = [&](int lo, int hi) { return lo + static_cast<int>(rng() % static_cast<uint64_t>(hi - lo + 1)); };
    CollisionConstraint c;
    c.num_forms = static_cast<uint32_t>(small(1, 4));
    c.rel = {0, 1};
    for (uint32_t k = 0; k < c.num_forms; ++k) c.base.push_back(small(-2, 2));
    std::vector<int64_t> coef(2 * static_cast<size_t>(c.num_forms), 0);
    for (auto& x : coef) x = small(-2, 2);
    c.set_coef(coef);
    std::vector<OffsetForm> forms;
    forms.reserve(c.num_forms);
    for (uint32_t k = 0; k < c.num_forms; ++k)
      forms.push_back({Rational(c.base[k]), Rational(c.coef_of(0)[k]), Rational(c.coef_of(1)[k])});
    const std::vector<OffsetInterval> iv = free_offsets(c);
    std::vector<FreeOffsets> free;
    free.reserve(iv.size());
    for (const OffsetInterval& x : iv) free.push_back({x.lo, x.hi});
    const auto ok = offsets_outside_collide(forms, free);
    EXPECT_FALSE(ok.has_value()) << "seed " << seed << ": " << *ok;
    for (size_t j = 0; j < free.size(); ++j) {
      if (free[j].lo && free[j].hi && *free[j].lo == *free[j].hi) continue;  // a point: dropping it may stay hidden
      std::vector<FreeOffsets> less = free;
      less.erase(less.begin() + static_cast<long>(j));
      EXPECT_TRUE(offsets_outside_collide(forms, less).has_value()) << "seed " << seed << ": interval " << j;
      ++dropped;
    }
    // Sampled offsets: free iff inside some interval.
    for (int s = -16; s <= 16; ++s) {
      const Rational d(s, 4);
      bool inside = false;
      for (const OffsetInterval& x : iv) inside = inside || x.contains(d);
      EXPECT_EQ(pair_free_at_offset(c, d), inside) << "seed " << seed << ": d = " << d.str();
    }
  }
  std::printf("offsets: %d pairs, %d intervals dropped and refused\n", count, dropped);
  EXPECT_GT(dropped, count / 4);
}

// The RUP check against a naive twin: propagation by scanning every clause
// until nothing changes, on random small clause sets.
bool naive_rup(const std::vector<std::vector<int>>& cnf, const std::vector<int>& lemma, int vars) {
  std::vector<int> val(static_cast<size_t>(vars) + 1, 0);
  for (int l : lemma) {
    if (val[static_cast<size_t>(std::abs(l))] == (l > 0 ? 1 : -1)) return true;  // both l and -l: a tautology
    val[static_cast<size_t>(std::abs(l))] = l > 0 ? -1 : 1;
  }
  for (bool changed = true; changed;) {
    changed = false;
    for (const auto& c : cnf) {
      int open = 0, unit = 0;
      bool sat = false;
      for (int l : c) {
        const int v = val[static_cast<size_t>(std::abs(l))] * (l > 0 ? 1 : -1);
        if (v > 0) sat = true;
        if (v == 0 && l != unit) ++open, unit = l;  // a repeated literal counts once (clauses come sorted)
      }
      if (sat) continue;
      if (open == 0) return true;
      if (open == 1) val[static_cast<size_t>(std::abs(unit))] = unit > 0 ? 1 : -1, changed = true;
    }
  }
  return false;
}

TEST(CertifyBounds, ClauseProofAgreesWithNaiveRup) {
  const uint64_t base = test::base_seed(9700);
  const int count = test::scaled(3000);
  int accepted = 0, refused = 0;
  for (int i = 0; i < count; ++i) {
    const uint64_t seed = base + static_cast<uint64_t>(i);
    std::mt19937_64 rng(seed);
    const int vars = 3 + static_cast<int>(rng() % 6);
    auto lit = [&] { return (1 + static_cast<int>(rng() % static_cast<uint64_t>(vars))) * (rng() % 2 ? 1 : -1); };
    ClauseProof proof(static_cast<uint32_t>(vars));
    std::vector<std::vector<int>> cnf;
    const int axioms = 2 + static_cast<int>(rng() % 12);
    for (int a = 0; a < axioms; ++a) {
      std::vector<int> c(1 + rng() % 3);
      for (int& l : c) l = lit();
      std::sort(c.begin(), c.end());
      proof.add_axiom(c);
      cnf.push_back(c);
    }
    for (int k = 0; k < 6; ++k) {
      std::vector<int> lemma(rng() % 3);
      for (int& l : lemma) l = lit();
      std::sort(lemma.begin(), lemma.end());
      const bool want = naive_rup(cnf, lemma, vars);
      ASSERT_EQ(proof.add_lemma(lemma), want) << "seed " << seed << " lemma " << k;
      (want ? accepted : refused)++;
      if (want) cnf.push_back(lemma);
    }
  }
  std::printf("clause proof: %d lemmas accepted, %d refused, as the naive twin\n", accepted, refused);
  EXPECT_GT(accepted, count / 2);
  EXPECT_GT(refused, count / 2);
}

// The real binary on a compiled unsatisfiable formula: solve writes the
// certificate, certify accepts it (exit 20), a broken copy is refused with
// FILE:LINE and the reason.
TEST(CertifyBounds, CommandLineEndToEnd) {
  using test::run_gridlock;
  const std::string d = test::temp_dir();
  const std::string cnf = d + "/u.cnf", grid = d + "/u.grid", cert = d + "/u.nocert", bad = d + "/bad.nocert";
  test::write_file(cnf, "p cnf 2 4\n1 2 0\n-1 2 0\n1 -2 0\n-1 -2 0\n");
  ASSERT_EQ(run_gridlock({"compile", cnf, "--model", "continuous", "-o", grid}).exit_code, 0);
  const auto s = run_gridlock({"solve", grid, "--model", "continuous", "--certificate", cert});
  ASSERT_EQ(s.exit_code, 20) << s.out << s.err;
  const std::string text = test::read_file(cert);
  ASSERT_NE(text.find("\nbounds\n"), std::string::npos) << text;
  const auto c = run_gridlock({"certify", grid, cert, "--model", "continuous"});
  EXPECT_EQ(c.exit_code, 20) << c.out << c.err;
  EXPECT_NE(c.out.find("c certificate checked"), std::string::npos);
  // The empty clause gone.
  std::vector<std::string> ls = lines_of(text);
  ls.pop_back();
  test::write_file(bad, join_lines(ls));
  const auto t = run_gridlock({"certify", grid, bad, "--model", "continuous"});
  EXPECT_EQ(t.exit_code, 1);
  EXPECT_NE(t.err.find("does not end with the empty clause"), std::string::npos) << t.err;
  // A literal of no declared variable.
  ls = lines_of(text);
  const size_t i = first_line(ls, "t", 2);
  ASSERT_NE(i, 0u);
  ls[i] += " 999999";
  test::write_file(bad, join_lines(ls));
  const auto u = run_gridlock({"certify", grid, bad, "--model", "continuous"});
  EXPECT_EQ(u.exit_code, 1);
  EXPECT_NE(u.err.find("bad.nocert:" + std::to_string(i + 1) + ": certificate rejected: literal 999999 of no declared"),
            std::string::npos)
      << u.err;
  // Checked as discrete: refused.
  const auto v = run_gridlock({"certify", grid, cert});
  EXPECT_EQ(v.exit_code, 1);
}

// A continuous NO with no certificate says what stops the proof: here Z3
// decides on the clamped encoding and a pair of more than 8 couplings
// keeps the learning engine's relaxation out (docs/certificates.md, "Not
// certified"); the NO stands, no file is written.
TEST(CertifyBounds, UncertifiedNoSaysWhatStopsTheRelaxation) {
  using test::run_gridlock;
  const std::string d = test::temp_dir(), grid = d + "/p.grid", cert = d + "/p.nocert";
  ASSERT_EQ(run_gridlock({"random", "--family", "path", "--couplings", "10", "--max-coupling", "4", "--seed", "5059",
                          "-o", grid})
                .exit_code,
            0);
  const auto s = run_gridlock({"solve", grid, "--model", "continuous", "--certificate", cert});
  ASSERT_EQ(s.exit_code, 20) << s.out << s.err;
  EXPECT_NE(s.out.find("c no certificate written: decided by Z3 on the clamped encoding"), std::string::npos) << s.out;
  EXPECT_NE(s.out.find("the learning engine's relaxation cannot take it (a pair of more than 8 couplings)"),
            std::string::npos)
      << s.out;
  EXPECT_FALSE(std::filesystem::exists(cert));
}

}  // namespace
}  // namespace gridlock
