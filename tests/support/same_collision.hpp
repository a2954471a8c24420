// The twin tests' comparison of two simulator runs' first collisions: the
// same kind, moment, pair, cycle flag and moving couplings.
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

}  // namespace gridlock::test
