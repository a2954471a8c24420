// The one-gap gadget: the shape behind both the clause gadget and the order
// gadget. Two rows; the attach node is (0, row):
//
//   row+1:  A . . . B =n1= o - o =n2= o ... o    (g empty cells between A and B)
//           |                               |
//   row:    @ =w1= o - o =w2= o - - - - - - o
//
// A hangs from the left end of the backbone (row), B from the right end
// through the hook (row+1). Each widening operation w_j is an expansion on
// the backbone: it pushes B's side away from A. Each narrowing operation n_j
// is an expansion on the hook, to the right of B: it pushes B toward A.
//
// Contract: exactly one gap can change, g + sum w_j - sum n_j >= 0.
// Every other pair of consecutive nodes in a row is joined by an edge.
//
// detach_widening (mutation only): the widening operations are drawn on a
// tail to the right of the backbone instead, off the path between A and B,
// so they no longer change the gap.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gadgets/contract.hpp"
#include "gadgets/internal/canvas.hpp"

namespace gridlock {

struct GapGadgetSpec {
  int64_t gap = 0;                  // g >= 0
  std::vector<std::string> widen;   // operation names
  std::vector<std::string> narrow;  // operation names
  bool detach_widening = false;
};

// Two operations never share a node (docs/model.md), hence the plain edges between
// consecutive expansions.
//
// Draws the gadget with its attach node at (0, row); uses rows row, row+1 and
// columns 0 .. E = max(g + 2|narrow|, 2|widen| - 1, g + 1) (plus 2|widen|
// when detached). Nodes: 2E - g + 2 (plus 2|widen| when detached). O(nodes).
GadgetPlacement place_gap_gadget(Canvas& canvas, int64_t row, const GapGadgetSpec& spec);

}  // namespace gridlock
