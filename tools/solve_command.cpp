// gridlock solve: the exact Collision-free Schedule solvers, discrete
// (solver/solve.hpp, the default) and continuous (solver/continuous.hpp).
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <optional>

#include "common/limits.hpp"
#include "solver/continuous.hpp"
#include "solver/no_certificate.hpp"
#include "solver/solve.hpp"
#include "tools/cli_common.hpp"
#include "tools/command.hpp"
#include "tools/options.hpp"
#include "tools/output.hpp"
#include "tools/progress_line.hpp"
#include "tools/user_error.hpp"

namespace gridlock {
namespace {

std::string fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

nlohmann::json stats_json(const SolveStats& st) {
  return {{"states", st.states},           {"refuted", st.refuted},       {"propagations", st.propagations},
          {"decisions", st.decisions},     {"safe_moves", st.safe_moves}, {"memo_hits", st.memo_hits},
          {"constraints", st.constraints}, {"seconds", st.seconds}};
}

// --certificate C: writes the certificate of a NO (atomically), or says why there is none.
void write_certificate(Answer& ans, const std::string& cert_path, const std::string& text, const std::string& why) {
  if (cert_path.empty()) return;
  if (text.empty()) {
    ans.comment("no certificate written: " + why + "; " + cli::certificate_left(cert_path));
    return;
  }
  cli::write_text_file(cert_path, text);
  ans.comment("certificate written to " + cert_path + " ('gridlock certify' checks it)");
  ans.data()["certificate"] = cert_path;
}

// A lone collider (both models): the comment that names it and its JSON field.
// constraints_kind says what the builder had made when it stopped.
void report_lone_collider(Answer& ans, const Instance& inst, CouplingId q, const std::string& pair, size_t constraints,
                          const std::string& constraints_kind) {
  ans.comment("coupling " + inst.couplings()[q].name + " alone moves " + pair +
              " against each other: they collide whenever it runs");
  ans.comment("found after " + std::to_string(constraints) + " " + constraints_kind + "; no search needed");
  ans.data()["lone_collider"] = {{"coupling", inst.couplings()[q].name}, {"pair", pair}};
}

int run_continuous(const std::string& path, const Instance& inst, const SolveOptions& opt, ContinuousEngine engine,
                   bool json, const std::string& cert_path) {
  Answer ans("solve", json);
  ans.witness_one_per_line();
  ans.comment("gridlock solve --model continuous " + path + ": " + std::to_string(inst.num_nodes()) + " nodes, " +
              std::to_string(inst.ops().size()) + " operations, " + std::to_string(inst.couplings().size()) +
              " couplings" + (inst.horizontal_only() ? ", horizontal-only" : ""));
  CertifiedContinuous cc;
  if (cert_path.empty()) cc.result = solve_continuous(inst, opt, engine);
  else cc = solve_continuous_certified(inst, opt, engine);
  const ContinuousResult& r = cc.result;
  const SolveStats& st = r.stats;
  if (st.engine == "gaps") {
    ans.comment("horizontal-only: linear gap check (" + std::to_string(st.constraints) + " gaps and cycles)");
  } else if (r.lone_collider != kNone) {
    report_lone_collider(ans, inst, r.lone_collider, r.lone_pair, st.constraints, "pair and cycle constraints");
  } else {
    ans.comment("engine " + st.engine + " on " + std::to_string(st.constraints) + " pair and cycle constraints");
    ans.comment("components settled by a cheap test " + std::to_string(st.safe_moves) + ", searched " +
                std::to_string(st.states) + ", decisions " + std::to_string(st.decisions) + ", conflicts " +
                std::to_string(st.refuted) + ", learned " + std::to_string(st.propagations));
  }
  ans.comment("time " + fixed(st.seconds, 3) + " s");
  if (r.status == Verdict::Yes) ans.comment("start times checked by the simulator: collision-free");
  if (r.status == Verdict::Unknown) ans.comment("limit reached before an answer");
  if (r.status == Verdict::No) write_certificate(ans, cert_path, cc.certificate, cc.why_none);
  else if (!cert_path.empty()) ans.comment(cli::certificate_not_written(cert_path, r.status == Verdict::Yes));
  if (r.status == Verdict::Yes)
    for (CouplingId q = 0; q < inst.couplings().size(); ++q)
      ans.witness(inst.couplings()[q].name + " " + r.schedule.start[q].str());
  nlohmann::json& d = ans.data();
  d["model"] = "continuous";
  d["engine"] = st.engine;
  d["stats"] = stats_json(st);
  return ans.finish(r.status);
}

// The discrete solver on inst (--engine engine_name, already in opt).
int run_discrete(const std::string& path, const Instance& inst, const SolveOptions& opt, const std::string& engine_name,
                 bool json, const std::string& cert_path) {
  if ((opt.engine == SolveOptions::Engine::Precedence || opt.engine == SolveOptions::Engine::Sat) &&
      !inst.horizontal_only())
    throw UserError(path + ": --engine " + engine_name + " needs a horizontal-only instance");
  Answer ans("solve", json);
  ans.comment("gridlock solve " + path + ": " + std::to_string(inst.num_nodes()) + " nodes, " +
              std::to_string(inst.ops().size()) + " operations, " + std::to_string(inst.couplings().size()) +
              " couplings" + (inst.horizontal_only() ? ", horizontal-only" : ""));
  CertifiedSolve cs;
  if (cert_path.empty()) {
    cs.result = solve_discrete(inst, opt);
  } else {
    const PreparedInstance prep(inst);
    cs = solve_discrete_certified(prep, opt);
  }
  const SolveResult& r = cs.result;
  const SolveStats& st = r.stats;
  if (r.cycle_breaker != kNone) {
    ans.comment("coupling " + inst.couplings()[r.cycle_breaker].name +
                " moves the shape unevenly around a cycle: it collides whenever it runs");
  } else if (r.lone_collider != kNone) {
    report_lone_collider(ans, inst, r.lone_collider, r.lone_pair, st.constraints, "collision constraints");
  } else {
    ans.comment("search " + st.engine + " on " + std::to_string(st.constraints) + " collision constraints");
    ans.comment("states " + std::to_string(st.states) + ", refuted " + std::to_string(st.refuted) + ", decisions " +
                std::to_string(st.decisions) + ", safe moves " + std::to_string(st.safe_moves) + ", propagations " +
                std::to_string(st.propagations) + ", memo hits " + std::to_string(st.memo_hits));
  }
  ans.comment("time " + fixed(st.seconds, 3) + " s");
  if (r.status == Verdict::Yes) ans.comment("order checked by the simulator: collision-free");
  if (r.status == Verdict::Unknown) ans.comment("limit reached before an answer");
  if (r.status == Verdict::No) write_certificate(ans, cert_path, cs.certificate, cs.why_none);
  else if (!cert_path.empty()) ans.comment(cli::certificate_not_written(cert_path, r.status == Verdict::Yes));
  for (CouplingId q : r.order) ans.witness(inst.couplings()[q].name);
  nlohmann::json& d = ans.data();
  d["engine"] = st.engine;
  d["model"] = "discrete";
  d["stats"] = stats_json(st);
  if (r.cycle_breaker != kNone) d["cycle_breaker"] = inst.couplings()[r.cycle_breaker].name;
  return ans.finish(r.status);
}

namespace po = boost::program_options;

po::options_description solve_options() {
  po::options_description opts("options");
  opts.add_options()("help,h", "show this help")("timeout", po::value<std::string>(),
                                                 "give up after S seconds (s UNKNOWN, exit 0)")(
      "max-states", po::value<std::string>(), "give up after N search nodes (s UNKNOWN, exit 0)")(
      "model", po::value<std::string>()->default_value("discrete"),
      "discrete (one coupling at a time, an order) or continuous (start times, couplings may overlap)")(
      "engine", po::value<std::string>()->default_value("auto"),
      "search: auto (sat for horizontal-only instances, else pairs), states, precedence, sat, pairs; "
      "continuous: auto or dl (the learning engine in Z3's difference logic), sat (its lazy "
      "CaDiCaL loop), z3 (Z3 on the clamped encoding)")("json", "print one JSON object instead of c/s/v lines")(
      "certificate", po::value<std::string>(),
      "with a NO, write a certificate to FILE that 'gridlock certify' checks (docs/certificates.md)");
  return opts;
}

const char* const kSolveDescription =
    "Collision-free Schedule, exactly. Discrete (default): is there an order of the couplings,\n"
    "run one at a time, with no collision? s YES (exit 10) with the order as v lines (checked by\n"
    "the simulator; 'gridlock check --order-file' reads it back), s NO (exit 20) after an\n"
    "exhaustive search, s UNKNOWN (exit 0) when a limit is reached.\n"
    "Continuous (--model continuous): are there start times (couplings may overlap) with no\n"
    "collision? s YES with lines 'v NAME TIME' (exact rationals, checked by the simulator;\n"
    "'gridlock check --times' reads them back), s NO only when proved (Z3, exact), s UNKNOWN on\n"
    "a limit (--max-states bounds Z3's conflicts).";

bool model_is_discrete(const po::variables_map& vm) { return vm["model"].as<std::string>() != "continuous"; }

SolveOptions::Engine engine_arg(const std::string& engine) {
  if (engine == "auto") return SolveOptions::Engine::Auto;
  if (engine == "states") return SolveOptions::Engine::States;
  if (engine == "precedence") return SolveOptions::Engine::Precedence;
  if (engine == "sat") return SolveOptions::Engine::Sat;
  if (engine == "pairs") return SolveOptions::Engine::Pairs;
  throw UserError("--engine must be auto, states, precedence, sat or pairs, not '" + engine + "'");
}

int run_solve(const std::vector<std::string>& args) {
  const Deadline since_start;  // --timeout counts from here: reading the instance is part of it
  po::options_description opts = solve_options();
  po::variables_map vm;
  if (!cli::parse_args_one_input(
          args, opts, "instance", vm,
          "solve INSTANCE.grid [--model discrete|continuous] [--timeout S] [--max-states N] [--json]",
          kSolveDescription))
    return 0;
  SolveOptions opt;
  opt.seconds = cli::seconds_arg_opt(vm, "timeout").value_or(0);
  opt.max_states = cli::count_arg_opt(vm, "max-states").value_or(0);
  cli::ProgressLine progress(!vm.count("json"));  // drawn only on a terminal; outlives every solve below
  opt.on_progress = cli::solve_progress_to(progress);
  const std::string engine = vm["engine"].as<std::string>();
  if (model_is_discrete(vm)) opt.engine = engine_arg(engine);

  const std::string model = vm["model"].as<std::string>();
  if (model != "discrete" && model != "continuous")
    throw UserError("--model must be discrete or continuous, not '" + model + "'");
  ContinuousEngine cont_engine = ContinuousEngine::Auto;
  if (model == "continuous") {
    const std::optional<ContinuousEngine> named = continuous_engine_named(engine);
    if (!named)
      throw UserError(std::string("--engine with --model continuous must be ") + kContinuousEngineNames + ", not '" +
                      engine + "'");
    cont_engine = *named;
  }

  const std::string path = vm["instance"].as<std::string>();
  // Kept until the process ends (reachable, so no leak report): freeing an
  // instance of a million nodes takes a noticeable part of a short --timeout.
  // volatile: the store must stay, or the optimiser drops it and
  // LeakSanitizer sees the instance as leaked.
  static Instance* volatile kept = nullptr;
  kept = new Instance(cli::load_instance(path));
  const Instance& inst = *kept;
  cli::Activity act(path, "solving the instance");
  if (opt.seconds > 0) opt.seconds = std::max(opt.seconds - since_start.elapsed(), 1e-6);
  const std::string cert_path = vm.count("certificate") ? vm["certificate"].as<std::string>() : "";
  if (!cert_path.empty()) cli::refuse_overwriting_input(cert_path, {path});
  if (model == "continuous") return run_continuous(path, inst, opt, cont_engine, vm.count("json") > 0, cert_path);
  return run_discrete(path, inst, opt, engine, vm.count("json") > 0, cert_path);
}

Command reg{"solve", "decide Collision-free Schedule exactly, discrete or continuous (any instance)", run_solve};

}  // namespace
}  // namespace gridlock
