// gridlock compile: a CNF formula to a lattice instance (the paper's
// reduction; reductions/compile.hpp, docs/gadgets.md).
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "gadgets/mutation.hpp"
#include "lattice/grid_format.hpp"
#include "reductions/compile.hpp"
#include "render/picture.hpp"
#include "tools/cli_common.hpp"
#include "tools/command.hpp"
#include "tools/output.hpp"
#include "tools/user_error.hpp"

namespace gridlock {
namespace {

// The c-lines of `gridlock compile`: sizes, the size formulas checked against
// the counts, and the coupling-size report.
std::vector<std::string> describe_compiled(const CompiledFormula& c) {
  const CompileStats& s = c.stats;
  std::vector<std::string> lines;
  lines.push_back("instance: " + std::to_string(s.nodes) + " nodes, " + std::to_string(s.edges) + " edges, " +
                  std::to_string(s.ops) + " operations (" +
                  (s.vertical_ops ? "expansions, " + std::to_string(s.vertical_ops) + " of them vertical"
                                  : std::string("horizontal expansions")) +
                  "), " + std::to_string(s.couplings) + " couplings, " + std::to_string(s.rows) + " rows");
  lines.push_back("model: " + std::string(time_model_name(c.model)) + " time" +
                  (c.model == TimeModel::Continuous ? " (the link y_n < z_1 is a separation gadget)" : ""));
  lines.push_back(
      "gadgets: " + std::to_string(s.variable_gadgets) + " variable, " + std::to_string(s.clause_gadgets) +
      " clause, " + std::to_string(s.order_gadgets) + " order" +
      (c.model == TimeModel::Continuous ? ", " + std::to_string(s.separation_gadgets) + " separation" : std::string()));
  if (c.num_vars >= 1) {
    const auto n = static_cast<long long>(c.num_vars), m = static_cast<long long>(c.num_clauses),
               L = static_cast<long long>(s.literals);
    const bool cont = c.model == TimeModel::Continuous;
    lines.push_back("size formulas (n=" + std::to_string(n) + ", m=" + std::to_string(m) + ", L=" + std::to_string(L) +
                    "): nodes " +
                    (cont ? "43n+5L+15m-9 = " + std::to_string(43 * n + 5 * L + 15 * m - 9)
                          : "43n+5L+15m-11 = " + std::to_string(43 * n + 5 * L + 15 * m - 11)) +
                    ", operations 8n+L+3m-2 = " + std::to_string(8 * n + L + 3 * m - 2) +
                    ", couplings 4n+m = " + std::to_string(4 * n + m));
  }
  lines.push_back("largest coupling: " + s.max_coupling_name + " with " + std::to_string(s.max_coupling) +
                  " operations" + (s.max_coupling <= 3 ? " (at most 3, as the paper's theorem needs)" : ""));
  for (const auto& o : s.oversize) lines.push_back("coupling above 3: " + o);
  return lines;
}

int run_compile(const std::vector<std::string>& args) {
  namespace po = boost::program_options;
  po::options_description opts("options");
  opts.add_options()("help,h", "show this help")("output,o", po::value<std::string>()->default_value("-"),
                                                 "write the instance (.grid) here ('-': standard output)")(
      "svg", po::value<std::string>(), "also draw the instance to this SVG file")(
      "model", po::value<std::string>()->default_value("discrete"),
      "discrete (the NP-completeness reduction) or continuous (the link y_n < z_1 becomes a separation gadget)")(
      "json", "print the sizes as one JSON object (needs -o FILE)");
  po::options_description hidden;
  hidden.add_options()("break-gadget", po::value<std::string>()->default_value("none"),
                       "test only: compile with a broken gadget");
  po::variables_map vm;
  if (!cli::parse_args_one_input(
          args, opts, "formula", vm,
          "compile FORMULA.cnf [--model discrete|continuous] [-o INSTANCE.grid] [--svg INSTANCE.svg]",
          "Compiles a CNF formula (clauses of 1 or more literals; LSAT<=3 for couplings of at most 3\n"
          "operations, see 'gridlock cnf to-lsat') into a lattice instance of Discrete Collision-free\n"
          "Schedule: collision-free schedule exists iff the formula is satisfiable (docs/gadgets.md).\n"
          "With --model continuous, of continuous Collision-free Schedule (start times), the same\n"
          "way: one separation gadget (a vertical expansion) makes z_1 wait until y_n has finished.\n"
          "Operations are named after their gadget: x3.T, x3.F, x3.y, x3.z (variable x3), C5.~x3,\n"
          "C5.u (clause 5), O7.y2 (order gadget 7); couplings x3:T, x3:F, y3, z3, u5.",
          &hidden))
    return 0;
  const std::string path = vm["formula"].as<std::string>();
  const std::string out_path = vm["output"].as<std::string>();
  auto mutation = parse_mutation(vm["break-gadget"].as<std::string>());
  if (!mutation) throw UserError("unknown --break-gadget '" + vm["break-gadget"].as<std::string>() + "'");
  const std::string model_name = vm["model"].as<std::string>();
  if (model_name != "discrete" && model_name != "continuous")
    throw UserError("--model must be discrete or continuous, not '" + model_name + "'");
  const TimeModel model = model_name == "continuous" ? TimeModel::Continuous : TimeModel::Discrete;
  if (vm.count("json") && out_path == "-") throw UserError("--json needs -o FILE for the instance");
  const std::string svg_path = vm.count("svg") ? vm["svg"].as<std::string>() : "";
  cli::refuse_overwriting_input(out_path, {path});
  if (!svg_path.empty()) cli::refuse_overwriting_input(svg_path, {path, out_path});
  Formula f = cli::load_formula(path, true, cli::FormulaUse::CompileAsIs);
  cli::Activity act(path, "compiling the formula");
  CompiledFormula c;
  try {
    c = compile_formula(f, *mutation, model);
  } catch (const std::invalid_argument& e) {
    throw UserError(Diagnostic{path, 0, e.what()});
  }
  std::vector<std::string> lines = describe_compiled(c);
  lines.insert(lines.begin(), "gridlock compile " + path + ": " + summary(f));
  if (*mutation != Mutation::None)
    lines.push_back("BROKEN GADGET (test only): " + std::string(mutation_name(*mutation)));
  std::ostringstream grid;
  write_instance(grid, c.instance, lines);
  // The instance and its picture are written together: both or neither.
  std::vector<std::pair<std::string, std::string>> files;
  if (!svg_path.empty()) {
    RenderOptions ro;
    ro.title = path + ": " + std::to_string(c.stats.nodes) + " nodes, " + std::to_string(c.stats.couplings) +
               " couplings";
    files.emplace_back(svg_path, render_svg(c.instance, ro));
  }
  files.emplace_back(out_path, grid.str());
  cli::write_text_files(files);
  if (out_path == "-") return 0;
  Answer ans("compile", vm.count("json") > 0);
  for (const auto& l : lines) ans.comment(l);
  ans.comment("wrote " + out_path);
  const CompileStats& s = c.stats;
  ans.data()["nodes"] = s.nodes;
  ans.data()["edges"] = s.edges;
  ans.data()["operations"] = s.ops;
  ans.data()["couplings"] = s.couplings;
  ans.data()["model"] = time_model_name(model);
  ans.data()["vertical_operations"] = s.vertical_ops;
  ans.data()["max_coupling"] = s.max_coupling;
  ans.data()["oversize"] = s.oversize;
  ans.data()["output"] = out_path;
  if (ans.json()) ans.finish(Verdict::Unknown, "DONE");  // not a decision: exit 0 either way
  return 0;
}

Command reg{"compile", "compile a CNF formula into a lattice instance (the paper's NP-hardness reduction)",
            run_compile};

}  // namespace
}  // namespace gridlock
