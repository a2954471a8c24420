// Colliding Schedule, one pair of regions at a time (docs/collide.md).
//
// Every region (node, inserted node, grown node; Regions in lattice/motion.hpp)
// is written as a rectangle whose four faces are
//     base[f] + D_ref(p)[axis f] + own_coef[f] * p_own
// where D_ref(p) is the displacement of one node (its "ref") as a function of
// the progress vector p (one entry per coupling), and p_own is the progress of
// the coupling of the region's own operation (the one that changes its width).
// This holds exactly when no coupling breaks a cycle (then displacements do
// not depend on the path: D_v - D_u = p_q * vec over the operation edge uv).
//
// For a pair (A, B) the overlap is eight strict linear inequalities in p
// (four for the open overlap, four for the positive widths), which only see
// p through Delta = D_refB - D_refA (a sum over the couplings on the tree
// path, one net vector per coupling) and through the own progresses.
//  - Continuous time: every p in [0,1]^k is the configuration at some moment,
//    so A and B can collide iff the inequalities are feasible over the cube.
//    Delta ranges over a zonotope; we eliminate it through the support
//    function on the normals of zonotope + rectangle and the at most two own
//    progresses by Fourier-Motzkin, or (ZonotopeTest::AngleTree) project the
//    own progresses out into a polygon and test one point against the
//    Minkowski sum with the angle-sorted tree. Exact integer arithmetic.
//  - Discrete time: p = 1_S + s e_q (the set S done, q running). For each
//    choice of the running coupling (one per distinct vector) and the states
//    of the own couplings, a subset-sum table over the other vectors (one
//    pass per distinct vector) gives every reachable Delta, and a
//    one-variable test in s settles each cell the running coupling reaches.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "common/limits.hpp"
#include "lattice/instance.hpp"
#include "lattice/motion.hpp"
#include "lattice/rational.hpp"
#include "lattice/time_model.hpp"

namespace gridlock {

struct RegionForm {
  NodeId ref = kNone;
  CouplingId own = kNone;          // coupling whose progress changes a width, or kNone
  int64_t base[4] = {0, 0, 0, 0};  // xlo, xhi, ylo, yhi at p = 0 (ref undisplaced)
  int own_coef[4] = {0, 0, 0, 0};
};

// One form per region (same ids as Regions). Requires that no coupling breaks
// a cycle. O(n).
std::vector<RegionForm> region_forms(const Instance& inst, const Regions& regions);

// The couplings with a non-zero net vector on the tree path ref(A) -> ref(B):
// Delta(p) = sum p_q * net.
using PathNets = std::vector<std::pair<CouplingId, Vec2>>;

// A witness for a pair: progress per coupling in `couplings` (continuous:
// values in [0,1], all multiples of 2^-20), or a discrete prefix (done set,
// then `running` runs and the pair collides while it does).
struct PairWitness {
  std::vector<std::pair<CouplingId, Rational>> progress;  // continuous
  std::vector<CouplingId> done;                           // discrete
  CouplingId running = kNone;                             // discrete
};

// Quick necessary condition (O(1) given the sums of |net.x| and |net.y| over
// the path): false means the pair can never overlap.
bool pair_may_meet(const RegionForm& A, const RegionForm& B, int64_t reach_x, int64_t reach_y);

// Continuous model: can A and B overlap for some p in [0,1]^k? With `want`,
// also returns progress values that make them overlap.
bool continuous_pair_collides(const RegionForm& A, const RegionForm& B, const PathNets& nets,
                              PairWitness* want = nullptr);

// Discrete model: can A and B overlap in some state 1_S + s e_q? The
// paper's distinct-vector refinement: per running choice (each own
// coupling, one per distinct vector) the subset sums of the rest in one
// pass per distinct vector (O(c A)), and only the O(1 + |q|^2) cells the
// running coupling can bring into the overlap window are tested:
// O(c^2 A + c (1 + L^2)) per pair for c distinct vectors, grid area A,
// L operations on the path.
bool discrete_pair_collides(const RegionForm& A, const RegionForm& B, const PathNets& nets,
                            PairWitness* want = nullptr);

// The same answer the way it was computed before (the twin): subset sums
// one vector at a time and every cell of the grid tested, O(c K A) per pair.
bool discrete_pair_collides_per_vector(const RegionForm& A, const RegionForm& B, const PathNets& nets,
                                       PairWitness* want = nullptr);

// True iff the eight inequalities hold at p (progress of every coupling that
// appears in A, B or nets; the others are irrelevant). For checking witnesses.
bool pair_overlaps_at(const RegionForm& A, const RegionForm& B, const PathNets& nets, const std::vector<Rational>& p);

struct PairwiseStats {
  uint64_t pairs = 0;            // region pairs considered
  uint64_t full_tests = 0;       // pairs that passed the quick filter
  uint64_t line_purges = 0;      // continuous, incremental: times the empty lines were dropped
  uint64_t angle_fallbacks = 0;  // continuous, angle tree: pairs decided per pair instead (never seen)
};

struct PairCollision {
  uint32_t a = kNone, b = kNone;  // regions
  PairWitness witness;
};

// How pairwise_collision decides a pair in the continuous model (the
// answer is the same; docs/collide.md, "Incremental support values"):
enum class ZonotopeTest {
  // The traversal keeps, next to the nets, the support value of the path's
  // zonotope on the axis normals and on both normals of every direction
  // present among the non-zero nets (D of them): O(D) per traversal step
  // (O(K) more when a direction first appears), and per pair only the own
  // couplings' nets are subtracted: O(D) plus Fourier-Motzkin.
  Incremental,
  // Per pair, normals and supports rebuilt from the path's nets: O(K + d K).
  PerPair,
  // Both on every pair; std::logic_error if they ever disagree (the twin).
  Both,
  // The paper's angle-sorted augmented tree (collide/internal/angle_tree.hpp): the
  // traversal keeps the path's nets sorted by angle with subtree sums,
  // O(log m) per step; per pair the own couplings' nets are taken out
  // (O(log m)), the own progresses are projected out exactly into a
  // convex polygon Q of O(1) vertices, and "0 in the interior of
  // Z' - cl U" is one binary search over the vertices of Z' + Q:
  // O(log^2 m). docs/collide.md, "The angle tree".
  AngleTree,
  // AngleTree and PerPair on every pair; std::logic_error on a disagreement.
  AngleBoth,
};

// The O(n^2)-pairs method for any instance in which no coupling breaks a
// cycle: a traversal of the spanning tree from every node keeps the net
// vector of every coupling on the path (the paper's T(v, w), here a plain
// array with a list of non-zero entries), and every pair of regions is tested
// as above. Returns the first colliding pair found (with its witness; a
// continuous witness always comes from the per-pair method).
// deadline (optional) is checked once per source node and every 4096
// steps of the traversal: LimitReached when it has passed. ztest: see above;
// in the discrete model PerPair selects discrete_pair_collides_per_vector
// (the twin), anything else discrete_pair_collides. on_source (optional)
// is called before each source node's traversal with (sources done, n).
// on_apart (optional) is called with every pair of regions the exact test
// finds apart and the path's nets between their references (O(nets) more
// per such pair): the certificate writer's hook
// (collide/collide_certificate.hpp). Pairs the quick filter drops need no
// call: one of their eight forms alone is <= 0 on the whole cube (the
// filter's bounds are sums of per-term maxima of one form).
// around (optional): traverse only from the nodes that the faces of these
// regions follow (at most 2 per region: a unit node itself; an inserted,
// grown or contracting region also the node it is attached to) and test
// their regions against every region of the instance (not only those of
// later nodes): O(|around| n) pairs instead of O(n^2). The discrete
// witness search after a continuous YES (collide.cpp; docs/collide.md,
// "the models agree", says why it finds one).
using ApartFn = std::function<void(uint32_t, uint32_t, const PathNets&)>;
std::optional<PairCollision> pairwise_collision(const Instance& inst, const SpanningTree& tree, const Regions& regions,
                                                TimeModel model, PairwiseStats* stats = nullptr,
                                                const Deadline* deadline = nullptr,
                                                ZonotopeTest ztest = ZonotopeTest::Incremental,
                                                const std::function<void(uint64_t, uint64_t)>& on_source = {},
                                                const ApartFn& on_apart = {},
                                                const std::vector<uint32_t>* around = nullptr);

// The pair tests on a given list of region pairs only: the path's nets
// between ref(a) and ref(b) are kept by walking the two ends over the tree
// (moving an end one edge changes each coupling's net by that edge's
// vector, whether the path grows or shrinks), the pairs taken in Mo's
// order on the ends' Euler-walk positions: O(n sqrt(P)) end moves for P
// pairs, plus one exact test per pair. The continuous model uses the
// support table (ZonotopeTest::Incremental), the discrete one the subset
// sums. First meeting pair in that order, with its witness, or nullopt.
// Requires that no coupling breaks a cycle; deadline and on_apart as
// pairwise_collision (on_apart: every listed pair the exact test finds
// apart, before the first meeting one).
std::optional<PairCollision> listed_pairs_collision(const Instance& inst, const SpanningTree& tree,
                                                    const Regions& regions, TimeModel model,
                                                    const std::vector<std::pair<uint32_t, uint32_t>>& pairs,
                                                    PairwiseStats* stats = nullptr, const Deadline* deadline = nullptr,
                                                    const ApartFn& on_apart = {});

// One axis, any couplings (docs/collide.md, "One axis, any couplings"):
// when every operation moves along x (or every one along y) and no
// coupling breaks a cycle, some schedule collides iff one of these pairs
// can overlap. A unit region (a node whose width never changes) keeps its
// place among the units of its row; every other region stays between the
// two units around it at p = 0 (it is attached to one of their faces)
// until the first collision, which is therefore inside one group: two
// consecutive units of a row and the regions between them. The pairs of
// every group, O(n) of them (a group holds two units and at most the
// regions of their two operations); nullopt when the operations use both
// axes. O(n log n).
std::optional<std::vector<std::pair<uint32_t, uint32_t>>> one_axis_group_pairs(const Instance& inst,
                                                                               const Regions& regions);

}  // namespace gridlock
