// The one exception for "this input is too large for what the library can
// represent" (more variables than an int holds, denominators or bounds past
// the exact arithmetic's range). It is a user's condition, not a bug: the
// command line reports it as "FILE: too large ..." with exit code 1, never as
// "internal:" (tools/main.cpp, docs/errors.md). Derives from
// std::length_error (a size past an implementation limit), so a caller that
// catches that still sees it.
#pragma once

#include <stdexcept>

namespace gridlock {

class InputTooLarge : public std::length_error {
 public:
  using std::length_error::length_error;
};

}  // namespace gridlock
