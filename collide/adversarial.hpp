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

// The band sweep: the diagonal sweep's staircase carried along (p, 1)
// past a thin static band beside its path (no triangle), so that the
// total motion is quadratic: Theta(K^2) over about (5 p + 5) K nodes.
// For K >= 1, p in {1, 2, 3} and w >= 1:
//   - a staircase from the anchor (0,0): K periods of 2p rights and 2 ups,
//     an expansion on every odd right (p of them) and on the first up, so
//     the tip (2pK, 2K) moves (pK, K), and every cell moves at most p
//     units further along x - p y than p times its y motion;
//   - a w x w blob above the tip moving with it;
//   - a static floor row y = -1 from x = 0 to G + p, joined to the anchor,
//     carrying the band {G <= x - p y <= G + p, 0 <= y <= 3K + w + 1},
//     G = max(4p + 1, w) + 1, each row joined to the one below at its
//     left end.
// Every moving cell keeps x - p y below G - p over its area (the
// staircase's up to 3p + 1, the blob's up to w - p), and the band lies at
// or above it: NO. No two faces of an axis keep their order and no cut
// along x or y separates anything, but a cut along x - p y does: for
// p = 1 the diagonal x - y, for p >= 2 the direction across the
// commonest motion (docs/collide.md, "Separated groups"); before those
// cuts Auto swept cells here, quadratic.
// With `hits` (needs w <= 4p), the band starts at G = 4p instead, one
// unit closer: from K = 2 on the staircase's cells reach into it (YES,
// named as the simulator does); with K = 1 nothing moves far enough (NO).
// Deterministic, O(n). Throws std::invalid_argument for K == 0, w == 0,
// p outside 1..3, or hits with w > 4p.
Instance band_sweep_instance(uint32_t K, uint32_t p, uint32_t w = 3, bool hits = false);

// The band sweep of about n nodes for slope p: K = max(2, n / (5 p + 5)). O(n).
Instance band_sweep_of_size(int64_t n, uint32_t p);

// The arc sweep: a convex staircase that grows away from its anchor,
// beside a static copy of itself. For J >= 1 and g >= 1:
//   - the staircase from the anchor (0,0): J runs, run j of J - j rights
//     then j + 1 ups (so it turns from along x to along y, bulging toward
//     the lower right), with an expansion on every other edge (the first
//     included), all in one coupling: each cell moves by about half its
//     position, away from the anchor, in its own direction;
//   - the band: a static path from the anchor left to (-g, 0) and up to
//     (-g, g - 1), then the staircase moved by (-g, g), each cell joined
//     to the one before.
// About 2 J^2 nodes, total motion Theta(J^4) = Theta(n^2), and the cells
// move in Theta(J) directions. With g = max(3, J / 3) (arc_sweep_of_size)
// nothing collides (checked by Auto for every J <= 90 and J = 91, 94, ..
// 109, by the simulator in the tests); with g = 3 the staircase meets
// the band (YES) for J = 14, 16 and every J >= 18. From J = 38 (about
// 2 900 nodes) no cut along x, y, a diagonal or across the commonest
// motion separates the staircase from the band, the time slabs exceed
// their budget and the motion classes are as many as the cells: Auto
// sweeps cells, Theta(n^2 log n) (the single coupling's worst case
// today: docs/collide.md, "Honest deviations"). Smaller ones may be cut
// (J = 4 .. 7) or cut over time slabs (J = 8, 24, 25, ...).
// Deterministic, O(n). Throws std::invalid_argument for J == 0 or g == 0,
// std::logic_error if the band meets the staircase at t = 0.
Instance arc_sweep_instance(uint32_t J, uint32_t g);

// The arc sweep of about n nodes: J = max(4, round(sqrt(n / 2))), g = max(3, J / 3). O(n).
Instance arc_sweep_of_size(int64_t n);

}  // namespace gridlock
