#include "verify/verify.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "certify/certify.hpp"
#include "cnf/dimacs.hpp"
#include "cnf/lsat.hpp"
#include "cnf/sat_solver.hpp"
#include "common/clock.hpp"
#include "common/internal/atomic_file.hpp"
#include "lattice/grid_format.hpp"
#include "lattice/simulate.hpp"
#include "reductions/compile.hpp"
#include "reductions/to_lsat.hpp"
#include "solver/continuous.hpp"
#include "solver/gaps.hpp"
#include "solver/no_certificate.hpp"
#include "solver/solve.hpp"

namespace gridlock {

int VerifyResult::witnesses_checked() const {
  return (sat_witness == Check::Valid) + (solver_witness == Check::Valid) + (gaps_witness == Check::Valid) +
         (no_certificate == Check::Valid) + (csat_witness == Check::Valid) + (csolver_witness == Check::Valid) +
         (cno_certificate == Check::Valid);
}

namespace {

std::vector<std::string> names_of(const Instance& inst, const std::vector<CouplingId>& order) {
  std::vector<std::string> out;
  out.reserve(order.size());
  for (CouplingId q : order) out.push_back(inst.couplings()[q].name);
  return out;
}

std::vector<std::string> times_of(const Instance& inst, const Schedule& s) {
  std::vector<std::string> out;
  for (CouplingId q = 0; q < inst.couplings().size(); ++q)
    out.push_back(inst.couplings()[q].name + " " + s.start[q].str());
  return out;
}

// The certificate maps between F and G: to-lsat's, or the identity when G = F
// (VerifyOptions::direct).
struct Lift {
  const LsatReduction* red = nullptr;  // nullptr: identity
  std::vector<bool> lift_to_target(const std::vector<bool>& v) const { return red ? red->lift_to_target(v) : v; }
  std::vector<bool> lift_to_source(const std::vector<bool>& v) const { return red ? red->lift_to_source(v) : v; }
};

// The Verifier's simulator, pointed at prep (created on first use).
Simulator& simulator_for(std::unique_ptr<Simulator>& sim, const PreparedInstance& prep) {
  if (sim) sim->rebind(prep);
  else sim = std::make_unique<Simulator>(prep);
  return *sim;
}

SolveOptions solve_options(const VerifyOptions& opt) {
  SolveOptions so;
  so.seconds = opt.solve_seconds;
  so.max_states = opt.max_states;
  return so;
}

// What disagreed, joined by "; ".
struct Problems {
  std::string text;
  void add(const std::string& p) { text += (text.empty() ? "" : "; ") + p; }
  // An exact solver's answer against CaDiCaL's (UNKNOWN on either side is no disagreement).
  void compare(const std::string& solver, Verdict got, Verdict sat) {
    if (got != Verdict::Unknown && sat != Verdict::Unknown && got != sat)
      add(solver + " says " + verdict_name(got) + ", CaDiCaL says " + (sat == Verdict::Yes ? "SAT" : "UNSAT"));
  }
  void check(Check c, const std::string& what) {
    if (c == Check::Invalid) add(what);
  }
};

// A solver's NO certificate (or why it wrote none) through the independent
// checker: Valid, or Invalid with the issue. who: "the solver" and the like.
Check checked_certificate(const Instance& inst, const std::string& text, const std::string& why_none,
                          const std::string& model, const std::string& who, std::string& issue, double& ms) {
  const Stopwatch t0;
  Check out = Check::Valid;
  if (text.empty()) {
    out = Check::Invalid;
    issue = who + "'s NO has no certificate: " + why_none;
  } else if (const CertifyResult checked = certify(inst, text, model); !checked.proved) {
    out = Check::Invalid;
    issue = who + "'s NO certificate is rejected: " + checked.reason;
  }
  ms += t0.milliseconds();
  return out;
}

// The continuous reduction: compile G for continuous time, CaDiCaL's model
// as start times through the simulator, the exact continuous solver, its
// start times through the simulator and back to an assignment of F.
void verify_continuous(VerifyResult& r, const SatResult& sat, const Lift& red, const VerifyOptions& opt,
                       std::unique_ptr<Simulator>& simulator) {
  r.ran_continuous = true;
  Stopwatch t0;
  r.compiled_continuous = compile_formula(r.lsat, opt.mutation, TimeModel::Continuous);
  r.ms_compile += t0.milliseconds();
  const CompiledFormula& c = r.compiled_continuous;
  const Instance& inst = c.instance;
  r.cnodes = c.stats.nodes;
  r.couplings = c.stats.couplings;  // the same in both reductions
  r.max_coupling = c.stats.max_coupling;
  const PreparedInstance prep(inst);
  Simulator& sim = simulator_for(simulator, prep);
  if (r.sat == Verdict::Yes) {
    Schedule s = times_from_assignment(c, red.lift_to_target(sat.model));
    r.csat_times = times_of(inst, s);
    r.csat_witness = sim.run(s).collision ? Check::Invalid : Check::Valid;
  }
  t0.restart();
  CertifiedContinuous cc;
  if (opt.certify) cc = solve_continuous_certified(inst, solve_options(opt));
  else cc.result = solve_continuous(inst, solve_options(opt));
  const ContinuousResult& cr = cc.result;
  r.ms_csolve = t0.milliseconds();
  if (opt.certify && cr.status == Verdict::No) {
    r.ccertificate = cc.certificate;
    r.cno_certificate = checked_certificate(inst, cc.certificate, cc.why_none, "continuous", "the continuous solver",
                                            r.ccertificate_issue, r.ms_certify);
  }
  r.csolver_conflicts = cr.stats.refuted;
  r.continuous_solver = cr.status;
  if (r.continuous_solver == Verdict::Yes) {
    r.csolver_times = times_of(inst, cr.schedule);
    // The solver replays its schedule itself; replay it here too, then lift.
    if (check_schedule_bounds(inst, cr.schedule) || sim.run(cr.schedule).collision)
      r.csolver_issue = "the continuous solver's start times collide in the simulator";
    else if (!satisfies(r.source, red.lift_to_source(assignment_from_times(c, cr.schedule))))
      r.csolver_issue = "the continuous solver's start times lift to an assignment that falsifies the formula";
    r.csolver_witness = r.csolver_issue.empty() ? Check::Valid : Check::Invalid;
  }
}

void continuous_problems(const VerifyResult& r, Problems& p) {
  p.compare("exact continuous solver", r.continuous_solver, r.sat);
  p.check(r.csat_witness, "the SAT model's start times collide in the simulator (continuous)");
  if (r.csolver_witness == Check::Invalid) p.add(r.csolver_issue);
  if (r.cno_certificate == Check::Invalid) p.add(r.ccertificate_issue);
}

// G: F itself (VerifyOptions::direct, no empty clause) or to-lsat's output.
Lift lsat_form(VerifyResult& r, const VerifyOptions& opt, std::optional<LsatReduction>& lsat) {
  const Formula& f = r.source;
  Stopwatch t0;
  const bool direct = opt.direct && std::none_of(f.clauses.begin(), f.clauses.end(),
                                                 [](const std::vector<int>& cl) { return cl.empty(); });
  Lift red;
  if (direct) {
    r.lsat = f;
  } else {
    lsat = reduce_to_lsat(f);
    red.red = &*lsat;
    r.reduced = !lsat->stats().identity;
    r.lsat = lsat->output();
  }
  r.ms_compile = t0.milliseconds();
  return red;
}

// The discrete reduction: compile G, lift CaDiCaL's model to a schedule
// through the simulator, the exact discrete solver (its YES order replayed
// by the simulator, lifted back to F), the gap checker and its witness.
void verify_discrete(VerifyResult& r, const SatResult& sat, const Lift& red, const VerifyOptions& opt,
                     std::unique_ptr<Simulator>& simulator, Problems& p) {
  r.ran_discrete = true;
  Stopwatch t0;
  r.compiled = compile_formula(r.lsat, opt.mutation);
  const CompiledFormula& c = r.compiled;
  r.ms_compile += t0.milliseconds();
  r.nodes = c.stats.nodes;
  r.ops = c.stats.ops;
  r.couplings = c.stats.couplings;
  r.max_coupling = c.stats.max_coupling;
  const Instance& inst = c.instance;
  // The motion tables, built once for every check below; the simulator's
  // work arrays serve its three runs (and every formula of a Verifier).
  const PreparedInstance prep(inst);
  Simulator& sim = simulator_for(simulator, prep);
  if (r.sat == Verdict::Yes) {
    std::vector<CouplingId> order = schedule_from_assignment(c, red.lift_to_target(sat.model));
    r.sat_schedule = names_of(inst, order);
    r.sat_witness = sim.run_order(order).collision ? Check::Invalid : Check::Valid;
  }
  t0.restart();
  CertifiedSolve cs;
  SolveOptions so = solve_options(opt);
  // The default engine decides, as without certificates (the precedence
  // engine then runs again on a NO to write the log: a second engine's NO).
  if (inst.horizontal_only()) so.engine = SolveOptions::Engine::Sat;
  if (opt.certify) cs = solve_discrete_certified(prep, so, &sim);
  else cs.result = solve_discrete(prep, solve_options(opt), &sim);
  const SolveResult& sr = cs.result;
  r.ms_solve = t0.milliseconds();
  if (opt.certify && sr.status == Verdict::No) {
    r.certificate = cs.certificate;
    r.no_certificate = checked_certificate(inst, cs.certificate, cs.why_none, "discrete", "the solver",
                                           r.certificate_issue, r.ms_certify);
  }
  r.solver_states = sr.stats.states;
  r.discrete = sr.status;
  if (r.discrete == Verdict::Yes) {
    r.solver_schedule = names_of(inst, sr.order);
    std::vector<bool> back = red.lift_to_source(assignment_from_schedule(c, sr.order));
    r.solver_witness = satisfies(r.source, back) ? Check::Valid : Check::Invalid;
  }
  // The gap checker (continuous model), its witness through the simulator.
  t0.restart();
  GapVerdict gv = check_gaps(prep);
  r.ms_gaps = t0.milliseconds();
  r.continuous = gv.verdict();
  if (gv.collision_free) {
    Schedule all_at_once;
    all_at_once.start.assign(inst.couplings().size(), Rational(0));
    r.gaps_witness = sim.run(all_at_once).collision ? Check::Invalid : Check::Valid;
  }
  p.compare("exact solver", r.discrete, r.sat);
  if (r.continuous != Verdict::Yes)
    p.add("gap checker says the continuous model collides: " + describe_gap_verdict(inst, gv));
  p.check(r.sat_witness, "the SAT model's schedule collides in the simulator");
  p.check(r.solver_witness, "the solver's schedule lifts to an assignment that falsifies the formula");
  p.check(r.gaps_witness, "running every coupling at time 0 collides in the simulator");
  if (r.no_certificate == Check::Invalid) p.add(r.certificate_issue);
}

}  // namespace

Verifier::Verifier() = default;
Verifier::~Verifier() = default;
Verifier::Verifier(Verifier&&) noexcept = default;
Verifier& Verifier::operator=(Verifier&&) noexcept = default;

VerifyResult Verifier::verify(const Formula& f, const std::string& name, const VerifyOptions& opt) {
  VerifyResult r;
  r.name = name;
  r.source = f;
  // 1. CaDiCaL on the source.
  Stopwatch t0;
  SatResult sat = solve_sat(f);
  r.ms_sat = t0.milliseconds();
  r.sat = sat.status;
  // 2. to-lsat if needed, then each reduction asked for.
  std::optional<LsatReduction> lsat;
  const Lift red = lsat_form(r, opt, lsat);
  Problems p;
  if (r.sat == Verdict::Unknown) p.add("CaDiCaL gave no answer");
  if (opt.models.has(TimeModel::Discrete)) verify_discrete(r, sat, red, opt, sim_, p);
  if (opt.models.has(TimeModel::Continuous)) {
    verify_continuous(r, sat, red, opt, sim_);
    continuous_problems(r, p);
  }
  r.problem = p.text;
  r.agree = p.text.empty();
  return r;
}

VerifyResult verify_formula(const Formula& f, const std::string& name, const VerifyOptions& opt) {
  return Verifier().verify(f, name, opt);
}

MaybeError write_reproducer(const VerifyResult& r, const std::string& dir, const VerifyOptions& opt) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return Diagnostic{dir, 0, "cannot create folder: " + ec.message()};
  MaybeError first;  // the first failure; later writes are skipped
  auto write = [&](const std::string& file, const std::string& text) {
    if (!first) first = write_file_atomic(dir + "/" + file, text);
  };
  write("formula.cnf", to_dimacs(r.source));
  write("lsat.cnf", to_dimacs(r.lsat));
  auto lines = [](const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += x + "\n";
    return s;
  };
  if (r.ran_discrete) {
    std::ostringstream grid;
    write_instance(grid, r.instance(), {"reproducer of a disagreement: " + r.problem});
    write("instance.grid", grid.str());
    write("sat-schedule.txt", lines(r.sat_schedule));
    write("solver-schedule.txt", lines(r.solver_schedule));
  }
  std::string continuous_files;
  if (r.ran_continuous) {
    std::ostringstream grid;
    write_instance(grid, r.compiled_continuous.instance, {"reproducer of a disagreement: " + r.problem});
    write("instance-continuous.grid", grid.str());
    write("sat-times.txt", lines(r.csat_times));
    write("solver-times.txt", lines(r.csolver_times));
    continuous_files =
        "instance-continuous.grid  the instance compiled for continuous time\n"
        "sat-times.txt        CaDiCaL's model lifted to start times (gridlock check instance-continuous.grid "
        "--times sat-times.txt)\n"
        "solver-times.txt     the exact continuous solver's start times\n";
  }
  std::string flags;
  if (opt.models.has(TimeModel::Continuous)) flags += std::string(" --model ") + opt.models.name();
  if (opt.mutation != Mutation::None) flags += std::string(" --break-gadget ") + mutation_name(opt.mutation);
  if (opt.direct) flags += " --direct";
  write(
      "README.txt",
      "gridlock verify found a disagreement on " + r.name + ":\n  " + r.problem +
          "\n\nCaDiCaL: " + verdict_name(r.sat) + "  exact solver: " + verdict_name(r.discrete) +
          "  gap checker: " + verdict_name(r.continuous) +
          (r.ran_continuous ? std::string("  exact continuous solver: ") + verdict_name(r.continuous_solver)
                            : std::string()) +
          "\n\nformula.cnf          the formula\n"
          "lsat.cnf             its LSAT<=3 form (the compiled one)\n" +
          (r.ran_discrete
               ? std::string("instance.grid        the compiled instance\n"
                             "sat-schedule.txt     CaDiCaL's model lifted to a schedule (gridlock check instance.grid "
                             "--order-file sat-schedule.txt)\n"
                             "solver-schedule.txt  the exact solver's schedule\n")
               : std::string()) +
          continuous_files + "run.sh               replays the check\n");
  write("run.sh",
        "#!/bin/sh\n# Replays the disagreement (run from this folder, gridlock on PATH or GRIDLOCK set).\n"
        "exec \"${GRIDLOCK:-gridlock}\" verify formula.cnf" +
            flags + "\n");
  if (first) return first;
  std::filesystem::permissions(dir + "/run.sh", std::filesystem::perms::owner_exec, std::filesystem::perm_options::add,
                               ec);
  return std::nullopt;
}

}  // namespace gridlock
