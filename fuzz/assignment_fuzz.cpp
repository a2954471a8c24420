// libFuzzer target: the assignment reader (cnf/assignment.hpp), used by
// `gridlock lift --model`. The first byte picks the formula's variable count;
// the rest is the file. Any input gives a Diagnostic or an assignment of
// exactly that many variables; never a crash or a sanitizer report.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "cnf/assignment.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const int num_vars = data[0];
  std::istringstream in(std::string(reinterpret_cast<const char*>(data + 1), size - 1));
  std::vector<bool> value;
  if (gridlock::read_assignment(in, "fuzz.txt", num_vars, value)) return 0;
  if (value.size() != static_cast<size_t>(num_vars) + 1) __builtin_trap();
  return 0;
}
