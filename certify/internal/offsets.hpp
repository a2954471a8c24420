// Which offsets of two couplings make a pair of regions collide, computed
// exactly by the checker (continuous certificates, kind bounds, "i" lines).
//
// Coupling a starts at 0 and b at d; at time t their progress is clamp(t)
// and clamp(t - d) (clamp to [0, 1]). A pair of regions moved only by a
// and b collides at offset d iff some t makes every form
// base_k + ca_k clamp(t) + cb_k clamp(t - d) positive. The (t, d) plane
// falls into nine cells where both clamps are affine (before, during,
// after each coupling); in each cell the colliding set is a polygon given
// by strict and weak linear inequalities, and Fourier-Motzkin elimination
// of t projects it exactly onto an interval of d. The colliding offsets
// are the union of the nine intervals.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "lattice/rational.hpp"

namespace gridlock {

struct OffsetForm {
  Rational base, ca, cb;
};

// The closed interval lo <= d <= hi (an end may be absent: unbounded).
struct FreeOffsets {
  std::optional<Rational> lo, hi;
};

// nullopt if every offset d outside the union of `free` makes the forms
// collide; else a reason naming an offset that does not. Rational
// arithmetic may throw std::overflow_error. O(9 * forms^2 + free log free).
std::optional<std::string> offsets_outside_collide(const std::vector<OffsetForm>& forms,
                                                   const std::vector<FreeOffsets>& free);

}  // namespace gridlock
