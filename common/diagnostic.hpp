// Diagnostics: how every reader in gridlock reports bad input.
//
// Readers never print and never exit: they return a Diagnostic, and only
// tools/main.cpp turns it into "gridlock: error: FILE:LINE: what" and exit 1
// (CaDiCaL's rule: parse errors are returned, the driver decides).
#pragma once

#include <optional>
#include <string>
#include <utility>

namespace gridlock {

struct Diagnostic {
  std::string file;     // as the user named it; "-" or "<stdin>" for standard input
  long line = 0;        // 1-based; 0 when the problem is not tied to a line
  std::string message;  // lower case, no trailing period, says what is wrong

  // "FILE:LINE: message" (or "FILE: message" when line is 0).
  std::string str() const {
    std::string s = file;
    if (line > 0) s += ":" + std::to_string(line);
    if (!s.empty()) s += ": ";
    return s + message;
  }
};

// A readers' result: either a value or the first problem found.
using MaybeError = std::optional<Diagnostic>;

}  // namespace gridlock
