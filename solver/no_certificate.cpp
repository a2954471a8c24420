#include "solver/no_certificate.hpp"

#include <algorithm>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>

#include "cnf/internal/incremental_sat.hpp"
#include "common/limits.hpp"
#include "solver/gaps.hpp"
#include "solver/internal/constraints.hpp"
#include "solver/internal/continuous_sat.hpp"
#include "solver/internal/search.hpp"

namespace gridlock {
namespace {

std::string header(const Instance& inst, const char* model) {
  return std::string("c gridlock NO certificate (docs/certificates.md)\np gridlock-no-certificate 1 ") + model + "\n" +
         couplings_line(inst);
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
  if (kind != '\0') out += kind;
  for (auto [a, b] : lits) {
    out += ' ';
    out += inst.couplings()[a].name;
    out += '<';
    out += inst.couplings()[b].name;
  }
  out += '\n';
}

std::string region_text(const Instance& inst, const Regions& regions, uint32_t r) {
  const RegionShape& sh = regions.shapes[r];
  return sh.kind == RegionKind::Node ? cell_text(inst, sh.id) : "+" + inst.ops()[sh.id].name;
}

// Reads the text DRAT proof in f from its start and calls each(line) for
// every line (without its newline) up to and including the first empty
// clause "0" (CaDiCaL may repeat it: the proof ends there). True iff that
// empty clause was met.
bool each_drat_line(std::FILE* f, const std::function<void(const std::string&)>& each) {
  std::rewind(f);
  std::string line;
  for (int ch; (ch = std::fgetc(f)) != EOF;) {
    if (ch != '\n') {
      line += static_cast<char>(ch);
      continue;
    }
    each(line);
    if (line == "0") return true;
    line.clear();
  }
  return false;
}

// One DRAT line ("1 -2 0"; "d ..." deletions are skipped: a forward RUP
// check only gets stricter with fewer clauses, and never needs them) as an
// "l" line of order literals.
void append_drat_line(std::string& out, const Instance& inst, const PairsProof& proof, const std::string& line) {
  if (line.empty() || line[0] == 'd') return;
  std::vector<std::pair<CouplingId, CouplingId>> lits;
  size_t pos = 0;
  while (pos < line.size()) {
    size_t used = 0;
    const long long l = std::stoll(line.substr(pos), &used);
    pos += used;
    while (pos < line.size() && line[pos] == ' ') ++pos;
    if (l == 0) break;
    const auto v = static_cast<size_t>(l > 0 ? l : -l);
    if (v >= proof.var_pair.size()) throw std::logic_error("NO certificate: a proof variable that is no pair");
    const auto [lo, hi] = proof.var_pair[v];
    lits.push_back(l > 0 ? std::make_pair(lo, hi) : std::make_pair(hi, lo));
  }
  append_lemma(out, 'l', inst, lits);
}

// The pairs engine in proof mode: "pairs", its clauses with their reasons
// ("o" cycles, "x" colliding pair patterns), then CaDiCaL's lemmas. Empty
// with why set when a limit is reached.
std::string pairs_certificate(const PreparedInstance& prep, const SolveOptions& opt, std::string& why) {
  const Instance& inst = prep.inst;
  SearchBudget budget(opt);
  SolveStats st;
  PairsProof proof;
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> drat(std::tmpfile(), &std::fclose);
  if (!drat) throw std::runtime_error("NO certificate: cannot open a temporary file for the proof");
  proof.drat = drat.get();
  SearchOutcome out;
  try {
    const ConstraintSystem sys = build_pair_constraints(prep, &budget.deadline(), /*stop_at_refuting=*/true);
    out = search_pairs_proof(sys, budget, st, proof);
    if (out.status != Verdict::No)
      throw std::logic_error("NO certificate: the pairs engine in proof mode finds an order");
    std::string text = "pairs\n";
    for (const PairsProof::Axiom& a : proof.axioms) {
      if (a.constraint == kNone) {  // the literals, as edges, are a directed cycle
        append_lemma(text, 'o', inst, a.lits);
        continue;
      }
      const CollisionConstraint& c = sys.constraints[a.constraint];
      text += "x " + region_text(inst, prep.regions, c.region_a) + " " + region_text(inst, prep.regions, c.region_b) +
              " " + inst.couplings()[a.runner].name;
      append_lemma(text, '\0', inst, a.lits);
    }
    const bool empty_clause = each_drat_line(
        drat.get(), [&](const std::string& line) { append_drat_line(text, inst, proof, line); });
    if (!empty_clause) text += "l\n";
    return text;
  } catch (const LimitReached&) {
    why = "limit reached while the pairs engine wrote the certificate";
    return {};
  }
}

std::string literals_text(const std::vector<int>& lits) {
  std::string s;
  for (int l : lits) s += " " + std::to_string(l);
  return s;
}

// The variables and clauses of a continuous proof (kind bounds; the
// definitions of selectors are left to the checker).
std::string bounds_text(const Instance& inst, const Regions& regions, const ContinuousProof& p) {
  using Reason = ContinuousProof::Reason;
  const auto& cs = inst.couplings();
  std::string text = "bounds\n";
  for (size_t i = 0; i < p.vars.size(); ++i) {
    const ContinuousProof::Var& v = p.vars[i];
    const std::string n = std::to_string(i + 1);
    if (v.guard) {
      text += "g " + n + " " + region_text(inst, regions, v.region_a) + " " + region_text(inst, regions, v.region_b) +
              " " + std::to_string(v.form + 1) + "\n";
    } else if (v.selector) {
      text += "s " + n + " " + cs[v.x].name + " " + cs[v.y].name + " " + (v.lo ? v.lo->str() : "*") + " " +
              (v.hi ? v.hi->str() : "*") + "\n";
    } else if (v.x != kNone) {
      text += "a " + n + " " + cs[v.x].name + " " + cs[v.y].name + (v.strict ? " < " : " <= ") + v.v.str() + "\n";
    }
  }
  for (const ContinuousProof::Clause& c : p.clauses) {
    if (c.reason == Reason::Definition) continue;
    if (c.reason == Reason::Theory) {
      text += "t" + literals_text(c.lits) + "\n";
      continue;
    }
    if (c.reason == Reason::Face) {
      text += "w " + cs[c.runner].name;
      for (NodeId w : c.walk) text += " " + cell_text(inst, w);
      text += literals_text(c.lits) + "\n";
      continue;
    }
    text += std::string(c.reason == Reason::Event   ? "e "
                        : c.reason == Reason::Forms ? "f "
                                                    : "i ") +
            region_text(inst, regions, c.region_a) + " " + region_text(inst, regions, c.region_b);
    if (c.reason == Reason::Event)
      text += " " + (c.runner == kNone ? std::string("-") : cs[c.runner].name) + " " + std::to_string(c.delta);
    if (c.reason == Reason::Interval)
      text += " " + cs[c.movers[0]].name + " " + (c.movers.size() > 1 ? cs[c.movers[1]].name : std::string("-"));
    text += literals_text(c.lits) + "\n";
  }
  return text;
}

// CaDiCaL's DRAT proof that the clauses of p are unsatisfiable, as "l"
// lines (deletions left out), ending with "l" alone; empty if dl expires
// first (the time left of --timeout, or a stop request).
std::string bounds_drat(const ContinuousProof& p, const Deadline& dl) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> drat(std::tmpfile(), &std::fclose);
  if (!drat) throw std::runtime_error("NO certificate: cannot open a temporary file for the proof");
  IncrementalSat sat;
  sat.trace_proof(drat.get());
  for (size_t i = 0; i < p.vars.size(); ++i) sat.new_var();
  for (const ContinuousProof::Clause& c : p.clauses) sat.add_clause(c.lits);
  const Verdict v = sat.solve([&](uint64_t) { return dl.expired(); });
  if (v == Verdict::Unknown) return {};
  if (v != Verdict::No) throw std::logic_error("NO certificate: the continuous proof's clauses are satisfiable");
  sat.flush_proof();
  std::string text;
  each_drat_line(drat.get(), [&](const std::string& line) {
    if (line != "0" && line.size() > 2 && line[0] != 'd') text += "l " + line.substr(0, line.size() - 2) + "\n";
  });
  return text + "l\n";
}

// Runs the precedence engine with a log of its cycles and nogoods.
// kept: the constraint system of an earlier engine on prep, or empty
// (solve_discrete_kept, solver/internal/search.hpp).
SolveResult logged_precedence(const PreparedInstance& prep, SolveOptions opt, std::string& log, Simulator* replay,
                              std::optional<ConstraintSystem>& kept) {
  PrecedenceHooks hooks;
  hooks.on_learned = [&](const auto& lits) { append_lemma(log, 'l', prep.inst, lits); };
  hooks.on_cycle = [&](const auto& lits) { append_lemma(log, 'o', prep.inst, lits); };
  opt.engine = SolveOptions::Engine::Precedence;
  opt.precedence_hooks = &hooks;
  return solve_discrete_kept(prep, opt, replay, kept);
}

}  // namespace

CertifiedSolve solve_discrete_certified(const PreparedInstance& prep, const SolveOptions& opt, Simulator* replay) {
  using Engine = SolveOptions::Engine;
  const Instance& inst = prep.inst;
  const bool horizontal = inst.horizontal_only();
  CertifiedSolve out;
  std::string log;
  const bool logged = horizontal && (opt.engine == Engine::Auto || opt.engine == Engine::Precedence);
  std::optional<ConstraintSystem> kept;  // the gap constraints, built once for both engines
  out.result = logged ? logged_precedence(prep, opt, log, replay, kept) : solve_discrete_kept(prep, opt, replay, kept);
  if (out.result.status != Verdict::No) return out;
  if (out.result.cycle_breaker != kNone) {
    out.certificate = header(inst, "discrete") + breaker_text(prep, out.result.cycle_breaker);
    return out;
  }
  if (!horizontal) {
    const std::string proof = pairs_certificate(prep, opt, out.why_none);
    if (!proof.empty()) out.certificate = header(inst, "discrete") + proof;
    return out;
  }
  if (!logged) {
    const SolveResult again = logged_precedence(prep, opt, log, replay, kept);
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

CertifiedContinuous solve_continuous_certified(const Instance& inst, const SolveOptions& opt, ContinuousEngine engine) {
  CertifiedContinuous out;
  if (inst.horizontal_only()) {
    out.result = solve_continuous(inst, opt, engine);
    if (out.result.status == Verdict::No) out.certificate = continuous_no_certificate(inst);
    return out;
  }
  ContinuousProof proof;
  out.result = solve_continuous_proved(inst, opt, engine, proof);
  if (out.result.status != Verdict::No) return out;
  if (!proof.complete) {
    out.why_none = proof.why_none;
    return out;
  }
  const Deadline dl(opt.seconds > 0 ? std::max(opt.seconds - out.result.stats.seconds, 1e-6) : 0);
  const std::string drat = bounds_drat(proof, dl);
  if (drat.empty()) {
    out.why_none = "limit reached while CaDiCaL wrote the certificate's proof";
    return out;
  }
  const Regions regions = Regions::build(inst);
  out.certificate = header(inst, "continuous") + bounds_text(inst, regions, proof) + drat;
  return out;
}

}  // namespace gridlock
