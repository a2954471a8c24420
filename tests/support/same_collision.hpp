// The twin tests' comparison of two simulator runs' first collisions: the
// same kind, moment, pair, cycle flag and moving couplings; and of two whole
// runs.
#pragma once

#include <gtest/gtest.h>

#include <utility>

#include "lattice/simulate.hpp"

namespace gridlock::test {

inline void expect_same_collision(const Collision& x, const Collision& y) {
  EXPECT_EQ(x.kind, y.kind);
  EXPECT_EQ(x.time, y.time);
  EXPECT_EQ(std::pair(x.a, x.b), std::pair(y.a, y.b));
  EXPECT_EQ(x.cycle, y.cycle);
  EXPECT_EQ(x.moving, y.moving);
}

// Two runs of one schedule: the same first collision (if any) and the same
// statistics (the twins' own counters, row_sweeps and reused_intervals, aside).
inline void expect_same_run(const SimResult& x, const SimResult& y) {
  EXPECT_EQ(x.stats.intervals, y.stats.intervals);
  EXPECT_EQ(x.stats.moved_regions, y.stats.moved_regions);
  EXPECT_EQ(x.stats.candidate_pairs, y.stats.candidate_pairs);
  ASSERT_EQ(x.collision.has_value(), y.collision.has_value());
  if (x.collision) expect_same_collision(*x.collision, *y.collision);
}

}  // namespace gridlock::test
