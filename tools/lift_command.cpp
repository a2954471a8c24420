// gridlock lift: the reduction's certificates, both ways (reductions/compile.hpp).
//   --model M     satisfying assignment -> collision-free schedule, checked by the simulator
//   --schedule S  collision-free schedule -> satisfying assignment, checked against the formula
//   --continuous  the same for the continuous reduction: start times instead of an order
//   --times T     collision-free start times -> satisfying assignment (continuous)
#include <stdexcept>

#include "cnf/assignment.hpp"
#include "lattice/schedule.hpp"
#include "lattice/simulate.hpp"
#include "reductions/compile.hpp"
#include "tools/cli_common.hpp"
#include "tools/command.hpp"
#include "tools/output.hpp"
#include "tools/user_error.hpp"

namespace gridlock {
namespace {

namespace po = boost::program_options;

po::options_description lift_options() {
  po::options_description opts("options");
  opts.add_options()("help,h", "show this help")(
      "model", po::value<std::string>(),
      "an assignment: a file holding a SAT-competition answer ('s SATISFIABLE' and "
      "'v' lines ending in 0, as 'gridlock cnf solve' prints), or the literals "
      "themselves (\"1 -2 3\"), every variable given: lift it to a schedule")(
      "schedule", po::value<std::string>(),
      "a discrete order of the couplings (e.g. 'gridlock solve' output): "
      "lift it to an assignment")("continuous",
                                  "the continuous reduction (compile --model continuous): --model gives start times")(
      "times", po::value<std::string>(),
      "start times of the continuous instance ('NAME TIME' lines, e.g. 'gridlock "
      "solve --model continuous' output): lift them to an assignment")("json",
                                                                       "print one JSON object instead of c/s/v lines");
  return opts;
}

const char* const kLiftDescription =
    "The certificates of the reduction, each checked by an independent path. The formula is\n"
    "compiled exactly as 'gridlock compile' does.\n"
    "  --model M: the schedule x_i:T/F (by M), y_1..y_n, z_1..z_n, u_1..u_m, then the other\n"
    "    values; run through the exact simulator: s YES (10) with the order on v lines if it\n"
    "    is collision-free, s NO (20) with the collision otherwise (M does not satisfy F).\n"
    "  --schedule S: simulated first (it must be collision-free), then x_i = [x_i:T before x_i:F];\n"
    "    s YES (10) with the assignment on v lines if it satisfies F, s NO (20) otherwise.\n"
    "  --continuous: compile for continuous time; --model M then gives start times (the value of\n"
    "    each x_i at 0, every y_i at 1, the rest at 2), as 'NAME TIME' v lines.\n"
    "  --times T: start times of the continuous instance, simulated first, then\n"
    "    x_i = [t(x_i:T) <= t(y_n)]; checked against F as for --schedule.";

// --model: the assignment in model_arg -> a schedule, run by the simulator.
int lift_assignment(Answer& ans, const Formula& f, const CompiledFormula& c, const std::string& model_arg) {
  const Instance& inst = c.instance;
  const bool continuous = c.model == TimeModel::Continuous;
  std::vector<bool> value;
  if (auto e = read_model(model_arg, f.num_vars, value)) throw UserError(*e);
  long bad = first_falsified_clause(f, value);
  ans.comment(bad < 0 ? "the model satisfies the formula"
                      : "the model falsifies clause " + std::to_string(bad + 1) + ": expect a collision");
  std::vector<CouplingId> order;
  Schedule sched;
  if (continuous) {
    sched = times_from_assignment(c, value);
  } else {
    order = schedule_from_assignment(c, value);
    sched = schedule_from_order(order);
  }
  Simulator sim(inst);
  SimResult r = sim.run(sched);
  if (r.collision) {
    ans.comment("simulator: " + describe(inst, sim.regions(), *r.collision));
    ans.data()["collision"] = describe(inst, sim.regions(), *r.collision);
    return ans.finish(Verdict::No);
  }
  ans.comment("simulator: the schedule is collision-free");
  if (continuous) {
    ans.witness_one_per_line();
    for (CouplingId q = 0; q < inst.couplings().size(); ++q)
      ans.witness(inst.couplings()[q].name + " " + sched.start[q].str());
  } else {
    for (CouplingId q : order) ans.witness(inst.couplings()[q].name);
  }
  return ans.finish(Verdict::Yes);
}

// --schedule / --times: a schedule, run by the simulator -> an assignment,
// checked against the formula.
int lift_schedule(Answer& ans, const Formula& f, const CompiledFormula& c, const po::variables_map& vm) {
  const Instance& inst = c.instance;
  const bool continuous = c.model == TimeModel::Continuous;
  Schedule sched;
  if (continuous) {
    if (auto e = read_times_file(inst, vm["times"].as<std::string>(), sched)) throw UserError(*e);
  } else {
    std::vector<CouplingId> order;
    if (auto e = read_order_file(inst, vm["schedule"].as<std::string>(), order)) throw UserError(*e);
    sched = schedule_from_order(order);
  }
  Simulator sim(inst);
  SimResult r = sim.run(sched);
  if (r.collision) {
    ans.comment("simulator: the schedule collides: " + describe(inst, sim.regions(), *r.collision));
    return ans.finish(Verdict::No);
  }
  ans.comment("simulator: the schedule is collision-free");
  std::vector<bool> value = continuous ? assignment_from_times(c, sched) : assignment_from_schedule(c, sched.order);
  long bad = first_falsified_clause(f, value);
  if (bad >= 0) {
    ans.comment("the lifted assignment falsifies clause " + std::to_string(bad + 1) +
                ": a collision-free schedule of an unsatisfied formula, the reduction is wrong here");
    return ans.finish(Verdict::No);
  }
  ans.comment("the lifted assignment satisfies the formula");
  for (int lit : model_literals(value, f.num_vars)) ans.witness(std::to_string(lit));
  ans.witness("0");
  return ans.finish(Verdict::Yes);
}

int run_lift(const std::vector<std::string>& args) {
  po::options_description opts = lift_options();
  po::variables_map vm;
  if (!cli::parse_args_one_input(args, opts, "formula", vm,
                                 "lift FORMULA.cnf (--model M [--continuous] | --schedule S | --times T)",
                                 kLiftDescription))
    return 0;
  if (vm.count("model") + vm.count("schedule") + vm.count("times") != 1)
    throw UserError("give exactly one of --model, --schedule, --times");
  if (vm.count("schedule") && vm.count("continuous"))
    throw UserError("--schedule is a discrete order; use --times for the continuous instance");
  const bool continuous = vm.count("continuous") || vm.count("times");
  const std::string path = vm["formula"].as<std::string>();
  Formula f = cli::load_formula(path, true, cli::FormulaUse::CompileAsIs);
  cli::Activity act(path, "compiling the formula");
  CompiledFormula c;
  try {
    c = compile_formula(f, Mutation::None, continuous ? TimeModel::Continuous : TimeModel::Discrete);
  } catch (const std::invalid_argument& e) {
    throw UserError(Diagnostic{path, 0, e.what()});
  }
  const Instance& inst = c.instance;
  Answer ans("lift", vm.count("json") > 0);
  ans.comment("gridlock lift " + path + ": " + summary(f) + "; " + time_model_name(c.model) + " instance of " +
              std::to_string(inst.num_nodes()) + " nodes, " + std::to_string(inst.couplings().size()) + " couplings");
  if (vm.count("model")) return lift_assignment(ans, f, c, vm["model"].as<std::string>());
  return lift_schedule(ans, f, c, vm);
}

Command reg{"lift", "certificates of the reduction: assignment -> schedule, schedule -> assignment (both checked)",
            run_lift};

}  // namespace
}  // namespace gridlock
