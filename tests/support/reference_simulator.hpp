// The deliberately simple twin of lattice/simulate: all pairs, every interval.
//
// Independent of the fast simulator on purpose: its own spanning tree (from
// any root, so anchor independence is tested too), region rectangles written
// again from docs/model.md's words, overlap found by sampling between the roots of
// the eight linear constraints (not by solving them), and cycle collisions
// from the fundamental cycles of its tree (not from face walks).
// O(k (n^2 + e n)) rationals: for small instances only.
#pragma once

#include <optional>
#include <vector>

#include "lattice/instance.hpp"
#include "lattice/rational.hpp"
#include "lattice/schedule.hpp"

namespace gridlock::test {

struct ReferenceCollision {
  bool cycle = false;
  Rational time;
  // All pairs of regions (fast simulator's numbering: nodes, then one region
  // per expansion/growth in operation order) that begin to overlap at `time`.
  std::vector<std::pair<uint32_t, uint32_t>> pairs;
};

std::optional<ReferenceCollision> reference_simulate(const Instance& inst, const Schedule& s, NodeId root);

}  // namespace gridlock::test
