// gridlock gen-instances: a labelled benchmark set of lattice instances of
// Discrete (and/or, --model, Continuous) Collision-free Schedule, each answer
// certified (docs/verify.md):
// YES by a schedule the simulator has accepted, NO by CaDiCaL's UNSAT of the
// source formula (the reduction preserves satisfiability: docs/gadgets.md,
// and verify/fuzz test it).
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cnf/dimacs.hpp"
#include "cnf/generate.hpp"
#include "cnf/sat_solver.hpp"
#include "lattice/grid_format.hpp"
#include "lattice/simulate.hpp"
#include "reductions/compile.hpp"
#include "reductions/fuzz.hpp"
#include "reductions/to_lsat.hpp"
#include "tools/cli_common.hpp"
#include "tools/command.hpp"

namespace gridlock {
namespace {

namespace fs = std::filesystem;

struct Source {
  std::string name, origin;  // file stem, how it was made
  Formula formula;
  uint64_t seed = 0;
};

int run_gen_instances(const std::vector<std::string>& args) {
  namespace po = boost::program_options;
  po::options_description opts("options");
  opts.add_options()
    ("help,h", "show this help")
    ("out,o", po::value<std::string>()->required(), "folder to write (created): instances, formulas, witnesses, manifest.json")
    ("seed", po::value<uint64_t>()->default_value(1), "seed of the random formulas")
    ("threshold", po::value<int>()->default_value(10), "random 3-SAT formulas at the threshold ratio 4.26")
    ("lsat", po::value<int>()->default_value(10), "random LSAT<=3 formulas (clauses of 1 to 3 literals)")
    ("vars", po::value<int>()->default_value(12), "variables of each random formula (3 to 1000)")
    ("yes", po::value<int>()->default_value(-1), "keep only this many YES instances of the random ones (-1: all)")
    ("no", po::value<int>()->default_value(-1), "keep only this many NO instances of the random ones (-1: all); "
                                               "with --yes/--no, formulas are drawn until both are met")
    ("formula", po::value<std::vector<std::string>>()->composing(), "also compile this given formula (repeatable)")
    ("model", po::value<std::string>()->default_value("discrete"),
     "discrete (NAME.grid, NAME.schedule), continuous (the continuous reduction: NAME.grid, NAME.times) or both "
     "(NAME.grid and NAME-continuous.grid)");
  po::positional_options_description pos;
  po::variables_map vm;
  if (!cli::parse_args(args, opts, pos, vm, "gen-instances -o DIR [--threshold N] [--lsat N] [--vars V] [--formula F]...",
                       "Writes a labelled set of lattice instances: each formula (random 3-SAT at the threshold,\n"
                       "random LSAT<=3, or given) goes through to-lsat and the gadget compiler. Labels are certified:\n"
                       "YES with a witness schedule (CaDiCaL's model lifted, accepted by the exact simulator, saved\n"
                       "as NAME.schedule for 'gridlock check --order-file'), NO by CaDiCaL's UNSAT of the source.\n"
                       "manifest.json lists every instance with its answer, certificate, sizes and seed.\n"
                       "--model continuous: instances of Continuous Collision-free Schedule (compile --model\n"
                       "continuous); YES certified by start times (NAME.times, for 'gridlock check --times').",
                       nullptr))
    return 0;
  const std::string out = vm["out"].as<std::string>();
  const uint64_t seed = vm["seed"].as<uint64_t>();
  const int vars = vm["vars"].as<int>();
  if (vars < 3 || vars > 1000) throw UserError("--vars must be 3 to 1000");
  const int want_yes = vm["yes"].as<int>(), want_no = vm["no"].as<int>();
  const bool mix = want_yes >= 0 || want_no >= 0;
  const std::string model_name = vm["model"].as<std::string>();
  if (model_name != "discrete" && model_name != "continuous" && model_name != "both")
    throw UserError("--model must be discrete, continuous or both, not '" + model_name + "'");
  std::vector<ReductionModel> models;
  if (model_name != "continuous") models.push_back(ReductionModel::Discrete);
  if (model_name != "discrete") models.push_back(ReductionModel::Continuous);

  std::vector<Source> given;
  if (vm.count("formula"))
    for (const auto& path : vm["formula"].as<std::vector<std::string>>())
      given.push_back({"given-" + fs::path(path).stem().string(), "given " + path, cli::load_formula(path), 0});

  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) throw UserError(Diagnostic{out, 0, "cannot create folder"});
  auto write = [&](const std::string& file, const std::string& text) { cli::write_text_file(out + "/" + file, text); };

  nlohmann::json entries = nlohmann::json::array();
  int yes = 0, no = 0;
  // Labels one formula; returns false if --yes/--no say it is not wanted.
  auto label = [&](const Source& s, bool random) {
    SatResult sat = solve_sat(s.formula);
    const bool is_yes = sat.status == SatResult::Sat;
    if (random && mix && ((is_yes && want_yes >= 0 && yes >= want_yes) || (!is_yes && want_no >= 0 && no >= want_no)))
      return false;
    LsatReduction red = reduce_to_lsat(s.formula);
    for (ReductionModel model : models) {
      const bool cont = model == ReductionModel::Continuous;
      // With both models the continuous files get a suffix.
      const std::string name = s.name + (cont && models.size() == 2 ? "-continuous" : "");
      CompiledFormula c = compile_formula(red.output(), Mutation::None, model);
      nlohmann::json e;
      e["name"] = name;
      e["model"] = reduction_model_name(model);
      e["instance"] = name + ".grid";
      e["formula"] = s.name + ".cnf";
      e["origin"] = s.origin;
      if (s.seed) e["seed"] = s.seed;
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
      write_instance(grid, c.instance, {name + ": " + s.origin, std::string("model: ") + reduction_model_name(model),
                                        std::string("answer: ") + (is_yes ? "YES" : "NO")});
      write(name + ".grid", grid.str());
      entries.push_back(e);
      std::cout << "c " << name << ": " << (is_yes ? "YES" : "NO") << ", " << c.stats.nodes << " nodes, "
                << c.stats.couplings << " couplings" << std::endl;
    }
    (is_yes ? yes : no) += 1;
    write(s.name + ".cnf", to_dimacs(s.formula));
    return true;
  };

  for (const Source& s : given) label(s, false);
  // Random formulas. Formula j of a kind has seed fuzz_formula_seed(seed, j).
  auto draw = [&](const std::string& kind, int count) {
    int made = 0;
    const int limit = mix ? 100 * std::max(count, 1) : count;  // attempts
    for (int j = 0; j < limit && made < count; ++j) {
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
      made += label(s, true);
    }
  };
  draw("threshold", vm["threshold"].as<int>());
  draw("lsat", vm["lsat"].as<int>());

  nlohmann::json manifest;
  manifest["generator"] = "gridlock gen-instances";
  manifest["problem"] =
      model_name == "discrete"
          ? "Discrete Collision-free Schedule (is there an order of the couplings with no collision?)"
      : model_name == "continuous"
          ? "Continuous Collision-free Schedule (are there start times of the couplings with no collision?)"
          : "Discrete and Continuous Collision-free Schedule (entry field 'model')";
  manifest["model"] = model_name;
  manifest["seed"] = seed;
  manifest["vars"] = vars;
  manifest["yes"] = yes;
  manifest["no"] = no;
  manifest["instances"] = entries;
  write("manifest.json", manifest.dump(2) + "\n");
  std::cout << "c wrote " << entries.size() << " instances (" << yes << " YES, " << no << " NO) and " << out
            << "/manifest.json" << std::endl;
  if (mix && ((want_yes >= 0 && yes < want_yes) || (want_no >= 0 && no < want_no)))
    std::cout << "c note: fewer instances than asked for of one answer (random formulas of this kind rarely have it)"
              << std::endl;
  return 0;
}

Command reg{"gen-instances", "write a labelled benchmark set of lattice instances (certified answers, manifest)",
            run_gen_instances};

}  // namespace
}  // namespace gridlock
