// gridlock random: seeded random instances of the named shape families
// (lattice/random_instance.hpp, random_family_instance): one instance to a
// file or standard output, or a folder of them with a manifest, optionally
// labelled by the exact discrete solver (docs/grid-format.md, "Random
// instances").
#include <filesystem>
#include <sstream>

#include <nlohmann/json.hpp>

#include "lattice/grid_format.hpp"
#include "lattice/random_instance.hpp"
#include "solver/planted.hpp"
#include "solver/solve.hpp"
#include "tools/cli_common.hpp"
#include "tools/command.hpp"
#include "tools/options.hpp"
#include "tools/set_folder.hpp"
#include "tools/user_error.hpp"

namespace gridlock {
namespace {

namespace po = boost::program_options;

po::options_description random_options() {
  po::options_description opts("options");
  opts.add_options()("help,h", "show this help")("family", po::value<std::string>()->default_value("tree"),
                                                 "tree, cycles, sparse, dense or path")(
      "couplings", po::value<std::string>()->default_value("100"), "couplings wanted (1 to 100000)")(
      "max-coupling", po::value<std::string>()->default_value("3"), "operations per coupling: 1 to this (1 to 16)")(
      "kinds", po::value<std::string>()->default_value("expand,contract,grow"),
      "operation kinds allowed, comma-separated: expand, contract, grow")("horizontal",
                                                                          "only horizontal operations (+x, -x)")(
      "planted",
      "a YES instance: couplings drawn from a larger instance of the family and kept while a "
      "random order stays collision-free (that order is written as a comment and to the manifest)")(
      "seed", po::value<std::string>()->default_value("1"), "seed of the first instance (then seed+1, ...)")(
      "count", po::value<std::string>()->default_value("1"), "instances to make (more than 1: --output is a folder)")(
      "label", po::value<std::string>(),
      "solve each instance (discrete, default engine) for at most S seconds and record the answer")(
      "output,o", po::value<std::string>()->default_value("-"), "file (or folder with --count > 1); - = stdout")(
      "force", "with --count > 1: write the set into a folder that is not empty (files of the same names replaced)");
  return opts;
}

// Before any work (--label solves): the set's folder can be made and is
// empty, or force; a set never lands on someone else's files unasked.
void check_set_folder(const std::string& out, bool force) {
  if (out == "-") throw UserError("--count above 1 needs a folder: -o FOLDER");
  cli::check_folder_can_be_made(out);
  if (!cli::folder_empty(out) && !force)
    throw UserError(Diagnostic{out, 0, "folder is not empty (give --force to write the set into it)"});
}

RandomFamilyParams family_args(const po::variables_map& vm) {
  RandomFamilyParams f;
  if (!parse_shape_family(vm["family"].as<std::string>(), f.family))
    throw UserError("--family must be tree, cycles, sparse, dense or path, not '" + vm["family"].as<std::string>() +
                    "'");
  f.couplings = static_cast<uint32_t>(cli::int_arg(vm, "couplings", 1, 100000));
  f.max_coupling = static_cast<uint32_t>(cli::int_arg(vm, "max-coupling", 1, 16));
  f.expand = f.contract = f.grow = false;
  std::stringstream kinds(vm["kinds"].as<std::string>());
  for (std::string k; std::getline(kinds, k, ',');) {
    if (k == "expand") f.expand = true;
    else if (k == "contract") f.contract = true;
    else if (k == "grow") f.grow = true;
    else throw UserError("--kinds takes expand, contract and grow, not '" + k + "'");
  }
  if (!f.expand && !f.contract && !f.grow) throw UserError("--kinds needs at least one operation kind");
  f.horizontal_only = vm.count("horizontal") > 0;
  return f;
}

// The command line that makes exactly this instance again.
std::string replay_line(const RandomFamilyParams& f, const po::variables_map& vm, uint64_t seed) {
  std::string s = "gridlock random --family " + std::string(shape_family_name(f.family)) + " --couplings " +
                  std::to_string(f.couplings) + " --max-coupling " + std::to_string(f.max_coupling) + " --kinds " +
                  vm["kinds"].as<std::string>();
  if (f.horizontal_only) s += " --horizontal";
  if (vm.count("planted")) s += " --planted";
  return s + " --seed " + std::to_string(seed);
}

int run_random(const std::vector<std::string>& args) {
  po::variables_map vm;
  po::positional_options_description none;
  if (!cli::parse_args(args, random_options(), none, vm,
                       "random [--family F] [--couplings K] [--max-coupling M] [--kinds LIST] [--horizontal] "
                       "[--planted] [--seed S] [--count N] [--label SECONDS] [--force] [-o OUT]",
                       "Seeded random instances of Collision-free Schedule: connected shapes (trees, shapes with\n"
                       "cycles, sparse or dense), operations of the chosen kinds in all four directions (or only\n"
                       "horizontal), grouped into K couplings of 1 to M operations. The same options and seed give\n"
                       "the same instance on every machine; each file names the command that makes it again.\n"
                       "--count N > 1 writes NAME.grid files and manifest.json into the folder -o (empty, or\n"
                       "with --force); --label S solves each one (discrete model) and records YES / NO / UNKNOWN\n"
                       "(and the order of a YES). --planted makes YES instances: a random order, kept\n"
                       "collision-free, is recorded."))
    return 0;
  const RandomFamilyParams f = family_args(vm);
  const uint64_t seed0 = cli::seed_arg(vm, "seed");
  const int count = cli::int_arg(vm, "count", 1, 1'000'000);
  const std::string out = vm["output"].as<std::string>();
  const double label = vm.count("label") ? cli::seconds_arg(vm, "label") : -1;
  if (count > 1) check_set_folder(out, vm.count("force") > 0);
  std::vector<std::pair<std::string, std::string>> files;
  nlohmann::json entries = nlohmann::json::array();
  for (int i = 0; i < count; ++i) {
    const uint64_t seed = seed0 + static_cast<uint64_t>(i);
    nlohmann::json e;
    Instance inst;
    std::vector<std::string> comments = {replay_line(f, vm, seed)};
    if (vm.count("planted")) {
      PlantedInstance p = planted_family_instance(f, seed);
      inst = std::move(p.instance);
      std::string order;
      for (const std::string& n : p.hidden_order) order += (order.empty() ? "" : " ") + n;
      e["hidden_order"] = order;
      comments.push_back("planted: YES, collision-free order: " + order);
    } else {
      inst = random_family_instance(f, seed);
    }
    const std::string name = std::string(shape_family_name(f.family)) + "-k" + std::to_string(f.couplings) + "-s" +
                             std::to_string(seed);
    e["name"] = name;
    e["seed"] = std::to_string(seed);
    e["nodes"] = inst.num_nodes();
    e["operations"] = inst.ops().size();
    e["couplings"] = inst.couplings().size();
    if (label >= 0) {
      SolveOptions o;
      o.seconds = label;
      const SolveResult r = solve_discrete(inst, o);
      e["answer"] = verdict_name(r.status);
      e["engine"] = r.stats.engine;
      e["seconds"] = r.stats.seconds;
      comments.push_back("discrete: " + std::string(verdict_name(r.status)) + " (engine " + r.stats.engine + ")");
      if (r.status == Verdict::Yes) {
        std::string order;
        for (CouplingId q : r.order) order += (order.empty() ? "" : " ") + inst.couplings()[q].name;
        e["order"] = order;
      }
    }
    std::ostringstream grid;
    write_instance(grid, inst, comments);
    if (count == 1) {
      files.emplace_back(out, grid.str());
    } else {
      e["instance"] = name + ".grid";
      files.emplace_back((std::filesystem::path(out) / (name + ".grid")).string(), grid.str());
    }
    entries.push_back(e);
  }
  if (count > 1) {
    std::error_code ec;
    std::filesystem::create_directories(out, ec);
    if (ec) throw UserError(Diagnostic{out, 0, "cannot create folder: " + ec.message()});
    nlohmann::json manifest;
    manifest["generator"] = "gridlock random";
    manifest["command"] = replay_line(f, vm, seed0) + " --count " + std::to_string(count);
    manifest["instances"] = entries;
    files.emplace_back((std::filesystem::path(out) / "manifest.json").string(), manifest.dump(2) + "\n");
  }
  cli::write_text_files(files);
  return 0;
}

Command reg{"random", "write seeded random instances of a shape family (trees, cycles, sparse, dense)", run_random};

}  // namespace
}  // namespace gridlock
