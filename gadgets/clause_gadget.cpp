#include "gadgets/internal/clause_gadget.hpp"

#include <stdexcept>

#include "gadgets/internal/gap_gadget.hpp"

namespace gridlock {

GadgetPlacement place_clause_gadget(Canvas& canvas, int64_t row, const std::vector<std::string>& literal_ops,
                                    const std::string& release, Mutation mutation) {
  if (literal_ops.empty()) throw std::logic_error("clause gadget: empty clause");
  GapGadgetSpec spec;
  spec.gap = static_cast<int64_t>(literal_ops.size()) - 1;
  if (mutation == Mutation::ClauseLoose) spec.gap += 1;
  if (mutation == Mutation::ClauseTight && spec.gap > 0) spec.gap -= 1;  // unit clauses stay as they are
  spec.widen = {release};
  spec.narrow = literal_ops;
  return place_gap_gadget(canvas, row, spec);
}

}  // namespace gridlock
