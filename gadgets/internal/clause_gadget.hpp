// The clause gadget for a clause of k >= 1 literals (paper, proof of the
// NP-completeness theorem): one operation per literal occurrence, coupled
// with the operation that makes the literal false, and a release u.
//
// It is the one-gap gadget (gadgets/internal/gap_gadget.hpp) with gap k - 1, u on the
// backbone (widens) and the k literal operations on the hook (narrow):
//
//   row+1:  o . . B =l1= o - o =l2= o - o =l3= o     (k = 3: two empty cells)
//           |                                  |
//   row:    @ =u= o - o - o - o - o - o - o - o
//
// Contract: the state S collides iff all k literal operations are in S and u
// is not: k - 1 - l1 - ... - lk + u >= 0. After u, all k may run.
// Nodes: 5k + 1; operations: k + 1.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gadgets/contract.hpp"
#include "gadgets/internal/canvas.hpp"
#include "gadgets/mutation.hpp"

namespace gridlock {

// Draws the gadget in rows row, row+1 with its attach node at (0, row).
// Requires literal_ops non-empty.
GadgetPlacement place_clause_gadget(Canvas& canvas, int64_t row, const std::vector<std::string>& literal_ops,
                                    const std::string& release, Mutation mutation = Mutation::None);

}  // namespace gridlock
