// gridlock gen-instances: a labelled benchmark set of lattice instances of
// Discrete Collision-free Schedule, each answer certified (docs/verify.md):
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
    ("shard", po::value<std::string>()->default_value("0/1"), "K/N: make only the instances i (given ones first, then "
                                                             "threshold, then lsat) with i % N == K; the manifest is then "
                                                             "manifest-shard-K-of-N.json (not with --yes/--no)")
    ("json-out", po::value<std::string>(), "also write the manifest to this file ('gridlock merge' combines shards)");
  po::positional_options_description pos;
  po::variables_map vm;
  if (!cli::parse_args(args, opts, pos, vm, "gen-instances -o DIR [--threshold N] [--lsat N] [--vars V] [--formula F]...",
                       "Writes a labelled set of lattice instances: each formula (random 3-SAT at the threshold,\n"
                       "random LSAT<=3, or given) goes through to-lsat and the gadget compiler. Labels are certified:\n"
                       "YES with a witness schedule (CaDiCaL's model lifted, accepted by the exact simulator, saved\n"
                       "as NAME.schedule for 'gridlock check --order-file'), NO by CaDiCaL's UNSAT of the source.\n"
                       "manifest.json lists every instance with its answer, certificate, sizes and seed.",
                       nullptr))
    return 0;
  const std::string out = vm["out"].as<std::string>();
  const uint64_t seed = vm["seed"].as<uint64_t>();
  const int vars = vm["vars"].as<int>();
  if (vars < 3 || vars > 1000) throw UserError("--vars must be 3 to 1000");
  const int want_yes = vm["yes"].as<int>(), want_no = vm["no"].as<int>();
  const bool mix = want_yes >= 0 || want_no >= 0;
  uint64_t shard = 0, shards = 1;
  cli::parse_shard(vm["shard"].as<std::string>(), shard, shards);
  if (mix && shards > 1) throw UserError("--shard cannot be combined with --yes/--no (they draw until counts are met)");

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
  auto label = [&](const Source& s, bool random, uint64_t index) {
    SatResult sat = solve_sat(s.formula);
    const bool is_yes = sat.status == SatResult::Sat;
    if (random && mix && ((is_yes && want_yes >= 0 && yes >= want_yes) || (!is_yes && want_no >= 0 && no >= want_no)))
      return false;
    LsatReduction red = reduce_to_lsat(s.formula);
    CompiledFormula c = compile_formula(red.output());
    nlohmann::json e;
    e["index"] = index;  // position in the unsharded set
    e["name"] = s.name;
    e["instance"] = s.name + ".grid";
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
      std::vector<CouplingId> order = schedule_from_assignment(c, red.lift_to_target(sat.model));
      Simulator sim(c.instance);
      if (sim.run_order(order).collision)
        throw std::logic_error("the lifted schedule of " + s.name + " collides: the reduction is wrong here");
      std::string text;
      for (CouplingId q : order) text += c.instance.couplings()[q].name + "\n";
      write(s.name + ".schedule", text);
      e["answer"] = "YES";
      e["certificate"] = {{"kind", "schedule"}, {"file", s.name + ".schedule"}, {"checked_by", "gridlock simulator"}};
      ++yes;
    } else {
      e["answer"] = "NO";
      e["certificate"] = {{"kind", "source formula unsatisfiable"}, {"solver", sat_solver_name()}};
      ++no;
    }
    std::ostringstream grid;
    write_instance(grid, c.instance, {s.name + ": " + s.origin, std::string("answer: ") + (is_yes ? "YES" : "NO")});
    write(s.name + ".grid", grid.str());
    write(s.name + ".cnf", to_dimacs(s.formula));
    entries.push_back(e);
    std::cout << "c " << s.name << ": " << (is_yes ? "YES" : "NO") << ", " << c.stats.nodes << " nodes, "
              << c.stats.couplings << " couplings" << std::endl;
    return true;
  };

  for (size_t i = 0; i < given.size(); ++i)
    if (i % shards == shard) label(given[i], false, i);
  // Random formulas. Formula j of a kind has seed fuzz_formula_seed(seed, j).
  auto draw = [&](const std::string& kind, int count, uint64_t offset) {
    int made = 0;
    const int limit = mix ? 100 * std::max(count, 1) : count;  // attempts
    for (int j = 0; j < limit && made < count; ++j) {
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
  const int n_threshold = std::max(vm["threshold"].as<int>(), 0), n_lsat = std::max(vm["lsat"].as<int>(), 0);
  draw("threshold", n_threshold, given.size());
  draw("lsat", n_lsat, given.size() + static_cast<uint64_t>(n_threshold));

  nlohmann::json manifest;
  manifest["generator"] = "gridlock gen-instances";
  manifest["problem"] = "Discrete Collision-free Schedule (is there an order of the couplings with no collision?)";
  manifest["seed"] = seed;
  manifest["vars"] = vars;
  manifest["yes"] = yes;
  manifest["no"] = no;
  manifest["shard"] = std::to_string(shard) + "/" + std::to_string(shards);
  if (!mix) manifest["planned"] = given.size() + static_cast<size_t>(n_threshold) + static_cast<size_t>(n_lsat);
  manifest["instances"] = entries;
  const std::string manifest_name = shards == 1 ? "manifest.json"
                                                : "manifest-shard-" + std::to_string(shard) + "-of-" +
                                                      std::to_string(shards) + ".json";
  write(manifest_name, manifest.dump(2) + "\n");
  if (vm.count("json-out")) cli::write_text_file(vm["json-out"].as<std::string>(), manifest.dump(2) + "\n");
  std::cout << "c wrote " << entries.size() << " instances (" << yes << " YES, " << no << " NO) and " << out
            << "/" << manifest_name << std::endl;
  if (mix && ((want_yes >= 0 && yes < want_yes) || (want_no >= 0 && no < want_no)))
    std::cout << "c note: fewer instances than asked for of one answer (random formulas of this kind rarely have it)"
              << std::endl;
  return 0;
}

Command reg{"gen-instances", "write a labelled benchmark set of lattice instances (certified answers, manifest)",
            run_gen_instances};

}  // namespace
}  // namespace gridlock
