// Assignments as files: the 'v' lines a SAT solver prints, or bare literals.
//
//   c comment            skipped (as is an 's ...' status line)
//   v 1 -2 3             a leading 'v' is dropped; literals v / -v
//   v -4 0               a 0 ends the assignment (optional)
//
// So the output of `gridlock cnf solve` and of any SAT-competition solver can
// be read back as it is.
#pragma once

#include <string>
#include <vector>

#include "common/diagnostic.hpp"

namespace gridlock {

// Reads an assignment of variables 1..num_vars into value (indexed
// 1..num_vars, value[0] unused). Variables not mentioned are false. Errors
// (with file and line): a token that is not an integer, a literal beyond
// num_vars, a variable given twice with opposite signs, text after the 0.
// "-" reads standard input. O(size of input + num_vars).
MaybeError read_assignment_file(const std::string& path, int num_vars, std::vector<bool>& value);
MaybeError read_assignment(std::istream& in, const std::string& name, int num_vars, std::vector<bool>& value);

}  // namespace gridlock
