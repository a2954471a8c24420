#include "solver/no_certificate.hpp"

#include <cstdio>
#include <stdexcept>

#include "solver/gaps.hpp"
#include "solver/search.hpp"

namespace gridlock {
namespace {

std::string header(const Instance& inst, const char* model) {
  char digest[17];
  std::snprintf(digest, sizeof digest, "%016llx", static_cast<unsigned long long>(coupling_digest(inst)));
  return std::string("c gridlock NO certificate (docs/certificates.md)\np gridlock-no-certificate 1 ") + model +
         "\ncouplings " + std::to_string(inst.couplings().size()) + " " + digest + "\n";
}

std::string cell_text(const Instance& inst, NodeId w) {
  const Vec2 c = inst.cells()[w];
  return std::to_string(c.x) + "," + std::to_string(c.y);
}

// "breaker Q x,y x,y ...": a face walk around which Q's operations do not sum to zero.
std::string breaker_text(const PreparedInstance& prep, CouplingId q) {
  for (const FaceNets::Face& f : prep.faces.faces)
    for (const auto& [c, net] : f.nets) {
      if (c != q) continue;
      std::string s = "breaker " + prep.inst.couplings()[q].name;
      for (NodeId w : f.walk) s += " " + cell_text(prep.inst, w);
      return s + "\n";
    }
  throw std::logic_error("NO certificate: a cycle breaker without a face");
}

// Appends one lemma line ("o" or "l") of order literals.
void append_lemma(std::string& out, char kind, const Instance& inst,
                  const std::vector<std::pair<CouplingId, CouplingId>>& lits) {
  out += kind;
  for (auto [a, b] : lits) {
    out += ' ';
    out += inst.couplings()[a].name;
    out += '<';
    out += inst.couplings()[b].name;
  }
  out += '\n';
}

// Runs the precedence engine with a log of its cycles and nogoods.
SolveResult logged_precedence(const PreparedInstance& prep, SolveOptions opt, std::string& log, Simulator* replay) {
  PrecedenceHooks hooks;
  hooks.on_learned = [&](const auto& lits) { append_lemma(log, 'l', prep.inst, lits); };
  hooks.on_cycle = [&](const auto& lits) { append_lemma(log, 'o', prep.inst, lits); };
  opt.engine = SolveOptions::Engine::Precedence;
  opt.precedence_hooks = &hooks;
  return solve_discrete(prep, opt, replay);
}

}  // namespace

uint64_t coupling_digest(const Instance& inst) {
  uint64_t h = 14695981039346656037ull;
  auto add = [&](char ch) { h = (h ^ static_cast<unsigned char>(ch)) * 1099511628211ull; };
  for (const Coupling& c : inst.couplings()) {
    for (char ch : c.name) add(ch);
    add('\n');
  }
  return h;
}

CertifiedSolve solve_discrete_certified(const PreparedInstance& prep, const SolveOptions& opt, Simulator* replay) {
  using Engine = SolveOptions::Engine;
  const Instance& inst = prep.inst;
  const bool horizontal = inst.horizontal_only();
  CertifiedSolve out;
  std::string log;
  const bool logged = horizontal && (opt.engine == Engine::Auto || opt.engine == Engine::Precedence);
  out.result = logged ? logged_precedence(prep, opt, log, replay) : solve_discrete(prep, opt, replay);
  if (out.result.status != Verdict::No) return out;
  if (out.result.cycle_breaker != kNone) {
    out.certificate = header(inst, "discrete") + breaker_text(prep, out.result.cycle_breaker);
    return out;
  }
  if (!horizontal) {
    out.why_none = "no NO certificate for instances with vertical operations yet (only for cycle breakers)";
    return out;
  }
  if (!logged) {
    const SolveResult again = logged_precedence(prep, opt, log, replay);
    if (again.status == Verdict::Unknown) {
      out.why_none = "limit reached while the precedence engine wrote the certificate";
      return out;
    }
    if (again.status != Verdict::No)
      throw std::logic_error("NO certificate: the precedence engine finds an order the " + out.result.stats.engine +
                             " engine missed");
  }
  out.certificate = header(inst, "discrete") + "gaps\n" + log + "l\n";
  return out;
}

std::string continuous_no_certificate(const Instance& inst) {
  const GapVerdict v = check_gaps(inst);
  if (v.collision_free) return {};
  std::string s = header(inst, "continuous");
  if (v.reason == GapVerdict::Reason::Cycle) {
    s += "final-cycle";
    for (NodeId w : v.cycle) s += " " + cell_text(inst, w);
    return s + "\n";
  }
  return s + "final-gap " + cell_text(inst, v.left) + " " + cell_text(inst, v.right) + "\n";
}

}  // namespace gridlock
