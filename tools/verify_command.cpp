// gridlock verify: is the reduction right on these formulas? CaDiCaL vs the
// exact discrete solver vs the gap checker, every certificate checked
// (verify/verify.hpp, docs/verify.md).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cnf/dimacs.hpp"
#include "common/limits.hpp"
#include "lattice/render.hpp"
#include "lattice/schedule.hpp"
#include "lattice/simulate.hpp"
#include "reductions/compile.hpp"
#include "tools/animate_page.hpp"
#include "tools/cli_common.hpp"
#include "tools/command.hpp"
#include "tools/options.hpp"
#include "verify/verify.hpp"

namespace gridlock {
namespace {

namespace fs = std::filesystem;

// The formulas named on the command line: files, every *.cnf of a folder
// (sorted), or "-".
std::vector<std::string> expand_inputs(const std::vector<std::string>& inputs) {
  std::vector<std::string> out;
  for (const auto& in : inputs) {
    std::error_code ec;
    if (in != "-" && fs::is_directory(in, ec)) {
      std::vector<std::string> files;
      for (const auto& e : fs::directory_iterator(in, ec))
        if (e.is_regular_file() && e.path().extension() == ".cnf") files.push_back(e.path().string());
      if (ec) throw UserError(Diagnostic{in, 0, "cannot list folder"});
      if (files.empty()) throw UserError(Diagnostic{in, 0, "folder holds no .cnf file"});
      // Natural order, so uf20-2 comes before uf20-10.
      std::sort(files.begin(), files.end(), [](const std::string& a, const std::string& b) {
        return a.size() != b.size() ? a.size() < b.size() : a < b;
      });
      out.insert(out.end(), files.begin(), files.end());
    } else {
      out.push_back(in);
    }
  }
  return out;
}

std::string stem(const std::string& path) { return path == "-" ? "stdin" : fs::path(path).stem().string(); }

std::string fmt_ms(double ms) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(ms < 10 ? 2 : ms < 100 ? 1 : 0) << ms;
  return s.str();
}

std::string sat_word(Verdict t) { return t == Verdict::Yes ? "SAT" : t == Verdict::No ? "UNSAT" : "?"; }

// Pictures of a small compiled instance and of its witness (or, for an
// unsatisfiable formula, of one lifted schedule's collision).
void draw(const VerifyResult& r, const std::string& dir) {
  fs::create_directories(dir);
  const Instance& inst = r.instance();
  const std::string base = dir + "/" + stem(r.name);
  RenderOptions ro;
  ro.title = stem(r.name) + ": " + std::to_string(r.nodes) + " nodes";
  cli::write_text_file(base + ".svg", render_svg(inst, ro));
  const auto& names = !r.solver_schedule.empty() ? r.solver_schedule : r.sat_schedule;
  std::vector<CouplingId> order;
  if (!names.empty()) {
    if (parse_order(inst, names, r.name, 0, order)) return;
  } else {
    // Unsatisfiable: the schedule of the all-false assignment must collide.
    order = schedule_from_assignment(r.compiled, std::vector<bool>(static_cast<size_t>(r.lsat.num_vars) + 1, false));
  }
  Schedule s = schedule_from_order(order);
  Simulator sim(inst);
  SimResult res = sim.run(s);
  RenderOptions wo;
  wo.schedule = &s;
  if (res.collision) {
    wo.time = res.collision->time;
    wo.collision = &*res.collision;
    wo.title = stem(r.name) + ": UNSAT; the all-false schedule collides";
    cli::write_text_file(base + "-collision.svg", render_svg(inst, wo));
    write_animation(base + "-collision.html", inst, s, wo.title);
  } else {
    wo.time = Rational(static_cast<int64_t>(order.size()));
    wo.title = stem(r.name) + ": witness schedule, done";
    cli::write_text_file(base + "-witness.svg", render_svg(inst, wo));
    write_animation(base + "-witness.html", inst, s, stem(r.name) + ": witness schedule");
  }
}

int run_verify(const std::vector<std::string>& args) {
  cli::install_stop_handlers();  // first: a signal at any moment gives the partial summary
  namespace po = boost::program_options;
  po::options_description opts("options");
  opts.add_options()("help,h", "show this help")(
      "model", po::value<std::string>()->default_value("discrete"),
      "which reduction to check: discrete (exact discrete solver and gap checker), continuous (the continuous "
      "reduction and the exact continuous solver) or both")(
      "direct",
      "compile each formula as it is, not its LSAT<=3 form (couplings may exceed 3 operations; keeps small "
      "formulas small, e.g. for the continuous solver)")(
      "timeout", po::value<std::string>()->default_value("60"),
      "seconds the exact solver may spend on one formula (then UNKNOWN)")(
      "max-states", po::value<std::string>()->default_value("0"),
      "search nodes the exact solver may visit per formula (0: no limit)")(
      "reproducers", po::value<std::string>()->default_value("verify-failures"),
      "folder for reproducers of disagreements (one subfolder each)")(
      "pictures", po::value<std::string>(),
      "draw each compiled instance of at most --picture-nodes nodes, and its "
      "witness (or a collision), into this folder")("picture-nodes", po::value<std::string>()->default_value("1500"),
                                                    "largest instance drawn by --pictures")(
      "json", "print one JSON object instead of the table")(
      "shard", po::value<std::string>()->default_value("0/1"),
      "K/N: check only the formulas i (in input order) with i % N == K")(
      "json-out", po::value<std::string>(),
      "also write the JSON object to this file ('gridlock merge' combines shards)");
  po::options_description hidden;
  hidden.add_options()("inputs", po::value<std::vector<std::string>>()->required(), "formulas")(
      "break-gadget", po::value<std::string>()->default_value("none"), "test only: compile with a broken gadget");
  po::positional_options_description pos;
  pos.add("inputs", -1);
  po::variables_map vm;
  if (!cli::parse_args(args, opts, pos, vm, "verify FORMULA.cnf|FOLDER|- ...",
                       "Checks the reduction end to end on each formula: to-lsat if needed, compile, then\n"
                       "  SAT        CaDiCaL on the formula (model checked),\n"
                       "  discrete   the exact solver on the instance (expected: the same answer),\n"
                       "  continuous the gap checker (expected: YES for every compiled instance),\n"
                       "and every certificate: CaDiCaL's model -> schedule -> simulator; the solver's\n"
                       "schedule -> assignment -> formula; 'all at time 0' -> simulator. With --model continuous\n"
                       "(or both): the formula compiled for continuous time, the exact continuous solver on it\n"
                       "(column c-exact, expected: CaDiCaL's answer), CaDiCaL's model -> start times -> simulator,\n"
                       "the solver's start times -> simulator -> assignment -> formula. One row per formula,\n"
                       "then a summary. Exit 0 iff everything agrees (UNKNOWN, a limit hit, is no disagreement);\n"
                       "exit 1 on any disagreement, with a reproducer written for each.\n"
                       "SIGINT/SIGTERM stop after the formula in progress is abandoned: the summary covers the\n"
                       "formulas finished, is marked interrupted, and the exit code is 130/143.",
                       &hidden))
    return 0;
  VerifyOptions opt;
  opt.solve_seconds = cli::seconds_arg(vm, "timeout");
  opt.max_states = cli::count_arg(vm, "max-states", 0);  // 0: no limit
  const auto picture_nodes = static_cast<size_t>(cli::count_arg(vm, "picture-nodes", 1));
  auto mutation = parse_mutation(vm["break-gadget"].as<std::string>());
  if (!mutation) throw UserError("unknown --break-gadget '" + vm["break-gadget"].as<std::string>() + "'");
  opt.mutation = *mutation;
  auto model = parse_verify_model(vm["model"].as<std::string>());
  if (!model)
    throw UserError("--model must be discrete, continuous or both, not '" + vm["model"].as<std::string>() + "'");
  opt.model = *model;
  opt.direct = vm.count("direct") > 0;
  const bool with_discrete = opt.model != VerifyModel::Continuous, with_continuous = opt.model != VerifyModel::Discrete;
  const bool json = vm.count("json") > 0;
  std::vector<std::string> files = expand_inputs(vm["inputs"].as<std::vector<std::string>>());
  uint64_t shard = 0, shards = 1;
  cli::parse_shard(vm["shard"].as<std::string>(), shard, shards);
  // Read everything first: a bad file is reported before any work is done.
  std::vector<Formula> formulas;
  for (const auto& f : files) formulas.push_back(cli::load_formula(f, true, cli::FormulaUse::Compile));

  std::ostream& out = std::cout;
  const int w = 14;
  if (!json) {
    out << std::left << std::setw(w) << "formula" << std::right << std::setw(5) << "vars" << std::setw(8) << "clauses"
        << std::setw(8) << "nodes" << std::setw(7) << "coupl" << std::setw(7) << "SAT" << std::setw(9) << "discrete"
        << std::setw(7) << "contin";
    if (with_continuous) out << std::setw(9) << "c-exact";
    out << std::setw(6) << "wit" << std::setw(10) << "states"
        << "  ms sat/compile/solve/gaps" << (with_continuous ? "/c-solve" : "") << '\n';
  }
  nlohmann::json rows = nlohmann::json::array();
  size_t agree = 0, unknown = 0, disagree = 0, witnesses = 0, sat = 0, unsat = 0;
  double total_ms = 0;
  size_t done = 0;
  for (size_t i = 0; i < files.size() && !stop_requested(); ++i) {
    if (i % shards != shard) continue;
    cli::Activity act(files[i], "verifying the formula");
    VerifyResult r = verify_formula(formulas[i], files[i], opt);
    if (stop_requested()) break;  // its answers may be cut short: not counted
    ++done;
    witnesses += static_cast<size_t>(r.witnesses_checked());
    sat += r.sat == Verdict::Yes;
    unsat += r.sat == Verdict::No;
    total_ms += r.ms_sat + r.ms_compile + r.ms_solve + r.ms_gaps + r.ms_csolve;
    const bool unknown_answer = r.solver_unknown();
    std::string status = r.agree ? (unknown_answer ? "unknown" : "agree") : "DISAGREE";
    if (!r.agree) {
      ++disagree;
      std::string dir = vm["reproducers"].as<std::string>() + "/" + stem(files[i]);
      write_reproducer(r, dir, opt);
      r.problem += " (reproducer: " + dir + ")";
    } else if (unknown_answer) {
      ++unknown;
    } else {
      ++agree;
    }
    if (with_discrete && vm.count("pictures") && r.nodes <= picture_nodes) draw(r, vm["pictures"].as<std::string>());
    if (json || vm.count("json-out")) {
      rows.push_back({{"index", i},
                      {"formula", files[i]},
                      {"variables", r.source.num_vars},
                      {"clauses", r.source.clauses.size()},
                      {"reduced", r.reduced},
                      {"nodes", r.nodes},
                      {"operations", r.ops},
                      {"couplings", r.couplings},
                      {"max_coupling", r.max_coupling},
                      {"sat", verdict_name(r.sat)},
                      {"discrete", verdict_name(r.discrete)},
                      {"continuous", verdict_name(r.continuous)},
                      {"witnesses_checked", r.witnesses_checked()},
                      {"solver_states", r.solver_states},
                      {"ms_sat", r.ms_sat},
                      {"ms_compile", r.ms_compile},
                      {"ms_solve", r.ms_solve},
                      {"ms_gaps", r.ms_gaps},
                      {"status", status},
                      {"problem", r.problem}});
      if (with_continuous) {
        auto& row = rows.back();
        row["continuous_nodes"] = r.cnodes;
        row["continuous_solver"] = verdict_name(r.continuous_solver);
        row["continuous_solver_conflicts"] = r.csolver_conflicts;
        row["ms_continuous_solve"] = r.ms_csolve;
      }
      if (!with_discrete) {
        auto& row = rows.back();
        row["discrete"] = nullptr;
        row["continuous"] = nullptr;
      }
    }
    if (!json) {
      std::string name = stem(files[i]);
      if (name.size() > static_cast<size_t>(w - 1)) name = name.substr(0, static_cast<size_t>(w - 2)) + "~";
      out << std::left << std::setw(w) << name << std::right << std::setw(5) << r.source.num_vars << std::setw(8)
          << r.source.clauses.size() << std::setw(8) << (with_discrete ? r.nodes : r.cnodes) << std::setw(7)
          << r.couplings << std::setw(7) << sat_word(r.sat) << std::setw(9)
          << (with_discrete ? verdict_name(r.discrete) : "-") << std::setw(7)
          << (with_discrete ? verdict_name(r.continuous) : "-");
      if (with_continuous) out << std::setw(9) << verdict_name(r.continuous_solver);
      const int expected = with_discrete * ((r.sat == Verdict::Yes) + (r.discrete == Verdict::Yes) +
                                            (r.continuous == Verdict::Yes)) +
                           with_continuous * ((r.sat == Verdict::Yes) + (r.continuous_solver == Verdict::Yes));
      out << std::setw(6) << (std::to_string(r.witnesses_checked()) + "/" + std::to_string(expected)) << std::setw(10)
          << (with_discrete ? r.solver_states : r.csolver_conflicts) << "  " << fmt_ms(r.ms_sat) << "/"
          << fmt_ms(r.ms_compile) << "/" << fmt_ms(r.ms_solve) << "/" << fmt_ms(r.ms_gaps)
          << (with_continuous ? "/" + fmt_ms(r.ms_csolve) : "") << (r.agree ? "" : "  DISAGREE: " + r.problem)
          << std::endl;
    }
  }
  const bool interrupted = stop_requested();
  std::string summary = std::to_string(done) + " formulas (" + std::to_string(sat) + " SAT, " + std::to_string(unsat) +
                        " UNSAT): " + std::to_string(agree) + " agree, " + std::to_string(unknown) +
                        " unknown (solver limit), " + std::to_string(disagree) + " disagree; " +
                        std::to_string(witnesses) + " certificates checked; " + fmt_ms(total_ms / 1000) + " s";
  if (interrupted)
    summary += "; INTERRUPTED by signal " + std::to_string(stop_signal().load()) + " after " + std::to_string(done) +
               " formulas";
  nlohmann::json j;
  j["command"] = "verify";
  j["model"] = verify_model_name(opt.model);
  j["shard"] = std::to_string(shard) + "/" + std::to_string(shards);
  j["inputs"] = files.size();
  j["formulas"] = rows;
  j["summary"] = {{"formulas", done},
                  {"sat", sat},
                  {"unsat", unsat},
                  {"agree", agree},
                  {"unknown", unknown},
                  {"disagree", disagree},
                  {"certificates_checked", witnesses}};
  j["interrupted"] = interrupted;
  j["exit_code"] = interrupted ? cli::interrupted_exit_code() : disagree ? 1 : 0;
  if (vm.count("json-out")) cli::write_text_file(vm["json-out"].as<std::string>(), j.dump(2) + "\n");
  if (json) {
    out << j.dump() << std::endl;
  } else {
    out << "summary: " << summary << std::endl;
  }
  if (interrupted) return cli::interrupted_exit_code();
  if (disagree) {
    std::cerr << "gridlock: error: verify: " << disagree << " disagreement" << (disagree > 1 ? "s" : "")
              << "; reproducers in " << vm["reproducers"].as<std::string>() << "\n";
    return 1;
  }
  return 0;
}

Command reg{"verify",
            "is the reduction right on these formulas? CaDiCaL vs exact solver vs gap checker, certificates checked",
            run_verify};

}  // namespace
}  // namespace gridlock
