#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "cnf/assignment.hpp"

namespace gridlock {

namespace {

std::string shown(const std::string& tok) { return tok.size() > 40 ? tok.substr(0, 40) + "..." : tok; }

// Literal parsing shared by files and command-line literals: records lit in
// value/seen; sets ended on 0. Returns an error message or "".
std::string take_literal(const std::string& tok, int num_vars, std::vector<bool>& value, std::vector<signed char>& seen,
                         bool& ended) {
  if (ended) return "text after the terminating 0: '" + shown(tok) + "'";
  long long lit = 0;
  auto [p, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), lit);
  if (ec != std::errc() || p != tok.data() + tok.size()) return "'" + shown(tok) + "' is not a literal";
  if (lit == 0) {
    if (tok != "0") return "'" + shown(tok) + "' is not a literal (0 alone ends the model)";
    ended = true;
    return "";
  }
  long long var = lit < 0 ? -lit : lit;
  if (var > num_vars) return "literal " + tok + " beyond the formula's " + std::to_string(num_vars) + " variables";
  auto v = static_cast<size_t>(var);
  signed char sign = lit > 0 ? 1 : -1;
  if (seen[v] == -sign) return "variable " + std::to_string(var) + " given both values";
  seen[v] = sign;
  value[v] = lit > 0;
  return "";
}

// The first variable not given, or 0.
int first_missing(const std::vector<signed char>& seen) {
  for (size_t v = 1; v < seen.size(); ++v)
    if (seen[v] == 0) return static_cast<int>(v);
  return 0;
}

}  // namespace

MaybeError read_assignment(std::istream& in, const std::string& name, int num_vars, std::vector<bool>& value) {
  value.assign(static_cast<size_t>(num_vars) + 1, false);
  std::vector<signed char> seen(static_cast<size_t>(num_vars) + 1, 0);
  std::string line;
  long lineno = 0, status_line = 0;
  bool ended = false, any = false;
  while (std::getline(in, line)) {
    ++lineno;
    std::istringstream ss(line);
    std::string tok;
    if (!(ss >> tok)) continue;
    any = true;
    if (tok[0] == 'c') continue;
    if (tok == "s") {
      std::string status, extra;
      ss >> status;
      if (status_line > 0)
        return Diagnostic{name, lineno, "second status line (the first is line " + std::to_string(status_line) + ")"};
      if (status != "SATISFIABLE" || (ss >> extra))
        return Diagnostic{name, lineno,
                          "the answer is not 's SATISFIABLE' but '" + shown(line) + "': it holds no model"};
      status_line = lineno;
      continue;
    }
    if (tok != "v")
      return Diagnostic{name, lineno, "expected a 'c', 's SATISFIABLE' or 'v' line, got '" + shown(tok) + "'"};
    while (ss >> tok)
      if (std::string e = take_literal(tok, num_vars, value, seen, ended); !e.empty())
        return Diagnostic{name, lineno, e};
  }
  if (in.bad()) return Diagnostic{name, 0, "read error"};
  const long last = std::max<long>(lineno, 1);
  if (!any) return Diagnostic{name, 1, "empty model: want 's SATISFIABLE' and 'v' lines ending in 0"};
  if (status_line == 0) return Diagnostic{name, last, "no 's SATISFIABLE' line: not a SAT-competition answer"};
  if (!ended) return Diagnostic{name, last, "the 'v' lines do not end in 0 (truncated?)"};
  if (int v = first_missing(seen))
    return Diagnostic{name, last,
                      "variable " + std::to_string(v) + " is missing: the model must give all " +
                          std::to_string(num_vars) + " variables"};
  return std::nullopt;
}

MaybeError read_assignment_file(const std::string& path, int num_vars, std::vector<bool>& value) {
  if (path == "-") return read_assignment(std::cin, "<stdin>", num_vars, value);
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return Diagnostic{path, 0, "is a directory, not a file"};
  std::ifstream in(path, std::ios::binary);
  if (!in) return Diagnostic{path, 0, "cannot open file"};
  return read_assignment(in, path, num_vars, value);
}

bool looks_like_literals(const std::string& text) {
  bool digit = false;
  for (char ch : text) {
    if (ch >= '0' && ch <= '9') digit = true;
    else if (ch != '-' && ch != ' ' && ch != '\t' && ch != '\n') return false;
  }
  return digit;
}

MaybeError parse_assignment_literals(const std::string& text, const std::string& name, int num_vars,
                                     std::vector<bool>& value) {
  value.assign(static_cast<size_t>(num_vars) + 1, false);
  std::vector<signed char> seen(static_cast<size_t>(num_vars) + 1, 0);
  std::istringstream ss(text);
  bool ended = false;
  for (std::string tok; ss >> tok;)
    if (std::string e = take_literal(tok, num_vars, value, seen, ended); !e.empty()) return Diagnostic{name, 0, e};
  if (int v = first_missing(seen))
    return Diagnostic{name, 0,
                      "variable " + std::to_string(v) + " is missing: the model must give all " +
                          std::to_string(num_vars) + " variables"};
  return std::nullopt;
}

MaybeError read_model(const std::string& arg, int num_vars, std::vector<bool>& value) {
  std::error_code ec;
  if (arg != "-" && !std::filesystem::exists(arg, ec) && looks_like_literals(arg))
    return parse_assignment_literals(arg, "--model", num_vars, value);
  return read_assignment_file(arg, num_vars, value);
}

}  // namespace gridlock
