// Certificates and other text outputs as lines, for tests that drop, change
// or reorder lines and put the text back together.
#pragma once

#include <string>
#include <vector>

namespace gridlock::test {

// The lines of s without their '\n' (a last line without one is kept).
inline std::vector<std::string> lines_of(const std::string& s) {
  std::vector<std::string> out;
  for (size_t pos = 0; pos < s.size();) {
    const size_t end = s.find('\n', pos);
    out.push_back(s.substr(pos, end - pos));
    if (end == std::string::npos) break;
    pos = end + 1;
  }
  return out;
}

// Each line followed by '\n'.
inline std::string join_lines(const std::vector<std::string>& lines) {
  std::string s;
  for (const std::string& l : lines) s += l + "\n";
  return s;
}

}  // namespace gridlock::test
