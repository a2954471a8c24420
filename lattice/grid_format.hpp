// The .grid instance format (documented in docs/grid-format.md).
//
//   c any comment                       comment lines anywhere
//   p grid NODES EDGES OPS COUPLINGS    header, before every other line;
//                                       COUPLINGS counts the q lines
//   n X Y                               a node in cell (X, Y)
//   e X1 Y1 X2 Y2                       an edge between two adjacent nodes
//   o NAME expand|grow|contract X Y DIR an operation of the node in (X, Y)
//                                       toward DIR in {+x, -x, +y, -y};
//                                       contract X Y DIR is "v into u" with
//                                       u = (X, Y) and v = (X, Y) + DIR
//   q NAME OP...                        a coupling of named operations
//   a X Y                               the anchor (optional; default: first node)
//
// A line may refer only to what lines above it defined. Operations named in no
// q line are singleton couplings named after the operation.
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
