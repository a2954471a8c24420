// gridlock animate: a self-contained HTML page that plays a schedule
// (render/animation_page.hpp, lattice/animation.hpp).
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>

#include "lattice/animation.hpp"
#include "lattice/schedule.hpp"
#include "solver/solve.hpp"
#include "tools/animation_files.hpp"
#include "tools/cli_common.hpp"
#include "tools/command.hpp"
#include "tools/options.hpp"
#include "tools/progress_line.hpp"
#include "tools/user_error.hpp"

namespace gridlock {
namespace {

int run_animate(const std::vector<std::string>& args) {
  namespace po = boost::program_options;
  po::options_description opts("options");
  opts.add_options()("help,h", "show this help")("order", po::value<std::string>(),
                                                 "discrete schedule: all coupling names in order, e.g. \"Q3 Q1 Q2\"")(
      "order-file", po::value<std::string>(), "discrete schedule from a file ('v' lines of 'gridlock solve' work)")(
      "times", po::value<std::string>(), "continuous schedule: a file of lines 'COUPLING TIME' (TIME like 3 or 5/2)")(
      "solve", "play the exact solver's collision-free order (if it finds none: the couplings in file order)")(
      "timeout", po::value<std::string>()->default_value("60"), "seconds the solver may spend with --solve")(
      "out,o", po::value<std::string>()->required(), "the HTML file to write")(
      "title", po::value<std::string>(), "title shown on the page (default: the instance and the schedule)");
  po::variables_map vm;
  if (!cli::parse_args_one_input(
          args, opts, "instance", vm,
          "animate INSTANCE.grid (--order \"Q...\" | --order-file F | --times F | --solve) -o VIEW.html",
          "Writes one self-contained HTML file (no network) that plays the schedule: play/pause,\n"
          "a time slider, previous/next event, speed; the running couplings highlighted and\n"
          "listed; the first collision marked, the overlap shaded, the player stopping there;\n"
          "hovering a node names it. Positions are exact: the page gets the event times and each\n"
          "rigid part's displacement at its events from the simulator and interpolates linearly\n"
          "in between. The fragment #t=P/Q opens the page at time P/Q."))
    return 0;
  int given = static_cast<int>(vm.count("order") + vm.count("order-file") + vm.count("times") + vm.count("solve"));
  if (given != 1) throw UserError("give exactly one of --order, --order-file, --times, --solve");
  if (!vm.count("solve") && !vm["timeout"].defaulted()) throw UserError("--timeout applies to --solve only");
  const std::string path = vm["instance"].as<std::string>();
  const std::string out = vm["out"].as<std::string>();
  cli::refuse_overwriting_input(out, {path});
  const double timeout = cli::seconds_arg(vm, "timeout");
  Instance inst = cli::load_instance(path);
  cli::Activity act(path, "animating the schedule");  // out of memory names the file
  std::string what = vm.count("times")        ? "start times " + vm["times"].as<std::string>()
                     : vm.count("order-file") ? "order " + vm["order-file"].as<std::string>()
                                              : "the given order";
  std::optional<Schedule> given_schedule = cli::schedule_from_options(vm, inst);
  Schedule sched;
  if (given_schedule) {
    sched = std::move(*given_schedule);
  } else {  // --solve
    SolveOptions so;
    so.seconds = timeout;
    cli::ProgressLine line(true);  // drawn only on a terminal; erased at the solver's last report
    so.on_progress = cli::solve_progress_to(line);
    SolveResult r = solve_discrete(inst, so);
    std::vector<CouplingId> order;
    if (r.status == Verdict::Yes) {
      order = r.order;
      what = "the solver's collision-free order";
    } else {
      for (CouplingId q = 0; q < inst.couplings().size(); ++q) order.push_back(q);
      what = std::string("the couplings in file order (the solver answered ") + verdict_name(r.status) + ")";
    }
    sched = schedule_from_order(order);
  }
  std::string title = vm.count("title") ? vm["title"].as<std::string>()
                                        : std::filesystem::path(path).filename().string() + ": " + what;
  Animation a = write_animation(out, inst, sched, title);
  std::cout << "c gridlock animate " << path << ": " << inst.num_nodes() << " nodes, " << inst.couplings().size()
            << " couplings; " << what << "\n";
  std::cout << "c " << a.events.size() << " events, " << a.parts.size() << " rigid parts, " << a.keyframes()
            << " keyframes\n";
  if (a.collision) {
    std::cout << "c first collision at time " << a.collision->time.str() << "; the player stops at " << a.stop.str()
              << "\n";
  } else {
    std::cout << "c collision-free; the player stops at " << a.stop.str() << "\n";
  }
  std::cout << "c wrote " << out << std::endl;
  return 0;
}

Command reg{"animate", "write a self-contained HTML page that plays a schedule (exact positions, collision marked)",
            run_animate};

}  // namespace
}  // namespace gridlock
