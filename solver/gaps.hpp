// The continuous model for horizontal-only instances, in linear time
// (paper, Theorem "Collision-free Schedule is solvable in linear time if all
// operations are horizontal"; docs/model.md, "Consequences").
//
// Horizontal operations keep every node in its row, so a node collision is a
// gap between two consecutive nodes of a row going negative. All gap and
// cycle constraints are linear in the progress vector, and the feasible set is
// convex, so a collision-free schedule exists iff running every coupling at
// time 0 is collision-free, iff
//   - around every cycle the net displacement at the end is zero (we check the
//     fundamental cycle of each non-tree edge; with everything at once the
//     mismatch at time t is t times the final one), and
//   - every gap's final size is >= 0: initial size plus one per operation on
//     the tree path between the two nodes that widens it, minus one per
//     operation that narrows it (a growth into the gap narrows it; a
//     contracting node's face bound to its partner is taken into account).
//
// No comparison sort: rows come from a radix sort (lattice/row_order.hpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "common/verdict.hpp"
#include "lattice/instance.hpp"

namespace gridlock {

struct PreparedInstance;  // lattice/prepared.hpp

struct GapChange {
  OpId op = kNone;
  int64_t delta = 0;  // its effect on the gap: > 0 widens, < 0 narrows
};

struct GapVerdict {
  bool collision_free = true;
  // The answer as every decision procedure gives it (common/verdict.hpp):
  // Yes (collision-free) or No; the checker has no limit, so never Unknown.
  Verdict verdict() const { return collision_free ? Verdict::Yes : Verdict::No; }
  enum class Reason { None, Gap, Cycle } reason = Reason::None;
  // Reason::Gap: the first gap (by row, then x) whose final size is negative.
  int64_t row = 0;
  NodeId left = kNone, right = kNone;  // its two end nodes
  int64_t initial_size = 0;            // empty cells between them at the start
  int64_t final_size = 0;              // < 0
  std::vector<GapChange> changes;      // the operations that change it
  // Reason::Cycle: a non-tree edge whose fundamental cycle does not close.
  std::vector<NodeId> cycle;  // the cycle's nodes, from one end of the edge around to the other
  int64_t mismatch = 0;       // net horizontal displacement around it at the end
  // Statistics.
  uint64_t gaps_checked = 0;  // consecutive pairs in rows
  uint64_t negative_gaps = 0;
  uint64_t cycles_checked = 0;  // non-tree edges
  uint64_t open_cycles = 0;
};

// Decides the continuous Collision-free Schedule question.
// Requires inst.horizontal_only() (throws std::invalid_argument otherwise).
// Returns collision_free == true iff starting every coupling at time 0 is
// collision-free, which holds iff some schedule is.
// Complexity: O(n + e) time and memory (plus O(n) for the one reported gap's
// operations).
GapVerdict check_gaps(const Instance& inst);
// The same from prepared tables (the row order and, for a reported gap, the
// tree are not rebuilt). The same verdict, field for field.
GapVerdict check_gaps(const PreparedInstance& prep);

// One line for the verdict's reason, e.g. "gap in row 0 between (0,0) and
// (2,0): initial size 1, final size -1; narrowed by g1 (-1), g2 (-1)".
std::string describe_gap_verdict(const Instance& inst, const GapVerdict& v);

}  // namespace gridlock
