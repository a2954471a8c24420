// The eight inequalities of one pair of regions (collide/internal/collide_pairs.hpp)
// in the variables the pair tests eliminate: the progresses of the pair's
// own couplings (at most two) and Delta', the sum of the other couplings'
// nets on the tree path. Internal to collide/ (not installed).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "collide/internal/collide_pairs.hpp"
#include "collide/internal/lp_elimination.hpp"

namespace gridlock::pairs {

inline int64_t comp(Vec2 v, int axis) { return axis == 0 ? v.x : v.y; }

// The pair's constraints: c + e0 v0 + e1 v1 + sign * Delta'[axis] > 0, where
// v0, v1 are the progresses of the own couplings and Delta' is the sum over
// the other couplings' nets.
struct PairSystem {
  int nv = 0;
  CouplingId var[2] = {kNone, kNone};
  int64_t c[8] = {};
  int64_t e[8][2] = {};
  int axis[8] = {};  // -1: no Delta term
  int sign[8] = {};
  std::vector<std::pair<CouplingId, Vec2>> gens;
  std::vector<std::pair<CouplingId, Vec2>> var_nets;  // net of each own coupling on the path
};

// The system of regions A and B with the path's nets. O(|nets|).
PairSystem build_system(const RegionForm& A, const RegionForm& B, const PathNets& nets);

// Rectangle bounds for Delta' as affine forms in (v0, v1): U_x from row 0,
// L_x from row 1 (as -row), U_y row 2, L_y row 3.
struct Bound {
  i128 c = 0, e[2] = {0, 0};
};

// The rectangle bounds of Delta' from rows 0..3 of S. O(1).
void rect_bounds(const PairSystem& S, Bound& Ux, Bound& Lx, Bound& Uy, Bound& Ly);

}  // namespace gridlock::pairs
