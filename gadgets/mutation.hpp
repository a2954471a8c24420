// Deliberately broken gadgets, for the mutation tests and for proving that
// `gridlock fuzz` finds and shrinks a real bug (tools/fuzz_command.cpp,
// hidden option --break-gadget). Never used otherwise.
//
// Each mutation changes one gadget kind everywhere it is drawn. The ones
// listed are those that change the answer of the reduction on some formula
// (so the end-to-end check can catch them): widening the variable gadget's
// "not both values" gap, by contrast, changes nothing, since setting a
// variable both ways only makes more literals false (docs/gadgets.md).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace gridlock {

enum class Mutation {
  None,
  VariableLooseY,    // the y gap of the variable gadget widened by one: y no longer forces a value
  ClauseLoose,       // the clause gap widened by one: a clause never collides
  ClauseTight,       // the clause gap narrowed by one: a clause needs two true literals
  OrderLoose,        // the order gap widened by one: b may run before a
  OrderDropRelease,  // the order gadget's widening operation moved off the gap's path
  SeparationLoose,   // the separation gadget with one empty cell more: b never collides
                     // (continuous reduction only: the discrete one draws no separation gadget)
};

// Stable names for the command line: "none", "variable-loose-y",
// "clause-loose", "clause-tight", "order-loose", "order-drop-release",
// "separation-loose".
const char* mutation_name(Mutation m);
std::optional<Mutation> parse_mutation(const std::string& s);
std::vector<Mutation> all_mutations();  // every one except None

}  // namespace gridlock
