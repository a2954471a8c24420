// gridlock collide: Colliding Schedule (is there a schedule that collides?).
#include <algorithm>

#include "collide/collide.hpp"
#include "collide/collide_certificate.hpp"
#include "common/clock.hpp"
#include "common/limits.hpp"
#include "lattice/simulate.hpp"
#include "tools/cli_common.hpp"
#include "tools/command.hpp"
#include "tools/options.hpp"
#include "tools/output.hpp"
#include "tools/progress_line.hpp"
#include "tools/user_error.hpp"

namespace gridlock {
namespace {

namespace po = boost::program_options;

po::options_description collide_options() {
  po::options_description opts("options");
  opts.add_options()("help,h", "show this help")("model", po::value<std::string>()->default_value("continuous"),
                                                 "time model: continuous or discrete")(
      "method", po::value<std::string>()->default_value("auto"),
      "auto, tree (no couplings: centroid decomposition), tree-pairwise (no couplings: all pairs), "
      "pairwise (any instance: exact per-pair tests)")(
      "svg", po::value<std::string>(), "draw the colliding schedule's configuration at the collision to this SVG file")(
      "certificate", po::value<std::string>(),
      "with a NO, write a certificate to FILE that 'gridlock certify' checks (docs/certificates.md)")(
      "timeout", po::value<std::string>(), "give up after S seconds, reading included (s UNKNOWN, exit 0)")(
      "json", "print one JSON object instead of c/s/v lines");
  return opts;
}

TimeModel time_model_arg(const std::string& name) {
  if (name == "continuous") return TimeModel::Continuous;
  if (name == "discrete") return TimeModel::Discrete;
  throw UserError("--model must be 'continuous' or 'discrete', not '" + name + "'");
}

CollideMethod method_arg(const std::string& name) {
  if (name == "auto") return CollideMethod::Auto;
  if (name == "tree") return CollideMethod::Tree;
  if (name == "tree-pairwise") return CollideMethod::TreePairwise;
  if (name == "pairwise") return CollideMethod::Pairwise;
  throw UserError("--method must be auto, tree, tree-pairwise or pairwise, not '" + name + "'");
}

// --certificate C with a NO: the certificate (continuous; it proves the
// discrete NO too), or a comment saying why there is none.
void write_no_certificate(Answer& ans, const Instance& inst, TimeModel model, const std::string& cert_path,
                          const Deadline* deadline) {
  CollideCertificate cert;
  // The certificate covers every pair (O(n^2)) unless every operation
  // moves along one axis, even when the answer came in O(n log n): a
  // terminal sees how far it is.
  cli::ProgressLine line(!ans.json());
  const Stopwatch since;
  auto on_source = [&](uint64_t done, uint64_t total) {
    line.show(cli::collide_progress_text(CollideProgress{"certificate", done, total, since.seconds()}));
  };
  try {
    cert = collide_no_certificate(inst, deadline, false, on_source);
    line.clear();
  } catch (const LimitReached&) {
    line.clear();
    ans.comment("no certificate: limit reached while writing it; " + cli::certificate_left(cert_path));
    return;
  }
  if (cert.text.empty()) {
    if (model == TimeModel::Continuous)
      throw std::logic_error("collide: a continuous NO without a certificate: " + cert.why_none);
    ans.comment("no certificate: " + cert.why_none +
                " (the models agree on whole instances, docs/collide.md: a bug, please report it)");
    return;
  }
  cli::write_text_file(cert_path, cert.text);
  ans.comment("certificate written to " + cert_path + ": " + std::to_string(cert.pairs) + " pairs of regions" +
              (cert.one_axis         ? " (one axis: the row groups' pairs)"
               : cert.kept_axis == 2 ? std::string(" (one coupling, separated groups each keeping an order: their "
                                                   "sweeps' pairs)")
               : cert.kept_axis == 3 ? std::string(" (one coupling, groups over time slabs each keeping an order: "
                                                   "their sweeps' pairs)")
               : cert.kept_axis >= 0 ? std::string(" (one coupling, the ") + (cert.kept_axis == 0 ? "x" : "y") +
                                           " order kept: the sweep's pairs)"
                                     : "") +
              ", " + std::to_string(cert.lines) + " with multipliers ('gridlock certify' checks it)");
  ans.data()["certificate"] = cert_path;
  ans.data()["certificate_kind"] = cert.one_axis ? "one-axis" : cert.kept_axis >= 0 ? "kept-order" : "every-pair";
}

// A colliding schedule found: what was predicted, the simulator's collision,
// the picture and the witness (s YES).
int report_collision(Answer& ans, const Instance& inst, const CollideResult& res, TimeModel model,
                     const po::variables_map& vm) {
  Regions regions = Regions::build(inst);
  if (!res.cycle.empty()) {
    std::string walk;
    for (size_t i = 0; i < res.cycle.size() && i < 12; ++i) walk += " " + inst.node_label(res.cycle[i]);
    if (res.cycle.size() > 12) walk += " ...";
    ans.comment("predicted: cycle collision around" + walk);
  } else if (res.region_a != kNone) {
    ans.comment("predicted: " + region_label(inst, regions, res.region_a) + " and " +
                region_label(inst, regions, res.region_b) + " can collide");
  }
  const Collision& c = *res.simulated;
  if (res.checked_at) {  // one coupling: the first collision, named by its proof, confirmed at one moment
    ans.comment("first " + describe(inst, regions, c));
    ans.comment("checked in the simulator's configuration at time " + res.checked_at->str() + ": they overlap");
    ans.data()["checked_at"] = res.checked_at->str();
  } else {
    ans.comment("checked by the simulator: " + describe(inst, regions, c));
  }
  ans.data()["collision"] = collision_json(inst, regions, c);
  if (vm.count("svg")) {
    write_collision_svg(vm["svg"].as<std::string>(), inst, res.witness, c);
    ans.comment("wrote " + vm["svg"].as<std::string>() + " (configuration during the collision)");
  }
  if (model == TimeModel::Discrete) {
    for (CouplingId q : res.witness.order) ans.witness(inst.couplings()[q].name);
  } else {
    ans.witness_one_per_line();
    nlohmann::json times = nlohmann::json::object();
    for (CouplingId q = 0; q < inst.couplings().size(); ++q) {
      ans.witness(inst.couplings()[q].name + " " + res.witness.start[q].str());
      times[inst.couplings()[q].name] = res.witness.start[q].str();
    }
    ans.data()["times"] = times;
  }
  return ans.finish(Verdict::Yes);
}

int run_collide(const std::vector<std::string>& args) {
  const Deadline since_start;  // --timeout counts from here: reading the instance is part of it
  po::options_description opts = collide_options();
  po::variables_map vm;
  if (!cli::parse_args_one_input(
          args, opts, "instance", vm,
          "collide INSTANCE.grid [--model continuous|discrete] [--svg OUT.svg] [--certificate C] [--json]",
          "Colliding Schedule: can some schedule of the couplings cause a collision?\n"
          "s YES (exit 10) with a colliding schedule, already run through the exact simulator:\n"
          "discrete model: 'v' lines with the order (gridlock check --order-file reads them);\n"
          "continuous model: one 'v NAME TIME' line per coupling (gridlock check --times reads them).\n"
          "s NO (exit 20): no schedule collides (with --certificate C, a certificate 'gridlock certify'\n"
          "checks). s UNKNOWN (exit 0): --timeout reached first."))
    return 0;
  const std::string model_name = vm["model"].as<std::string>();
  const TimeModel model = time_model_arg(model_name);
  const CollideMethod method = method_arg(vm["method"].as<std::string>());

  const std::string path = vm["instance"].as<std::string>();
  if (vm.count("svg")) cli::refuse_overwriting_input(vm["svg"].as<std::string>(), {path});
  if (vm.count("certificate")) cli::refuse_overwriting_input(vm["certificate"].as<std::string>(), {path});
  const double seconds = cli::seconds_arg_opt(vm, "timeout").value_or(0);
  Instance inst = cli::load_instance(path);
  cli::Activity act(path, "finding a colliding schedule");  // out of memory names the file
  const Deadline deadline(seconds > 0 ? std::max(seconds - since_start.elapsed(), 1e-6) : 0);
  Answer ans("collide", vm.count("json") > 0);
  ans.comment("gridlock collide " + path + ": " + std::to_string(inst.num_nodes()) + " nodes, " +
              std::to_string(inst.ops().size()) + " operations, " + std::to_string(inst.couplings().size()) +
              " couplings; " + model_name + " model");
  CollideResult res;
  cli::ProgressLine line(!vm.count("json"));  // drawn only on a terminal
  try {
    res = find_collision(inst, model, method, seconds > 0 ? &deadline : nullptr, cli::collide_progress_to(line));
    line.clear();
  } catch (const std::invalid_argument& e) {
    throw UserError(e.what());
  } catch (const LimitReached&) {
    line.clear();
    ans.comment("limit reached before an answer (--timeout " + vm["timeout"].as<std::string>() + ")");
    if (vm.count("certificate")) ans.comment(cli::certificate_not_written(vm["certificate"].as<std::string>(), false));
    ans.data()["model"] = model_name;
    return ans.finish(Verdict::Unknown);
  }
  ans.comment("algorithm: " + res.algorithm + " (" + res.complexity + ")");
  if (res.stats.pairs)
    ans.comment("pairs: " + std::to_string(res.stats.pairs) + " considered, " + std::to_string(res.stats.full_tests) +
                " tested in full");
  if (res.stats.cell_items)
    ans.comment("cell-time items: " + std::to_string(res.stats.cell_items) +
                ", pair tests: " + std::to_string(res.stats.pair_tests));
  else if (res.stats.pair_tests) ans.comment("pair tests: " + std::to_string(res.stats.pair_tests));
  if (res.stats.witness_fallbacks)
    ans.comment(
        "the discrete witness search from the nodes the continuous pair's faces follow found nothing; every pair was "
        "searched (docs/collide.md, \"the models agree\": please report this instance)");
  if (res.stats.levels)
    ans.comment("centroid levels: " + std::to_string(res.stats.levels) +
                ", rectangles swept: " + std::to_string(res.stats.rectangles));
  ans.data()["model"] = model_name;
  ans.data()["algorithm"] = res.algorithm;
  if (!res.collides) {
    if (vm.count("certificate"))
      write_no_certificate(ans, inst, model, vm["certificate"].as<std::string>(), seconds > 0 ? &deadline : nullptr);
    return ans.finish(Verdict::No);
  }
  if (vm.count("certificate")) ans.comment(cli::certificate_not_written(vm["certificate"].as<std::string>(), true));
  return report_collision(ans, inst, res, model, vm);
}

Command reg{"collide", "Colliding Schedule: find a schedule that collides, or show that none does", run_collide};

}  // namespace
}  // namespace gridlock
