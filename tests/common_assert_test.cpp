// GRIDLOCK_ASSERT: in builds that check assertions (Debug, sanitizers), a
// broken "Requires" stops the program with a message naming the contract;
// elsewhere the condition is not evaluated at all.
#include <gtest/gtest.h>

#include <climits>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "cnf/formula.hpp"
#include "common/assert.hpp"
#include "common/random.hpp"
#include "lattice/random_instance.hpp"
#include "lattice/schedule.hpp"

namespace gridlock {
namespace {

#ifdef GRIDLOCK_ENABLE_ASSERT

TEST(AssertDeathTest, BrokenRequiresStopsWithTheContract) {
  Rng rng(1);
  EXPECT_DEATH(rng.below(0), "assertion failed: .*Rng::below needs bound > 0");
  EXPECT_DEATH(rng.between(2, 1), "Rng::between needs lo <= hi");
  EXPECT_DEATH(var_of(0), "var_of needs a non-zero literal");
  EXPECT_DEATH(var_of(INT_MIN), "var_of needs a non-zero literal");
  EXPECT_DEATH(schedule_from_order({0, 0}), "needs a permutation of all coupling ids");
  EXPECT_DEATH(schedule_from_order({1}), "needs a permutation of all coupling ids");
}

TEST(AssertDeathTest, KeptContractsPass) {
  Rng rng(1);
  EXPECT_LT(rng.below(3), 3U);
  EXPECT_EQ(var_of(-4), 4);
  EXPECT_EQ(schedule_from_order({1, 0}).start.size(), 2U);
}

#else

TEST(AssertDeathTest, ConditionIsNotEvaluatedWhenOff) {
  int evaluated = 0;
  GRIDLOCK_ASSERT(++evaluated > 0, "never evaluated");
  EXPECT_EQ(evaluated, 0);
}

#endif

// GRIDLOCK_REQUIRE is on in every build: a broken precondition of a public
// function is an std::invalid_argument carrying the message; the message
// is built only when the check fails.
TEST(Require, ThrowsInvalidArgumentInEveryBuild) {
  int built = 0;
  auto message = [&] {
    ++built;
    return std::string("needs a positive count");
  };
  EXPECT_NO_THROW(GRIDLOCK_REQUIRE(1 > 0, message()));
  EXPECT_EQ(built, 0);
  try {
    GRIDLOCK_REQUIRE(1 < 0, message());
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "needs a positive count");
  }
  EXPECT_EQ(built, 1);
  // A library precondition checked by it, in an optimised build too.
  RandomInstanceParams none;
  none.nodes = 0;
  EXPECT_THROW(random_instance(none, 1), std::invalid_argument);
}

}  // namespace
}  // namespace gridlock
