// Reading and writing the .grid instance format. The format is specified in
// one place only, docs/grid-format.md (lines, names, bounds, every error
// message); this reader and writer implement that page, and
// tests/lattice_format_test.cpp checks them against it.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "common/diagnostic.hpp"
#include "lattice/instance.hpp"

namespace gridlock {

// Reads one instance. On any problem returns a Diagnostic naming `name`, the
// line, and what is wrong; `out` is then unspecified. Never crashes, whatever
// the bytes (binary input, overlong lines, huge numbers are all reported).
// Time O(size of input) expected.
MaybeError read_instance(std::istream& in, const std::string& name, Instance& out);
// Same from a file; "-" reads standard input. A missing file is a Diagnostic.
MaybeError read_instance_file(const std::string& path, Instance& out);

// Writes inst so that read_instance gives it back exactly (same node, edge,
// operation and coupling order, same names, the anchor). Each comment becomes
// a "c" line after the header comment.
void write_instance(std::ostream& out, const Instance& inst, const std::vector<std::string>& comments = {});

}  // namespace gridlock
