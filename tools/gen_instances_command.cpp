// gridlock gen-instances: a labelled benchmark set of lattice instances of
// Discrete (and/or, --model, Continuous) Collision-free Schedule, each answer
// certified (docs/verify.md):
// YES by a schedule the simulator has accepted, NO by CaDiCaL's UNSAT of the
// source formula (the reduction preserves satisfiability: docs/gadgets.md,
// and verify/fuzz test it). The generation is verify/instance_set.hpp's
// make_instance_set; this file reads the options, prepares the folder,
// writes the files and the manifest, and prints the c lines.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cnf/sat_solver.hpp"
#include "common/limits.hpp"
#include "tools/campaign_cli.hpp"
#include "tools/cli_common.hpp"
#include "tools/command.hpp"
#include "tools/options.hpp"
#include "tools/run_identity.hpp"
#include "tools/set_folder.hpp"
#include "tools/user_error.hpp"
#include "verify/instance_set.hpp"

namespace gridlock {
namespace {

namespace fs = std::filesystem;
namespace po = boost::program_options;

po::options_description gen_instances_options() {
  po::options_description opts("options");
  opts.add_options()("help,h", "show this help")("out,o", po::value<std::string>()->required(),
                                                 "folder to write (created; must be empty unless --force): "
                                                 "instances, formulas, witnesses, manifest.json")(
      "force",
      "write into a non-empty folder: the files a previous gridlock run wrote there (listed in its "
      "manifests and ledger) are removed first; nothing else")("seed", po::value<std::string>()->default_value("1"),
                                                               "seed of the random formulas")(
      "threshold", po::value<std::string>()->default_value("10"), "random 3-SAT formulas at the threshold ratio 4.26")(
      "lsat", po::value<std::string>()->default_value("10"), "random LSAT<=3 formulas (clauses of 1 to 3 literals)")(
      "vars", po::value<std::string>()->default_value("12"), "variables of each random formula (3 to 1000)")(
      "yes", po::value<std::string>(), "keep only this many YES instances of the random ones (default: all)")(
      "no", po::value<std::string>(),
      "keep only this many NO instances of the random ones (default: all); "
      "with --yes/--no, formulas are drawn until both are met")(
      "timeout", po::value<std::string>()->default_value("60"),
      "seconds CaDiCaL may spend labelling one formula; a formula not decided in time is skipped (noted)")(
      "formula", po::value<std::vector<std::string>>()->composing(), "also compile this given formula (repeatable)")(
      "shard", po::value<std::string>()->default_value("0/1"),
      "K/N: make only the instances i (given ones first, then "
      "threshold, then lsat) with i % N == K; the manifest is then "
      "manifest-shard-K-of-N.json, and shards may share a folder "
      "(not with --yes/--no)")("json-out", po::value<std::string>(),
                               "also write the manifest to this file ('gridlock merge' combines shards)")(
      "model", po::value<std::string>()->default_value("discrete"),
      "discrete (NAME.grid, NAME.schedule), continuous (the continuous reduction: NAME.grid, NAME.times) or both "
      "(NAME.grid and NAME-continuous.grid)");
  cli::add_jobs_option(opts);
  return opts;
}

const char* const kGenInstancesDescription =
    "Writes a labelled set of lattice instances: each formula (random 3-SAT at the threshold,\n"
    "random LSAT<=3, or given) goes through to-lsat and the gadget compiler. Labels are certified:\n"
    "YES with a witness schedule (CaDiCaL's model lifted, accepted by the exact simulator, saved\n"
    "as NAME.schedule for 'gridlock check --order-file'), NO by CaDiCaL's UNSAT of the source\n"
    "and by a NO certificate (NAME.nocert, for 'gridlock certify [--model continuous]').\n"
    "manifest.json lists every instance with its answer, certificate, sizes and seed; it is\n"
    "written last. Every file is written atomically. On a terminal a progress line shows the\n"
    "count and the formula in progress. SIGINT/SIGTERM stop between formulas: the finished\n"
    "ones stay, with a manifest marked \"interrupted\": true; exit 130/143.\n"
    "--model continuous: instances of Continuous Collision-free Schedule (compile --model\n"
    "continuous); YES certified by start times (NAME.times, for 'gridlock check --times'),\n"
    "NO also proved by the exact continuous solver within 60 s (manifest field\n"
    "solver_check) with its NO certificate (kind bounds, docs/certificates.md).\n"
    "--jobs N labels N formulas at once (default: every core); the files, the manifest and the\n"
    "c lines are the same for every N.";

InstanceSetPlan read_plan(const po::variables_map& vm, std::string& model_name) {
  InstanceSetPlan plan;
  plan.seed = cli::seed_arg(vm, "seed");
  plan.vars = cli::int_arg(vm, "vars", 3, 1000);
  plan.threshold = cli::int_arg(vm, "threshold", 0, 1'000'000);
  plan.lsat = cli::int_arg(vm, "lsat", 0, 1'000'000);
  plan.want_yes = vm.count("yes") ? cli::int_arg(vm, "yes", 0, 1'000'000) : -1;
  plan.want_no = vm.count("no") ? cli::int_arg(vm, "no", 0, 1'000'000) : -1;
  plan.sat_seconds = cli::seconds_arg(vm, "timeout");
  plan.shard = cli::shard_arg(vm);
  plan.jobs = cli::jobs_arg(vm);
  if (plan.mix() && plan.shard.n > 1)
    throw UserError("--shard cannot be combined with --yes/--no (they draw until counts are met)");
  model_name = vm["model"].as<std::string>();
  if (model_name != "discrete" && model_name != "continuous" && model_name != "both")
    throw UserError("--model must be discrete, continuous or both, not '" + model_name + "'");
  plan.models.clear();
  if (model_name != "continuous") plan.models.push_back(TimeModel::Discrete);
  if (model_name != "discrete") plan.models.push_back(TimeModel::Continuous);
  if (vm.count("formula")) {
    cli::refuse_name_clashes(vm["formula"].as<std::vector<std::string>>(), "the files given-NAME.*");
    for (const auto& path : vm["formula"].as<std::vector<std::string>>())
      plan.given.push_back({"given-" + fs::path(path).stem().string(), "given " + path,
                            cli::load_formula(path, true, cli::FormulaUse::Compile), 0});
  }
  return plan;
}

nlohmann::json entry_json(const SetInstance& e) {
  nlohmann::json j;
  j["index"] = e.index;  // position in the unsharded set
  j["name"] = e.name;
  j["model"] = time_model_name(e.model);
  j["instance"] = e.instance_file;
  j["formula"] = e.formula_file;
  j["origin"] = e.origin;
  if (e.seed) j["seed"] = std::to_string(e.seed);  // a string: seeds above 2^53 survive JSON readers
  j["variables"] = e.variables;
  j["clauses"] = e.clauses;
  j["lsat_variables"] = e.lsat_variables;
  j["lsat_clauses"] = e.lsat_clauses;
  j["nodes"] = e.nodes;
  j["operations"] = e.operations;
  j["couplings"] = e.couplings;
  j["max_coupling"] = e.max_coupling;
  if (e.yes) {
    const bool cont = e.model == TimeModel::Continuous;
    j["certificate"] = {{"kind", cont ? "start times" : "schedule"},
                        {"file", e.certificate_file},
                        {"checked_by", "gridlock simulator"}};
    j["answer"] = "YES";
  } else {
    j["answer"] = "NO";
    j["certificate"] = {{"kind", "source formula unsatisfiable"}, {"solver", sat_solver_name()}};
    if (!e.no_certificate_file.empty())
      j["no_certificate"] = {{"kind", "NO certificate (docs/certificates.md)"},
                             {"file", e.no_certificate_file},
                             {"checked_by", "gridlock certify"}};
    if (!e.solver_check.empty())
      j["solver_check"] = {{"solver", "gridlock solve --model continuous"}, {"answer", e.solver_check}};
  }
  return j;
}

// The run's identity: every option that changes the set, and the given
// formulas with their content hashes. Not the split (--shard K/N): instance
// i is the same in every split, so all shards and the unsharded run share
// the identity (and may share a folder: names never clash, files agree).
nlohmann::json set_run(const po::variables_map& vm, const InstanceSetPlan& plan, const std::string& model_name) {
  nlohmann::json options = {{"seed", std::to_string(plan.seed)},
                            {"vars", plan.vars},
                            {"threshold", plan.threshold},
                            {"lsat", plan.lsat},
                            {"yes", plan.want_yes},
                            {"no", plan.want_no},
                            {"timeout", plan.sat_seconds},
                            {"model", model_name}};
  const auto given = vm.count("formula") ? vm["formula"].as<std::vector<std::string>>() : std::vector<std::string>{};
  return cli::run_json("gen-instances", options, cli::input_list(given));
}

nlohmann::json manifest_json(const InstanceSetPlan& plan, const std::string& model_name, const InstanceSetTally& t,
                             const nlohmann::json& run) {
  nlohmann::json entries = nlohmann::json::array();
  for (const SetInstance& e : t.instances) entries.push_back(entry_json(e));
  nlohmann::json manifest;
  manifest["generator"] = "gridlock gen-instances";
  manifest["problem"] =
      model_name == "discrete"
          ? "Discrete Collision-free Schedule (is there an order of the couplings with no collision?)"
      : model_name == "continuous"
          ? "Continuous Collision-free Schedule (are there start times of the couplings with no collision?)"
          : "Discrete and Continuous Collision-free Schedule (entry field 'model')";
  manifest["model"] = model_name;
  manifest["seed"] = std::to_string(plan.seed);  // a string: seeds above 2^53 survive JSON readers
  manifest["vars"] = plan.vars;
  manifest["yes"] = t.yes;
  manifest["no"] = t.no;
  manifest["skipped"] = t.skipped;
  manifest["interrupted"] = t.interrupted;
  manifest["shard"] = plan.shard.str();
  if (!plan.mix()) manifest["planned"] = plan.planned();
  manifest["run"] = run;
  manifest["run_id"] = cli::run_id(run);
  manifest["instances"] = entries;
  return manifest;
}

int run_gen_instances(const std::vector<std::string>& args) {
  cli::install_stop_handlers();  // first: a signal at any moment gives the partial summary
  po::options_description opts = gen_instances_options();
  po::positional_options_description pos;
  po::variables_map vm;
  if (!cli::parse_args(args, opts, pos, vm,
                       "gen-instances -o DIR [--threshold N] [--lsat N] [--vars V] [--formula F]...",
                       kGenInstancesDescription, nullptr))
    return 0;
  const std::string out = vm["out"].as<std::string>();
  std::string model_name;
  const InstanceSetPlan plan = read_plan(vm, model_name);
  const Shard& shard = plan.shard;
  const std::string manifest_name = shard.n == 1 ? "manifest.json"
                                                 : "manifest-shard-" + std::to_string(shard.k) + "-of-" +
                                                       std::to_string(shard.n) + ".json";
  const cli::SetFolder folder{out, shard.k, shard.n, set_run(vm, plan, model_name)};
  cli::prepare_set_folder(folder, manifest_name, vm.count("force") > 0);

  const Deadline clock;  // only its clock: the progress line's seconds
  cli::ProgressLine progress(true);
  InstanceSetEvents events;
  events.labelling = [&](const std::string& name, const InstanceSetTally& t) {
    progress.show("gen-instances: " + std::to_string(t.instances.size()) + " written (" + std::to_string(t.yes) +
                      " YES, " + std::to_string(t.no) + " NO), labelling " + name + ", " +
                      std::to_string(static_cast<uint64_t>(clock.elapsed())) + " s",
                  true);
  };
  events.labelled = [&] { progress.clear(); };
  events.skipped = [&](const std::string& name) {
    std::cout << "c " << name << ": skipped, CaDiCaL did not decide it within --timeout " << plan.sat_seconds << " s"
              << std::endl;
  };
  events.write = [&](const std::string& file, const std::string& text) { cli::write_set_file(folder, file, text); };
  events.instance = [&](const SetInstance& e) {
    std::cout << "c " << e.name << ": " << (e.yes ? "YES" : "NO") << ", " << e.nodes << " nodes, " << e.couplings
              << " couplings" << std::endl;
  };
  const InstanceSetTally t = make_instance_set(plan, events);
  progress.clear();  // a stop may cut a labelling short, with its progress line still drawn

  const nlohmann::json manifest = manifest_json(plan, model_name, t, folder.run);
  events.write(manifest_name, manifest.dump(2) + "\n");  // last: it lists only files already in place
  cli::write_json_out(vm, manifest);
  std::cout << "c wrote " << t.instances.size() << " instances (" << t.yes << " YES, " << t.no << " NO) and " << out
            << "/" << manifest_name << std::endl;
  if (t.interrupted) {
    std::cout << "c " << cli::interrupted_note() << ": the manifest lists the " << t.instances.size()
              << " instances finished" << std::endl;
    return cli::interrupted_exit_code();
  }
  if (t.short_of(plan))
    std::cout << "c note: fewer instances than asked for of one answer (random formulas of this kind rarely have it)"
              << std::endl;
  return 0;
}

Command reg{"gen-instances", "write a labelled benchmark set of lattice instances (certified answers, manifest)",
            run_gen_instances};

}  // namespace
}  // namespace gridlock
