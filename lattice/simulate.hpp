// The exact simulator: does a schedule collide, and if so, when, where, how.
//
// Semantics: docs/model.md. All arithmetic is on integers: times and
// coordinates are scaled by the common denominator D of the start times, so
// every position at an event time is an integer multiple of 1/D, and within
// an interval between consecutive events every face moves linearly.
//
// Algorithm (docs/simulator.md): the events (starts and ends of couplings)
// cut time into intervals with a fixed set of running couplings. In each one
//  - cutting the spanning tree at the running operations' edges leaves rigid
//    components; the largest stays put (only relative motion matters), and
//    only the regions of the other components, plus the regions whose width
//    changes, move;
//  - a broad phase finds the pairs whose swept boxes overlap: moving regions
//    query a table of all regions by grid cell (a dense array over the
//    shape's box, a hash table elsewhere), and moving regions meet each
//    other in per-cell lists of their swept boxes (up to 48 moving regions:
//    every pair whose swept boxes overlap; in horizontal-only instances,
//    when a quarter of the regions move at most 4 cells per unit of time,
//    a sweep of each row by swept x-extents instead of the cells);
//  - the exact test solves eight strict linear inequalities in time.
// Cycle collisions are found up front from the face walks (FaceNets): the
// mismatch around a face is piecewise linear in time, so the first moment it
// is non-zero is an event time.
// Cost: O(n + e log e + k log k) set-up, then per interval
// O(c log c + m * s + p) for c running operations, m moving regions, s cells
// per swept box and p candidate pairs. Worst case O(k n); on random trees and
// schedules m is small (see docs/performance.md).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/limits.hpp"
#include "lattice/instance.hpp"
#include "lattice/motion.hpp"
#include "lattice/prepared.hpp"
#include "lattice/rational.hpp"
#include "lattice/schedule.hpp"

namespace gridlock {

struct Collision {
  enum class Kind { Node, Cycle };
  Kind kind = Kind::Node;
  Rational time;                   // the first moment (infimum) of the collision
  uint32_t a = kNone, b = kNone;   // the two regions (node collision), a < b
  std::vector<NodeId> cycle;       // the face walk (cycle collision)
  std::vector<CouplingId> moving;  // couplings running right after `time`
};

struct SimStats {
  uint64_t intervals = 0;         // intervals with at least one running coupling
  uint64_t moved_regions = 0;     // sum over intervals of moving regions
  uint64_t candidate_pairs = 0;   // pairs passed by the broad phase
  uint64_t row_sweeps = 0;        // intervals whose broad phase swept rows (horizontal-only instances)
  uint64_t reused_intervals = 0;  // intervals whose moving regions came from an earlier one (set_reuse_intervals)
};

struct SimResult {
  std::optional<Collision> collision;  // nullopt: the schedule is collision-free
  SimStats stats;
};

class Simulator {
 public:
  // O(n + e log e): builds the instance's motion tables (a PreparedInstance).
  // Keeps a reference to inst, which must outlive it.
  explicit Simulator(const Instance& inst);
  // O(1): uses prep's tables, which must outlive the simulator.
  explicit Simulator(const PreparedInstance& prep);
  ~Simulator();
  Simulator(Simulator&&) noexcept;
  Simulator(const Simulator&) = delete;
  Simulator& operator=(const Simulator&) = delete;
  Simulator& operator=(Simulator&&) = delete;

  // Runs schedule s. Requires check_schedule_bounds(inst, s) to pass. Work
  // arrays are kept between runs: after the first run of a simulator, runs
  // allocate only for what they return, and a run resets only the regions
  // the previous run moved (all of them when the time scale D changes).
  SimResult run(const Schedule& s);
  SimResult run_order(const std::vector<CouplingId>& order) { return run(schedule_from_order(order)); }

  // From now on, run() calls deadline->check() between intervals and every
  // few thousand faces of the cycle check: a run past the deadline (or after
  // a stop request) throws LimitReached (common/limits.hpp) instead of
  // finishing. nullptr (the default): no limit. d must outlive the runs.
  void set_deadline(const Deadline* d) { deadline_ = d; }

  // Whether the broad phase drops pairs of moving regions that share their
  // four face velocities and do not overlap now (they cannot meet in the
  // interval: exact). On by default; off only for the twin tests, which
  // compare both paths.
  void set_skip_rigid_pairs(bool on) { skip_rigid_ = on; }

  // Whether intervals in which many regions of a horizontal-only instance
  // move slowly (verify's gap witness) take the row sweep as their broad
  // phase instead of the cell grid: the same answer (both are exact
  // filters). On by default; off only for the twin tests.
  void set_row_sweep(bool on) { row_sweep_ = on; }

  // Whether intervals skip work that cannot change their answer: moving
  // regions query only the cells a static region overlapping their swept
  // box can start in (two per unit move in every order, not six), and an
  // interval in which one coupling alone runs (every interval of an order)
  // takes its moving regions and face velocities from the first such
  // interval of that coupling since the last rebind instead of cutting the
  // tree again; the row sweep starts from the prepared node order merged
  // with the other regions (regions_by_row, lattice/row_order.hpp) instead
  // of sorting all regions again; and the last interval of a run does not
  // advance the regions (nothing reads them after it); few moving regions
  // (an order's intervals) are paired by rigid-velocity class, the moved
  // component's regions not with each other. The same pairs are
  // tested: identical results and stats, but for the reused_intervals
  // counter. On by default; off only for the twin tests (the old
  // computation).
  void set_reuse_intervals(bool on) { reuse_ = on; }

  // Simulates prep from now on (its tables must outlive the simulator),
  // keeping the work arrays' memory: one simulator serves many instances
  // (verify's Verifier, one formula after another). O(n + r).
  void rebind(const PreparedInstance& prep);

  const Instance& instance() const { return prep_->inst; }
  const PreparedInstance& prepared() const { return *prep_; }
  const Regions& regions() const { return prep_->regions; }
  const SpanningTree& tree() const { return prep_->tree; }
  const FaceNets& faces() const { return prep_->faces; }

 private:
  struct Scratch;
  std::unique_ptr<PreparedInstance> owned_;  // when built from an Instance
  const PreparedInstance* prep_;
  std::unique_ptr<Scratch> scratch_;
  const Deadline* deadline_ = nullptr;
  bool skip_rigid_ = true;
  bool row_sweep_ = true;
  bool reuse_ = true;
};

// An exact rectangle, for drawing the configuration at a moment.
struct RectQ {
  Rational xlo, xhi, ylo, yhi;
};
// Every region's rectangle at time t under schedule s (on the spanning tree
// from the anchor; meaningful up to the first collision). O(n) rationals.
std::vector<RectQ> configuration_at(const Instance& inst, const Schedule& s, const Rational& t);

// "node (1,1) and node (0,1) collide at time 3/2" and similar one-liners.
std::string describe(const Instance& inst, const Regions& regions, const Collision& c);

}  // namespace gridlock
