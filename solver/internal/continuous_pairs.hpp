// Exact analysis of one collision constraint (solver/internal/constraints.hpp) with at
// most two couplings, in the continuous model: it depends only on the offset
// d = t_(rel[1]) - t_(rel[0]) of the two start times.
//
// With rel[0] at time 0 and rel[1] at d, the events 0, 1, d, d + 1 cut time
// into pieces on which every form is linear in t; on a piece the pair
// collides iff the lower bounds of {t : f_i(t) > 0} lie below the upper
// bounds (and the piece's own ends). Every such bound is a line t = u + v d,
// so the answer can change only at the d where two of these lines cross, or
// a form that is constant in t changes sign, or two events meet
// (d in {-1, 0, 1}). Between two consecutive candidates it is constant; we
// test each candidate and one point between each pair of neighbours (and
// beyond the extremes) exactly, and merge: the collision-free offsets are a
// finite union of closed intervals with rational ends.
//
// Used by solve_continuous to turn most pairs into a disjunction of
// difference bounds (often one: t_b >= t_a + 1 for a separation gadget),
// which Z3 solves far faster than the general segment cover.
#pragma once

#include <optional>
#include <vector>

#include "lattice/rational.hpp"
#include "solver/internal/constraints.hpp"

namespace gridlock {

// A closed interval of offsets; nullopt ends are unbounded.
struct OffsetInterval {
  std::optional<Rational> lo, hi;
  bool contains(const Rational& d) const { return (!lo || *lo <= d) && (!hi || d <= *hi); }
};

// True iff the pair never overlaps when rel[j] starts at start[j] (any
// number of couplings; start.size() == c.rel.size()). The events cut time
// into pieces on which every form is linear; on each, the exact 1-D test.
// O(r log r + r * num_forms * r) rationals.
bool pair_free_at_times(const CollisionConstraint& c, const std::vector<Rational>& start);

// pair_free_at_times with rel[0] at 0 and rel[1] (if any) at d.
// Requires c.rel.size() <= 2.
bool pair_free_at_offset(const CollisionConstraint& c, const Rational& d);

// The offsets at which the pair never overlaps: disjoint closed intervals in
// increasing order (empty: it collides at every offset). Requires
// c.rel.size() == 2. O(m^2 log m + m^2 * num_forms) for m = 9 * num_forms + 4
// candidate lines (at most 76).
std::vector<OffsetInterval> free_offsets(const CollisionConstraint& c);

// True iff f_i + f_j > 0 on the whole progress cube for every two forms of c
// (the minimum over the cube is at a vertex: base + the negative
// coefficients): no two forms are ever <= 0 together, so a collision-free
// pair keeps one form <= 0 for all time. O(forms^2 * couplings of c).
bool forms_never_both_nonpositive(const CollisionConstraint& c);

}  // namespace gridlock
