// DIMACS CNF writer; the reader (parse_dimacs.cpp) reads its output back.
#include <ostream>
#include <sstream>
#include <string>
#include <string_view>

#include "cnf/dimacs.hpp"
#include "common/assert.hpp"

namespace gridlock {

void write_dimacs(std::ostream& out, const Formula& f) {
  GRIDLOCK_ASSERT(validate(f).empty(), "write_dimacs needs a valid formula");
  for (const auto& comment : f.comments) {
    // One "c" line per line of the comment, so that a multi-line comment
    // cannot smuggle a clause or a header into the file.
    size_t start = 0;
    while (true) {
      size_t end = comment.find('\n', start);
      std::string_view part(comment);
      part = part.substr(start, end == std::string::npos ? std::string::npos : end - start);
      out << (part.empty() ? "c" : "c ") << part << '\n';
      if (end == std::string::npos) break;
      start = end + 1;
    }
  }
  out << "p cnf " << f.num_vars << ' ' << f.clauses.size() << '\n';
  std::string line;
  for (const auto& clause : f.clauses) {
    line.clear();
    for (int lit : clause) {
      line += std::to_string(lit);
      line += ' ';
    }
    line += "0\n";
    out << line;
  }
}

std::string to_dimacs(const Formula& f) {
  std::ostringstream out;
  write_dimacs(out, f);
  return out.str();
}

}  // namespace gridlock
