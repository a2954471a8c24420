// gridlock render: pictures of an instance (SVG, ASCII, TikZ).
#include <iostream>

#include "render/picture.hpp"
#include "tools/cli_common.hpp"
#include "tools/command.hpp"
#include "tools/user_error.hpp"

namespace gridlock {
namespace {

int run_render(const std::vector<std::string>& args) {
  namespace po = boost::program_options;
  po::options_description opts("options");
  opts.add_options()("help,h", "show this help")("output,o", po::value<std::string>()->default_value("-"),
                                                 "output file ('-' = standard output)")(
      "ascii", "draw with characters for a terminal instead of SVG")(
      "tikz", "write a TikZ picture for LaTeX instead of SVG")("title", po::value<std::string>()->default_value(""),
                                                               "title drawn above the SVG");
  po::variables_map vm;
  if (!cli::parse_args_one_input(
          args, opts, "instance", vm, "render INSTANCE.grid [-o OUT.svg] [--ascii | --tikz]",
          "Draws an instance: nodes, edges, operations as arrows coloured by coupling, the anchor."))
    return 0;
  if (vm.count("ascii") && vm.count("tikz")) throw UserError("give at most one of --ascii and --tikz");
  if ((vm.count("ascii") || vm.count("tikz")) && !vm["title"].defaulted())
    throw UserError("--title applies to SVG pictures only, not --ascii or --tikz");
  cli::refuse_overwriting_input(vm["output"].as<std::string>(), {vm["instance"].as<std::string>()});
  Instance inst = cli::load_instance(vm["instance"].as<std::string>());
  cli::Activity act(vm["instance"].as<std::string>(), "drawing the instance");
  std::string text;
  if (vm.count("ascii")) {
    if (std::string why = ascii_too_large(inst); !why.empty())
      throw UserError(Diagnostic{vm["instance"].as<std::string>(), 0, why});
    text = render_ascii(inst);
  } else if (vm.count("tikz")) {
    text = render_tikz(inst);
  } else {
    RenderOptions ro;
    ro.title = vm["title"].as<std::string>();
    text = render_svg(inst, ro);
  }
  cli::write_text_file(vm["output"].as<std::string>(), text);
  return 0;
}

Command reg{"render", "draw an instance as SVG, ASCII or TikZ", run_render};

}  // namespace
}  // namespace gridlock
