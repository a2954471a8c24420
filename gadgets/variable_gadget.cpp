#include "gadgets/internal/variable_gadget.hpp"

namespace gridlock {

GadgetPlacement place_variable_gadget(Canvas& canvas, int64_t row, const VariableOps& ops, Mutation mutation) {
  const int64_t low = row, mid = row + 1, back = row + 2, top = row + 3;
  const int64_t y_gap = mutation == Mutation::VariableLooseY ? 1 : 0;
  const int64_t z_gap = 1;
  const int64_t hook_end = 3 + y_gap;  // x where the hook comes down to the backbone

  // Backbone: @ =T= o - o =F= o (- o with the loose mutation).
  for (int64_t x = 0; x <= hook_end; ++x) canvas.node({x, back});
  canvas.expansion(ops.set_true, {0, back}, Dir::PosX);
  canvas.edge({1, back}, {2, back});
  canvas.expansion(ops.set_false, {2, back}, Dir::PosX);
  if (hook_end > 3) canvas.edge({3, back}, {4, back});

  // Gap yB in the top row: A over @, B =y= o - o down to the backbone's end.
  canvas.node({0, top});
  canvas.edge({0, back}, {0, top});
  canvas.node({1 + y_gap, top});
  canvas.path({2 + y_gap, top}, {hook_end, top});
  canvas.expansion(ops.y, {1 + y_gap, top}, Dir::PosX);
  canvas.edge({hook_end, top}, {hook_end, back});

  // Gap zA in row mid: a hangs from the right end of F, b from the loop
  // through row low, which starts under @.
  const int64_t a = 3, b = a + 1 + z_gap;
  canvas.node({0, mid});
  canvas.edge({0, back}, {0, mid});
  canvas.node({a, mid});
  canvas.edge({a, back}, {a, mid});
  canvas.node({b, mid});
  canvas.path({0, low}, {2, low});
  canvas.path({3, low}, {b, low});
  canvas.expansion(ops.z, {2, low}, Dir::PosX);
  canvas.edge({0, mid}, {0, low});
  canvas.edge({b, low}, {b, mid});

  GadgetPlacement p;
  p.bottom_row = low;
  p.top_row = top;
  p.attach_row = back;
  p.contract.gaps.push_back({y_gap, {{ops.set_true, +1}, {ops.set_false, +1}, {ops.y, -1}}});
  p.contract.gaps.push_back({z_gap, {{ops.set_true, -1}, {ops.set_false, -1}, {ops.z, +1}}});
  return p;
}

}  // namespace gridlock
