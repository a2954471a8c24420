#include "support/reference_solver.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "lattice/simulate.hpp"

namespace gridlock::test {

std::optional<std::vector<CouplingId>> reference_solve(const Instance& inst) {
  const size_t k = inst.couplings().size();
  if (k > 8) throw std::invalid_argument("reference_solve: too many couplings");
  std::vector<CouplingId> order(k);
  std::iota(order.begin(), order.end(), 0);
  Simulator sim(inst);
  do {
    if (!sim.run_order(order).collision) return order;
  } while (std::next_permutation(order.begin(), order.end()));
  return std::nullopt;
}

bool reference_all_at_once(const Instance& inst) {
  Schedule s;
  s.start.assign(inst.couplings().size(), Rational(0));
  Simulator sim(inst);
  return !sim.run(s).collision;
}

}  // namespace gridlock::test
