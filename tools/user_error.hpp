// The command line's one error type. Thrown only by tools/ code, for bad
// usage or for bad input that the library has already reported as a
// Diagnostic (common/diagnostic.hpp); main() catches it, prints
// "gridlock: error: <what>" and exits 1. Library code never throws it: it
// returns Diagnostics (docs/architecture.md, Conventions).
#pragma once

#include <stdexcept>
#include <string>

#include "common/diagnostic.hpp"

namespace gridlock {

class UserError : public std::runtime_error {
 public:
  explicit UserError(const std::string& what) : std::runtime_error(what) {}
  explicit UserError(const Diagnostic& d) : std::runtime_error(d.str()) {}
};

}  // namespace gridlock
