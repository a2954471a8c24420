// gridlock gadget: one gadget of the reduction, alone, as an instance whose
// comments state its contract (gadgets/, docs/gadgets.md). Each operation is
// its own coupling, so `gridlock check --order` can try any order of them.
#include <sstream>

#include "gadgets/internal/canvas.hpp"
#include "gadgets/internal/clause_gadget.hpp"
#include "gadgets/internal/order_gadget.hpp"
#include "gadgets/internal/separation_gadget.hpp"
#include "gadgets/internal/variable_gadget.hpp"
#include "lattice/grid_format.hpp"
#include "render/picture.hpp"
#include "tools/cli_common.hpp"
#include "tools/command.hpp"
#include "tools/options.hpp"
#include "tools/user_error.hpp"

namespace gridlock {
namespace {

namespace po = boost::program_options;

struct DrawnGadget {
  Instance inst;
  GadgetPlacement p;
  std::string words, title;
};

// The gadget `kind` with mutation m (UserError for an unknown kind).
DrawnGadget draw_gadget(const std::string& kind, Mutation m, const po::variables_map& vm) {
  Canvas canvas;
  DrawnGadget g;
  if (kind == "variable") {
    g.p = place_variable_gadget(canvas, 0, {"T", "F", "y", "z"}, m);
    g.words = "variable gadget: collides iff T and F are both done before z, or y is done before T and F";
    g.title = "variable gadget";
  } else if (kind == "clause") {
    const int k = cli::int_arg(vm, "literals", 1, 16);
    std::vector<std::string> lits;
    for (int i = 1; i <= k; ++i) lits.push_back("l" + std::to_string(i));
    g.p = place_clause_gadget(canvas, 0, lits, "u", m);
    g.words = "clause gadget: collides iff all " + std::to_string(k) + " literal operations are done before u";
    g.title = "clause gadget, " + std::to_string(k) + (k == 1 ? " literal" : " literals");
  } else if (kind == "order") {
    g.p = place_order_gadget(canvas, 0, "a", "b", m);
    g.words = "order gadget a < b: collides iff b is done before a";
    g.title = "order gadget a < b";
  } else if (kind == "separation") {
    g.p = place_separation_gadget(canvas, 0, "a", "b", m);
    g.words =
        "separation gadget a << b (continuous model): collides iff b starts before a has finished, "
        "i.e. t(b) < t(a) + 1; a is vertical, the row above the gadget must stay free";
    g.title = "separation gadget a << b";
  } else {
    throw UserError("unknown gadget '" + kind + "' (variable, clause, order or separation)");
  }
  g.inst = canvas.build();
  return g;
}

std::string grid_text(const Instance& inst, const std::vector<std::string>& comments) {
  std::ostringstream grid;
  write_instance(grid, inst, comments);
  return grid.str();
}

// A mutation breaks one gadget kind; on another kind (or a size where it
// has nothing to loosen) it would change nothing, and the drawing labelled
// broken would be the sound gadget: refused, by comparing the two.
void refuse_unbroken(const std::string& kind, Mutation m, const DrawnGadget& broken, const po::variables_map& vm) {
  if (m == Mutation::None) return;
  const std::string name = mutation_name(m);
  const char* applies = m == Mutation::VariableLooseY                              ? "variable"
                        : m == Mutation::ClauseLoose || m == Mutation::ClauseTight ? "clause"
                        : m == Mutation::SeparationLoose                           ? "separation"
                                                                                   : "order";
  if (kind != applies)
    throw UserError("--break-gadget " + name + " breaks the " + applies + " gadget, not the " + kind + " gadget");
  const DrawnGadget sound = draw_gadget(kind, Mutation::None, vm);
  if (grid_text(sound.inst, {}) == grid_text(broken.inst, {}))
    throw UserError("--break-gadget " + name + " changes nothing in this " + kind +
                    " gadget (give a size it breaks, e.g. more --literals)");
}

int run_gadget(const std::vector<std::string>& args) {
  po::options_description opts("options");
  opts.add_options()("help,h", "show this help")("literals,k", po::value<std::string>()->default_value("3"),
                                                 "clause gadget: literals in the clause (1 to 16)")(
      "output,o", po::value<std::string>()->default_value("-"),
      "write the instance (.grid) here ('-': standard output)")("svg", po::value<std::string>(),
                                                                "also draw it to this SVG file")(
      "break-gadget", po::value<std::string>()->default_value("none"),
      "draw a deliberately broken version (variable-loose-y, clause-loose, clause-tight, order-loose, "
      "order-drop-release, separation-loose)");
  po::variables_map vm;
  if (!cli::parse_args_one_input(
          args, opts, "kind", vm, "gadget variable|clause|order|separation [-k K] [-o OUT.grid] [--svg OUT.svg]",
          "Draws one gadget of the reduction alone, with its contract (the states of its operations\n"
          "that collide) in 'c' lines. Every operation is its own coupling."))
    return 0;
  const std::string kind = vm["kind"].as<std::string>();
  auto mutation = parse_mutation(vm["break-gadget"].as<std::string>());
  if (!mutation) throw UserError("unknown --break-gadget '" + vm["break-gadget"].as<std::string>() + "'");
  if (kind != "clause" && !vm["literals"].defaulted()) throw UserError("--literals applies to the clause gadget only");
  const DrawnGadget g = draw_gadget(kind, *mutation, vm);
  refuse_unbroken(kind, *mutation, g, vm);
  std::vector<std::string> comments = {g.words, "contract: " + g.p.contract.str()};
  if (*mutation != Mutation::None)
    comments.push_back("BROKEN GADGET (" + std::string(mutation_name(*mutation)) +
                       "): the contract above is the broken one");
  std::vector<std::pair<std::string, std::string>> files;
  if (vm.count("svg")) {
    RenderOptions ro;
    ro.title = g.title;
    files.emplace_back(vm["svg"].as<std::string>(), render_svg(g.inst, ro));
  }
  files.emplace_back(vm["output"].as<std::string>(), grid_text(g.inst, comments));
  cli::write_text_files(files);
  return 0;
}

Command reg{"gadget", "draw one gadget of the reduction alone, with its contract", run_gadget};

}  // namespace
}  // namespace gridlock
