// The reduction at the level of gadget contracts (gadgets/contract.hpp):
// a twin of the lattice, used to test that the compiled instance behaves
// exactly as its gadgets' contracts say (non-interference), and as a
// reference answer for small formulas.
#pragma once

#include <vector>

#include "reductions/compile.hpp"

namespace gridlock::test {

// True iff some prefix of `order` leaves some gadget's contract violated:
// the simulator's verdict on the instance, if the gadgets do not interfere.
// O(couplings * total contract size).
bool order_breaks_contracts(const CompiledFormula& c, const std::vector<CouplingId>& order);

// Is there an order of all couplings none of whose prefixes breaks a
// contract? Exhaustive search over sets of couplings done (at most 2^22).
// If found, *witness receives the order.
bool contract_schedule_exists(const CompiledFormula& c, std::vector<CouplingId>* witness = nullptr);

}  // namespace gridlock::test
