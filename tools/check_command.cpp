// gridlock check: run one schedule through the exact simulator.
#include <algorithm>
#include <sstream>

#include "common/limits.hpp"
#include "lattice/schedule.hpp"
#include "lattice/simulate.hpp"
#include "render/picture.hpp"
#include "tools/cli_common.hpp"
#include "tools/command.hpp"
#include "tools/options.hpp"
#include "tools/output.hpp"
#include "tools/user_error.hpp"

namespace gridlock {
namespace {

int run_check(const std::vector<std::string>& args) {
  const Deadline since_start;  // --timeout counts from here: reading the instance is part of it
  namespace po = boost::program_options;
  po::options_description opts("options");
  opts.add_options()("help,h", "show this help")("order", po::value<std::string>(),
                                                 "discrete schedule: all coupling names in order, e.g. \"Q3 Q1 Q2\"")(
      "order-file", po::value<std::string>(),
      "discrete schedule from a file (whitespace-separated names; "
      "'v' lines of 'gridlock solve' output work)")(
      "times", po::value<std::string>(), "continuous schedule: a file of lines 'COUPLING TIME' (TIME like 3 or 5/2)")(
      "svg", po::value<std::string>(), "draw the configuration at the collision (or at the end) to this SVG file")(
      "timeout", po::value<std::string>(), "give up after S seconds, reading included (s UNKNOWN, exit 0)")(
      "json", "print one JSON object instead of c/s/v lines");
  po::variables_map vm;
  if (!cli::parse_args_one_input(
          args, opts, "instance", vm,
          "check INSTANCE.grid (--order \"Q...\" | --order-file F | --times F) [--svg OUT.svg]",
          "Runs one schedule and answers: is it collision-free? s YES (exit 10) or s NO (exit 20)\n"
          "with the first collision: its exact moment, kind, the two nodes (or the cycle) and\n"
          "the couplings moving then. s UNKNOWN (exit 0): --timeout reached first."))
    return 0;
  int given = static_cast<int>(vm.count("order") + vm.count("order-file") + vm.count("times"));
  if (given != 1) throw UserError("give exactly one of --order, --order-file, --times");
  const std::string path = vm["instance"].as<std::string>();
  if (vm.count("svg")) cli::refuse_overwriting_input(vm["svg"].as<std::string>(), {path});
  const double seconds = cli::seconds_arg_opt(vm, "timeout").value_or(0);
  Instance inst = cli::load_instance(path);
  cli::Activity act(path, "checking the schedule");              // out of memory names the file
  const Schedule sched = *cli::schedule_from_options(vm, inst);  // exactly one was given
  const std::string model = vm.count("times") ? "continuous" : "discrete";
  Answer ans("check", vm.count("json") > 0);
  ans.comment("gridlock check " + path + ": " + std::to_string(inst.num_nodes()) + " nodes, " +
              std::to_string(inst.edges().size()) + " edges, " + std::to_string(inst.ops().size()) + " operations, " +
              std::to_string(inst.couplings().size()) + " couplings; " + model + " schedule");
  Simulator sim(inst);
  const Deadline deadline(seconds > 0 ? std::max(seconds - since_start.elapsed(), 1e-6) : 0);
  if (seconds > 0) sim.set_deadline(&deadline);
  SimResult res;
  try {
    res = sim.run(sched);
  } catch (const LimitReached&) {
    ans.comment("limit reached before an answer (--timeout " + vm["timeout"].as<std::string>() + ")");
    ans.data()["model"] = model;
    return ans.finish(Verdict::Unknown);
  }
  ans.comment("simulated " + std::to_string(res.stats.intervals) + " intervals, " +
              std::to_string(res.stats.moved_regions) + " region moves, " + std::to_string(res.stats.candidate_pairs) +
              " candidate pairs");
  ans.data()["model"] = model;
  Rational draw_time;
  for (const auto& t : sched.start) draw_time = std::max(draw_time, t + Rational(1));
  if (res.collision) {
    const Collision& c = *res.collision;
    ans.comment(describe(inst, sim.regions(), c));
    std::string moving;
    for (CouplingId q : c.moving) moving += " " + inst.couplings()[q].name;
    ans.comment("moving then:" + moving);
    ans.data()["collision"] = collision_json(inst, sim.regions(), c);
  }
  if (vm.count("svg") && res.collision) {
    write_collision_svg(vm["svg"].as<std::string>(), inst, sched, *res.collision);
    ans.comment("wrote " + vm["svg"].as<std::string>() + " (configuration during the collision)");
  } else if (vm.count("svg")) {
    RenderOptions ro;
    ro.schedule = &sched;
    ro.time = draw_time;
    cli::write_text_file(vm["svg"].as<std::string>(), render_svg(inst, ro));
    ans.comment("wrote " + vm["svg"].as<std::string>() + " (configuration at time " + draw_time.str() + ")");
  }
  return ans.finish(res.collision ? Verdict::No : Verdict::Yes);
}

Command reg{"check", "run one schedule (discrete order or continuous start times) through the exact simulator",
            run_check};

}  // namespace
}  // namespace gridlock
