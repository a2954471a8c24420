#include "gadgets/internal/gap_gadget.hpp"

#include <algorithm>
#include <stdexcept>

namespace gridlock {

GadgetPlacement place_gap_gadget(Canvas& canvas, int64_t row, const GapGadgetSpec& spec) {
  if (spec.gap < 0) throw std::logic_error("gap gadget: negative gap");
  const auto nw = static_cast<int64_t>(spec.widen.size());
  const auto nn = static_cast<int64_t>(spec.narrow.size());
  // Two operations never share a node (docs/model.md), so the expansions sit on
  // every other edge: widening j on the backbone edge x = 2j, narrowing j on
  // the hook edge x = b + 2j.
  const int64_t b = spec.gap + 1;
  const int64_t end = std::max({b + 2 * nn - 1, spec.detach_widening ? int64_t{1} : 2 * nw - 1, b, int64_t{1}});
  const int64_t top = row + 1;
  auto is_op_edge = [](int64_t x, int64_t first, int64_t count) {
    return x >= first && (x - first) % 2 == 0 && (x - first) / 2 < count;
  };

  // Backbone: (0,row) .. (end,row).
  for (int64_t x = 0; x <= end; ++x) canvas.node({x, row});
  for (int64_t x = 0; x < end; ++x) {
    if (!spec.detach_widening && is_op_edge(x, 0, nw))
      canvas.expansion(spec.widen[static_cast<size_t>(x / 2)], {x, row}, Dir::PosX);
    else canvas.edge({x, row}, {x + 1, row});
  }
  if (spec.detach_widening) {  // a tail o - o =w1= o - o =w2= o to the right
    for (int64_t j = 0; j < nw; ++j) {
      const int64_t x = end + 1 + 2 * j;
      canvas.node({x, row});
      canvas.node({x + 1, row});
      canvas.edge({x - 1, row}, {x, row});
      canvas.expansion(spec.widen[static_cast<size_t>(j)], {x, row}, Dir::PosX);
    }
  }
  // A, above the attach node.
  canvas.node({0, top});
  canvas.edge({0, row}, {0, top});
  // B and the hook: (b, top) .. (end, top).
  for (int64_t x = b; x <= end; ++x) canvas.node({x, top});
  for (int64_t x = b; x < end; ++x) {
    if (is_op_edge(x, b, nn)) canvas.expansion(spec.narrow[static_cast<size_t>((x - b) / 2)], {x, top}, Dir::PosX);
    else canvas.edge({x, top}, {x + 1, top});
  }
  canvas.edge({end, top}, {end, row});

  GadgetPlacement p;
  p.bottom_row = row;
  p.top_row = top;
  p.attach_row = row;
  GapSpec g;
  g.size = spec.gap;
  g.terms.reserve(spec.widen.size() + spec.narrow.size());
  if (!spec.detach_widening)
    for (const auto& w : spec.widen) g.terms.push_back({w, +1});
  for (const auto& n : spec.narrow) g.terms.push_back({n, -1});
  p.contract.gaps.push_back(std::move(g));
  return p;
}

}  // namespace gridlock
