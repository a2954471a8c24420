// gridlock gen-instances: a labelled benchmark set of lattice instances of
// Discrete (and/or, --model, Continuous) Collision-free Schedule, each answer
// certified (docs/verify.md):
// YES by a schedule the simulator has accepted, NO by CaDiCaL's UNSAT of the
// source formula (the reduction preserves satisfiability: docs/gadgets.md,
// and verify/fuzz test it).
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cnf/dimacs.hpp"
#include "cnf/generate.hpp"
#include "cnf/sat_solver.hpp"
#include "common/limits.hpp"
#include "lattice/grid_format.hpp"
#include "lattice/simulate.hpp"
#include "reductions/compile.hpp"
#include "reductions/to_lsat.hpp"
#include "tools/cli_common.hpp"
#include "tools/command.hpp"
#include "tools/options.hpp"
#include "verify/fuzz.hpp"

namespace gridlock {
namespace {

namespace fs = std::filesystem;

// Creates out, or checks that it is empty. With force, a non-empty folder is
// accepted after removing what a previous set left there (manifest.json and
// top-level *.grid, *.cnf, *.schedule files, and temporary *.tmp.* files);
// anything else in it stays.
void prepare_output_folder(const std::string& out, bool force) {
  std::error_code ec;
  if (fs::exists(out, ec) && !fs::is_directory(out, ec))
    throw UserError(Diagnostic{out, 0, "exists and is not a folder"});
  fs::create_directories(out, ec);
  if (ec) throw UserError(Diagnostic{out, 0, "cannot create folder: " + ec.message()});
  std::vector<fs::path> old;
  bool non_empty = false;
  for (const auto& e : fs::directory_iterator(out, ec)) {
    non_empty = true;
    const std::string name = e.path().filename().string();
    const std::string ext = e.path().extension().string();
    if (e.is_regular_file() && (name == "manifest.json" || ext == ".grid" || ext == ".cnf" || ext == ".schedule" ||
                                name.find(".tmp.") != std::string::npos))
      old.push_back(e.path());
  }
  if (ec) throw UserError(Diagnostic{out, 0, "cannot list folder: " + ec.message()});
  if (!non_empty) return;
  if (!force) throw UserError(Diagnostic{out, 0, "folder is not empty (give --force to replace the set in it)"});
  // The manifest first: a folder is never described by a stale manifest.
  std::sort(old.begin(), old.end(), [](const fs::path& a, const fs::path& b) {
    return (a.filename() == "manifest.json") > (b.filename() == "manifest.json");
  });
  for (const auto& p : old)
    if (!fs::remove(p, ec) || ec) throw UserError(Diagnostic{p.string(), 0, "cannot remove: " + ec.message()});
}

// A sharded run shares its folder with the other shards of the set: the
// folder may hold their files, but not this shard's manifest (a shard
// written twice), unless force, which removes that manifest first.
void prepare_shard_folder(const std::string& out, const std::string& manifest_name, bool force) {
  std::error_code ec;
  if (fs::exists(out, ec) && !fs::is_directory(out, ec))
    throw UserError(Diagnostic{out, 0, "exists and is not a folder"});
  fs::create_directories(out, ec);
  if (ec) throw UserError(Diagnostic{out, 0, "cannot create folder: " + ec.message()});
  const fs::path manifest = fs::path(out) / manifest_name;
  if (!fs::exists(manifest, ec)) return;
  if (!force)
    throw UserError(
        Diagnostic{manifest.string(), 0, "this shard was already written here (give --force to write it again)"});
  if (!fs::remove(manifest, ec) || ec)
    throw UserError(Diagnostic{manifest.string(), 0, "cannot remove: " + ec.message()});
}

struct Source {
  std::string name, origin;  // file stem, how it was made
  Formula formula;
  uint64_t seed = 0;
};

int run_gen_instances(const std::vector<std::string>& args) {
  cli::install_stop_handlers();  // first: a signal at any moment gives the partial summary
  namespace po = boost::program_options;
  po::options_description opts("options");
  opts.add_options()("help,h", "show this help")("out,o", po::value<std::string>()->required(),
                                                 "folder to write (created; must be empty unless --force): "
                                                 "instances, formulas, witnesses, manifest.json")(
      "force",
      "write into a non-empty folder: the files of a previous set there (manifest.json, *.grid, *.cnf, "
      "*.schedule) are removed first")("seed", po::value<std::string>()->default_value("1"),
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
  po::positional_options_description pos;
  po::variables_map vm;
  if (!cli::parse_args(args, opts, pos, vm,
                       "gen-instances -o DIR [--threshold N] [--lsat N] [--vars V] [--formula F]...",
                       "Writes a labelled set of lattice instances: each formula (random 3-SAT at the threshold,\n"
                       "random LSAT<=3, or given) goes through to-lsat and the gadget compiler. Labels are certified:\n"
                       "YES with a witness schedule (CaDiCaL's model lifted, accepted by the exact simulator, saved\n"
                       "as NAME.schedule for 'gridlock check --order-file'), NO by CaDiCaL's UNSAT of the source.\n"
                       "manifest.json lists every instance with its answer, certificate, sizes and seed; it is\n"
                       "written last. Every file is written atomically. On a terminal a progress line shows the\n"
                       "count and the formula in progress. SIGINT/SIGTERM stop between formulas: the finished\n"
                       "ones stay, with a manifest marked \"interrupted\": true; exit 130/143.\n"
                       "--model continuous: instances of Continuous Collision-free Schedule (compile --model\n"
                       "continuous); YES certified by start times (NAME.times, for 'gridlock check --times').",
                       nullptr))
    return 0;
  const std::string out = vm["out"].as<std::string>();
  const uint64_t seed = cli::seed_arg(vm, "seed");
  const int vars = cli::int_arg(vm, "vars", 3, 1000);
  const int threshold_count = cli::int_arg(vm, "threshold", 0, 1'000'000);
  const int lsat_count = cli::int_arg(vm, "lsat", 0, 1'000'000);
  const int want_yes = vm.count("yes") ? cli::int_arg(vm, "yes", 0, 1'000'000) : -1;
  const int want_no = vm.count("no") ? cli::int_arg(vm, "no", 0, 1'000'000) : -1;
  const double timeout = cli::seconds_arg(vm, "timeout");
  const bool mix = want_yes >= 0 || want_no >= 0;
  uint64_t shard = 0, shards = 1;
  cli::parse_shard(vm["shard"].as<std::string>(), shard, shards);
  if (mix && shards > 1) throw UserError("--shard cannot be combined with --yes/--no (they draw until counts are met)");
  const std::string model_name = vm["model"].as<std::string>();
  if (model_name != "discrete" && model_name != "continuous" && model_name != "both")
    throw UserError("--model must be discrete, continuous or both, not '" + model_name + "'");
  std::vector<ReductionModel> models;
  if (model_name != "continuous") models.push_back(ReductionModel::Discrete);
  if (model_name != "discrete") models.push_back(ReductionModel::Continuous);

  std::vector<Source> given;
  if (vm.count("formula"))
    for (const auto& path : vm["formula"].as<std::vector<std::string>>())
      given.push_back({"given-" + fs::path(path).stem().string(), "given " + path,
                       cli::load_formula(path, true, cli::FormulaUse::Compile), 0});

  const std::string manifest_name = shards == 1 ? "manifest.json"
                                                : "manifest-shard-" + std::to_string(shard) + "-of-" +
                                                      std::to_string(shards) + ".json";
  if (shards == 1) prepare_output_folder(out, vm.count("force") > 0);
  else prepare_shard_folder(out, manifest_name, vm.count("force") > 0);
  const bool progress = isatty(STDERR_FILENO);
  const auto t0 = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  auto write = [&](const std::string& file, const std::string& text) { cli::write_text_file(out + "/" + file, text); };
  int skipped = 0;

  nlohmann::json entries = nlohmann::json::array();
  int yes = 0, no = 0;
  // Labels one formula; returns false if --yes/--no say it is not wanted.
  auto label = [&](const Source& s, bool random, uint64_t index) {
    if (progress)
      std::cerr << "\r\033[Kgen-instances: " << entries.size() << " written (" << yes << " YES, " << no
                << " NO), labelling " << s.name << ", " << static_cast<uint64_t>(elapsed()) << " s" << std::flush;
    SatLimits limits;
    limits.seconds = timeout;
    SatResult sat = solve_sat(s.formula, limits);
    if (progress) std::cerr << "\r\033[K" << std::flush;
    if (stop_requested()) return false;
    if (sat.status == Verdict::Unknown) {
      ++skipped;
      std::cout << "c " << s.name << ": skipped, CaDiCaL did not decide it within --timeout " << timeout << " s"
                << std::endl;
      return false;
    }
    const bool is_yes = sat.status == Verdict::Yes;
    if (random && mix && ((is_yes && want_yes >= 0 && yes >= want_yes) || (!is_yes && want_no >= 0 && no >= want_no)))
      return false;
    LsatReduction red = reduce_to_lsat(s.formula);
    // The formula first, each instance after its witness: a .grid on disk
    // always has its formula and witness.
    write(s.name + ".cnf", to_dimacs(s.formula));
    for (ReductionModel model : models) {
      const bool cont = model == ReductionModel::Continuous;
      // With both models the continuous files get a suffix.
      const std::string name = s.name + (cont && models.size() == 2 ? "-continuous" : "");
      CompiledFormula c = compile_formula(red.output(), Mutation::None, model);
      nlohmann::json e;
      e["index"] = index;  // position in the unsharded set
      e["name"] = name;
      e["model"] = reduction_model_name(model);
      e["instance"] = name + ".grid";
      e["formula"] = s.name + ".cnf";
      e["origin"] = s.origin;
      if (s.seed) e["seed"] = std::to_string(s.seed);  // a string: seeds above 2^53 survive JSON readers
      e["variables"] = s.formula.num_vars;
      e["clauses"] = s.formula.clauses.size();
      e["lsat_variables"] = red.output().num_vars;
      e["lsat_clauses"] = red.output().clauses.size();
      e["nodes"] = c.stats.nodes;
      e["operations"] = c.stats.ops;
      e["couplings"] = c.stats.couplings;
      e["max_coupling"] = c.stats.max_coupling;
      if (is_yes) {
        Simulator sim(c.instance);
        std::string text, file;
        if (cont) {
          Schedule times = times_from_assignment(c, red.lift_to_target(sat.model));
          if (sim.run(times).collision)
            throw std::logic_error("the lifted start times of " + name + " collide: the reduction is wrong here");
          for (CouplingId q = 0; q < c.instance.couplings().size(); ++q)
            text += c.instance.couplings()[q].name + " " + times.start[q].str() + "\n";
          file = name + ".times";
          e["certificate"] = {{"kind", "start times"}, {"file", file}, {"checked_by", "gridlock simulator"}};
        } else {
          std::vector<CouplingId> order = schedule_from_assignment(c, red.lift_to_target(sat.model));
          if (sim.run_order(order).collision)
            throw std::logic_error("the lifted schedule of " + name + " collides: the reduction is wrong here");
          for (CouplingId q : order) text += c.instance.couplings()[q].name + "\n";
          file = name + ".schedule";
          e["certificate"] = {{"kind", "schedule"}, {"file", file}, {"checked_by", "gridlock simulator"}};
        }
        write(file, text);
        e["answer"] = "YES";
      } else {
        e["answer"] = "NO";
        e["certificate"] = {{"kind", "source formula unsatisfiable"}, {"solver", sat_solver_name()}};
      }
      std::ostringstream grid;
      write_instance(grid, c.instance,
                     {name + ": " + s.origin, std::string("model: ") + reduction_model_name(model),
                      std::string("answer: ") + (is_yes ? "YES" : "NO")});
      write(name + ".grid", grid.str());
      entries.push_back(e);
      std::cout << "c " << name << ": " << (is_yes ? "YES" : "NO") << ", " << c.stats.nodes << " nodes, "
                << c.stats.couplings << " couplings" << std::endl;
    }
    (is_yes ? yes : no) += 1;
    return true;
  };

  for (size_t i = 0; i < given.size() && !stop_requested(); ++i)
    if (i % shards == shard) label(given[i], false, i);
  // Random formulas. Formula j of a kind has seed fuzz_formula_seed(seed, j).
  auto draw = [&](const std::string& kind, int count, uint64_t offset) {
    int made = 0;
    const int limit = mix ? 100 * std::max(count, 1) : count;  // attempts
    for (int j = 0; j < limit && made < count && !stop_requested(); ++j) {
      if ((offset + static_cast<uint64_t>(j)) % shards != shard) continue;
      Source s;
      s.seed = fuzz_formula_seed(seed, static_cast<uint64_t>(j) + (kind == "lsat" ? 1'000'000'000ull : 0));
      if (kind == "threshold") {
        KSatParams k;
        k.n = vars;
        k.m = clauses_for_ratio(vars, 4.26);
        k.seed = s.seed;
        s.formula = random_ksat(k);
        s.origin = "random 3-SAT, n=" + std::to_string(vars) + ", m=" + std::to_string(k.m) + " (ratio 4.26)";
      } else {
        LsatParams l;
        l.n = vars;
        l.min_len = 1;
        l.max_len = 3;
        l.m = lsat_max_clauses(vars, 1);
        l.seed = s.seed;
        s.formula = random_lsat(l);
        s.origin = "random LSAT<=3, n=" + std::to_string(vars) + ", m=" + std::to_string(l.m);
      }
      s.name = kind + "-" + std::to_string(j + 1);
      made += label(s, true, offset + static_cast<uint64_t>(j));
    }
  };
  draw("threshold", threshold_count, given.size());
  draw("lsat", lsat_count, given.size() + static_cast<uint64_t>(threshold_count));
  const bool interrupted = stop_requested();

  nlohmann::json manifest;
  manifest["generator"] = "gridlock gen-instances";
  manifest["problem"] =
      model_name == "discrete"
          ? "Discrete Collision-free Schedule (is there an order of the couplings with no collision?)"
      : model_name == "continuous"
          ? "Continuous Collision-free Schedule (are there start times of the couplings with no collision?)"
          : "Discrete and Continuous Collision-free Schedule (entry field 'model')";
  manifest["model"] = model_name;
  manifest["seed"] = std::to_string(seed);  // a string: seeds above 2^53 survive JSON readers
  manifest["vars"] = vars;
  manifest["yes"] = yes;
  manifest["no"] = no;
  manifest["skipped"] = skipped;
  manifest["interrupted"] = interrupted;
  manifest["shard"] = std::to_string(shard) + "/" + std::to_string(shards);
  if (!mix) manifest["planned"] = given.size() + static_cast<size_t>(threshold_count) + static_cast<size_t>(lsat_count);
  manifest["instances"] = entries;
  write(manifest_name, manifest.dump(2) + "\n");  // last: it lists only files already in place
  if (vm.count("json-out")) cli::write_text_file(vm["json-out"].as<std::string>(), manifest.dump(2) + "\n");
  std::cout << "c wrote " << entries.size() << " instances (" << yes << " YES, " << no << " NO) and " << out << "/"
            << manifest_name << std::endl;
  if (interrupted) {
    std::cout << "c INTERRUPTED by signal " << stop_signal().load() << ": the manifest lists the " << entries.size()
              << " instances finished" << std::endl;
    return cli::interrupted_exit_code();
  }
  if (mix && ((want_yes >= 0 && yes < want_yes) || (want_no >= 0 && no < want_no)))
    std::cout << "c note: fewer instances than asked for of one answer (random formulas of this kind rarely have it)"
              << std::endl;
  return 0;
}

Command reg{"gen-instances", "write a labelled benchmark set of lattice instances (certified answers, manifest)",
            run_gen_instances};

}  // namespace
}  // namespace gridlock
