#include "reductions/verify.hpp"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "cnf/dimacs.hpp"
#include "cnf/lsat.hpp"
#include "cnf/sat_solver.hpp"
#include "common/atomic_file.hpp"
#include "lattice/grid_format.hpp"
#include "lattice/simulate.hpp"
#include "reductions/compile.hpp"
#include "reductions/to_lsat.hpp"
#include "solver/gaps.hpp"
#include "solver/solve.hpp"

namespace gridlock {

const char* tri_name(Tri t) { return t == Tri::Yes ? "YES" : t == Tri::No ? "NO" : "UNKNOWN"; }

int VerifyResult::witnesses_checked() const {
  return (sat_witness == Check::Valid) + (solver_witness == Check::Valid) + (gaps_witness == Check::Valid);
}

namespace {

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

std::vector<std::string> names_of(const Instance& inst, const std::vector<CouplingId>& order) {
  std::vector<std::string> out;
  for (CouplingId q : order) out.push_back(inst.couplings()[q].name);
  return out;
}

Tri tri(bool yes) { return yes ? Tri::Yes : Tri::No; }

}  // namespace

VerifyResult verify_formula(const Formula& f, const std::string& name, const VerifyOptions& opt) {
  VerifyResult r;
  r.name = name;
  r.source = f;

  // 1. CaDiCaL on the source.
  auto t0 = std::chrono::steady_clock::now();
  SatResult sat = solve_sat(f);
  r.ms_sat = ms_since(t0);
  r.sat = sat.status == SatResult::Sat ? Tri::Yes : sat.status == SatResult::Unsat ? Tri::No : Tri::Unknown;

  // 2. to-lsat if needed, compile.
  t0 = std::chrono::steady_clock::now();
  LsatReduction red = reduce_to_lsat(f);
  r.reduced = !red.stats().identity;
  r.lsat = red.output();
  r.compiled = compile_formula(r.lsat, opt.mutation);
  const CompiledFormula& c = r.compiled;
  r.ms_compile = ms_since(t0);
  r.nodes = c.stats.nodes;
  r.ops = c.stats.ops;
  r.couplings = c.stats.couplings;
  r.max_coupling = c.stats.max_coupling;
  const Instance& inst = c.instance;
  // The motion tables, built once for every check below (and the simulator's
  // work arrays, reused by its three runs).
  const PreparedInstance prep(inst);
  Simulator sim(prep);

  // Certificate: the SAT model, lifted to a schedule, through the simulator.
  if (r.sat == Tri::Yes) {
    std::vector<CouplingId> order = schedule_from_assignment(c, red.lift_to_target(sat.model));
    r.sat_schedule = names_of(inst, order);
    r.sat_witness = sim.run_order(order).collision ? Check::Invalid : Check::Valid;
  }

  // The exact discrete solver.
  t0 = std::chrono::steady_clock::now();
  SolveOptions so;
  so.seconds = opt.solve_seconds;
  so.max_states = opt.max_states;
  SolveResult sr = solve_discrete(prep, so, &sim);
  r.ms_solve = ms_since(t0);
  r.solver_states = sr.stats.states;
  r.discrete = sr.status == SolveResult::Status::Yes  ? Tri::Yes
               : sr.status == SolveResult::Status::No ? Tri::No
                                                      : Tri::Unknown;
  if (r.discrete == Tri::Yes) {
    r.solver_schedule = names_of(inst, sr.order);
    std::vector<bool> back = red.lift_to_source(assignment_from_schedule(c, sr.order));
    r.solver_witness = satisfies(f, back) ? Check::Valid : Check::Invalid;
  }

  // 3. The gap checker (continuous model), its witness through the simulator.
  t0 = std::chrono::steady_clock::now();
  GapVerdict gv = check_gaps(inst);
  r.ms_gaps = ms_since(t0);
  r.continuous = tri(gv.collision_free);
  if (gv.collision_free) {
    Schedule all_at_once;
    all_at_once.start.assign(inst.couplings().size(), Rational(0));
    r.gaps_witness = sim.run(all_at_once).collision ? Check::Invalid : Check::Valid;
  }

  // Compare.
  std::string p;
  auto problem = [&](const std::string& s) { p += (p.empty() ? "" : "; ") + s; };
  if (r.sat == Tri::Unknown) problem("CaDiCaL gave no answer");
  if (r.discrete != Tri::Unknown && r.sat != Tri::Unknown && r.discrete != r.sat)
    problem(std::string("exact solver says ") + tri_name(r.discrete) + ", CaDiCaL says " +
            (r.sat == Tri::Yes ? "SAT" : "UNSAT"));
  if (r.continuous != Tri::Yes) problem("gap checker says the continuous model collides: " + describe_gap_verdict(inst, gv));
  if (r.sat_witness == Check::Invalid) problem("the SAT model's schedule collides in the simulator");
  if (r.solver_witness == Check::Invalid) problem("the solver's schedule lifts to an assignment that falsifies the formula");
  if (r.gaps_witness == Check::Invalid) problem("running every coupling at time 0 collides in the simulator");
  r.problem = p;
  r.agree = p.empty();
  return r;
}

std::string write_reproducer(const VerifyResult& r, const std::string& dir, const VerifyOptions& opt) {
  std::filesystem::create_directories(dir);
  auto write = [&](const std::string& file, const std::string& text) {
    if (auto err = write_file_atomic(dir + "/" + file, text)) throw std::runtime_error(err->str());
  };
  write("formula.cnf", to_dimacs(r.source));
  write("lsat.cnf", to_dimacs(r.lsat));
  std::ostringstream grid;
  write_instance(grid, r.instance(), {"reproducer of a disagreement: " + r.problem});
  write("instance.grid", grid.str());
  auto lines = [](const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += x + "\n";
    return s;
  };
  write("sat-schedule.txt", lines(r.sat_schedule));
  write("solver-schedule.txt", lines(r.solver_schedule));
  std::string flags;
  if (opt.mutation != Mutation::None) flags += std::string(" --break-gadget ") + mutation_name(opt.mutation);
  write("README.txt", "gridlock verify found a disagreement on " + r.name + ":\n  " + r.problem +
                          "\n\nCaDiCaL: " + tri_name(r.sat) + "  exact solver: " + tri_name(r.discrete) +
                          "  gap checker: " + tri_name(r.continuous) +
                          "\n\nformula.cnf          the formula\n"
                          "lsat.cnf             its LSAT<=3 form (the compiled one)\n"
                          "instance.grid        the compiled instance\n"
                          "sat-schedule.txt     CaDiCaL's model lifted to a schedule (gridlock check instance.grid "
                          "--order-file sat-schedule.txt)\n"
                          "solver-schedule.txt  the exact solver's schedule\n"
                          "run.sh               replays the check\n");
  write("run.sh", "#!/bin/sh\n# Replays the disagreement (run from this folder, gridlock on PATH or GRIDLOCK set).\n"
                  "exec \"${GRIDLOCK:-gridlock}\" verify formula.cnf" +
                      flags + "\n");
  std::filesystem::permissions(dir + "/run.sh", std::filesystem::perms::owner_exec, std::filesystem::perm_options::add);
  return dir;
}

}  // namespace gridlock
