// The deliberately naive twin of solver/solve: every permutation of the
// couplings, each run through the exact Simulator. O(k! * simulation): for
// instances with at most 8 couplings.
#pragma once

#include <optional>
#include <vector>

#include "lattice/instance.hpp"

namespace gridlock::test {

// A collision-free order of all couplings (the first in lexicographic order
// of coupling ids), or nullopt if every order collides.
std::optional<std::vector<CouplingId>> reference_solve(const Instance& inst);

// True iff starting every coupling at time 0 is collision-free (the
// continuous model's witness for horizontal-only instances), by the Simulator.
bool reference_all_at_once(const Instance& inst);

}  // namespace gridlock::test
