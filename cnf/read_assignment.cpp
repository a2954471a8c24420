#include <charconv>
#include <fstream>
#include <iostream>
#include <sstream>

#include "cnf/assignment.hpp"

namespace gridlock {

MaybeError read_assignment(std::istream& in, const std::string& name, int num_vars, std::vector<bool>& value) {
  value.assign(static_cast<size_t>(num_vars) + 1, false);
  std::vector<signed char> seen(static_cast<size_t>(num_vars) + 1, 0);
  std::string line;
  long lineno = 0;
  bool ended = false;
  while (std::getline(in, line)) {
    ++lineno;
    std::istringstream ss(line);
    std::string tok;
    bool first = true;
    while (ss >> tok) {
      if (first && (tok[0] == 'c' || tok == "s")) break;  // comment or status line
      if (first && tok == "v") {
        first = false;
        continue;
      }
      first = false;
      if (ended) return Diagnostic{name, lineno, "text after the terminating 0: '" + tok.substr(0, 40) + "'"};
      long long lit = 0;
      auto [p, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), lit);
      if (ec != std::errc() || p != tok.data() + tok.size())
        return Diagnostic{name, lineno, "'" + tok.substr(0, 40) + "' is not a literal"};
      if (lit == 0) {
        ended = true;
        continue;
      }
      long long var = lit < 0 ? -lit : lit;
      if (var > num_vars)
        return Diagnostic{name, lineno, "literal " + tok + " beyond the formula's " + std::to_string(num_vars) +
                                            " variables"};
      auto v = static_cast<size_t>(var);
      signed char sign = lit > 0 ? 1 : -1;
      if (seen[v] == -sign) return Diagnostic{name, lineno, "variable " + std::to_string(var) + " given both values"};
      seen[v] = sign;
      value[v] = lit > 0;
    }
  }
  if (in.bad()) return Diagnostic{name, 0, "read error"};
  return std::nullopt;
}

MaybeError read_assignment_file(const std::string& path, int num_vars, std::vector<bool>& value) {
  if (path == "-") return read_assignment(std::cin, "<stdin>", num_vars, value);
  std::ifstream in(path, std::ios::binary);
  if (!in) return Diagnostic{path, 0, "cannot open file"};
  return read_assignment(in, path, num_vars, value);
}

}  // namespace gridlock
