// gridlock verify: is the reduction right on these formulas? CaDiCaL vs the
// exact discrete solver vs the gap checker, every certificate checked
// (verify/verify.hpp, docs/verify.md). The loop over the formulas and its
// tally are verify/campaign.hpp's run_verify_campaign; this file reads the
// options, prints the table, the JSON and the pictures, and sets the exit code.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "cnf/dimacs.hpp"
#include "common/limits.hpp"
#include "lattice/schedule.hpp"
#include "lattice/simulate.hpp"
#include "reductions/compile.hpp"
#include "render/picture.hpp"
#include "tools/animation_files.hpp"
#include "tools/campaign_cli.hpp"
#include "tools/cli_common.hpp"
#include "tools/command.hpp"
#include "tools/options.hpp"
#include "tools/run_identity.hpp"
#include "tools/set_folder.hpp"
#include "tools/user_error.hpp"
#include "verify/campaign.hpp"
#include "verify/verify.hpp"

namespace gridlock {
namespace {

namespace fs = std::filesystem;
namespace po = boost::program_options;

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
  const std::string base = dir + "/" + formula_stem(r.name);
  RenderOptions ro;
  ro.title = formula_stem(r.name) + ": " + std::to_string(r.nodes) + " nodes";
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
    wo.title = formula_stem(r.name) + ": UNSAT; the all-false schedule collides";
    cli::write_text_file(base + "-collision.svg", render_svg(inst, wo));
    write_animation(base + "-collision.html", inst, s, wo.title);
  } else {
    wo.time = Rational(static_cast<int64_t>(order.size()));
    wo.title = formula_stem(r.name) + ": witness schedule, done";
    cli::write_text_file(base + "-witness.svg", render_svg(inst, wo));
    write_animation(base + "-witness.html", inst, s, formula_stem(r.name) + ": witness schedule");
  }
}

po::options_description verify_options() {
  po::options_description opts("options");
  opts.add_options()("help,h", "show this help")(
      "model", po::value<std::string>()->default_value("discrete"),
      "which reduction to check: discrete (exact discrete solver and gap checker), continuous (the continuous "
      "reduction and the exact continuous solver) or both")(
      "direct",
      "compile each formula as it is, not its LSAT<=3 form (couplings may exceed 3 operations; keeps small "
      "formulas small, e.g. for the continuous solver)")(
      "no-certificates", "do not write and check a NO certificate for each NO (docs/certificates.md)")(
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
  cli::add_jobs_option(opts);
  return opts;
}

const char* const kVerifyDescription =
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
    "formulas finished, is marked interrupted, and the exit code is 130/143.\n"
    "--jobs N checks N formulas at once (default: every core); rows stay in input order and the\n"
    "output is the same for every N.";

// What the table and the JSON rows show, besides the results.
struct VerifyView {
  bool with_discrete = true, with_continuous = false;
  bool json = false, rows = false;  // print JSON; collect rows (for --json or --json-out)
  std::optional<std::string> pictures;
  size_t picture_nodes = 0;
};

constexpr int kNameWidth = 14;

void print_table_header(std::ostream& out, const VerifyView& v) {
  const int w = kNameWidth;
  out << std::left << std::setw(w) << "formula" << std::right << std::setw(5) << "vars" << std::setw(8) << "clauses"
      << std::setw(8) << "nodes" << std::setw(7) << "coupl" << std::setw(7) << "SAT" << std::setw(9) << "discrete"
      << std::setw(7) << "contin";
  if (v.with_continuous) out << std::setw(9) << "c-exact";
  out << std::setw(6) << "wit" << std::setw(6) << "cert" << std::setw(10) << "states"
      << "  ms sat/compile/solve/gaps" << (v.with_continuous ? "/c-solve" : "") << '\n';
}

void print_table_row(std::ostream& out, const VerifyView& v, const std::string& file, const VerifyResult& r) {
  const int w = kNameWidth;
  const bool d = v.with_discrete, c = v.with_continuous;
  std::string name = formula_stem(file);
  if (name.size() > static_cast<size_t>(w - 1)) name = name.substr(0, static_cast<size_t>(w - 2)) + "~";
  out << std::left << std::setw(w) << name << std::right << std::setw(5) << r.source.num_vars << std::setw(8)
      << r.source.clauses.size() << std::setw(8) << (d ? r.nodes : r.cnodes) << std::setw(7) << r.couplings
      << std::setw(7) << sat_word(r.sat) << std::setw(9) << (d ? verdict_name(r.discrete) : "-") << std::setw(7)
      << (d ? verdict_name(r.continuous) : "-");
  if (c) out << std::setw(9) << verdict_name(r.continuous_solver);
  const bool certified = r.no_certificate != Check::None, ccertified = r.cno_certificate != Check::None;
  const int expected = d * ((r.sat == Verdict::Yes) + (r.discrete == Verdict::Yes) + (r.continuous == Verdict::Yes) +
                            certified) +
                       c * ((r.sat == Verdict::Yes) + (r.continuous_solver == Verdict::Yes) + ccertified);
  // Both NO certificates in one column: BAD if either is rejected.
  const bool bad = r.no_certificate == Check::Invalid || r.cno_certificate == Check::Invalid;
  const bool ok = r.no_certificate == Check::Valid || r.cno_certificate == Check::Valid;
  const char* cert = bad ? "BAD" : ok ? "ok" : "-";
  out << std::setw(6) << (std::to_string(r.witnesses_checked()) + "/" + std::to_string(expected)) << std::setw(6)
      << cert << std::setw(10) << (d ? r.solver_states : r.csolver_conflicts) << "  " << fmt_ms(r.ms_sat) << "/"
      << fmt_ms(r.ms_compile) << "/" << fmt_ms(r.ms_solve) << "/" << fmt_ms(r.ms_gaps)
      << (c ? "/" + fmt_ms(r.ms_csolve) : "") << (r.agree ? "" : "  DISAGREE: " + r.problem) << std::endl;
}

nlohmann::json result_row(const VerifyView& v, size_t i, const std::string& file, const VerifyResult& r,
                          FormulaStatus status) {
  nlohmann::json row = {{"index", i},
                        {"formula", file},
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
                        {"no_certificate", r.no_certificate == Check::None    ? "none"
                                           : r.no_certificate == Check::Valid ? "checked"
                                                                              : "rejected"},
                        {"continuous_no_certificate", r.cno_certificate == Check::None    ? "none"
                                                      : r.cno_certificate == Check::Valid ? "checked"
                                                                                          : "rejected"},
                        {"ms_certify", r.ms_certify},
                        {"solver_states", r.solver_states},
                        {"ms_sat", r.ms_sat},
                        {"ms_compile", r.ms_compile},
                        {"ms_solve", r.ms_solve},
                        {"ms_gaps", r.ms_gaps},
                        {"status", formula_status_name(status)},
                        {"problem", r.problem}};
  if (v.with_continuous) {
    row["continuous_nodes"] = r.cnodes;
    row["continuous_solver"] = verdict_name(r.continuous_solver);
    row["continuous_solver_conflicts"] = r.csolver_conflicts;
    row["ms_continuous_solve"] = r.ms_csolve;
  }
  if (!v.with_discrete) {
    row["discrete"] = nullptr;
    row["continuous"] = nullptr;
  }
  return row;
}

std::string summary_line(const VerifyTally& t) {
  std::string summary = std::to_string(t.formulas) + " formulas (" + std::to_string(t.sat) + " SAT, " +
                        std::to_string(t.unsat) + " UNSAT): " + std::to_string(t.agree) + " agree, " +
                        std::to_string(t.unknown) + " unknown (solver limit), " + std::to_string(t.disagree) +
                        " disagree; " + std::to_string(t.certificates) + " certificates checked (" +
                        std::to_string(t.no_certified) + " NO certificates checked, " + std::to_string(t.no_rejected) +
                        " missing or rejected); " + fmt_ms(t.ms / 1000) + " s";
  if (t.interrupted) summary += "; " + cli::interrupted_note() + " after " + std::to_string(t.formulas) + " formulas";
  return summary;
}

// The run's identity (tools/run_identity.hpp): what changes the answers,
// and the input list with content hashes ("-": the formula as read); not
// the split, which merge checks itself.
nlohmann::json verify_run(const VerifyCampaign& c, const std::vector<std::string>& files,
                          const std::vector<Formula>& formulas) {
  nlohmann::json inputs = nlohmann::json::array();
  for (size_t i = 0; i < files.size(); ++i)
    inputs.push_back(files[i] == "-" ? cli::input_list({"-"}, to_dimacs(formulas[i]))[0]
                                     : cli::input_list({files[i]})[0]);
  const nlohmann::json options = {{"model", c.verify.models.name()},
                                  {"direct", c.verify.direct},
                                  {"break_gadget", mutation_name(c.verify.mutation)},
                                  {"timeout", c.verify.solve_seconds},
                                  {"max_states", c.verify.max_states}};
  return cli::run_json("verify", options, inputs);
}

nlohmann::json verify_json(const VerifyCampaign& c, size_t inputs, nlohmann::json rows, const VerifyTally& t,
                           const nlohmann::json& run) {
  nlohmann::json j;
  j["command"] = "verify";
  j["model"] = c.verify.models.name();
  j["shard"] = c.shard.str();
  j["inputs"] = inputs;
  j["run"] = run;
  j["run_id"] = cli::run_id(run);
  j["formulas"] = std::move(rows);
  j["summary"] = {{"formulas", t.formulas},
                  {"sat", t.sat},
                  {"unsat", t.unsat},
                  {"agree", t.agree},
                  {"unknown", t.unknown},
                  {"disagree", t.disagree},
                  {"certificates_checked", t.certificates},
                  {"no_certificates_checked", t.no_certified},
                  {"no_certificates_rejected", t.no_rejected}};
  j["interrupted"] = t.interrupted;
  j["exit_code"] = t.interrupted ? cli::interrupted_exit_code() : t.disagree ? 1 : 0;
  return j;
}

// A disagreement whose reproducer could not be written is printed in full
// on stderr (never lost), then the command fails naming the file.
void report_unsaved(const VerifyTally& t, const std::vector<std::string>& files, const std::vector<Formula>& formulas) {
  if (t.unsaved.empty()) return;
  for (const auto& [i, err] : t.unsaved) {
    std::cerr << "c disagreement on " << files[i] << " NOT saved (" << err.str() << "); the formula:\n";
    std::istringstream lines(to_dimacs(formulas[i]));
    for (std::string l; std::getline(lines, l);) std::cerr << "c   " << l << "\n";
  }
  std::cerr << std::flush;
  throw UserError(t.unsaved.front().second);
}

int run_verify(const std::vector<std::string>& args) {
  cli::install_stop_handlers();  // first: a signal at any moment gives the partial summary
  po::options_description opts = verify_options();
  po::options_description hidden;
  hidden.add_options()("inputs", po::value<std::vector<std::string>>()->required(), "formulas")(
      "break-gadget", po::value<std::string>()->default_value("none"), "test only: compile with a broken gadget");
  po::positional_options_description pos;
  pos.add("inputs", -1);
  po::variables_map vm;
  if (!cli::parse_args(args, opts, pos, vm, "verify FORMULA.cnf|FOLDER|- ...", kVerifyDescription, &hidden)) return 0;
  VerifyCampaign c;
  c.verify.solve_seconds = cli::seconds_arg(vm, "timeout");
  c.verify.max_states = cli::count_arg(vm, "max-states", 0);  // 0: no limit
  VerifyView v;
  v.picture_nodes = static_cast<size_t>(cli::count_arg(vm, "picture-nodes", 1));
  cli::verify_model_args(vm, c.verify);
  v.with_discrete = c.verify.models.has(TimeModel::Discrete);
  v.with_continuous = c.verify.models.has(TimeModel::Continuous);
  v.json = vm.count("json") > 0;
  v.rows = v.json || vm.count("json-out");
  if (vm.count("pictures")) v.pictures = vm["pictures"].as<std::string>();
  if (!v.pictures && !vm["picture-nodes"].defaulted()) throw UserError("--picture-nodes applies with --pictures only");
  c.reproducers = vm["reproducers"].as<std::string>();
  // Findings survive: the folders are checked before any work.
  cli::check_folder_can_be_made(c.reproducers);
  if (v.pictures) cli::check_writable_folder(*v.pictures);
  const std::vector<std::string> files = expand_inputs(vm["inputs"].as<std::vector<std::string>>());
  c.shard = cli::shard_arg(vm);
  c.jobs = cli::jobs_arg(vm);
  // Read everything first: a bad file is reported before any work is done.
  std::vector<Formula> formulas;
  formulas.reserve(files.size());
  for (const auto& f : files) formulas.push_back(cli::load_formula(f, true, cli::FormulaUse::Compile));

  if (!v.json) print_table_header(std::cout, v);
  nlohmann::json rows = nlohmann::json::array();
  std::optional<cli::Activity> act;  // the formula in progress, for an out-of-memory report
  VerifyEvents events;
  events.start = [&](size_t i) { act.emplace(files[i], "verifying the formula"); };
  events.result = [&](size_t i, const VerifyResult& r, FormulaStatus status) {
    if (v.with_discrete && v.pictures && r.nodes <= v.picture_nodes) draw(r, *v.pictures);
    if (v.rows) rows.push_back(result_row(v, i, files[i], r, status));
    if (!v.json) print_table_row(std::cout, v, files[i], r);
  };
  const VerifyTally t = run_verify_campaign(formulas, files, c, events);
  act.reset();
  const nlohmann::json j = verify_json(c, files.size(), std::move(rows), t, verify_run(c, files, formulas));
  cli::write_json_out(vm, j);
  if (v.json) std::cout << j.dump() << std::endl;
  else std::cout << "summary: " << summary_line(t) << std::endl;
  report_unsaved(t, files, formulas);
  if (t.interrupted) return cli::interrupted_exit_code();
  if (t.disagree)
    throw UserError("verify: " + std::to_string(t.disagree) + " disagreement" + (t.disagree > 1 ? "s" : "") +
                    "; reproducers in " + c.reproducers);
  return 0;
}

Command reg{"verify",
            "is the reduction right on these formulas? CaDiCaL vs exact solver vs gap checker, certificates checked",
            run_verify};

}  // namespace
}  // namespace gridlock
