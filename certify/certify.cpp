// Which evidence proves what (docs/certificates.md, "Why each kind proves NO").
#include "certify/certify.hpp"

#include "certify/internal/bounds_proof.hpp"
#include "certify/internal/certificate_text.hpp"
#include "certify/internal/collide_proof.hpp"
#include "certify/internal/geometry.hpp"
#include "certify/internal/order_proof.hpp"
#include "certify/internal/pair_pattern.hpp"

namespace gridlock {
namespace {

std::string at(size_t line, const std::string& what) { return "line " + std::to_string(line) + ": " + what; }

// breaker Q WALK: Q's operations sum to a non-zero vector around a closed
// walk, so whenever Q runs (and it must) the walk cannot stay closed: a
// cycle collision. Discrete model only (there Q runs alone).
void check_breaker(const Instance& inst, const CertificateText& c, CertifyResult& r) {
  std::vector<char> in(inst.couplings().size(), 0);
  in[c.breaker] = 1;
  Vec2 net;
  if (c.nodes.size() < 2) return void(r.reason = at(c.kind_line, "the walk needs at least two cells"));
  if (auto e = CertifyGeometry(inst).walk_net(c.nodes, in, net)) return void(r.reason = at(c.kind_line, *e));
  if (net == Vec2{0, 0})
    return void(r.reason = at(c.kind_line, "coupling " + inst.couplings()[c.breaker].name +
                                               " sums to zero around this walk: it breaks no cycle here"));
  r.proved = true;
}

// final-cycle WALK: with every coupling done the walk does not close. Every
// schedule ends there, so every schedule ends in a cycle collision.
void check_final_cycle(const Instance& inst, const CertificateText& c, CertifyResult& r) {
  const std::vector<char> all(inst.couplings().size(), 1);
  Vec2 net;
  if (c.nodes.size() < 2) return void(r.reason = at(c.kind_line, "the walk needs at least two cells"));
  if (auto e = CertifyGeometry(inst).walk_net(c.nodes, all, net)) return void(r.reason = at(c.kind_line, *e));
  if (net == Vec2{0, 0}) return void(r.reason = at(c.kind_line, "the walk closes with every coupling done"));
  r.proved = true;
}

// final-gap A B: A and B are row neighbours whose gap is negative with every
// coupling done. Gaps are linear in the progress of everything-at-once, and
// by the paper's theorem (horizontal-only) a schedule exists iff
// everything-at-once is collision-free.
void check_final_gap(const Instance& inst, const CertificateText& c, CertifyResult& r) {
  const CertifyGeometry geo(inst);
  const NodeId a = c.nodes[0], b = c.nodes[1];
  if (!inst.horizontal_only()) return void(r.reason = at(c.kind_line, "final-gap needs a horizontal-only instance"));
  if (!geo.row_neighbours(a, b))
    return void(r.reason = at(c.kind_line, inst.node_label(a) + " and " + inst.node_label(b) +
                                               " are not neighbours in a row (left one first)"));
  const CouplingForm f = geo.overlap_form(a, b);
  int64_t end = f.base;
  for (auto [q, coef] : f.terms) end += coef;
  if (end <= 0)
    return void(
        r.reason = at(c.kind_line, "the gap is " + std::to_string(-end) + " with every coupling done, not negative"));
  r.proved = true;
}

// gaps + lemmas: no order of the couplings meets every gap inequality.
void check_gaps_proof(const Instance& inst, const CertificateText& c, CertifyResult& r) {
  if (!inst.horizontal_only()) return void(r.reason = at(c.kind_line, "gaps needs a horizontal-only instance"));
  const std::vector<GapInequality> ineqs = CertifyGeometry(inst).gap_inequalities();
  r.inequalities = ineqs.size();
  if (c.lemmas.empty() || !c.lemmas.back().lits.empty() || c.lemmas.back().cycle)
    return void(r.reason = "the proof does not end with the empty clause (a line 'l' alone)");
  OrderProof proof(inst.couplings().size(), ineqs, c.lemmas);
  proof.start();
  r.axioms = proof.axioms();
  for (const CertificateLemma& lem : c.lemmas) {
    if (lem.lits.empty() && &lem != &c.lemmas.back())
      return void(r.reason = at(lem.line, "the empty clause before the end of the proof"));
    std::string e = proof.check(lem);
    if (!e.empty()) return void(r.reason = at(lem.line, e));
    ++r.lemmas;
  }
  r.proved = proof.refuted();
  if (!r.proved) r.reason = "the empty clause was accepted but the clauses are not refuted";
}

// pairs: clauses over order literals, each justified ("x": a colliding
// pair pattern; "o": a cycle) or RUP ("l"), ending with the empty clause.
// Sound for any instance: if some coupling breaks a cycle the answer is NO
// anyway; otherwise the tree positions are the positions, so the forms are
// the regions' true faces.
void check_pairs_proof(const Instance& inst, const CertificateText& c, CertifyResult& r) {
  if (c.lemmas.empty() || !c.lemmas.back().lits.empty() || c.lemmas.back().cycle || c.lemmas.back().runner != kNone)
    return void(r.reason = "the proof does not end with the empty clause (a line 'l' alone)");
  const CertifyGeometry geo(inst);
  OrderProof proof(inst.couplings().size(), {}, c.lemmas);
  bool started = false;  // the order closure: after the leading x lines
  for (const CertificateLemma& lem : c.lemmas) {
    if (lem.runner == kNone && !started) started = true, proof.start();
    if (lem.lits.empty() && !lem.cycle && lem.runner == kNone && &lem != &c.lemmas.back())
      return void(r.reason = at(lem.line, "the empty clause before the end of the proof"));
    if (lem.runner != kNone) {
      if (auto e = check_pair_pattern(inst, geo, lem)) return void(r.reason = at(lem.line, *e));
      proof.add_axiom(lem);
      ++r.inequalities;
      continue;
    }
    std::string e = proof.check(lem);
    if (!e.empty()) return void(r.reason = at(lem.line, e));
    ++r.lemmas;
  }
  r.axioms = proof.axioms();
  r.proved = proof.refuted();
  if (!r.proved) r.reason = "the empty clause was accepted but the clauses are not refuted";
}

}  // namespace

CertifyResult certify(const Instance& inst, std::string_view text, const std::string& model) {
  CertifyResult r;
  // gridlock collide's NO (no schedule collides): continuous, so it also
  // proves the discrete model's NO.
  if (is_collide_certificate(text)) {
    check_collide_proof(inst, text, r);
    return r;
  }
  CertificateText c;
  if (auto e = read_certificate(inst, text, c)) {
    r.reason = *e;
    return r;
  }
  r.kind = c.kind;
  if (c.model != model) {
    r.reason = "a " + c.model + " certificate, checked as " + model;
    return r;
  }
  const bool discrete = model == "discrete";
  if (c.kind == "breaker" && discrete) check_breaker(inst, c, r);
  else if (c.kind == "gaps" && discrete) check_gaps_proof(inst, c, r);
  else if (c.kind == "pairs" && discrete) check_pairs_proof(inst, c, r);
  else if (c.kind == "final-gap" && !discrete) check_final_gap(inst, c, r);
  else if (c.kind == "final-cycle" && !discrete) check_final_cycle(inst, c, r);
  else if (c.kind == "bounds" && !discrete) check_bounds_proof(inst, c, r);
  else r.reason = at(c.kind_line, c.kind + " does not prove NO in the " + model + " model");
  return r;
}

}  // namespace gridlock
