// DIMACS CNF: reader and writer (format and every error message are
// documented in docs/formulas.md; tests/cnf_dimacs_test.cpp checks each).
//
//   c a comment                 a line whose first non-blank byte is 'c', anywhere
//   p cnf VARIABLES CLAUSES     the header, once, before the first clause;
//                               any spacing (blanks and tabs)
//   1 -2 3 0                    clauses: literals separated by white space, each
//   -1                          clause ended by 0; a clause may span lines and a
//   2 0 3 0                     line may hold several clauses; "0" alone is the
//                               empty clause
//   %                           optional (SATLIB): ends the clause list; the
//                               rest of the input is ignored
//
// Lines may start with blanks and end with CR (Windows line ends).
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "cnf/formula.hpp"
#include "common/diagnostic.hpp"

namespace gridlock {

struct DimacsOptions {
  // true (default): a clause count different from the header's is an error,
  // because it almost always means a truncated or concatenated file. false:
  // the header's clause count is not checked (the variable count still is).
  bool strict_count = true;
  // If set, receives the line of the 'p cnf' header (0 if none was read), so
  // that size checks after reading can point at it.
  long* header_line = nullptr;
  // If set, receives the line on which each clause starts (where its first
  // literal, or the 0 of an empty clause, stands), one entry per clause of
  // `out`, so that checks after reading can point at a clause.
  std::vector<long>* clause_lines = nullptr;
};

// Reads one formula. Returns nullopt and fills `out` (num_vars from the
// header, clauses in file order, comment lines without their "c " prefix in
// file order) on success; on the first problem returns a Diagnostic naming
// `name`, the 1-based line and what is wrong, and leaves `out` unspecified.
// Never throws for bad input, never prints, never crashes whatever the bytes
// (binary input, huge numbers, huge header counts are all reported; nothing is
// allocated from header counts). Time and memory O(size of input).
MaybeError read_dimacs(std::istream& in, const std::string& name, Formula& out, const DimacsOptions& opt = {});

// Same from a file; "-" reads standard input (named "<stdin>" in messages).
// A file that cannot be opened is a Diagnostic "cannot open file" (line 0).
MaybeError read_dimacs_file(const std::string& path, Formula& out, const DimacsOptions& opt = {});

// Same from a string held in memory (tests, fuzzing).
MaybeError read_dimacs_string(const std::string& text, const std::string& name, Formula& out,
                              const DimacsOptions& opt = {});

// Writes f: its comments first ("c " + text; a comment holding '\n' becomes
// several lines), then "p cnf V C", then one clause per line ending in " 0".
// read_dimacs gives back an equal Formula when the comments hold no control
// bytes other than tab (and do not end in CR). Requires validate(f) to be
// empty (GRIDLOCK_ASSERT). O(size of f).
void write_dimacs(std::ostream& out, const Formula& f);

// write_dimacs into a string.
std::string to_dimacs(const Formula& f);

}  // namespace gridlock
