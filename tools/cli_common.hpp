// Helpers shared by the subcommands: loading inputs (turning Diagnostics into
// UserErrors) and the common option parsing pattern.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <boost/program_options.hpp>

#include "cnf/formula.hpp"
#include "lattice/instance.hpp"
#include "lattice/schedule.hpp"
#include "tools/user_error.hpp"

namespace gridlock::cli {

namespace po = boost::program_options;

// What a command builds from a formula: decides the size checks made right
// after reading, before anything is allocated per variable or node.
//   Read     none
//   Solve    (cnf solve, to-lsat, lift, verify) at most kMaxUnusedVariables
//            declared variables beyond the largest one a clause uses: the
//            header count must not drive allocation beyond what the file holds
//   Compile  Solve's check, and the compiled instance's node count in both
//            models (43n + 5L + 15m - 11, and 2 more in the continuous one)
//            within the .grid format's kMaxNodes
//   CompileAsIs  Compile's checks, and every clause holds a literal (compile
//            and lift hand the formula to the reduction as it is; verify,
//            fuzz and gen-instances go through to-lsat, which removes empty
//            clauses)
// A failed check is "FILE:LINE: ..." with the header's line (an empty clause:
// the line of its 0).
enum class FormulaUse { Read, Solve, Compile, CompileAsIs };
inline constexpr int64_t kMaxUnusedVariables = int64_t{1} << 20;

// Reads a DIMACS file ("-" = stdin) or throws UserError("FILE:LINE: ...").
Formula load_formula(const std::string& path, bool strict_count = true, FormulaUse use = FormulaUse::Read);

// Reads a .grid file ("-" = stdin) or throws UserError("FILE:LINE: ...").
Instance load_instance(const std::string& path);

// Parses args against visible options plus positionals; prints help (usage
// line, description, options) and returns false when --help is given. Throws
// UserError on bad usage. `usage` is the synopsis line after "usage: gridlock ".
bool parse_args(const std::vector<std::string>& args, const po::options_description& visible,
                const po::positional_options_description& positional, po::variables_map& vm, const std::string& usage,
                const std::string& description, const po::options_description* hidden = nullptr);

// parse_args for the common shape "SUBCOMMAND [OPTIONS] INPUT": one required
// positional argument, stored in vm[input_name]; extra_hidden adds options
// that --help does not list (test-only switches).
bool parse_args_one_input(const std::vector<std::string>& args, const po::options_description& visible,
                          const std::string& input_name, po::variables_map& vm, const std::string& usage,
                          const std::string& description, const po::options_description* extra_hidden = nullptr);

// Parses "--shard K/N" (0 <= K < N) or throws UserError naming the option.
void parse_shard(const std::string& text, uint64_t& k, uint64_t& n);

// Writes text to path ("-" = stdout) or throws UserError. A file is written
// atomically and checked (common/internal/atomic_file.hpp): a temporary file in the
// same folder renamed into place; a full disk is
// "PATH: write failed: No space left on device", never a success.
void write_text_file(const std::string& path, const std::string& text);

// Several outputs, all or none: every file is staged first (a failure
// removes what was staged and throws, leaving every path as it was), then
// all are renamed into place. "-" entries go to standard output last.
void write_text_files(const std::vector<std::pair<std::string, std::string>>& files);

// Throws UserError("OUT: output would overwrite the input INPUT") if output
// path out names the same file as one of inputs (same path, or the same file
// through links). "-" never conflicts. Call it before reading the inputs.
void refuse_overwriting_input(const std::string& out, const std::vector<std::string>& inputs);

// --certificate PATH on an answer that has no certificate (yes: a YES,
// whose witness is on the 'v' lines; else an UNKNOWN): the comment that
// says so and that PATH was left as it was, so a file already there is not
// taken for this answer's certificate.
std::string certificate_not_written(const std::string& path, bool yes);
// "PATH is left as it was (not this answer's)", "PATH not created", or for
// "-" "nothing printed": what became of PATH when no certificate was
// written there.
std::string certificate_left(const std::string& path);

// Inputs are sacred (docs/errors.md). parse_args calls guard_paths on every
// command line: each file named by an input option (instance, formula, file,
// inputs, times, order-file, schedule, model) is protected
// (common/internal/atomic_file.hpp's protect_input: no write, rename or removal of
// that file by device and inode, wherever the write comes from), and each
// output option (output, out, svg, json-out, reproducers, pictures) goes
// through check_output_path and refuse_overwriting_input. load_formula and
// load_instance protect what they read as well (files found in folders).
void guard_paths(const po::variables_map& vm, const std::string& command);

// Throws UserError("--OPTION: ...") for an empty output path, the file-system
// root, or (unless folder) a file directly in the root. "-" is fine.
void check_output_path(const std::string& option, const std::string& path, bool folder);

// Throws UserError("OUT: output would overwrite the input IN") if out names
// a file protected as an input (see guard_paths).
void protect_input_check(const std::string& out);

// The schedule given by exactly one of --order "Q..." (names in order),
// --order-file F or --times F (start times) in vm, for inst; nullopt if none
// of the three is given. Errors name the file and line (UserError).
std::optional<Schedule> schedule_from_options(const boost::program_options::variables_map& vm, const Instance& inst);

// Standard output is checked at exit (tools/main.cpp): a failed write or
// flush makes the command fail with "<stdout>: write failed: REASON", exit 1.
// Returns the error message, or "" if stdout is fine.
std::string stdout_error();

// text with every control byte (below 0x20, and 0x7f) written as \xNN, so
// that an error message never moves the cursor, recolours or clears the
// user's terminal (a file or option value may hold anything). UTF-8 stays.
std::string printable(const std::string& text);

// --- Interruption (SIGINT, SIGTERM) ---------------------------------------
// install_stop_handlers() makes SIGINT and SIGTERM set the stop request of
// common/limits.hpp instead of killing the process. Campaign commands (fuzz,
// verify, gen-instances) call it first, poll stop_requested() between items
// (long computations inside an item see it through Deadline/SearchBudget and
// end as UNKNOWN), finish or remove the file in progress, print a partial
// summary marked interrupted, and return interrupted_exit_code()
// (128 + signal: 130 for SIGINT, 143 for SIGTERM).
void install_stop_handlers();
int interrupted_exit_code();

// --- Out of memory ----------------------------------------------------------
// Work that cannot fit is refused before it starts: throws UserError
// "SUBJECT: too large: WHAT would need about X MB of memory, more than the
// Y MB available" when `bytes` (an estimate of the peak) exceeds the memory
// this process can have: the smaller of the physical memory and the
// address-space limit (RLIMIT_AS, `ulimit -v`). O(1).
void refuse_beyond_memory(const std::string& subject, unsigned __int128 bytes, const std::string& what);

// While an Activity is alive, an exception that reaches main is reported
// with its context (innermost activity): an std::bad_alloc as "FILE: out of
// memory while WHAT", an std::length_error (a size beyond what a container
// can hold) as "FILE: too large while WHAT: DETAIL". Only a real bad_alloc
// says "out of memory"; bad_array_new_length (a size that overflowed) and
// every other exception keep their own message.
//   cli::Activity act(path, "compiling the formula");
class Activity {
 public:
  Activity(std::string file, std::string what);
  ~Activity();
  Activity(const Activity&) = delete;
  Activity& operator=(const Activity&) = delete;
  // "FILE: out of memory while WHAT" of the innermost activity that was
  // alive when the exception was thrown (recorded as the stack unwinds), or
  // "out of memory" when none was.
  static std::string out_of_memory_message();
  // "FILE: too large while WHAT: DETAIL" (the same context), or
  // "too large: DETAIL".
  static std::string too_large_message(const std::string& detail);
  const std::string& file() const { return file_; }
  const std::string& what() const { return what_; }

 private:
  std::string file_, what_;
  Activity* outer_;
  int uncaught_;  // exceptions in flight at construction: more at destruction = unwinding
};

}  // namespace gridlock::cli
