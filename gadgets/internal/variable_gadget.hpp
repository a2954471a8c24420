// The variable gadget for x_i (paper, proof of the NP-completeness theorem):
// operations T (set x_i true), F (set x_i false), y (x_i must be set by now)
// and z (release: the other value may be set from now on).
//
//   row+3:  A B =y= o - o               gap yB: 0 + T + F - y
//           |           |
//   row+2:  @ =T= o - o =F= o           backbone; @ = attach node (0, row+2)
//           |           |
//   row+1:  o . . a . b                 gap zA: 1 - T - F + z
//           |         |
//   row:    o - o - o =z= o - o - o
//
// Gap yB (row+3): A = (0,row+3) hangs from @, B from the right end of the
// backbone through the hook, so T and F (on the backbone between them) widen
// it and y (on the hook, right of B) narrows it: y collides unless T or F
// ran before it.
// Gap zA (row+1): a = (3,row+1) hangs from the right end of the backbone,
// b = (5,row+1) from @ through the loop down to row and back up, so T and F
// (between @ and a's end) narrow it and z (on the loop) widens it: T and F
// both before z collides; after z the second value can be set.
// The gap between (0,row+1) and a only widens (T, F); all other neighbours
// in a row are joined by edges.
//
// Contract, on the set S of its operations done: S collides iff
//   (T in S and F in S and z not in S)  or  (y in S and T, F not in S).
#pragma once

#include <cstdint>
#include <string>

#include "gadgets/contract.hpp"
#include "gadgets/internal/canvas.hpp"
#include "gadgets/mutation.hpp"

namespace gridlock {

struct VariableOps {
  std::string set_true, set_false, y, z;  // operation names
};

// Draws the gadget in rows row .. row+3, columns 0..4, attach node (0, row+2).
// 17 nodes, 16 edges, 4 operations (18 nodes with Mutation::VariableLooseY).
GadgetPlacement place_variable_gadget(Canvas& canvas, int64_t row, const VariableOps& ops,
                                      Mutation mutation = Mutation::None);

}  // namespace gridlock
