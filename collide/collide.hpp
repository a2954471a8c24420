// Colliding Schedule (paper, "Algorithms for Colliding Schedule"; semantics:
// docs/model.md): is there a schedule that causes a collision?
//
// find_collision picks the algorithm that fits the instance (docs/collide.md):
//   1. a coupling with a non-zero net vector around some face walk: running
//      it alone breaks that cycle (both models)                     O(n + e log e)
//   2. a single coupling: both models have one schedule: on one axis the
//      row neighbours at t = 0 (O(n log n)), else the space-time cell sweep
//   3. no couplings (all singletons): centroid decomposition and a red-blue
//      rectangle sweep over full-width squares (both models)        O(n log^2 n)
//   4. couplings, continuous: every pair of regions against the zonotope of
//      the coupling vectors on its path, own widths by Fourier-Motzkin; when
//      every operation is on one axis only the O(n) pairs of one row group
//      (proven), their paths walked in Mo's order       O(n log n + n sqrt n)
//   5. couplings, discrete: the answer is the continuous one (proven:
//      docs/collide.md, "the models agree"), so step 4 decides it; after a
//      YES, subset sums over the path's vectors find the discrete witness
//      from the nodes the continuous pair's faces follow. (Pairwise: every pair by
//      subset sums, the discrete decider on its own.)
// Every YES comes with a schedule that the exact Simulator has run and seen
// collide (for one coupling, when the algorithm names the first collision:
// whose named pair overlaps in the simulator's configuration at
// checked_at); if the simulator disagrees,
// find_collision throws std::logic_error (a bug, never a silent wrong
// answer).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "lattice/instance.hpp"
#include "lattice/prepared.hpp"
#include "lattice/rational.hpp"
#include "lattice/schedule.hpp"
#include "lattice/simulate.hpp"
#include "lattice/time_model.hpp"

namespace gridlock {

enum class CollideMethod {
  Auto,          // the fastest that applies
  Tree,          // no couplings only: centroid decomposition (3)
  TreePairwise,  // no couplings only: the same model, all pairs (O(n^2))
  Pairwise,      // any instance: the per-pair exact tests of the model (4, 5; discrete: subset sums on every pair)
};

struct CollideStats {
  uint64_t pairs = 0;       // region pairs considered (pairwise methods)
  uint64_t full_tests = 0;  // pairs that passed the quick distance filter
  uint64_t levels = 0;      // centroid recursion depth (tree method)
  uint64_t rectangles = 0;  // rectangles swept (tree method)
  uint64_t cell_items = 0;  // single coupling: (cell, time interval) items of the sweep (M)
  uint64_t pair_tests = 0;  // single coupling: exact pair tests of the sweep (T)
  // Discrete, Auto, with couplings: times the witness search from the
  // nodes the continuous pair's faces follow found nothing and every pair was searched
  // (the models-agree theorem says it cannot happen; never seen).
  uint64_t witness_fallbacks = 0;
};

struct CollideResult {
  bool collides = false;
  // The colliding schedule (empty when !collides): for the discrete model an
  // order (witness.order set); for the continuous model start times (an
  // order's times 0, 1, 2, ... when the algorithm produced an order).
  Schedule witness;
  // What the algorithm predicted: two regions (node collision) or a face
  // walk (cycle collision).
  uint32_t region_a = kNone, region_b = kNone;
  std::vector<NodeId> cycle;
  // The first collision on the witness (it may be another pair: any
  // collision answers the question): the simulator's; for
  // "single-coupling-one-axis" and "single-coupling" (unless its packing
  // bound decided) the one that algorithm's proof names (the simulator's:
  // the same moment and pair), confirmed in the simulator's configuration
  // at checked_at.
  std::optional<Collision> simulated;
  // Set when the witness was confirmed by the configuration at this moment
  // (configuration_at: the pair overlaps) rather than by a full simulation.
  std::optional<Rational> checked_at;
  std::string algorithm;   // "cycle", "single-coupling", "single-coupling-one-axis", "no-operations",
                           // "tree-centroid", "tree-pairwise", "one-axis-groups", "pairwise-zonotope",
                           // "pairwise-angle-tree", "pairwise-subset-sum"; discrete under Auto, a continuous name,
                           // with "+subset-sum" when it found the discrete witness
  std::string complexity;  // e.g. "O(n log^2 n)"
  CollideStats stats;
};

// What a long find_collision reports through its on_progress callback: the
// step that runs (CollideResult::algorithm's names) and how far it is in
// that step's own units: source nodes of the pairwise traversal
// ("pairwise-zonotope", "pairwise-subset-sum"), column bands of the
// one-coupling sweep ("single-coupling"). The library never draws; the
// command line turns the reports into its progress line.
struct CollideProgress {
  std::string step;
  uint64_t done = 0, total = 0;  // done <= total
  double seconds = 0;            // since find_collision began
};
using CollideProgressFn = std::function<void(const CollideProgress&)>;

// deadline (optional): checked by the quadratic methods and the simulator's
// check of the witness; when it passes, LimitReached (common/limits.hpp) is
// thrown (the command line answers UNKNOWN).
// on_progress (optional): called from the calling thread at most about four
// times a second while a step runs, and once more when a step ends with
// done == total (not when it stops early at a collision). Cheap steps (the
// cycle test, the centroid method) do not report.
CollideResult find_collision(const Instance& inst, TimeModel model, CollideMethod method = CollideMethod::Auto,
                             const Deadline* deadline = nullptr, const CollideProgressFn& on_progress = {});
// The same on prepared tables (lattice/prepared.hpp): nothing is rebuilt.
CollideResult find_collision(const PreparedInstance& prep, TimeModel model, CollideMethod method = CollideMethod::Auto,
                             const Deadline* deadline = nullptr, const CollideProgressFn& on_progress = {});

}  // namespace gridlock
