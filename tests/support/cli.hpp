// Running the real `gridlock` binary from tests (end-to-end, no mocks).
#pragma once

#include <string>
#include <vector>

namespace gridlock::test {

struct CliResult {
  int exit_code = -1;
  std::string out;  // standard output
  std::string err;  // standard error
};

// Runs GRIDLOCK_BINARY with args (no shell; args passed as they are), with
// stdin_text on standard input. Captures stdout and stderr.
CliResult run_gridlock(const std::vector<std::string>& args, const std::string& stdin_text = "");

// A running gridlock (for tests that signal it): started by start_gridlock,
// reaped by finish_gridlock (which returns what run_gridlock would).
struct CliProcess {
  int pid = -1;
  std::string dir;  // holds stdout/stderr captures
  std::string out_path, err_path;
};

// Starts GRIDLOCK_BINARY with args (SIGINT, SIGTERM, SIGHUP, SIGQUIT at their
// default dispositions and unblocked, as a terminal gives them); standard
// output goes to stdout_path if
// given (e.g. "/dev/full"), else it is captured. stdin is /dev/null.
CliProcess start_gridlock(const std::vector<std::string>& args, const std::string& stdout_path = "");
CliResult finish_gridlock(CliProcess& p);

// run_gridlock with standard output sent to stdout_path (out is then empty).
CliResult run_gridlock_stdout_to(const std::vector<std::string>& args, const std::string& stdout_path);

// A fresh empty directory under the system temp dir, removed at exit.
std::string temp_dir();
// Writes text to path (creating it), returns path.
std::string write_file(const std::string& path, const std::string& text);
std::string read_file(const std::string& path);

}  // namespace gridlock::test
