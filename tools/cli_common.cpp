#include "tools/cli_common.hpp"

#include <cctype>
#include <fstream>
#include <iostream>
#include <sstream>

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

namespace {
// "cnf solve" from "cnf solve FILE.cnf [--time S]": the leading lower-case words.
std::string command_of(const std::string& usage) {
  std::string out;
  std::istringstream in(usage);
  for (std::string w; in >> w;) {
    bool word = !w.empty();
    for (char ch : w) word = word && ((ch >= 'a' && ch <= 'z') || ch == '-');
    word = word && w[0] != '-';
    if (!word) break;
    out += (out.empty() ? "" : " ") + w;
  }
  return out;
}
}  // namespace

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
  } catch (const po::required_option& e) {
    // Required options are our positional arguments: name them as such.
    std::string name = e.get_option_name();
    while (!name.empty() && name[0] == '-') name.erase(0, 1);
    if (visible.find_nothrow(name, false))
      throw UserError("missing option --" + name + " (see 'gridlock " + command_of(usage) + " --help')");
    for (char& ch : name) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    throw UserError("missing argument " + name + " (see 'gridlock " + command_of(usage) + " --help')");
  } catch (const po::error& e) {
    throw UserError(std::string(e.what()) + " (see 'gridlock " + command_of(usage) + " --help')");
  }
  return true;
}

bool parse_args_one_input(const std::vector<std::string>& args, const po::options_description& visible,
                          const std::string& input_name, po::variables_map& vm, const std::string& usage,
                          const std::string& description, const po::options_description* extra_hidden) {
  po::options_description hidden;
  hidden.add_options()(input_name.c_str(), po::value<std::string>()->required(), input_name.c_str());
  if (extra_hidden) hidden.add(*extra_hidden);
  po::positional_options_description pos;
  pos.add(input_name.c_str(), 1);
  return parse_args(args, visible, pos, vm, usage, description, &hidden);
}

void parse_shard(const std::string& text, uint64_t& k, uint64_t& n) {
  char slash = 0;
  std::istringstream in(text);
  if (!(in >> k >> slash >> n) || slash != '/' || n == 0 || k >= n || !in.eof() || text.find('-') != std::string::npos)
    throw UserError("--shard: want K/N with 0 <= K < N, not '" + text + "'");
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
