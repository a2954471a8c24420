// The independent twin of solver/continuous: Continuous Collision-free
// Schedule as one quantified formula, decided by Z3.
//
// Independent of the solver on purpose: no collision constraints, no pair
// filter, no components, no segment covers. Its own spanning tree (from the
// last node), region rectangles written again from docs/model.md's words as terms
// in the progress p_q(t) = clamp(t - t_q, 0, 1), every pair of regions, and
// the fundamental cycle of every non-tree edge. The formula is
//   exists t_q in [0, k]. forall t. no pair overlaps at t and every
//   non-tree edge keeps its length at t,
// which Z3 decides exactly (linear real arithmetic has quantifier
// elimination; we run the qsat tactic). For small instances only.
#pragma once

#include <optional>

#include "lattice/instance.hpp"
#include "lattice/schedule.hpp"

namespace gridlock::test {

// true: some schedule is collision-free (its start times in *witness if
// given); false: none is; nullopt: Z3 gave up (timeout_ms, 0 = none).
std::optional<bool> reference_continuous(const Instance& inst, Schedule* witness = nullptr, unsigned timeout_ms = 0);

}  // namespace gridlock::test
