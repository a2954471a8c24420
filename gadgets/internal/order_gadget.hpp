// The order gadget a < b (paper, proof of the NP-completeness theorem, and
// docs/model.md worked case 2): b collides unless a ran before it.
//
// It is the one-gap gadget (gadgets/internal/gap_gadget.hpp) with gap 0, a on the
// backbone (widens) and b on the hook (narrows):
//
//   row+1:  A B =b= o
//           |       |
//   row:    @ =a= o o
//
// Contract: the state S collides iff b is in S and a is not: 0 + a - b >= 0.
// In the discrete model that is "b before a collides"; with both at once
// (continuous model) the gap stays 0: no collision.
// 6 nodes, 5 edges, 2 operations.
#pragma once

#include <cstdint>
#include <string>

#include "gadgets/contract.hpp"
#include "gadgets/internal/canvas.hpp"
#include "gadgets/mutation.hpp"

namespace gridlock {

// Draws the gadget in rows row, row+1 with its attach node at (0, row).
GadgetPlacement place_order_gadget(Canvas& canvas, int64_t row, const std::string& first, const std::string& second,
                                   Mutation mutation = Mutation::None);

}  // namespace gridlock
