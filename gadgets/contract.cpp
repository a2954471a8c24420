#include "gadgets/contract.hpp"

namespace gridlock {

std::string GadgetContract::str() const {
  std::string s;
  for (const GapSpec& g : gaps) {
    if (!s.empty()) s += "; ";
    s += std::to_string(g.size);
    for (const GapTerm& t : g.terms) s += (t.sign > 0 ? " + " : " - ") + t.op;
    s += " >= 0";
  }
  return s;
}

}  // namespace gridlock
