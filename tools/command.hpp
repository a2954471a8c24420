// Subcommand registry of the single `gridlock` command line.
//
// Each subcommand lives in its own file tools/<name>_command.cpp and registers
// itself with a static Command object, so adding one never edits main.cpp:
//
//   static gridlock::Command reg{"check", "run one schedule through the simulator", run_check};
//
// run(args) gets the arguments after the subcommand name and returns the
// process exit code (10 yes, 20 no, 0 unknown/ok, 1 error). It throws
// gridlock::UserError for bad usage or bad input; main prints it and exits 1.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "tools/user_error.hpp"

namespace gridlock {

using CommandFn = std::function<int(const std::vector<std::string>& args)>;

struct CommandInfo {
  std::string summary;
  CommandFn run;
};

std::map<std::string, CommandInfo>& command_registry();

struct Command {
  Command(const std::string& name, const std::string& summary, CommandFn run) {
    command_registry()[name] = CommandInfo{summary, std::move(run)};
  }
};

}  // namespace gridlock
