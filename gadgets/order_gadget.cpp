#include "gadgets/internal/order_gadget.hpp"

#include "gadgets/internal/gap_gadget.hpp"

namespace gridlock {

GadgetPlacement place_order_gadget(Canvas& canvas, int64_t row, const std::string& first, const std::string& second,
                                   Mutation mutation) {
  GapGadgetSpec spec;
  spec.gap = mutation == Mutation::OrderLoose ? 1 : 0;
  spec.widen = {first};
  spec.narrow = {second};
  spec.detach_widening = mutation == Mutation::OrderDropRelease;
  return place_gap_gadget(canvas, row, spec);
}

}  // namespace gridlock
