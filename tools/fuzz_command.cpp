// gridlock fuzz: hunt for a formula on which the reduction, the solvers or a
// certificate disagree (verify/fuzz.hpp, docs/verify.md). Deterministic
// from --seed; --shard K/N splits a campaign across processes or machines.
#include <malloc.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cnf/dimacs.hpp"
#include "common/limits.hpp"
#include "tools/animate_page.hpp"
#include "tools/cli_common.hpp"
#include "tools/command.hpp"
#include "tools/options.hpp"
#include "verify/fuzz.hpp"

namespace gridlock {
namespace {

std::vector<FuzzKind> parse_kinds(const std::string& s) {
  std::vector<FuzzKind> kinds;
  std::istringstream in(s);
  for (std::string w; std::getline(in, w, ',');) {
    if (w == "ksat") kinds.push_back(FuzzKind::Ksat);
    else if (w == "lsat") kinds.push_back(FuzzKind::Lsat);
    else if (w == "planted") kinds.push_back(FuzzKind::Planted);
    else if (w == "mix") kinds.insert(kinds.end(), {FuzzKind::Ksat, FuzzKind::Lsat, FuzzKind::Planted});
    else throw UserError("--kinds: unknown kind '" + w + "' (ksat, lsat, planted, mix)");
  }
  if (kinds.empty()) throw UserError("--kinds: give at least one kind");
  return kinds;
}

int run_fuzz(const std::vector<std::string>& args) {
  cli::install_stop_handlers();  // first: a signal at any moment gives the partial summary
  namespace po = boost::program_options;
  po::options_description opts("options");
  opts.add_options()("help,h", "show this help")("seed", po::value<std::string>()->default_value("1"),
                                                 "campaign seed: formula i is drawn from (seed, i) alone")(
      "count", po::value<std::string>(), "formulas in the campaign (default 1000 unless --time is given)")(
      "time", po::value<std::string>(), "stop after this many seconds")(
      "shard", po::value<std::string>()->default_value("0/1"), "K/N: run only the formulas i with i % N == K")(
      "index", po::value<std::string>(), "run only formula i (replays a finding)")(
      "min-vars", po::value<std::string>()->default_value("3"), "fewest variables of a formula (1 to 64)")(
      "max-vars", po::value<std::string>()->default_value("6"), "most variables of a formula (1 to 64)")(
      "kinds", po::value<std::string>()->default_value("mix"), "generators, comma-separated: ksat, lsat, planted, mix")(
      "model", po::value<std::string>()->default_value("discrete"),
      "which reduction to check, as in 'gridlock verify': discrete, continuous or both")(
      "direct", "compile each formula as it is, not its LSAT<=3 form (as in 'gridlock verify')")(
      "timeout", po::value<std::string>()->default_value("10"), "seconds the exact solver may spend on one formula")(
      "max-states", po::value<std::string>()->default_value("2000000"),
      "search nodes the exact solver may visit per formula")(
      "out", po::value<std::string>()->default_value("fuzz-failures"), "folder for shrunk counterexamples")(
      "keep-going", "do not stop at the first disagreement")("json",
                                                             "print one JSON object at the end instead of c/s lines")(
      "json-out", po::value<std::string>(),
      "also write that JSON object to this file ('gridlock merge' combines shards)");
  po::options_description hidden;
  hidden.add_options()("break-gadget", po::value<std::string>()->default_value("none"),
                       "self-test: compile with a broken gadget, so that the fuzzer must find it");
  po::positional_options_description pos;
  po::variables_map vm;
  if (!cli::parse_args(
          args, opts, pos, vm, "fuzz [--seed S] [--count N | --time T] [--shard K/N]",
          "Random small formulas (random 3-SAT around the threshold, random LSAT<=3, planted 3-SAT),\n"
          "each checked as 'gridlock verify' does (--model continuous: against the exact continuous\n"
          "solver). Every disagreement is shrunk (delta\n"
          "debugging over clauses, literals, variables) and saved as a replayable folder before it\n"
          "is reported. On a terminal a progress line shows the rate and the counts.\n"
          "Exit 0 if no formula disagreed, 1 otherwise. SIGINT/SIGTERM end the campaign after the\n"
          "formula in progress is abandoned: the summary (JSON too) is marked interrupted, exit 130/143.\n"
          "A campaign over 8 processes:  parallel gridlock fuzz --seed 7 --count 1000000 --shard {}/8 ::: $(seq 0 7)",
          &hidden))
    return 0;
  FuzzParams p;
  p.seed = cli::seed_arg(vm, "seed");
  p.min_vars = cli::int_arg(vm, "min-vars", 1, 64);
  p.max_vars = cli::int_arg(vm, "max-vars", 1, 64);
  if (p.min_vars < 1 || p.max_vars > 64 || p.min_vars > p.max_vars)
    throw UserError("--min-vars and --max-vars: need 1 <= min <= max <= 64");
  p.kinds = parse_kinds(vm["kinds"].as<std::string>());
  uint64_t shard = 0, shards = 1;
  cli::parse_shard(vm["shard"].as<std::string>(), shard, shards);
  VerifyOptions vo;
  vo.solve_seconds = cli::seconds_arg(vm, "timeout");
  vo.max_states = cli::count_arg(vm, "max-states", 1);
  auto mutation = parse_mutation(vm["break-gadget"].as<std::string>());
  if (!mutation) throw UserError("unknown --break-gadget '" + vm["break-gadget"].as<std::string>() + "'");
  vo.mutation = *mutation;
  auto model = parse_verify_model(vm["model"].as<std::string>());
  if (!model)
    throw UserError("--model must be discrete, continuous or both, not '" + vm["model"].as<std::string>() + "'");
  vo.model = *model;
  vo.direct = vm.count("direct") > 0;
  const bool json = vm.count("json") > 0;
  uint64_t first = shard, last = UINT64_MAX;  // indices first, first + N, ... < last
  if (vm.count("index")) {
    first = cli::count_arg(vm, "index", 0, UINT64_MAX - 1);
    last = first + 1;
    shards = 1;
  } else if (vm.count("count")) {
    last = cli::count_arg(vm, "count", 1);
  } else if (!vm.count("time")) {
    last = 1000;
  }
  const double time_limit = cli::seconds_arg_opt(vm, "time").value_or(0);
  if (vm.count("index") && (vm.count("count") || vm.count("time")))
    throw UserError("--index replays one formula: give no --count or --time with it");
  const bool progress = !json && isatty(STDERR_FILENO);

  std::string header = "gridlock fuzz: seed " + std::to_string(p.seed) + ", shard " + std::to_string(shard) + "/" +
                       std::to_string(shards) + ", " + std::to_string(p.min_vars) + ".." + std::to_string(p.max_vars) +
                       " variables, kinds " + vm["kinds"].as<std::string>() + ", model " + verify_model_name(vo.model) +
                       (vo.direct ? ", direct" : "");
  if (*mutation != Mutation::None) header += ", BROKEN GADGET " + std::string(mutation_name(*mutation));
  if (!json) std::cout << "c " << header << std::endl;

  // Each formula allocates and frees the same few large tables (instance,
  // motion tables, simulator arrays); keep them in the heap instead of
  // mapping and unmapping fresh pages per formula (about 7% of the time).
  mallopt(M_MMAP_THRESHOLD, 64 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
  const auto t0 = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  uint64_t done = 0, sat = 0, unsat = 0, unknown = 0, disagreements = 0, certificates = 0;
  double last_print = -1;
  nlohmann::json findings = nlohmann::json::array();
  auto status_line = [&] {
    std::ostringstream s;
    s << done << " formulas (" << sat << " SAT, " << unsat << " UNSAT, " << unknown << " unknown), "
      << static_cast<uint64_t>(static_cast<double>(done) / std::max(elapsed(), 1e-9)) << "/s, " << certificates
      << " certificates, " << disagreements << " disagreements, " << static_cast<uint64_t>(elapsed()) << " s";
    return s.str();
  };
  for (uint64_t i = first; i < last && !stop_requested(); i += shards) {
    if (time_limit > 0 && elapsed() >= time_limit) break;
    Formula f = fuzz_formula(p, i);
    VerifyOptions vi = vo;  // --time bounds the campaign: the last formula's solver gets what is left
    if (time_limit > 0) vi.solve_seconds = std::min(vo.solve_seconds, std::max(time_limit - elapsed(), 0.001));
    VerifyResult r = verify_formula(f, "formula " + std::to_string(i), vi);
    if (stop_requested()) break;  // answers may be cut short: the formula is not counted
    ++done;
    sat += r.sat == Verdict::Yes;
    unsat += r.sat == Verdict::No;
    unknown += r.agree && r.solver_unknown();
    certificates += static_cast<uint64_t>(r.witnesses_checked());
    if (!r.agree) {
      ++disagreements;
      if (progress) std::cerr << "\r\033[K";
      if (!json) std::cout << "c formula " << i << " disagrees: " << r.problem << "; shrinking" << std::endl;
      ShrinkStats st;
      Formula small = shrink_disagreement(f, vo, &st);
      if (stop_requested()) break;  // shrinking cut short: no reproducer rather than a wrong one
      VerifyResult rs = verify_formula(small, "shrunk formula " + std::to_string(i), vo);
      const std::string dir = vm["out"].as<std::string>() + "/seed" + std::to_string(p.seed) + "-formula" +
                              std::to_string(i);
      write_reproducer(rs, dir, vo);
      cli::write_text_file(dir + "/original.cnf", to_dimacs(f));
      write_result_animations(rs, dir);  // watch the disagreeing schedules run
      std::string replay = "gridlock fuzz --seed " + std::to_string(p.seed) + " --index " + std::to_string(i) +
                           " --min-vars " + std::to_string(p.min_vars) + " --max-vars " + std::to_string(p.max_vars) +
                           " --kinds " + vm["kinds"].as<std::string>() +
                           (vo.model != VerifyModel::Discrete ? std::string(" --model ") + verify_model_name(vo.model)
                                                              : "") +
                           (vo.direct ? " --direct" : "") +
                           (*mutation != Mutation::None ? std::string(" --break-gadget ") + mutation_name(*mutation)
                                                        : "");
      if (!json) {
        std::cout << "c shrunk in " << st.tries << " tries to " << small.num_vars << " variables, "
                  << small.clauses.size() << " clauses: " << rs.problem << "\n";
        std::istringstream lines(to_dimacs(small));
        for (std::string l; std::getline(lines, l);)
          if (l.rfind("c ", 0) != 0) std::cout << "c   " << l << "\n";
        std::cout << "c saved to " << dir << " (replay: " << replay << ")" << std::endl;
      }
      findings.push_back({{"index", i},
                          {"problem", rs.problem},
                          {"folder", dir},
                          {"replay", replay},
                          {"shrunk_variables", small.num_vars},
                          {"shrunk_clauses", small.clauses.size()},
                          {"shrink_tries", st.tries},
                          {"dimacs", to_dimacs(small)}});
      if (!vm.count("keep-going")) break;
    }
    if (i > UINT64_MAX - shards) break;
    if (progress && elapsed() - last_print >= 0.5) {
      last_print = elapsed();
      std::cerr << "\r\033[Kfuzz: " << status_line() << std::flush;
    }
  }
  if (progress) std::cerr << "\r\033[K";
  const bool interrupted = stop_requested();
  nlohmann::json j;
  j["command"] = "fuzz";
  j["seed"] = std::to_string(p.seed);  // a string: seeds above 2^53 survive JSON readers
  j["shard"] = std::to_string(shard) + "/" + std::to_string(shards);
  j["formulas"] = done;
  j["sat"] = sat;
  j["unsat"] = unsat;
  j["unknown"] = unknown;
  j["certificates_checked"] = certificates;
  j["disagreements"] = disagreements;
  j["seconds"] = elapsed();
  j["findings"] = findings;
  j["status"] = disagreements ? "DISAGREE" : "AGREE";
  j["interrupted"] = interrupted;
  // The campaign's settings, so that 'gridlock merge' only combines shards of one campaign.
  j["campaign"] = {{"count", vm.count("count") ? nlohmann::json(last) : nlohmann::json()},
                   {"time", time_limit},
                   {"index", vm.count("index") ? nlohmann::json(first) : nlohmann::json()},
                   {"min_vars", p.min_vars},
                   {"max_vars", p.max_vars},
                   {"kinds", vm["kinds"].as<std::string>()},
                   {"max_states", vo.max_states},
                   {"keep_going", vm.count("keep-going") > 0},
                   {"break_gadget", mutation_name(*mutation)},
                   {"model", verify_model_name(vo.model)},
                   {"direct", vo.direct}};
  if (vm.count("json-out")) cli::write_text_file(vm["json-out"].as<std::string>(), j.dump(2) + "\n");
  if (json) {
    std::cout << j.dump() << std::endl;
  } else {
    std::cout << "c " << status_line() << "\n";
    if (interrupted) std::cout << "c INTERRUPTED by signal " << stop_signal().load() << ": partial campaign\n";
    std::cout << "s " << (disagreements ? "DISAGREE" : "AGREE") << std::endl;
  }
  if (interrupted) return cli::interrupted_exit_code();
  return disagreements ? 1 : 0;
}

Command reg{"fuzz", "hunt for a counterexample among many small formulas (seeded, sharded, shrinks what it finds)",
            run_fuzz};

}  // namespace
}  // namespace gridlock
