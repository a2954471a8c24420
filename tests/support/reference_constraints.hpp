// The per-face twin of build_pair_constraints: every pair of regions a < b
// (no box scan), the distance test by walking the tree path, and each of the
// eight forms built face by face (a walk from the pivot to the face's
// reference node, then the difference of two faces), as the builder did
// before it shared one walk per pair. O(regions^2 * path length): for the
// small random instances of the tests.
#pragma once

#include "lattice/instance.hpp"
#include "lattice/motion.hpp"
#include "solver/internal/constraints.hpp"

namespace gridlock::test {

// The constraints of every pair that passes the distance test and has no
// never-positive form, ordered by (region_a, region_b). Requires no coupling
// breaking a cycle.
ConstraintSystem reference_pair_constraints(const Instance& inst, const SpanningTree& tree);

}  // namespace gridlock::test
