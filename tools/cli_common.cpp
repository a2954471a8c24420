#include "tools/cli_common.hpp"

#include <fstream>
#include <iostream>

#include "cnf/dimacs.hpp"
#include "common/diagnostic.hpp"
#include "lattice/grid_format.hpp"

namespace gridlock::cli {

Formula load_formula(const std::string& path, bool strict_count) {
  Formula f;
  DimacsOptions opt;
  opt.strict_count = strict_count;
  if (auto err = read_dimacs_file(path, f, opt)) throw UserError(*err);
  return f;
}

Instance load_instance(const std::string& path) {
  Instance inst;
  if (auto err = read_instance_file(path, inst)) throw UserError(*err);
  return inst;
}

bool parse_args(const std::vector<std::string>& args, const po::options_description& visible,
                const po::positional_options_description& positional, po::variables_map& vm,
                const std::string& usage, const std::string& description, const po::options_description* hidden) {
  po::options_description all;
  all.add(visible);
  if (hidden) all.add(*hidden);
  try {
    po::store(po::command_line_parser(args).options(all).positional(positional).run(), vm);
    if (vm.count("help")) {
      std::cout << "usage: gridlock " << usage << "\n\n" << description << "\n\n" << visible << '\n';
      return false;
    }
    po::notify(vm);
  } catch (const po::error& e) {
    throw UserError(std::string(e.what()) + " (see 'gridlock " + usage.substr(0, usage.find(' ')) + " --help')");
  }
  return true;
}

void write_text_file(const std::string& path, const std::string& text) {
  if (path == "-") {
    std::cout << text;
    return;
  }
  std::ofstream out(path, std::ios::binary);
  if (!out) throw UserError(Diagnostic{path, 0, "cannot write file"});
  out << text;
  if (!out) throw UserError(Diagnostic{path, 0, "write failed"});
}

}  // namespace gridlock::cli
