#include "tools/cli_common.hpp"

#include <signal.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "cnf/dimacs.hpp"
#include "common/diagnostic.hpp"
#include "common/internal/atomic_file.hpp"
#include "common/limits.hpp"
#include "lattice/grid_format.hpp"
#include "reductions/compile.hpp"
#include "tools/options.hpp"
#include "tools/user_error.hpp"

namespace gridlock::cli {

namespace fs = std::filesystem;

Formula load_formula(const std::string& path, bool strict_count, FormulaUse use) {
  Formula f;
  DimacsOptions opt;
  opt.strict_count = strict_count;
  long header_line = 0;
  opt.header_line = &header_line;
  std::vector<long> clause_lines;
  if (use == FormulaUse::CompileAsIs) opt.clause_lines = &clause_lines;
  protect_input(path);
  {
    Activity act(path == "-" ? "<stdin>" : path, "reading the formula");
    if (auto err = read_dimacs_file(path, f, opt)) throw UserError(*err);
  }
  const std::string name = path == "-" ? "<stdin>" : path;
  if (use == FormulaUse::Read) return f;
  int max_used = 0;
  for (const auto& c : f.clauses)
    for (int lit : c) max_used = std::max(max_used, var_of(lit));
  if (f.num_vars - max_used > kMaxUnusedVariables)
    throw UserError(Diagnostic{name, header_line,
                               "the header declares " + std::to_string(f.num_vars) +
                                   " variables but no clause uses one above " + std::to_string(max_used) +
                                   ": at most " + std::to_string(kMaxUnusedVariables) +
                                   " unused variables beyond the last one used are accepted"});
  for (size_t h = 0; h < clause_lines.size(); ++h)
    if (f.clauses[h].empty())
      throw UserError(
          Diagnostic{name, clause_lines[h],
                     empty_clause_message(h) + " ('gridlock cnf to-lsat' gives an equivalent formula without it)"});
  if (use == FormulaUse::Compile || use == FormulaUse::CompileAsIs) {
    // Both models: the continuous reduction draws 2 nodes more, and verify,
    // fuzz and gen-instances may compile either (never "internal:" midway).
    const uint64_t discrete = compiled_node_count(f), continuous = compiled_node_count(f, TimeModel::Continuous);
    if (std::max(discrete, continuous) > static_cast<uint64_t>(kMaxNodes))
      throw UserError(Diagnostic{name, header_line,
                                 "the compiled instance would have " + std::to_string(discrete) +
                                     " nodes (43n + 5L + 15m - 11; " + std::to_string(continuous) +
                                     " in the continuous model), more than the .grid format's limit of " +
                                     std::to_string(kMaxNodes)});
  }
  return f;
}

Instance load_instance(const std::string& path) {
  Instance inst;
  protect_input(path);
  Activity act(path == "-" ? "<stdin>" : path, "reading the instance");
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

namespace {
// The options that name files a command reads, and those that name outputs.
const char* const kInputOptions[] = {"instance", "formula",    "file",     "inputs",
                                     "times",    "order-file", "schedule", "model"};
const char* const kOutputOptions[] = {"output", "out", "svg", "json-out", "reproducers", "pictures"};

std::vector<std::string> option_paths(const po::variables_map& vm, const char* name) {
  if (!vm.count(name)) return {};
  const boost::any& v = vm[name].value();
  if (const auto* one = boost::any_cast<std::string>(&v)) return {*one};
  if (const auto* many = boost::any_cast<std::vector<std::string>>(&v)) return *many;
  return {};
}

// Is output option `name` of `command` a folder (its files go below it)?
bool is_folder_option(const std::string& name, const std::string& command) {
  return name == "reproducers" || name == "pictures" ||
         (name == "out" && (command == "fuzz" || command == "gen-instances"));
}
}  // namespace

void check_output_path(const std::string& option, const std::string& path, bool folder) {
  if (path.empty()) throw UserError("--" + option + ": empty path: give a " + (folder ? "folder" : "file"));
  if (path == "-") return;
  std::error_code ec;
  const fs::path abs = fs::absolute(path, ec).lexically_normal();
  if (ec) return;  // the write itself reports what is wrong
  const fs::path root = abs.root_path();
  const bool is_root = abs == root || abs.relative_path().empty() || abs.relative_path() == ".";
  if (is_root) throw UserError("--" + option + ": '" + path + "' is the file-system root: give a folder below it");
  if (!folder && abs.parent_path() == root)
    throw UserError("--" + option + ": '" + path + "' is at the file-system root: give a file in a folder below it");
}

void guard_paths(const po::variables_map& vm, const std::string& command) {
  std::vector<std::string> inputs;
  for (const char* name : kInputOptions)
    for (const auto& p : option_paths(vm, name)) {
      protect_input(p);
      inputs.push_back(p);
    }
  for (const char* name : kOutputOptions)
    for (const auto& p : option_paths(vm, name)) {
      check_output_path(name, p, is_folder_option(name, command));
      refuse_overwriting_input(p, inputs);
    }
}

bool parse_args(const std::vector<std::string>& args, const po::options_description& visible,
                const po::positional_options_description& positional, po::variables_map& vm, const std::string& usage,
                const std::string& description, const po::options_description* hidden) {
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
    guard_paths(vm, command_of(usage));
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

std::optional<Schedule> schedule_from_options(const boost::program_options::variables_map& vm, const Instance& inst) {
  Schedule sched;
  if (vm.count("times")) {
    if (auto e = read_times_file(inst, vm["times"].as<std::string>(), sched)) throw UserError(*e);
    return sched;
  }
  std::vector<CouplingId> order;
  if (vm.count("order")) {
    std::istringstream ss(vm["order"].as<std::string>());
    std::vector<std::string> names;
    for (std::string w; ss >> w;) names.push_back(w);
    if (auto e = parse_order(inst, names, "--order", 0, order)) throw UserError(*e);
  } else if (vm.count("order-file")) {
    if (auto e = read_order_file(inst, vm["order-file"].as<std::string>(), order)) throw UserError(*e);
  } else {
    return std::nullopt;
  }
  return schedule_from_order(order);
}

void parse_shard(const std::string& text, uint64_t& k, uint64_t& n) {
  const size_t slash = text.find('/');
  if (slash == std::string::npos) throw UserError("--shard: want K/N with 0 <= K < N, not '" + text + "'");
  k = parse_count("shard", text.substr(0, slash), 0);
  n = parse_count("shard", text.substr(slash + 1), 1);
  if (k >= n) throw UserError("--shard: want K/N with 0 <= K < N, not '" + text + "'");
}

void write_text_file(const std::string& path, const std::string& text) {
  if (path == "-") {
    std::cout << text;
    return;
  }
  if (auto err = write_file_atomic(path, text)) throw UserError(*err);
}

void write_text_files(const std::vector<std::pair<std::string, std::string>>& files) {
  DeferSignals hold;  // the staged files are renamed or removed before a signal acts
  std::vector<StagedFile> staged;
  auto discard_all = [&] {
    for (auto& f : staged) discard_file(f);
  };
  for (const auto& [path, text] : files) {
    if (path == "-") continue;
    StagedFile f;
    if (auto err = stage_file(path, text, f)) {
      discard_all();
      throw UserError(*err);
    }
    staged.push_back(f);
  }
  for (auto& f : staged)
    if (auto err = commit_file(f)) {
      discard_all();
      throw UserError(*err);
    }
  for (const auto& [path, text] : files)
    if (path == "-") std::cout << text;
}

std::string certificate_not_written(const std::string& path, bool yes) {
  return std::string("no certificate written: ") +
         (yes ? "only a NO has one (the witness of this YES is on the 'v' lines)" : "no answer") + "; " +
         certificate_left(path);
}

std::string certificate_left(const std::string& path) {
  if (path == "-") return "nothing printed";
  std::error_code ec;
  return path + (std::filesystem::exists(path, ec) ? " is left as it was (not this answer's)" : " not created");
}

void refuse_overwriting_input(const std::string& out, const std::vector<std::string>& inputs) {
  if (out == "-") return;
  for (const auto& in : inputs) {
    if (in == "-") continue;
    std::error_code ec;
    bool same = fs::path(out).lexically_normal() == fs::path(in).lexically_normal() || fs::equivalent(out, in, ec);
    if (same) throw UserError(Diagnostic{out, 0, "output would overwrite the input " + in});
  }
  protect_input_check(out);
}

void protect_input_check(const std::string& out) {
  if (std::string in = protected_input_at(out); !in.empty())
    throw UserError(Diagnostic{out, 0, "output would overwrite the input " + in});
}

std::string printable(const std::string& text) {
  std::string out;
  for (char c : text) {
    const auto b = static_cast<unsigned char>(c);
    if (b >= 0x20 && b != 0x7f) {
      out += c;
      continue;
    }
    char hex[8];
    std::snprintf(hex, sizeof hex, "\\x%02x", b);
    out += hex;
  }
  return out;
}

std::string stdout_error() {
  std::cout.flush();
  if (!std::cout) return "<stdout>: write failed" + std::string(errno ? ": " + std::string(std::strerror(errno)) : "");
  if (std::fflush(stdout) != 0 || std::ferror(stdout))
    return "<stdout>: write failed: " + std::string(std::strerror(errno));
  return "";
}

namespace {
extern "C" void on_stop_signal(int sig) { stop_signal().store(sig, std::memory_order_relaxed); }
}  // namespace

void install_stop_handlers() {
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = 0;  // no SA_RESTART: a blocking read returns EINTR
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

int interrupted_exit_code() { return 128 + stop_signal().load(); }

namespace {
Activity* g_activity = nullptr;
// The innermost activity the exception in flight left (file, what), recorded
// as the stack unwinds; cleared when a new activity starts (the exception
// that left it was handled).
std::string g_unwound_file, g_unwound_what;
bool g_unwound = false;

// "FILE: PROBLEM while WHAT[: DETAIL]" for the activity an exception left or
// the one alive; "PROBLEM[: DETAIL]" when none.
std::string in_context(const std::string& problem, const std::string& detail) {
  const std::string tail = detail.empty() ? "" : ": " + detail;
  if (g_unwound) return Diagnostic{g_unwound_file, 0, problem + " while " + g_unwound_what + tail}.str();
  if (g_activity) return Diagnostic{g_activity->file(), 0, problem + " while " + g_activity->what() + tail}.str();
  return problem + tail;
}
}  // namespace

Activity::Activity(std::string file, std::string what)
    : file_(std::move(file)), what_(std::move(what)), outer_(g_activity), uncaught_(std::uncaught_exceptions()) {
  g_activity = this;
  if (outer_ == nullptr) g_unwound = false;
}

Activity::~Activity() {
  g_activity = outer_;
  // Unwinding: main's handler runs after every destructor, so the innermost
  // activity (the first destroyed) is remembered here.
  if (std::uncaught_exceptions() > uncaught_ && !g_unwound) {
    try {
      g_unwound_file = file_;
      g_unwound_what = what_;
      g_unwound = true;
    } catch (...) {  // no memory left even for the copy: main says "out of memory"
    }
  }
}

std::string Activity::out_of_memory_message() { return in_context("out of memory", ""); }

std::string Activity::too_large_message(const std::string& detail) { return in_context("too large", detail); }

void refuse_beyond_memory(const std::string& subject, unsigned __int128 bytes, const std::string& what) {
  unsigned __int128 limit = static_cast<unsigned __int128>(sysconf(_SC_PHYS_PAGES)) *
                            static_cast<unsigned __int128>(sysconf(_SC_PAGE_SIZE));
  std::string why = "physical memory";
  struct rlimit as {};
  if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY && as.rlim_cur < limit) {
    limit = as.rlim_cur;
    why = "address-space limit (ulimit -v)";
  }
  if (bytes <= limit) return;
  auto mb = [](unsigned __int128 b) {
    const unsigned __int128 m = b >> 20;
    return std::to_string(m > UINT64_MAX ? UINT64_MAX : static_cast<uint64_t>(m));
  };
  throw UserError(Diagnostic{subject, 0,
                             "too large: " + what + " would need about " + mb(bytes) + " MB of memory, more than the " +
                                 mb(limit) + " MB available (" + why + ")"});
}

}  // namespace gridlock::cli
