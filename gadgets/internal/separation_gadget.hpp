// The separation gadget a << b (paper, proof that continuous Collision-free
// Schedule is NP-hard, figure (d)): in continuous time, b collides iff it
// starts before a has finished. One vertical expansion a and one horizontal
// expansion b:
//
//   row+2:  .   .   .   .          free: X and X2 are lifted into it
//   row+1:  V =b= Y   X - X2       Y and X touch; no edge between them
//           |           ‖
//   row:    @ - o - o - W          a: W =a= X2, upward (+y)
//
// a lifts X2 and X (their side of W's edge) one row up; b pushes Y one cell
// right, into the cell X leaves. X is lifted by the expansion under X2, not
// by one under X itself: the node an expansion inserts stays in the cell it
// is inserted into (here X2's old cell), so X's cell is left empty. Y's and
// X's regions share area iff p_b(t) > 0 and p_a(t) < 1 at some moment t,
// i.e. iff some t has t_b < t < t_a + 1:
//
// Contract (continuous): collision-free iff t_b >= t_a + 1 (at t_b = t_a + 1
// Y only touches X's bottom corner: no collision). Discrete: collision-free
// iff a runs before b. Proof by an exact finite check: docs/gadgets.md,
// tests/gadgets_separation_test.cpp.
// 8 nodes, 7 edges (a tree), 2 operations (one vertical). Needs the row
// above it free in columns 2..3 (the compiler leaves an empty row between
// gadgets, and nothing above the topmost one).
//
// Mutation::SeparationLoose (fuzzer self-test only): X and X2 one column
// further right, so Y never reaches X and the gadget never collides.
#pragma once

#include <cstdint>
#include <string>

#include "gadgets/contract.hpp"
#include "gadgets/internal/canvas.hpp"
#include "gadgets/mutation.hpp"

namespace gridlock {

// Draws the gadget in rows row, row+1 with its attach node at (0, row);
// first = a (vertical), second = b (horizontal).
GadgetPlacement place_separation_gadget(Canvas& canvas, int64_t row, const std::string& first,
                                        const std::string& second, Mutation mutation = Mutation::None);

}  // namespace gridlock
