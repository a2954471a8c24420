// Helpers shared by the subcommands: loading inputs (turning Diagnostics into
// UserErrors) and the common option parsing pattern.
#pragma once

#include <string>
#include <vector>

#include <boost/program_options.hpp>

#include "cnf/formula.hpp"
#include "lattice/instance.hpp"

namespace gridlock::cli {

namespace po = boost::program_options;

// Reads a DIMACS file ("-" = stdin) or throws UserError("FILE:LINE: ...").
Formula load_formula(const std::string& path, bool strict_count = true);

// Reads a .grid file ("-" = stdin) or throws UserError("FILE:LINE: ...").
Instance load_instance(const std::string& path);

// Parses args against visible options plus positionals; prints help (usage
// line, description, options) and returns false when --help is given. Throws
// UserError on bad usage. `usage` is the synopsis line after "usage: gridlock ".
bool parse_args(const std::vector<std::string>& args, const po::options_description& visible,
                const po::positional_options_description& positional, po::variables_map& vm,
                const std::string& usage, const std::string& description,
                const po::options_description* hidden = nullptr);

// parse_args for the common shape "SUBCOMMAND [OPTIONS] INPUT": one required
// positional argument, stored in vm[input_name]; extra_hidden adds options
// that --help does not list (test-only switches).
bool parse_args_one_input(const std::vector<std::string>& args, const po::options_description& visible,
                          const std::string& input_name, po::variables_map& vm, const std::string& usage,
                          const std::string& description, const po::options_description* extra_hidden = nullptr);

// Parses "--shard K/N" (0 <= K < N) or throws UserError naming the option.
void parse_shard(const std::string& text, uint64_t& k, uint64_t& n);

// Writes text to path ("-" = stdout) or throws UserError.
void write_text_file(const std::string& path, const std::string& text);

}  // namespace gridlock::cli
