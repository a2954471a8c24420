#include "gadgets/internal/separation_gadget.hpp"

namespace gridlock {

GadgetPlacement place_separation_gadget(Canvas& canvas, int64_t row, const std::string& first,
                                        const std::string& second, Mutation mutation) {
  const int64_t top = row + 1;
  const int64_t shift = mutation == Mutation::SeparationLoose ? 1 : 0;
  const int64_t xx = 2 + shift, w = 3 + shift;  // X's column, W's (and X2's) column
  // Base row @ - o - ... - W.
  canvas.path({0, row}, {w, row});
  // V =b= Y, V over @.
  canvas.node({0, top});
  canvas.edge({0, row}, {0, top});
  canvas.node({1, top});
  canvas.expansion(second, {0, top}, Dir::PosX);
  // X - X2, X2 over W, lifted by a.
  canvas.node({xx, top});
  canvas.node({w, top});
  canvas.edge({xx, top}, {w, top});
  canvas.any_expansion(first, {w, row}, Dir::PosY);

  GadgetPlacement p;
  p.bottom_row = row;
  p.top_row = top;
  p.attach_row = row;
  if (shift == 0) p.contract.separations.push_back({first, second});
  else  // one empty cell between Y and X, which only b narrows
    p.contract.gaps.push_back({shift, {{second, -1}}});
  return p;
}

}  // namespace gridlock
