// GRIDLOCK_ASSERT(cond, msg): the run-time check of a contract's "Requires"
// inside the library (a bug of ours if it fails).
// GRIDLOCK_REQUIRE(cond, msg): the always-on check of a public function's
// precondition, for what a library user passes in: when cond is false it
// throws std::invalid_argument(msg) (msg, a string expression, is evaluated
// only then), in every build. The command line maps it to a message naming
// the input; docs/architecture.md, "Conventions".
//
// A failed assertion is a bug in the caller, not bad input (bad input is a
// Diagnostic, see common/diagnostic.hpp): it prints
//   gridlock: assertion failed: FILE:LINE: cond: msg
// on stderr and aborts. Checked when GRIDLOCK_ENABLE_ASSERT is defined, which
// the build does in Debug, sanitizer and fuzzing builds (CMake option
// GRIDLOCK_ASSERTIONS); otherwise cond is compiled but never evaluated, so a
// precondition costs nothing in an optimised build and cannot rot.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace gridlock::detail {

[[noreturn]] inline void assertion_failed(const char* file, int line, const char* cond, const char* msg) {
  std::fprintf(stderr, "gridlock: assertion failed: %s:%d: %s: %s\n", file, line, cond, msg);
  std::abort();
}

}  // namespace gridlock::detail

#define GRIDLOCK_REQUIRE(cond, msg)                             \
  do {                                                          \
    if (!(cond)) throw std::invalid_argument(std::string(msg)); \
  } while (false)

#ifdef GRIDLOCK_ENABLE_ASSERT
#define GRIDLOCK_ASSERT(cond, msg) \
  ((cond) ? static_cast<void>(0) : ::gridlock::detail::assertion_failed(__FILE__, __LINE__, #cond, msg))
#else
#define GRIDLOCK_ASSERT(cond, msg) \
  do {                             \
    if (false) {                   \
      static_cast<void>(cond);     \
    }                              \
  } while (false)
#endif
