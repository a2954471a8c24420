// gridlock: one command line, many subcommands (see tools/command.hpp).
//
// Only this file decides how an error ends the process:
// "gridlock: error: <what>" on stderr and exit code 1.
#include <exception>
#include <iostream>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/diagnostic.hpp"
#include "tools/cli_common.hpp"
#include "tools/command.hpp"
#include "tools/user_error.hpp"

namespace gridlock {

std::map<std::string, CommandInfo>& command_registry() {
  static std::map<std::string, CommandInfo> registry;
  return registry;
}

}  // namespace gridlock

namespace {

void print_usage(std::ostream& os) {
  os << "usage: gridlock SUBCOMMAND [OPTIONS] [ARGS]\n\n"
        "Collision detection for modular robots (Gupta, van Kreveld, Michail, Padalkin):\n"
        "instances, the exact simulator, solvers, the LSAT reduction and its checks.\n\n"
        "subcommands:\n";
  for (const auto& [name, info] : gridlock::command_registry()) {
    os << "  " << name;
    for (size_t i = name.size(); i < 16; ++i) os << ' ';
    os << info.summary << '\n';
  }
  os << "\n'gridlock SUBCOMMAND --help' documents each one.\n"
        "Decision commands print 'c' comment lines, one 's' status line and 'v' witness\n"
        "lines, and exit 10 (yes), 20 (no), 0 (unknown: a limit was hit) or 1 (error);\n"
        "--json prints one JSON object instead.\n";
}

}  // namespace

int main(int argc, char** argv) {
  std::ios::sync_with_stdio(false);
  if (argc < 2) {
    print_usage(std::cerr);
    return 1;
  }
  std::string name = argv[1];
  if (name == "--help" || name == "-h" || name == "help") {
    print_usage(std::cout);
    return 0;
  }
  auto& registry = gridlock::command_registry();
  auto it = registry.find(name);
  if (it == registry.end()) {
    std::cerr << "gridlock: error: unknown subcommand '" << gridlock::cli::printable(name)
              << "' (see 'gridlock --help')\n";
    return 1;
  }
  std::vector<std::string> args(argv + 2, argv + argc);
  int code = 1;
  try {
    code = it->second.run(args);
  } catch (const gridlock::UserError& e) {
    std::cout.flush();
    std::cerr << "gridlock: error: " << gridlock::cli::printable(e.what()) << '\n';
    return 1;
  } catch (const std::bad_array_new_length& e) {
    // A size that overflowed, not memory exhausted (it derives from bad_alloc).
    std::cout.flush();
    std::cerr << "gridlock: error: " << gridlock::cli::Activity::too_large_message(e.what()) << '\n';
    return 1;
  } catch (const std::bad_alloc&) {
    std::cout.flush();
    std::cerr << "gridlock: error: " << gridlock::cli::Activity::out_of_memory_message() << '\n';
    return 1;
  } catch (const std::length_error& e) {
    // A size beyond what a container can hold: "too large", never "out of memory".
    std::cout.flush();
    std::cerr << "gridlock: error: " << gridlock::cli::printable(gridlock::cli::Activity::too_large_message(e.what()))
              << '\n';
    return 1;
  } catch (const std::exception& e) {
    // Not a user error: a bug or a limit of ours. Still no crash, still exit 1.
    std::cout.flush();
    std::cerr << "gridlock: error: internal: " << gridlock::cli::printable(e.what()) << '\n';
    return 1;
  }
  // Output lost is never a success: a failed write to standard output (a
  // full disk, a closed pipe) turns any exit code into an error.
  if (std::string err = gridlock::cli::stdout_error(); !err.empty()) {
    std::cerr << "gridlock: error: " << err << '\n';
    return 1;
  }
  return code;
}
