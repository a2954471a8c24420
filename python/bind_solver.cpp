// solve (discrete and continuous), collide and gaps (solver/, collide/).
// Results are dicts with the fields of the command line's --json (exact
// times as Fractions); python/gridlock/__init__.py wraps them in dataclasses.
#include <optional>
#include <string>

#include "certify/certify.hpp"
#include "collide/collide.hpp"
#include "collide/collide_certificate.hpp"
#include "common/limits.hpp"
#include "python/bindings.hpp"
#include "solver/continuous.hpp"
#include "solver/gaps.hpp"
#include "solver/no_certificate.hpp"
#include "solver/solve.hpp"

namespace gridlock::python {
namespace {

py::dict stats_dict(const SolveStats& st) {
  py::dict d;
  d["states"] = st.states;
  d["refuted"] = st.refuted;
  d["propagations"] = st.propagations;
  d["decisions"] = st.decisions;
  d["safe_moves"] = st.safe_moves;
  d["memo_hits"] = st.memo_hits;
  d["constraints"] = st.constraints;
  d["seconds"] = st.seconds;
  return d;
}

SolveOptions::Engine engine_arg(const std::string& engine) {
  if (engine == "auto") return SolveOptions::Engine::Auto;
  if (engine == "states") return SolveOptions::Engine::States;
  if (engine == "precedence") return SolveOptions::Engine::Precedence;
  if (engine == "sat") return SolveOptions::Engine::Sat;
  if (engine == "pairs") return SolveOptions::Engine::Pairs;
  raise("engine must be auto, states, precedence, sat or pairs, not '" + engine + "'");
}

// The continuous model's engines (as `gridlock solve --model continuous --engine`).
ContinuousEngine continuous_engine_arg(const std::string& engine) {
  if (const std::optional<ContinuousEngine> named = continuous_engine_named(engine)) return *named;
  raise(std::string("engine with model='continuous' must be ") + kContinuousEngineNames + ", not '" + engine + "'");
}

SolveOptions solve_options(const std::string& model, const std::string& engine, const py::object& timeout,
                           uint64_t max_states, const Instance& inst) {
  if (model != "discrete" && model != "continuous") raise("model must be discrete or continuous, not '" + model + "'");
  SolveOptions opt;
  if (model == "discrete") opt.engine = engine_arg(engine);
  else continuous_engine_arg(engine);
  if ((opt.engine == SolveOptions::Engine::Precedence || opt.engine == SolveOptions::Engine::Sat) &&
      !inst.horizontal_only())
    raise("engine " + engine + " needs a horizontal-only instance");
  if (!timeout.is_none()) {
    opt.seconds = timeout.cast<double>();
    if (!(opt.seconds > 0)) raise("timeout must be a positive number of seconds");
  }
  opt.max_states = max_states;
  return opt;
}

py::dict solve(const Instance& inst, const std::string& model, const std::string& engine, const py::object& timeout,
               uint64_t max_states, bool certificate) {
  const SolveOptions opt = solve_options(model, engine, timeout, max_states, inst);
  py::dict d;
  d["model"] = model;
  d["certificate"] = py::none();
  d["certificate_note"] = py::none();
  // NO because one coupling alone moves a pair into a collision (both models).
  auto lone = [&](CouplingId q, const std::string& pair) {
    d["lone_collider"] = q != kNone ? py::object(py::str(inst.couplings()[q].name)) : py::object(py::none());
    d["lone_pair"] = q != kNone ? py::object(py::str(pair)) : py::object(py::none());
  };
  if (model == "continuous") {
    const ContinuousEngine ce = continuous_engine_arg(engine);
    CertifiedContinuous cc;
    if (certificate) cc = run_interruptible([&] { return solve_continuous_certified(inst, opt, ce); });
    else cc.result = run_interruptible([&] { return solve_continuous(inst, opt, ce); });
    const ContinuousResult& r = cc.result;
    d["status"] = verdict_name(r.status);
    d["engine"] = r.stats.engine;
    d["times"] = r.status == Verdict::Yes ? py::object(times_dict(inst, r.schedule)) : py::object(py::none());
    d["stats"] = stats_dict(r.stats);
    lone(r.lone_collider, r.lone_pair);
    if (certificate && r.status == Verdict::No) {
      if (!cc.certificate.empty()) d["certificate"] = cc.certificate;
      else d["certificate_note"] = cc.why_none;
    }
    return d;
  }
  CertifiedSolve cs;
  if (certificate) {
    const PreparedInstance prep(inst);
    cs = run_interruptible([&] { return solve_discrete_certified(prep, opt); });
  } else {
    cs.result = run_interruptible([&] { return solve_discrete(inst, opt); });
  }
  const SolveResult& r = cs.result;
  d["status"] = verdict_name(r.status);
  d["engine"] = r.stats.engine;
  d["order"] = r.status == Verdict::Yes ? py::object(order_names(inst, r.order)) : py::object(py::none());
  d["stats"] = stats_dict(r.stats);
  d["cycle_breaker"] = r.cycle_breaker != kNone ? py::object(py::str(inst.couplings()[r.cycle_breaker].name))
                                                : py::object(py::none());
  lone(r.lone_collider, r.lone_pair);
  if (certificate && r.status == Verdict::No) {
    if (!cs.certificate.empty()) d["certificate"] = cs.certificate;
    else d["certificate_note"] = cs.why_none;
  }
  return d;
}

// The independent checker (certify/, docs/certificates.md): never trusts the solvers.
py::dict certify_text(const Instance& inst, const std::string& text, const std::string& model) {
  if (model != "discrete" && model != "continuous") raise("model must be discrete or continuous, not '" + model + "'");
  const CertifyResult r = run_interruptible([&] { return certify(inst, text, model); });
  py::dict d;
  d["proved"] = r.proved;
  d["reason"] = r.proved ? py::object(py::none()) : py::object(py::str(r.reason));
  d["kind"] = r.kind;
  d["lemmas"] = r.lemmas;
  return d;
}

CollideMethod method_arg(const std::string& method) {
  if (method == "auto") return CollideMethod::Auto;
  if (method == "tree") return CollideMethod::Tree;
  if (method == "tree-pairwise") return CollideMethod::TreePairwise;
  if (method == "pairwise") return CollideMethod::Pairwise;
  raise("method must be auto, tree, tree-pairwise or pairwise, not '" + method + "'");
}

// With certificate, a NO carries collide_no_certificate's text (it proves
// the NO in both models) or, when there is none, the reason.
py::dict collide(const Instance& inst, const std::string& model, const std::string& method, bool certificate) {
  if (model != "discrete" && model != "continuous") raise("model must be discrete or continuous, not '" + model + "'");
  const TimeModel tm = model == "discrete" ? TimeModel::Discrete : TimeModel::Continuous;
  const CollideMethod cm = method_arg(method);
  const Deadline no_limit;  // no time limit, but a stop request (Ctrl-C) ends the quadratic methods
  const CollideResult r = run_interruptible([&] { return find_collision(inst, tm, cm, &no_limit); });
  py::dict d;
  d["status"] = r.collides ? "YES" : "NO";
  d["model"] = model;
  d["algorithm"] = r.algorithm;
  d["complexity"] = r.complexity;
  d["order"] = py::none();
  d["times"] = py::none();
  d["collision"] = py::none();
  d["certificate"] = py::none();
  d["certificate_note"] = py::none();
  d["checked_at"] = py::none();
  if (!r.collides) {
    if (!certificate) return d;
    const CollideCertificate cert = run_interruptible([&] { return collide_no_certificate(inst, &no_limit); });
    if (!cert.text.empty()) d["certificate"] = cert.text;
    else d["certificate_note"] = cert.why_none;
    return d;
  }
  d["collision"] = collision_dict(inst, Regions::build(inst), *r.simulated);
  if (r.checked_at) d["checked_at"] = r.checked_at->str();
  if (tm == TimeModel::Discrete) d["order"] = order_names(inst, r.witness.order);
  else d["times"] = times_dict(inst, r.witness);
  return d;
}

py::dict gaps(const Instance& inst) {
  if (!inst.horizontal_only()) raise("gaps decides horizontal-only instances; this one has a vertical operation");
  const GapVerdict v = check_gaps(inst);
  py::dict d;
  d["status"] = verdict_name(v.verdict());
  d["gaps_checked"] = v.gaps_checked;
  d["negative_gaps"] = v.negative_gaps;
  d["cycles_checked"] = v.cycles_checked;
  d["open_cycles"] = v.open_cycles;
  d["explanation"] = describe_gap_verdict(inst, v);
  d["gap"] = py::none();
  d["cycle"] = py::none();
  if (v.reason == GapVerdict::Reason::Gap) {
    py::dict g;
    g["row"] = v.row;
    g["left"] = inst.node_label(v.left);
    g["right"] = inst.node_label(v.right);
    g["initial_size"] = v.initial_size;
    g["final_size"] = v.final_size;
    py::list widened, narrowed;
    for (const GapChange& c : v.changes)
      (c.delta > 0 ? widened : narrowed)
          .append(py::dict(py::arg("op") = inst.ops()[c.op].name, py::arg("delta") = c.delta));
    g["widened_by"] = widened;
    g["narrowed_by"] = narrowed;
    d["gap"] = g;
  } else if (v.reason == GapVerdict::Reason::Cycle) {
    py::list nodes;
    for (NodeId w : v.cycle) nodes.append(inst.node_label(w));
    d["cycle"] = py::dict(py::arg("nodes") = nodes, py::arg("mismatch") = v.mismatch);
  }
  return d;
}

}  // namespace

void bind_solver(py::module_& m) {
  m.def("solve", &solve, py::arg("instance"), py::arg("model") = "discrete", py::arg("engine") = "auto",
        py::arg("timeout") = py::none(), py::arg("max_states") = 0, py::arg("certificate") = false);
  m.def("certify", &certify_text, py::arg("instance"), py::arg("certificate"), py::arg("model") = "discrete");
  m.def("collide", &collide, py::arg("instance"), py::arg("model") = "discrete", py::arg("method") = "auto",
        py::arg("certificate") = false);
  m.def("gaps", &gaps, py::arg("instance"));
}

}  // namespace gridlock::python
