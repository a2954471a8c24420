// gridlock fuzz: hunt for a formula on which the reduction, the solvers or a
// certificate disagree (verify/fuzz.hpp, docs/verify.md). Deterministic
// from --seed; --shard K/N splits a campaign across processes or machines.
// The campaign itself is verify/campaign.hpp's run_fuzz_campaign; this file
// reads the options, saves and prints what it finds, and sets the exit code.
#include <malloc.h>

#include <algorithm>
#include <cstdint>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "cnf/dimacs.hpp"
#include "common/limits.hpp"
#include "tools/animation_files.hpp"
#include "tools/campaign_cli.hpp"
#include "tools/cli_common.hpp"
#include "tools/command.hpp"
#include "tools/options.hpp"
#include "tools/set_folder.hpp"
#include "tools/user_error.hpp"
#include "verify/campaign.hpp"

namespace gridlock {
namespace {

namespace po = boost::program_options;

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

po::options_description fuzz_options() {
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
      "no-certificates", "do not write and check a NO certificate for each NO (docs/certificates.md)")(
      "timeout", po::value<std::string>()->default_value("10"), "seconds the exact solver may spend on one formula")(
      "max-states", po::value<std::string>()->default_value("2000000"),
      "search nodes the exact solver may visit per formula")(
      "out", po::value<std::string>()->default_value("fuzz-failures"), "folder for shrunk counterexamples")(
      "keep-going", "do not stop at the first disagreement")("json",
                                                             "print one JSON object at the end instead of c/s lines")(
      "json-out", po::value<std::string>(),
      "also write that JSON object to this file ('gridlock merge' combines shards)");
  cli::add_jobs_option(opts);
  return opts;
}

const char* const kFuzzDescription =
    "Random small formulas (random 3-SAT around the threshold, random LSAT<=3, planted 3-SAT),\n"
    "each checked as 'gridlock verify' does (--model continuous: against the exact continuous\n"
    "solver). Every disagreement is shrunk (delta\n"
    "debugging over clauses, literals, variables) and saved as a replayable folder before it\n"
    "is reported. On a terminal a progress line shows the rate and the counts.\n"
    "Exit 0 if no formula disagreed, 1 otherwise. SIGINT/SIGTERM end the campaign after the\n"
    "formula in progress is abandoned: the summary (JSON too) is marked interrupted, exit 130/143.\n"
    "--jobs N checks N formulas at once on one machine (default: every core), with the same\n"
    "output, findings and exit code for every N.\n"
    "A campaign over 8 processes:  parallel gridlock fuzz --seed 7 --count 1000000 --shard {}/8 ::: $(seq 0 7)";

// The command line's reading of a campaign.
struct FuzzRun {
  FuzzCampaign c;
  Shard shard;
  std::string kinds, out;
  bool json = false, count_given = false, index_given = false;
};

FuzzRun read_fuzz_options(const po::variables_map& vm) {
  FuzzRun run;
  FuzzParams& p = run.c.formulas;
  p.seed = cli::seed_arg(vm, "seed");
  p.min_vars = cli::int_arg(vm, "min-vars", 1, 64);
  p.max_vars = cli::int_arg(vm, "max-vars", 1, 64);
  if (p.min_vars < 1 || p.max_vars > 64 || p.min_vars > p.max_vars)
    throw UserError("--min-vars and --max-vars: need 1 <= min <= max <= 64");
  run.kinds = vm["kinds"].as<std::string>();
  p.kinds = parse_kinds(run.kinds);
  run.shard = cli::shard_arg(vm);
  VerifyOptions& vo = run.c.verify;
  vo.solve_seconds = cli::seconds_arg(vm, "timeout");
  vo.max_states = cli::count_arg(vm, "max-states", 1);
  cli::verify_model_args(vm, vo);
  run.json = vm.count("json") > 0;
  run.count_given = vm.count("count") > 0;
  run.index_given = vm.count("index") > 0;
  FuzzCampaign& c = run.c;
  c.first = run.shard.k;  // indices first, first + N, ... < last
  c.last = UINT64_MAX;
  c.step = run.shard.n;
  if (run.index_given) {
    c.first = cli::count_arg(vm, "index", 0, UINT64_MAX - 1);
    c.last = c.first + 1;
    run.shard.n = c.step = 1;
  } else if (run.count_given) {
    c.last = cli::count_arg(vm, "count", 1);
  } else if (!vm.count("time")) {
    c.last = 1000;
  }
  c.seconds = cli::seconds_arg_opt(vm, "time").value_or(0);
  if (run.index_given && (run.count_given || vm.count("time")))
    throw UserError("--index replays one formula: give no --count or --time with it");
  c.keep_going = vm.count("keep-going") > 0;
  c.jobs = cli::jobs_arg(vm);
  run.out = vm["out"].as<std::string>();
  return run;
}

std::string fuzz_header(const FuzzRun& run) {
  const FuzzParams& p = run.c.formulas;
  const VerifyOptions& vo = run.c.verify;
  std::string header = "gridlock fuzz: seed " + std::to_string(p.seed) + ", shard " + run.shard.str() + ", " +
                       std::to_string(p.min_vars) + ".." + std::to_string(p.max_vars) + " variables, kinds " +
                       run.kinds + ", model " + vo.models.name() + (vo.direct ? ", direct" : "");
  if (vo.mutation != Mutation::None) header += ", BROKEN GADGET " + std::string(mutation_name(vo.mutation));
  return header;
}

// The command that replays finding `index` alone.
std::string replay_command(const FuzzRun& run, uint64_t index) {
  const FuzzParams& p = run.c.formulas;
  const VerifyOptions& vo = run.c.verify;
  return "gridlock fuzz --seed " + std::to_string(p.seed) + " --index " + std::to_string(index) + " --min-vars " +
         std::to_string(p.min_vars) + " --max-vars " + std::to_string(p.max_vars) + " --kinds " + run.kinds +
         (vo.models.has(TimeModel::Continuous) ? std::string(" --model ") + vo.models.name() : "") +
         (vo.direct ? " --direct" : "") + (vo.certify ? "" : " --no-certificates") +
         (vo.mutation != Mutation::None ? std::string(" --break-gadget ") + mutation_name(vo.mutation) : "");
}

std::string finding_folder(const FuzzRun& run, uint64_t index) {
  return run.out + "/seed" + std::to_string(run.c.formulas.seed) + "-formula" + std::to_string(index);
}

std::string status_line(const FuzzTally& t) {
  std::ostringstream s;
  s << t.formulas << " formulas (" << t.sat << " SAT, " << t.unsat << " UNSAT, " << t.unknown << " unknown), "
    << static_cast<uint64_t>(static_cast<double>(t.formulas) / std::max(t.seconds, 1e-9)) << "/s, " << t.certificates
    << " certificates (" << t.no_certified << " NO certificates), " << t.disagreements << " disagreements, "
    << static_cast<uint64_t>(t.seconds) << " s";
  return s.str();
}

// Saves a finding as a replayable folder, then reports it (c lines).
// A finding that cannot be saved is printed in full on stderr first (never
// lost), then the command fails naming the file it could not write.
void save_finding(const FuzzRun& run, const FuzzFinding& f, const VerifyResult& shrunk) {
  const std::string dir = finding_folder(run, f.index);
  std::optional<UserError> failed;
  try {
    if (auto err = write_reproducer(shrunk, dir, run.c.verify)) throw UserError(*err);
    cli::write_text_file(dir + "/original.cnf", to_dimacs(f.original));
    write_result_animations(shrunk, dir);  // watch the disagreeing schedules run
  } catch (const UserError& e) {
    failed = e;
  }
  if (failed) {
    std::cerr << "c finding NOT saved (" << failed->what() << "): formula " << f.index << ": " << f.problem
              << "\nc replay: " << replay_command(run, f.index) << "\nc shrunk formula:\n";
    std::istringstream lines(to_dimacs(f.shrunk));
    for (std::string l; std::getline(lines, l);) std::cerr << "c   " << l << "\n";
    std::cerr << std::flush;
    throw *failed;
  }
  if (run.json) return;
  std::cout << "c shrunk in " << f.shrink.tries << " tries to " << f.shrunk.num_vars << " variables, "
            << f.shrunk.clauses.size() << " clauses: " << f.problem << "\n";
  std::istringstream lines(to_dimacs(f.shrunk));
  for (std::string l; std::getline(lines, l);)
    if (l.rfind("c ", 0) != 0) std::cout << "c   " << l << "\n";
  std::cout << "c saved to " << dir << " (replay: " << replay_command(run, f.index) << ")" << std::endl;
}

nlohmann::json fuzz_json(const FuzzRun& run, const FuzzTally& t) {
  const FuzzCampaign& c = run.c;
  nlohmann::json findings = nlohmann::json::array();
  for (const FuzzFinding& f : t.findings)
    findings.push_back({{"index", f.index},
                        {"problem", f.problem},
                        {"folder", finding_folder(run, f.index)},
                        {"replay", replay_command(run, f.index)},
                        {"shrunk_variables", f.shrunk.num_vars},
                        {"shrunk_clauses", f.shrunk.clauses.size()},
                        {"shrink_tries", f.shrink.tries},
                        {"dimacs", to_dimacs(f.shrunk)}});
  nlohmann::json j;
  j["command"] = "fuzz";
  j["seed"] = std::to_string(c.formulas.seed);  // a string: seeds above 2^53 survive JSON readers
  j["shard"] = run.shard.str();
  j["formulas"] = t.formulas;
  j["sat"] = t.sat;
  j["unsat"] = t.unsat;
  j["unknown"] = t.unknown;
  j["certificates_checked"] = t.certificates;
  j["no_certificates_checked"] = t.no_certified;
  j["disagreements"] = t.disagreements;
  j["seconds"] = t.seconds;
  j["findings"] = findings;
  j["status"] = t.disagreements ? "DISAGREE" : "AGREE";
  j["interrupted"] = t.interrupted;
  // The campaign's settings, so that 'gridlock merge' only combines shards of one campaign.
  j["campaign"] = {{"count", run.count_given ? nlohmann::json(c.last) : nlohmann::json()},
                   {"time", c.seconds},
                   {"index", run.index_given ? nlohmann::json(c.first) : nlohmann::json()},
                   {"min_vars", c.formulas.min_vars},
                   {"max_vars", c.formulas.max_vars},
                   {"kinds", run.kinds},
                   {"max_states", c.verify.max_states},
                   {"keep_going", c.keep_going},
                   {"break_gadget", mutation_name(c.verify.mutation)},
                   {"model", c.verify.models.name()},
                   {"direct", c.verify.direct}};
  return j;
}

int run_fuzz(const std::vector<std::string>& args) {
  cli::install_stop_handlers();  // first: a signal at any moment gives the partial summary
  po::options_description opts = fuzz_options();
  po::options_description hidden;
  hidden.add_options()("break-gadget", po::value<std::string>()->default_value("none"),
                       "self-test: compile with a broken gadget, so that the fuzzer must find it");
  po::positional_options_description pos;
  po::variables_map vm;
  if (!cli::parse_args(args, opts, pos, vm, "fuzz [--seed S] [--count N | --time T] [--shard K/N]", kFuzzDescription,
                       &hidden))
    return 0;
  const FuzzRun run = read_fuzz_options(vm);
  cli::check_folder_can_be_made(run.out);  // findings survive: checked before any work
  if (!run.json) std::cout << "c " << fuzz_header(run) << std::endl;

  // Each formula allocates and frees the same few large tables (instance,
  // motion tables, simulator arrays); with glibc's allocator, keep them in
  // the heap instead of mapping and unmapping fresh pages per formula
  // (about 7% of the time). No effect when the binary links jemalloc
  // (CMakeLists.txt, GRIDLOCK_JEMALLOC), which keeps them itself.
  mallopt(M_MMAP_THRESHOLD, 64 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
  cli::ProgressLine progress(!run.json);
  FuzzEvents events;
  events.disagreement = [&](uint64_t i, const VerifyResult& r) {
    progress.clear();
    if (!run.json) std::cout << "c formula " << i << " disagrees: " << r.problem << "; shrinking" << std::endl;
  };
  events.finding = [&](const FuzzFinding& f, const VerifyResult& shrunk) { save_finding(run, f, shrunk); };
  // The line adds up every worker's formulas (counted in order on this thread).
  const std::string progress_name = "fuzz (" + std::to_string(run.c.jobs) + " workers): ";
  events.progress = [&](const FuzzTally& t) { progress.show(progress_name + status_line(t)); };
  const FuzzTally t = run_fuzz_campaign(run.c, events);
  progress.clear();
  const nlohmann::json j = fuzz_json(run, t);
  cli::write_json_out(vm, j);
  if (run.json) {
    std::cout << j.dump() << std::endl;
  } else {
    std::cout << "c " << status_line(t) << "\n";
    if (t.interrupted) std::cout << "c " << cli::interrupted_note() << ": partial campaign\n";
    std::cout << "s " << (t.disagreements ? "DISAGREE" : "AGREE") << std::endl;
  }
  if (t.interrupted) return cli::interrupted_exit_code();
  return t.disagreements ? 1 : 0;
}

Command reg{"fuzz", "hunt for a counterexample among many small formulas (seeded, sharded, shrinks what it finds)",
            run_fuzz};

}  // namespace
}  // namespace gridlock
