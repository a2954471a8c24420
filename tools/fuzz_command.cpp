// gridlock fuzz: hunt for a formula on which the reduction, the solvers or a
// certificate disagree (reductions/fuzz.hpp, docs/verify.md). Deterministic
// from --seed; --shard K/N splits a campaign across processes or machines.
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cnf/dimacs.hpp"
#include "reductions/fuzz.hpp"
#include "tools/cli_common.hpp"
#include "tools/command.hpp"

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
  namespace po = boost::program_options;
  po::options_description opts("options");
  opts.add_options()
    ("help,h", "show this help")
    ("seed", po::value<uint64_t>()->default_value(1), "campaign seed: formula i is drawn from (seed, i) alone")
    ("count", po::value<uint64_t>(), "formulas in the campaign (default 1000 unless --time is given)")
    ("time", po::value<double>(), "stop after this many seconds")
    ("shard", po::value<std::string>()->default_value("0/1"), "K/N: run only the formulas i with i % N == K")
    ("index", po::value<uint64_t>(), "run only formula i (replays a finding)")
    ("min-vars", po::value<int>()->default_value(3), "fewest variables of a formula (1 to 64)")
    ("max-vars", po::value<int>()->default_value(6), "most variables of a formula (1 to 64)")
    ("kinds", po::value<std::string>()->default_value("mix"), "generators, comma-separated: ksat, lsat, planted, mix")
    ("model", po::value<std::string>()->default_value("discrete"),
     "which reduction to check, as in 'gridlock verify': discrete, continuous or both")
    ("direct", "compile each formula as it is, not its LSAT<=3 form (as in 'gridlock verify')")
    ("timeout", po::value<double>()->default_value(10), "seconds the exact solver may spend on one formula")
    ("max-states", po::value<uint64_t>()->default_value(2'000'000), "search nodes the exact solver may visit per formula")
    ("out", po::value<std::string>()->default_value("fuzz-failures"), "folder for shrunk counterexamples")
    ("keep-going", "do not stop at the first disagreement")
    ("json", "print one JSON object at the end instead of c/s lines");
  po::options_description hidden;
  hidden.add_options()("break-gadget", po::value<std::string>()->default_value("none"),
                       "self-test: compile with a broken gadget, so that the fuzzer must find it");
  po::positional_options_description pos;
  po::variables_map vm;
  if (!cli::parse_args(args, opts, pos, vm, "fuzz [--seed S] [--count N | --time T] [--shard K/N]",
                       "Random small formulas (random 3-SAT around the threshold, random LSAT<=3, planted 3-SAT),\n"
                       "each checked as 'gridlock verify' does (--model continuous: against the exact continuous\n"
                       "solver). Every disagreement is shrunk (delta\n"
                       "debugging over clauses, literals, variables) and saved as a replayable folder before it\n"
                       "is reported. On a terminal a progress line shows the rate and the counts.\n"
                       "Exit 0 if no formula disagreed, 1 otherwise.\n"
                       "A campaign over 8 processes:  parallel gridlock fuzz --seed 7 --count 1000000 --shard {}/8 ::: $(seq 0 7)",
                       &hidden))
    return 0;
  FuzzParams p;
  p.seed = vm["seed"].as<uint64_t>();
  p.min_vars = vm["min-vars"].as<int>();
  p.max_vars = vm["max-vars"].as<int>();
  if (p.min_vars < 1 || p.max_vars > 64 || p.min_vars > p.max_vars)
    throw UserError("--min-vars and --max-vars: need 1 <= min <= max <= 64");
  p.kinds = parse_kinds(vm["kinds"].as<std::string>());
  uint64_t shard = 0, shards = 1;
  {
    const std::string s = vm["shard"].as<std::string>();
    char slash = 0;
    std::istringstream in(s);
    if (!(in >> shard >> slash >> shards) || slash != '/' || shards == 0 || shard >= shards || !in.eof())
      throw UserError("--shard: want K/N with 0 <= K < N, not '" + s + "'");
  }
  VerifyOptions vo;
  vo.solve_seconds = vm["timeout"].as<double>();
  vo.max_states = vm["max-states"].as<uint64_t>();
  auto mutation = parse_mutation(vm["break-gadget"].as<std::string>());
  if (!mutation) throw UserError("unknown --break-gadget '" + vm["break-gadget"].as<std::string>() + "'");
  vo.mutation = *mutation;
  auto model = parse_verify_model(vm["model"].as<std::string>());
  if (!model) throw UserError("--model must be discrete, continuous or both, not '" + vm["model"].as<std::string>() + "'");
  vo.model = *model;
  vo.direct = vm.count("direct") > 0;
  const bool json = vm.count("json") > 0;
  uint64_t first = shard, last = UINT64_MAX;  // indices first, first + N, ... < last
  if (vm.count("index")) {
    first = vm["index"].as<uint64_t>();
    last = first + 1;
    shards = 1;
  } else if (vm.count("count")) {
    last = vm["count"].as<uint64_t>();
  } else if (!vm.count("time")) {
    last = 1000;
  }
  const double time_limit = vm.count("time") ? vm["time"].as<double>() : 0;
  const bool progress = !json && isatty(STDERR_FILENO);

  std::string header = "gridlock fuzz: seed " + std::to_string(p.seed) + ", shard " + std::to_string(shard) + "/" +
                       std::to_string(shards) + ", " + std::to_string(p.min_vars) + ".." + std::to_string(p.max_vars) +
                       " variables, kinds " + vm["kinds"].as<std::string>() + ", model " + verify_model_name(vo.model) +
                       (vo.direct ? ", direct" : "");
  if (*mutation != Mutation::None) header += ", BROKEN GADGET " + std::string(mutation_name(*mutation));
  if (!json) std::cout << "c " << header << std::endl;

  const auto t0 = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  uint64_t done = 0, sat = 0, unsat = 0, unknown = 0, disagreements = 0, certificates = 0;
  double last_print = -1;
  nlohmann::json findings = nlohmann::json::array();
  auto status_line = [&] {
    std::ostringstream s;
    s << done << " formulas (" << sat << " SAT, " << unsat << " UNSAT, " << unknown << " unknown), "
      << static_cast<uint64_t>(static_cast<double>(done) / std::max(elapsed(), 1e-9)) << "/s, " << certificates << " certificates, "
      << disagreements << " disagreements, " << static_cast<uint64_t>(elapsed()) << " s";
    return s.str();
  };
  for (uint64_t i = first; i < last; i += shards) {
    if (time_limit > 0 && elapsed() >= time_limit) break;
    Formula f = fuzz_formula(p, i);
    VerifyResult r = verify_formula(f, "formula " + std::to_string(i), vo);
    ++done;
    sat += r.sat == Tri::Yes;
    unsat += r.sat == Tri::No;
    unknown += r.agree && r.solver_unknown();
    certificates += static_cast<uint64_t>(r.witnesses_checked());
    if (!r.agree) {
      ++disagreements;
      if (progress) std::cerr << "\r\033[K";
      if (!json) std::cout << "c formula " << i << " disagrees: " << r.problem << "; shrinking" << std::endl;
      ShrinkStats st;
      Formula small = shrink_disagreement(f, vo, &st);
      VerifyResult rs = verify_formula(small, "shrunk formula " + std::to_string(i), vo);
      const std::string dir = vm["out"].as<std::string>() + "/seed" + std::to_string(p.seed) + "-formula" +
                              std::to_string(i);
      write_reproducer(rs, dir, vo);
      std::ofstream(dir + "/original.cnf") << to_dimacs(f);
      std::string replay = "gridlock fuzz --seed " + std::to_string(p.seed) + " --index " + std::to_string(i) +
                           " --min-vars " + std::to_string(p.min_vars) + " --max-vars " + std::to_string(p.max_vars) +
                           " --kinds " + vm["kinds"].as<std::string>() +
                           (vo.model != VerifyModel::Discrete ? std::string(" --model ") + verify_model_name(vo.model) : "") +
                           (vo.direct ? " --direct" : "") +
                           (*mutation != Mutation::None ? std::string(" --break-gadget ") + mutation_name(*mutation) : "");
      if (!json) {
        std::cout << "c shrunk in " << st.tries << " tries to " << small.num_vars << " variables, "
                  << small.clauses.size() << " clauses: " << rs.problem << "\n";
        std::istringstream lines(to_dimacs(small));
        for (std::string l; std::getline(lines, l);)
          if (l.rfind("c ", 0) != 0) std::cout << "c   " << l << "\n";
        std::cout << "c saved to " << dir << " (replay: " << replay << ")" << std::endl;
      }
      findings.push_back({{"index", i}, {"problem", rs.problem}, {"folder", dir}, {"replay", replay},
                          {"shrunk_variables", small.num_vars}, {"shrunk_clauses", small.clauses.size()},
                          {"shrink_tries", st.tries}, {"dimacs", to_dimacs(small)}});
      if (!vm.count("keep-going")) break;
    }
    if (progress && elapsed() - last_print >= 0.5) {
      last_print = elapsed();
      std::cerr << "\r\033[Kfuzz: " << status_line() << std::flush;
    }
  }
  if (progress) std::cerr << "\r\033[K";
  if (json) {
    nlohmann::json j;
    j["command"] = "fuzz";
    j["seed"] = p.seed;
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
    std::cout << j.dump() << std::endl;
  } else {
    std::cout << "c " << status_line() << "\n";
    std::cout << "s " << (disagreements ? "DISAGREE" : "AGREE") << std::endl;
  }
  return disagreements ? 1 : 0;
}

Command reg{"fuzz", "hunt for a counterexample among many small formulas (seeded, sharded, shrinks what it finds)",
            run_fuzz};

}  // namespace
}  // namespace gridlock
