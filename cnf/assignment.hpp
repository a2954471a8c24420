// Assignments (models): SAT-competition answers in files, or literals on the
// command line.
//
// A file is a SAT-competition answer, as `gridlock cnf solve` and every
// competition solver print it:
//
//   c comment            any number, anywhere
//   s SATISFIABLE        exactly one status line (another status: no model)
//   v 1 -2 3             literals v / -v, over one or more 'v' lines
//   v -4 0               a 0 ends the model; nothing but comments after it
//
// Every variable 1..num_vars must be given exactly once (a literal may
// repeat, never with both signs). Errors carry FILE:LINE ("FILE:1" for an
// empty file; the last line for what is missing at the end).
#pragma once

#include <string>
#include <vector>

#include "common/diagnostic.hpp"

namespace gridlock {

// Reads a SAT-competition answer (see above) into value (indexed
// 1..num_vars, value[0] unused). "-" reads standard input; a directory is
// refused. O(size of input + num_vars).
MaybeError read_assignment_file(const std::string& path, int num_vars, std::vector<bool>& value);
MaybeError read_assignment(std::istream& in, const std::string& name, int num_vars, std::vector<bool>& value);

// Literals given as text ("1 -2 3", an optional trailing 0), every variable
// once; errors name `name` (e.g. "--model") without a line.
MaybeError parse_assignment_literals(const std::string& text, const std::string& name, int num_vars,
                                     std::vector<bool>& value);

// True if text holds only digits, '-' and blanks (and some digit).
bool looks_like_literals(const std::string& text);

// The --model argument of the command line: a file (or "-") holding a
// SAT-competition answer, or, when no such file exists and the text looks
// like literals, the literals themselves ("1 -2 3").
MaybeError read_model(const std::string& arg, int num_vars, std::vector<bool>& value);

}  // namespace gridlock
