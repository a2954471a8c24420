// gridlock cnf: formulas. Sub-subcommands check (is it LSAT?), gen (seeded
// generators), to-lsat (CNF -> LSAT<=3) and solve (CaDiCaL). See
// docs/formulas.md.
#include <climits>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "cnf/brute_force.hpp"
#include "cnf/dimacs.hpp"
#include "cnf/generate.hpp"
#include "cnf/lsat.hpp"
#include "cnf/sat_solver.hpp"
#include "common/diagnostic.hpp"
#include "common/input_too_large.hpp"
#include "reductions/to_lsat.hpp"
#include "tools/cli_common.hpp"
#include "tools/command.hpp"
#include "tools/options.hpp"
#include "tools/output.hpp"
#include "tools/user_error.hpp"

namespace gridlock {
namespace {

namespace po = boost::program_options;

const char* const kCnfUsage =
    "usage: gridlock cnf SUBCOMMAND [OPTIONS] [ARGS]\n"
    "\n"
    "Formulas in DIMACS CNF (docs/formulas.md). FILE '-' reads standard input.\n"
    "\n"
    "subcommands:\n"
    "  check FILE      is FILE an LSAT formula (exactly 3 literals per clause, each clause\n"
    "                  sharing literals with at most one other, in exactly one literal)?\n"
    "                  s YES (exit 10) / s NO (exit 20); --relaxed asks LSAT<=3 (1 to 3)\n"
    "  gen KIND        seeded random formulas: ksat, lsat, lsat-le3, planted\n"
    "  to-lsat FILE    an equisatisfiable LSAT<=3 formula, linear size\n"
    "  solve FILE      CaDiCaL: s SATISFIABLE (exit 10, checked model on v lines) or\n"
    "                  s UNSATISFIABLE (exit 20)\n"
    "\n"
    "'gridlock cnf SUBCOMMAND --help' documents each one; every one takes --json.\n";

// The command line as one comment line: arguments with anything but
// [A-Za-z0-9_./=:,+-] are single-quoted, control bytes become '?', so the
// comment can never break the DIMACS file it is written into.
std::string command_line(const std::string& sub, const std::vector<std::string>& args) {
  std::string s = "gridlock cnf " + sub;
  for (const auto& a : args) {
    bool plain = !a.empty();
    std::string clean;
    for (char ch : a) {
      auto b = static_cast<unsigned char>(ch);
      if (b < 0x20 || b == 0x7f) ch = '?';
      bool ok = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') ||
                std::string_view("_./=:,+-").find(ch) != std::string_view::npos;
      plain = plain && ok;
      if (ch == '\'') clean += "'\\''";
      else clean += ch;
    }
    s += ' ';
    s += plain ? clean : "'" + clean + "'";
  }
  return s;
}

Formula load(const std::string& path, bool strict, cli::FormulaUse use = cli::FormulaUse::Read) {
  return cli::load_formula(path, strict, use);
}

std::string clause_lengths(const Formula& f) {
  if (f.clauses.empty()) return "no clauses";
  size_t lo = SIZE_MAX, hi = 0;
  for (const auto& c : f.clauses) {
    lo = std::min(lo, c.size());
    hi = std::max(hi, c.size());
  }
  return lo == hi ? "every clause has " + std::to_string(lo) + " literals"
                  : "clause lengths " + std::to_string(lo) + " to " + std::to_string(hi);
}

void add_reader_options(po::options_description& opts) {
  opts.add_options()("no-strict-count", "accept a clause count different from the header's");
}

// ---------------------------------------------------------------- check
int run_check(const std::vector<std::string>& args) {
  po::options_description opts("options");
  opts.add_options()("help,h", "show this help")(
      "relaxed", "decide LSAT<=3 (clauses of 1 to 3 literals) instead of exactly-3 LSAT")(
      "max-violations", po::value<std::string>()->default_value("3"), "how many broken rules to list")(
      "json", "print one JSON object instead of c/s lines");
  add_reader_options(opts);
  po::variables_map vm;
  if (!cli::parse_args_one_input(
          args, opts, "file", vm, "cnf check FILE.cnf [--relaxed] [--max-violations N]",
          "Answers whether FILE is an LSAT formula: every clause has exactly 3 distinct literals\n"
          "(1 to 3 with --relaxed), shares literals with at most one other clause, and shares\n"
          "exactly one literal with it. Literals, not variables: x and -x do not intersect.\n"
          "s YES (exit 10) or s NO (exit 20); c lines give both verdicts and name the first\n"
          "clauses that break a rule, and which rule. Tautologies are allowed and listed."))
    return 0;
  const std::string path = vm["file"].as<std::string>();
  const Formula f = load(path, vm.count("no-strict-count") == 0);
  const bool relaxed = vm.count("relaxed") > 0;
  const auto maxv = static_cast<size_t>(cli::count_arg(vm, "max-violations", 1, 1u << 30));
  Answer ans("cnf check", vm.count("json") > 0);
  ans.comment(path + ": " + summary(f) + "; " + clause_lengths(f));
  const LsatReport exact = check_lsat(f, LsatForm::Exact3, std::max<size_t>(maxv, 1));
  const LsatReport le3 = check_lsat(f, LsatForm::AtMost3, std::max<size_t>(maxv, 1));
  auto verdict_line = [&](const char* what, const LsatReport& r) {
    ans.comment(std::string(what) + (r.ok ? "yes" : "no: " + r.violations.front().message));
  };
  verdict_line("exactly-3 LSAT: ", exact);
  verdict_line("LSAT<=3 (1 to 3 literals per clause): ", le3);
  const LsatReport& asked = relaxed ? le3 : exact;
  for (size_t i = 1; i < asked.violations.size() && i < maxv; ++i) ans.comment("also: " + asked.violations[i].message);
  for (size_t i = 0; i < asked.tautologies.size() && i < maxv; ++i)
    ans.comment("note: clause " + std::to_string(asked.tautologies[i] + 1) +
                " is a tautology (holds a literal and its negation); LSAT allows it");
  if (exact.ok)
    ans.comment(
        "every exactly-3 LSAT formula is satisfiable (Hall's theorem, docs/formulas.md); "
        "the NP-complete form is LSAT<=3");
  auto to_json = [](const LsatReport& r) {
    nlohmann::json v = nlohmann::json::array();
    for (const auto& x : r.violations) {
      nlohmann::json j;
      j["rule"] = rule_name(x.rule);
      for (size_t c : x.clauses) j["clauses"].push_back(c + 1);
      j["literals"] = x.literals;
      j["message"] = x.message;
      v.push_back(j);
    }
    return v;
  };
  ans.data()["form"] = relaxed ? "lsat<=3" : "exact3";
  ans.data()["lsat"] = exact.ok;
  ans.data()["lsat_le3"] = le3.ok;
  ans.data()["violations"] = to_json(exact);
  ans.data()["violations_le3"] = to_json(le3);
  nlohmann::json taut = nlohmann::json::array();
  for (size_t c : exact.tautologies) taut.push_back(c + 1);
  ans.data()["tautologies"] = taut;
  return ans.finish(asked.ok ? Verdict::Yes : Verdict::No);
}

// ---------------------------------------------------------------- gen
// Refuses (UserError) a formula of m clauses of at most len literals over n
// variables that cannot fit in memory: about 64 bytes a clause and 24 a
// literal (the clause vectors and the DIMACS text), 16 a variable.
void refuse_formula_beyond_memory(const std::string& kind, int n, int m, int len) {
  using U = unsigned __int128;
  const U bytes = U{64} * static_cast<U>(m) + U{24} * static_cast<U>(m) * static_cast<U>(len) +
                  U{16} * static_cast<U>(n);
  cli::refuse_beyond_memory("cnf gen " + kind, bytes,
                            "a formula of " + std::to_string(m) + " clauses and " + std::to_string(n) + " variables");
}

int run_gen(const std::vector<std::string>& args) {
  po::options_description opts("options");
  opts.add_options()("help,h", "show this help")("n", po::value<std::string>(), "number of variables (required)")(
      "m", po::value<std::string>(), "number of clauses")(
      "ratio", po::value<double>(), "clauses per variable: m = round(ratio * n) (instead of --m)")(
      "k", po::value<std::string>()->default_value("3"), "literals per clause (ksat, planted)")(
      "min-len", po::value<std::string>(), "shortest clause (lsat: 3, lsat-le3: 1)")(
      "max-len", po::value<std::string>(), "longest clause (lsat: 3, lsat-le3: 3)")(
      "seed", po::value<std::string>()->default_value("1"), "random seed, 0 to 2^64-1")(
      "output,o", po::value<std::string>()->default_value("-"), "output file ('-' = standard output)")(
      "json", "print one JSON object (with the DIMACS text when writing to standard output)");
  po::variables_map vm;
  if (!cli::parse_args_one_input(args, opts, "kind", vm, "cnf gen KIND --n N (--m M | --ratio R) [--seed S] [-o FILE]",
                                 "Writes a seeded random formula in DIMACS. The same command gives the same bytes on\n"
                                 "every machine. The header comments record the command line, the generator, its\n"
                                 "parameters and the seed. KIND:\n"
                                 "  ksat      uniform random k-SAT: k distinct variables per clause, uniform signs\n"
                                 "  lsat      random exactly-3 LSAT (m <= about 4n/5; always satisfiable)\n"
                                 "  lsat-le3  random LSAT<=3, clause lengths uniform in [min-len, max-len]\n"
                                 "  planted   k-SAT clauses satisfied by a hidden assignment (recorded in a comment)"))
    return 0;
  const std::string kind = vm["kind"].as<std::string>();
  if (!vm.count("n")) throw UserError("cnf gen: --n is required");
  if (vm.count("m") + vm.count("ratio") != 1) throw UserError("cnf gen: give exactly one of --m and --ratio");
  const int n = cli::int_arg(vm, "n", 1, INT_MAX);
  const uint64_t seed = cli::seed_arg(vm, "seed");
  const int k = cli::int_arg(vm, "k", 1, INT_MAX);
  Formula f;
  try {
    const int m = vm.count("m") ? cli::int_arg(vm, "m", 0, INT_MAX) : clauses_for_ratio(n, vm["ratio"].as<double>());
    refuse_formula_beyond_memory(
        kind, n, m,
        kind == "lsat" || kind == "lsat-le3" ? (vm.count("max-len") ? cli::int_arg(vm, "max-len", 1, INT_MAX) : 3) : k);
    if (kind == "ksat") {
      f = random_ksat({n, m, k, seed});
    } else if (kind == "planted") {
      f = planted_ksat({n, m, k, seed});
    } else if (kind == "lsat" || kind == "lsat-le3") {
      LsatParams p;
      p.n = n;
      p.m = m;
      p.seed = seed;
      p.min_len = vm.count("min-len") ? cli::int_arg(vm, "min-len", 1, INT_MAX) : kind == "lsat" ? 3 : 1;
      p.max_len = vm.count("max-len") ? cli::int_arg(vm, "max-len", 1, INT_MAX) : 3;
      f = random_lsat(p);
    } else {
      throw UserError("cnf gen: unknown generator '" + kind + "' (ksat, lsat, lsat-le3 or planted)");
    }
  } catch (const std::invalid_argument& e) {
    throw UserError(std::string("cnf gen ") + kind + ": " + e.what());
  }
  f.comments.insert(f.comments.begin(), "command: " + command_line("gen", args));
  const std::string out = vm["output"].as<std::string>();
  const std::string text = to_dimacs(f);
  const bool json = vm.count("json") > 0;
  if (!json || out != "-") cli::write_text_file(out, text);
  if (!json) {
    if (out != "-") std::cout << "c wrote " << out << ": " << summary(f) << '\n';
    return 0;
  }
  Answer ans("cnf gen", true);
  for (const auto& c : f.comments) ans.comment(c);
  ans.data()["variables"] = f.num_vars;
  ans.data()["clauses"] = f.clauses.size();
  ans.data()["output"] = out;
  if (out == "-") ans.data()["dimacs"] = text;
  return ans.finish(Verdict::Unknown, "OK");
}

// ---------------------------------------------------------------- to-lsat
int run_to_lsat(const std::vector<std::string>& args) {
  po::options_description opts("options");
  opts.add_options()("help,h", "show this help")("output,o", po::value<std::string>()->default_value("-"),
                                                 "output file ('-' = standard output)")(
      "no-passthrough", "build the construction even when the input already is LSAT<=3")(
      "json", "print one JSON object (sizes; the DIMACS text when writing to standard output)");
  add_reader_options(opts);
  po::variables_map vm;
  if (!cli::parse_args_one_input(
          args, opts, "file", vm, "cnf to-lsat FILE.cnf [-o OUT.cnf] [--no-passthrough]",
          "Writes an LSAT<=3 formula (clauses of 1 to 3 literals; each clause shares literals\n"
          "with at most one other, exactly one) that is satisfiable iff FILE is. Any CNF is\n"
          "accepted: long clauses are split, tautologies and repeated literals dropped. Output\n"
          "variables 1..n are FILE's variables: truncating a model of the output gives a model\n"
          "of FILE. Size: at most 5m + n variables and 6m + n clauses for a 3-CNF with m clauses\n"
          "(exact formulas in docs/formulas.md). An input that already is LSAT<=3 is written\n"
          "unchanged unless --no-passthrough is given."))
    return 0;
  const std::string path = vm["file"].as<std::string>();
  cli::refuse_overwriting_input(vm["output"].as<std::string>(), {path});
  const Formula in = load(path, vm.count("no-strict-count") == 0, cli::FormulaUse::Solve);
  cli::Activity act(path, "reducing the formula to LSAT<=3");
  ToLsatOptions opt;
  opt.passthrough = vm.count("no-passthrough") == 0;
  LsatReduction red = [&] {
    try {
      return reduce_to_lsat(in, opt);
    } catch (const InputTooLarge& e) {
      throw UserError(Diagnostic{path, 0, e.what()});
    }
  }();
  Formula out = red.output();
  // Cheap insurance: the construction is proved, but a wrong output would
  // poison everything downstream.
  if (LsatReport r = check_lsat(out, LsatForm::AtMost3, 1); !r.ok)
    throw std::logic_error("to-lsat produced a formula that is not LSAT<=3: " + r.violations.front().message);
  const ToLsatStats& st = red.stats();
  out.comments.insert(out.comments.begin(),
                      {"command: " + command_line("to-lsat", args), "source: " + path + ": " + summary(in)});
  out.comments.push_back("sizes: " + std::to_string(st.in_vars) + " -> " + std::to_string(st.out_vars) +
                         " variables, " + std::to_string(st.in_clauses) + " -> " + std::to_string(st.out_clauses) +
                         " clauses");
  const std::string dest = vm["output"].as<std::string>();
  const std::string text = to_dimacs(out);
  const bool json = vm.count("json") > 0;
  if (!json || dest != "-") cli::write_text_file(dest, text);
  if (!json) {
    if (dest != "-") std::cout << "c wrote " << dest << ": " << summary(out) << '\n';
    return 0;
  }
  Answer ans("cnf to-lsat", true);
  for (const auto& c : out.comments) ans.comment(c);
  nlohmann::json s;
  s["identity"] = st.identity;
  s["in_vars"] = st.in_vars;
  s["in_clauses"] = st.in_clauses;
  s["repeated_literals"] = st.repeated_literals;
  s["tautologies"] = st.tautologies;
  s["empty_clauses"] = st.empty_clauses;
  s["split_clauses"] = st.split_clauses;
  s["chain_vars"] = st.chain_vars;
  s["normalised_clauses"] = st.normalised_clauses;
  s["cycle_vars"] = st.cycle_vars;
  s["copies"] = st.copies;
  s["links"] = st.links;
  s["out_vars"] = st.out_vars;
  s["out_clauses"] = st.out_clauses;
  ans.data()["stats"] = s;
  ans.data()["output"] = dest;
  if (dest == "-") ans.data()["dimacs"] = text;
  return ans.finish(Verdict::Unknown, "OK");
}

// ---------------------------------------------------------------- solve
int run_solve(const std::vector<std::string>& args) {
  po::options_description opts("options");
  opts.add_options()("help,h", "show this help")(
      "conflicts", po::value<std::string>(), "give up (s UNKNOWN, exit 0) after this many conflicts (cadical, dpll)")(
      "time", po::value<std::string>(), "give up (s UNKNOWN, exit 0) after this many seconds (every solver)")(
      "solver", po::value<std::string>()->default_value("cadical"),
      "cadical, or an independent oracle: dpll (small formulas), exhaustive (at most 24 variables)")(
      "json", "print one JSON object instead of c/s/v lines");
  add_reader_options(opts);
  po::variables_map vm;
  if (!cli::parse_args_one_input(args, opts, "file", vm, "cnf solve FILE.cnf [--conflicts N] [--time SECONDS]",
                                 "Decides satisfiability with CaDiCaL (linked as a library). Prints s SATISFIABLE and\n"
                                 "the model on v lines ending in 0 (exit 10), s UNSATISFIABLE (exit 20), or s UNKNOWN\n"
                                 "when a limit is hit (exit 0). The model is checked against the formula first."))
    return 0;
  const std::string path = vm["file"].as<std::string>();
  SatLimits lim;  // options first: a bad value is reported before the file is read
  if (auto c = cli::count_arg_opt(vm, "conflicts", 1, INT_MAX)) lim.conflicts = static_cast<int64_t>(*c);
  if (auto t = cli::seconds_arg_opt(vm, "time")) lim.seconds = *t;
  const Formula f = load(path, vm.count("no-strict-count") == 0, cli::FormulaUse::Solve);
  cli::Activity act(path, "solving the formula");
  const std::string solver = vm["solver"].as<std::string>();
  Answer ans("cnf solve", vm.count("json") > 0);
  ans.comment(path + ": " + summary(f));
  SatResult r;
  std::string name;
  if (solver == "cadical") {
    r = solve_sat(f, lim);
    name = sat_solver_name();
  } else if (solver == "dpll") {
    r = dpll_sat(f, 1000000, lim);
    name = "gridlock DPLL (unit propagation, no learning; gives up after 10^6 decisions)";
  } else if (solver == "exhaustive") {
    if (f.num_vars > kExhaustiveMaxVars)
      throw UserError(Diagnostic{path, 0,
                                 "--solver exhaustive takes at most " + std::to_string(kExhaustiveMaxVars) +
                                     " variables, the formula has " + std::to_string(f.num_vars)});
    if (vm.count("conflicts")) throw UserError("--conflicts applies to --solver cadical and dpll, not exhaustive");
    r = exhaustive_sat(f, lim);
    name = "gridlock exhaustive search";
  } else {
    throw UserError("cnf solve: unknown solver '" + solver + "' (cadical, dpll or exhaustive)");
  }
  char secs[32];
  std::snprintf(secs, sizeof secs, "%.3f", r.seconds);
  ans.comment("solver: " + name + ", " + secs + " s");
  ans.data()["solver"] = name;
  if (r.status == Verdict::Yes) {
    if (!satisfies(f, r.model)) throw std::logic_error(name + " returned a model that falsifies the formula");
    ans.comment("model checked: every clause has a true literal");
    std::vector<int> lits = model_literals(r.model, f.num_vars);
    for (int lit : lits) ans.witness(std::to_string(lit));
    ans.witness("0");
    ans.data()["model"] = lits;
  }
  return ans.finish(r.status, sat_status_name(r.status));
}

// ---------------------------------------------------------------- dispatch
int run_cnf(const std::vector<std::string>& args) {
  if (args.empty())
    throw UserError("cnf: missing subcommand: check, gen, to-lsat or solve (see 'gridlock cnf --help')");
  const std::string& sub = args[0];
  if (sub == "--help" || sub == "-h" || sub == "help") {
    std::cout << kCnfUsage;
    return 0;
  }
  std::vector<std::string> rest(args.begin() + 1, args.end());
  if (sub == "check") return run_check(rest);
  if (sub == "gen") return run_gen(rest);
  if (sub == "to-lsat") return run_to_lsat(rest);
  if (sub == "solve") return run_solve(rest);
  throw UserError("cnf: unknown subcommand '" + sub + "' (check, gen, to-lsat or solve; see 'gridlock cnf --help')");
}

}  // namespace

static Command reg{"cnf", "formulas: check LSAT, generate, reduce to LSAT, solve with CaDiCaL", run_cnf};

}  // namespace gridlock
