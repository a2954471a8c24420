// Adversarial instance families for Colliding Schedule with couplings
// (docs/collide.md, "Adversarial families"; bench/collide_bench.cpp).
//
// The benchmark combs are easy for the pairwise methods: few operations per
// path, so the O(1) distance filter (pair_may_meet) rejects almost every
// pair. The serpentine defeats it on purpose:
//
//   columns x = 0 .. C-1 of H nodes each, walked as one path: column i goes
//   up when i is even and down when it is odd; a connector edge joins the
//   top (i even) or the bottom (i odd) of column i to column i+1.
//   Operations: an expansion along +x on every connector, and an expansion
//   along the walking direction on every other edge inside a column
//   (edges k -> k+1 for odd k, so no node is in two operations).
//
// Every pair of regions in columns i < j has the j - i connectors on its
// tree path, all +x, so the filter's x reach equals the x distance and it
// passes; the column expansions on the path give a y reach of the order of
// (j - i) H / 2, so it passes in y for all but nearby columns. The paths
// are long (up to n) and carry Theta(min(n, couplings)) couplings with a
// non-zero net. Couplings: the operations (Mixed: all of them; Columns:
// only the column ones, connectors stay singletons) are shuffled with the
// seed and cut into groups of `coupling_size`: Mixed couplings combine +x
// connector steps with +-y column steps, so nets point in many directions;
// Columns couplings give axis-only nets.
//
// Answer with expansions only: NO in both models (every configuration keeps
// column j at least one unit right of column i < j: x_j - x_i = j - i + sum
// of connector progresses; inside a column, expansions only push apart;
// inserted nodes lie between their two ends). So every pairwise method runs
// to the end. With contract_percent > 0 each operation is a contraction
// instead (same edge, same direction) with that chance: a contracting
// connector pulls column i+1 into column i and the instance usually
// collides; these are for the twins in tests/collide_adversarial_test.cpp.
#pragma once

#include <cstdint>

#include "lattice/instance.hpp"

namespace gridlock {

enum class SerpentineCouplings {
  Mixed,    // connectors and column operations shuffled together
  Columns,  // only column operations grouped; connectors are singletons
  // One coupling per direction (a, b), a, b >= 0 coprime, 1 <= a + b <= L
  // for the largest L the operations allow: a connectors and b column
  // operations (shuffled); the rest stay singletons; coupling_size is
  // ignored. The net of such a coupling on a long path points in about
  // its own direction (column operations count + or - by the column), so
  // the paths carry D = Theta(L^2) distinct directions with L^3 / 5
  // operations: D = Theta(n^{2/3}), the support table's worst case, on
  // the flat serpentine (fan_serpentine).
  Fan,
};

struct SerpentineParams {
  uint32_t columns = 4;        // C >= 1
  uint32_t height = 8;         // H >= 2 nodes per column
  uint32_t coupling_size = 3;  // operations per coupling (>= 1); 0: ceil(sqrt(operations))
  SerpentineCouplings couplings = SerpentineCouplings::Mixed;
  uint32_t contract_percent = 0;  // 0..100: chance that an operation contracts
};

// n = C H nodes, C - 1 connector operations and (C) * floor((H - 2) / 2)
// column operations. Deterministic in (params, seed) on every machine.
// O(n). Throws std::invalid_argument on C == 0, H < 2 or
// contract_percent > 100.
Instance serpentine_instance(const SerpentineParams& p, uint64_t seed);

// A square serpentine of about n nodes (C = H = the even number nearest
// sqrt(n), at least 4) with the given couplings. O(1).
SerpentineParams square_serpentine(int64_t n, uint32_t coupling_size, SerpentineCouplings couplings);

// The flat serpentine of about n nodes with Fan couplings: height 4 (one
// column operation per column), C = max(2, n / 4) columns, so connectors
// and column operations are about n / 4 each. O(1).
SerpentineParams fan_serpentine(int64_t n);

// The largest L whose fan needs at most x connectors and y column
// operations (each side needs sum over the directions of a, resp. b). O(L^2 log L).
uint32_t fan_size(uint64_t x, uint64_t y);

// The diagonal sweep: a single-coupling family (every operation in one
// coupling) on which the simulator's broad phase meets a quadratic number
// of candidate pairs although nothing collides (docs/collide.md, "One
// coupling"). Cells, for K >= 1 and b >= 3:
//   - a staircase from the anchor (0,0): K periods of right, right, up, up
//     (tip (2K, 2K)); an expansion on the first right and the first up edge
//     of each period (no node in two operations), so the tip moves (K, K);
//   - a b x b blob above the tip, cells (2K + a, 2K + 1 + c), moving (K, K)
//     with it: each of its cells sweeps a diagonal band;
//   - a static floor row y = -1, x = 0 .. X (X = 3K + b + 1), joined to the
//     anchor, carrying the static triangle {0 <= y, y + b + 2 <= x <= X}.
// Relative to the static part every moving cell keeps x - y within
// [-b, 3] (motion along (1,1), or along an axis inside the staircase band),
// the triangle has x - y >= b + 2: the answer is NO. But each blob cell's
// swept box (K + 1 cells square) contains about (K - b)^2 / 2 triangle
// cells, so the simulator tests about b^2 (K - b)^2 / 2 static pairs: with
// b = K / 2, n ~ 4.75 K^2 nodes and ~ K^4 / 32 ~ n^2 / 720 candidate pairs,
// while the total motion of the regions is O(K^3) = O(n^{3/2}).
// With `hits`, a static post (b + 3 more nodes, up from the triangle at
// x = X to y = 3K + b, then left to x = 3K + b - 1) stands where the
// blob's top right cell arrives: the answer is YES, the first collision at
// t = 1 - 1/K between that cell and the post's end, after the same motion.
// Deterministic, O(n). Throws std::invalid_argument for K == 0 or b < 3.
Instance diagonal_sweep_instance(uint32_t K, uint32_t b, bool hits = false);

// The diagonal sweep of about n nodes: K = max(6, round(sqrt(n / 4.75))), b = K / 2. O(n).
Instance diagonal_sweep_of_size(int64_t n, bool hits = false);

}  // namespace gridlock
