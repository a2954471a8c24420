// One coupling: every operation of the instance runs together over
// progress t in [0, 1], so every face of every region moves linearly with
// an integer speed (docs/collide.md, "One coupling: the space-time cell
// sweep"). Does some pair of regions overlap (positive area) at some
// t in (0, 1]? Node collisions only: cycle collisions are the FaceNets
// test's (collide.cpp runs it first).
//
// The sweep: a common motion t * f of every region changes no overlap, so
// f is taken as the coordinatewise median of the nodes' displacements
// (the frame that minimises the total L1 motion of the nodes). Each region
// is cut into items (unit cell, open time interval during which it meets
// the cell's interior); two regions that overlap at time t meet a common
// cell at t, so per cell a sweep over time that tests each item against
// the items still present finds every colliding pair. Cost
// O(n + mu log mu) for the total motion mu = sum over regions of
// 1 + |speed_x| + |speed_y| in that frame: at most 6 mu items, and at most
// 43 exact tests per item (a packing lemma; proofs in docs/collide.md).
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

namespace gridlock {

struct SingleCouplingStats {
  uint64_t regions = 0;     // regions of positive width at some t in (0, 1)
  uint64_t motion = 0;      // sum over regions of 1 + |speed_x| + |speed_y| (largest face speeds), in the frame
  uint64_t items = 0;       // M: (cell, time interval) items kept (all of them on a NO)
  uint64_t tests = 0;       // T: exact pair tests
  uint64_t max_active = 0;  // most items present in one cell when an item entered
  uint64_t bands = 0;       // column bands swept one after another
  uint64_t peak_items = 0;  // most items in memory at once (the largest band)
};

// Items held in memory at once by default: 2^20 items of 48 bytes.
constexpr uint64_t kSingleCouplingBandItems = uint64_t{1} << 20;

struct RegionPair {
  uint32_t a = 0, b = 0;  // a < b
};

struct SingleCouplingAnswer {
  bool collides = false;
  // With collides, the first collision of the one schedule, as the
  // simulator names it: `pair` starts to overlap first (the smallest pair
  // on ties), at `first` (the infimum of all overlap times), and overlaps
  // at `during` (the middle of its overlap, first < during < 1). All three
  // unset when the sweep's packing bound decided (more items in one cell
  // at one moment than a configuration without overlaps allows:
  // docs/collide.md), the collision then to be found by the simulator.
  std::optional<RegionPair> pair;
  std::optional<Rational> first, during;
};

// Do two regions overlap while every operation of `inst` runs together
// from t = 0 to 1? The operations need not be in one coupling
// (all run at once either way); with one coupling this is the node part of
// the Colliding Schedule answer. t is the spanning tree of `inst`, regions
// its Regions. Checks deadline (if given) every few thousand items.
// Memory: O(n + columns + band_items + the items of the fullest column):
// the cells are swept in bands of whole columns holding at most band_items
// items each (one counting pass decides the bands), so the O(mu) items are
// never all in memory; time stays O(n + mu log mu). The sweep does not stop
// at the first overlap it meets: it keeps the earliest, entering no item
// that starts after it (nor keeps it, in a later band), so a YES names the
// first collision in the same bound (docs/collide.md, "The sweep's first
// collision"). The answer (pair
// included) is the same for every band_items >= 1. on_band (optional) is
// called before each band with (bands done, bands).
// Throws std::overflow_error if the motion spans more than 2^32 cells along
// an axis (not with coordinates within kMaxCoordinate and n < 10^9).
SingleCouplingAnswer single_coupling_sweep(const Instance& inst, const SpanningTree& t, const Regions& regions,
                                           SingleCouplingStats* stats = nullptr, const Deadline* deadline = nullptr,
                                           uint64_t band_items = kSingleCouplingBandItems,
                                           const std::function<void(uint64_t, uint64_t)>& on_band = {});

// One axis: every operation moves along x, or every one along y. No
// region then leaves its row (column), and the first overlap in time is
// between two regions next to each other in their row's order at t = 0,
// counting the regions of width 0 at t = 0 between two of positive width
// as next to both (docs/collide.md, "One coupling, one axis": the proof).
// So one sort per row and the exact test on those neighbours decide what
// single_coupling_sweep decides, the same answer, in O(n log n) whatever
// the motion. On a YES it names the first collision too: every pair that
// overlaps right after the first moment is in one group, so the earliest
// group pair, the smallest on ties, is the simulator's pair.
// nullopt when the operations use both axes, or when some region's width
// is not positive all along (0, 1), which happens only when the coupling
// breaks a cycle (the face test's case, which find_collision settles
// first). tests (optional): the exact pair tests made.
std::optional<SingleCouplingAnswer> single_coupling_one_axis(const Instance& inst, const SpanningTree& t,
                                                             const Regions& regions, uint64_t* tests = nullptr);

// When the faces of one axis keep their order: exact in O(r log r) for
// a NO. If no two faces of the kept axis s (xlo and xhi of every live
// region; else ylo and yhi) change order during (0, 1), two regions
// overlap along s at every t in (0, 1) or at none, so only the pairs
// that overlap along s at t = 1/2 can collide, and each of them does iff
// their intervals along the other axis overlap at some t. One sweep along
// s with the active regions ordered along the other axis at one moment
// finds such a pair or proves there is none: only neighbours are tested
// (docs/collide.md, "One coupling: one axis keeps its order").
// When neither axis keeps its order, the live regions are first cut into
// groups that never overlap one another: along an axis, where every
// region on one side lies at or below every region on the other at t = 0
// and at t = 1 (hence, linear, at every t), recursively along x and y
// until each group keeps the order of one axis; each group is swept on
// its own (docs/collide.md, "Separated groups").
struct FixedAxisAnswer {
  int axis = 0;       // the axis whose faces keep their order (0 x, 1 y; x when both do); -1 with several groups
  size_t groups = 1;  // separated groups swept (1: the whole instance keeps the order of `axis`)
  // collides; on a YES pair, first (the first collision's moment) and
  // during, as single_coupling_sweep and the simulator name them (the
  // smallest pair on ties of the first moment).
  SingleCouplingAnswer answer;
  uint64_t sweeps = 0;  // sweeps run: 1 on a NO; a YES bisects for its first moment
  uint64_t tests = 0;   // exact pair tests
};

// nullopt when a group that keeps neither order cannot be cut (or the
// cuts nest more than 64 deep, or the pieces placed hold more than 4 r
// members in all), or when some live region's width along its group's
// other axis is not positive all along (0, 1) (only when the coupling
// breaks a cycle: find_collision settles that first). The cuts cost
// O(r log r) per level of nesting, O(r log r) in all. A NO costs one
// sweep of every group, O(r log r); a YES bisects [0, 1] for the
// first moment, one or two sweeps per halving, at most about
// 2 log2(2 max speed) + 2 halvings (distinct starts are fractions with
// denominators up to twice the largest face speed), then the pairs whose
// closed boxes share a unit cell at that moment, for the smallest one
// starting then (the simulator's pair). Checks deadline (if
// given) once per piece of the cuts, between sweeps and every 4096
// events of a sweep.
std::optional<FixedAxisAnswer> single_coupling_fixed_axis(const Instance& inst, const SpanningTree& t,
                                                          const Regions& regions, const Deadline* deadline = nullptr);

// The pairs a NO of single_coupling_fixed_axis rests on: the pairs its
// sweep tests (an entering region against its two neighbours, each pair
// once per entry, as (smaller, larger)), at most 2 per live region. If no
// listed pair ever overlaps, the sweep answers NO, so no pair overlaps
// (docs/collide.md, "One coupling: one axis keeps its order"); the
// kept-order collide certificate covers only these (checked by certify's
// own sweep). With several separated groups, the pairs of every group's
// sweep (axis 2: the certificate's `kept-order separated`; the checker
// cuts the groups itself). nullopt when single_coupling_fixed_axis
// returns nullopt or a YES. O(r log r) per level of cuts. Checks
// deadline (if given) as single_coupling_fixed_axis does.
struct KeptOrderPairs {
  int axis = 0;  // the kept axis (0 x, 1 y), 2: several separated groups, each keeping one, 3: over time slabs
  std::vector<std::pair<uint32_t, uint32_t>> pairs;
};
std::optional<KeptOrderPairs> single_coupling_kept_order_pairs(const Instance& inst, const SpanningTree& t,
                                                               const Regions& regions,
                                                               const Deadline* deadline = nullptr);

// Motion classes: when some piece keeps neither order and has no cut
// (single_coupling_fixed_axis gives up), its regions are grouped by
// motion: the four face speeds and the two widths at t = 0. Two classes
// P and Q overlap before T iff the difference of some pair's low corners
// at t = 0 lies in an open convex polygon (at most 8 vertices, integer
// once scaled by T's denominator) that depends on P, Q and T alone; cut
// into vertical strips, each strip is one query of a sweep with a
// segment tree (docs/collide.md, "One coupling: motion classes", the
// proof). The kept-order groups are swept as single_coupling_fixed_axis
// sweeps them. A NO costs O(k r log r) for a piece of r regions in k
// classes, plus O(r log r) per level of cuts; a YES bisects for its first
// moment as single_coupling_fixed_axis does (at most about
// 2 log2(2 max speed) + 2 rounds, then the starts alone), and names the
// first collision as the simulator does.
struct MotionClassAnswer {
  // collides; on a YES pair, first and during, as single_coupling_sweep
  // and the simulator name them.
  SingleCouplingAnswer answer;
  size_t groups = 0;         // separated groups, kept-order ones included
  size_t class_groups = 0;   // of which decided by motion classes
  size_t classes = 0;        // most classes in one class group
  uint64_t class_pairs = 0;  // class pairs asked (over every round)
  uint64_t queries = 0;      // strip queries asked
  uint64_t sweeps = 0;       // rounds: 1 on a NO
  uint64_t tests = 0;        // exact pair tests of the kept-order sweeps
};

// nullopt when the cuts nest deeper (or place more members) than
// single_coupling_fixed_axis allows, when some region of a class group
// has a width that is not positive all along (0, 1) (only when the coupling breaks a cycle), when
// some face speed exceeds 2^19 (the exact arithmetic's bound), or,
// unless any_cost, when some class group's k r exceeds its motion (the
// sum of 1 + |speed_x| + |speed_y| over its regions, the cell sweep's
// cost): then the cell sweep is the cheaper method. whole (for tests):
// no cuts and no kept-order sweeps, every live region in one class
// group. Checks deadline (if given) per piece, per class pair, per
// round and every 4096 events of a kept-order sweep.
std::optional<MotionClassAnswer> single_coupling_motion_classes(const Instance& inst, const SpanningTree& t,
                                                                const Regions& regions,
                                                                const Deadline* deadline = nullptr, bool whole = false,
                                                                bool any_cost = false);

// Time slabs: a piece that keeps neither order and has no cut over
// (0, 1) may have cuts over parts of it (on the stalactite combs, teeth
// and stalactites lie apart along y before t = 1/2 and along x after).
// Motion is linear, so the cuts and kept-order sweeps apply to any time
// interval with the faces' values at its ends: such a piece is split into
// the two halves of its slab (dyadic, down to 2^-12) and each half cut
// and swept on its own (docs/collide.md, "One coupling: time slabs", the
// proof). A NO costs O(W log r), W the members placed over every slab
// (at most 32 (r + 1), and at most a quarter of the motion plus 1024,
// else nullopt); a YES asks the groups in the order of their slabs,
// bisects each that meets for its first moment as
// single_coupling_fixed_axis does, until a slab starts at or after the
// earliest start found, and names the simulator's first collision.
struct TimeSlabAnswer {
  // collides; on a YES pair, first and during, as single_coupling_sweep
  // and the simulator name them.
  SingleCouplingAnswer answer;
  size_t groups = 0;    // kept-order groups over every slab
  size_t slabs = 0;     // distinct slabs holding a group
  int finest = 0;       // the finest slab holding a group is 2^-finest long
  uint64_t work = 0;    // W: members of the pieces placed, summed over slabs
  uint64_t sweeps = 0;  // group sweeps, rounds of the bisection included
  uint64_t tests = 0;   // exact pair tests
};

// nullopt when a piece of more than 8 regions has no cut and keeps
// neither order in a slab of 2^-12 (a piece of at most 8 is a group of
// every pair), when the work exceeds the smaller of 32 (r + 1) and a
// quarter of the motion plus 1024 (the motion is the cell sweep's cost:
// it is then the faster), or when some face's position or speed exceeds
// 2^40 (the exact arithmetic's bound); cuts nested deeper than 64 are
// not followed. For tests: first_exp (0 to 12) starts from the 2^first_exp
// slabs of that length instead of [0, 1] (the budget times as much);
// any_cost drops the work budget (the depth's bound stays). Checks
// deadline (if given) per piece, per round and every 4096 events of a
// sweep.
std::optional<TimeSlabAnswer> single_coupling_time_slabs(const Instance& inst, const SpanningTree& t,
                                                         const Regions& regions, const Deadline* deadline = nullptr,
                                                         int first_exp = 0, bool any_cost = false);

// The pairs a NO of the time slabs rests on (axis 3: the certificate's
// `kept-order slabs`; the checker makes the slabs, cuts and sweeps
// itself): the pairs each kept-order group's sweep tests over its slab,
// and every pair of each small piece, as (smaller, larger), duplicates
// possible. If no listed pair ever overlaps, no pair does (Lemma 5 of
// docs/collide.md). The slabs are those of single_coupling_time_slabs
// with the work budget 32 (r + 1) alone (no motion term): O(r log r).
// nullopt when they decline or find an overlap. Checks deadline (if
// given) as single_coupling_time_slabs does.
std::optional<KeptOrderPairs> single_coupling_slab_pairs(const Instance& inst, const SpanningTree& t,
                                                         const Regions& regions, const Deadline* deadline = nullptr);

// The question each round of the classes' bisection asks, exposed for its
// twin test: with every live region in one class group (every class pair
// asked), some pair that overlaps at some t in (0, T), or none. nullopt
// when the classes decline (a width not positive all along (0, 1), a face
// speed above 2^19) or T is not in (0, 1] with a denominator of at most
// 2^40. O(k r log r) for r regions in k classes.
std::optional<std::optional<RegionPair>> single_coupling_classes_before(const Instance& inst, const SpanningTree& t,
                                                                        const Regions& regions, const Rational& T);

// Its twin: the exact pair test on every pair, restricted to (0, T).
// O(r^2).
std::optional<RegionPair> single_coupling_pairwise_before(const Instance& inst, const SpanningTree& t,
                                                          const Regions& regions, const Rational& T);

// The brute-force twin: the same exact test on every pair of regions.
// O(r^2) for r regions.
std::optional<RegionPair> single_coupling_pairwise(const Instance& inst, const SpanningTree& t, const Regions& regions);

}  // namespace gridlock
