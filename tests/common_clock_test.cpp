// The monotonic clock (common/clock.hpp) and the deadline built on it
// (common/limits.hpp) against their reference, std::chrono::steady_clock read
// directly: every reading of the kernel lies between two direct readings
// taken around it, readings never go back, and a deadline expires exactly
// when the directly measured time has passed its limit.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "common/clock.hpp"
#include "common/limits.hpp"

namespace gridlock {
namespace {

using Steady = std::chrono::steady_clock;

double seconds_between(Steady::time_point a, Steady::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

TEST(Clock, MonotonicSecondsMatchesSteadyClockAndNeverGoesBack) {
  double last = monotonic_seconds();
  for (int i = 0; i < 100000; ++i) {
    const double before = std::chrono::duration<double>(Steady::now().time_since_epoch()).count();
    const double t = monotonic_seconds();
    const double after = std::chrono::duration<double>(Steady::now().time_since_epoch()).count();
    ASSERT_LE(before, t);
    ASSERT_LE(t, after);
    ASSERT_LE(last, t);
    last = t;
  }
}

TEST(Clock, StopwatchLiesBetweenDirectReadings) {
  const Steady::time_point outer_start = Steady::now();
  Stopwatch w;
  const Steady::time_point inner_start = Steady::now();
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  const Steady::time_point inner_end = Steady::now();
  const double s = w.seconds();
  const Steady::time_point outer_end = Steady::now();
  EXPECT_GE(s, seconds_between(inner_start, inner_end));
  EXPECT_LE(s, seconds_between(outer_start, outer_end));
  EXPECT_GE(s, 0.02);
  EXPECT_NEAR(w.milliseconds(), 1000 * w.seconds(), 5.0);
  w.restart();
  EXPECT_LT(w.seconds(), s);
}

TEST(Deadline, ExpiresWhenTheDirectlyMeasuredTimePassesTheLimit) {
  const Steady::time_point start = Steady::now();
  const Deadline d(0.03);
  EXPECT_DOUBLE_EQ(d.limit(), 0.03);
  bool seen_live = false;
  for (;;) {
    const bool expired = d.expired();
    const double after = seconds_between(start, Steady::now());
    if (!expired) {
      seen_live = true;
      ASSERT_LT(d.elapsed(), 10.0);
      continue;
    }
    EXPECT_GT(after, 0.03);  // it cannot expire before its limit
    break;
  }
  EXPECT_TRUE(seen_live);
  EXPECT_THROW(d.check(), LimitReached);
  // No limit (0 or negative): never expires on time alone.
  const Deadline none, negative(-1);
  std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_FALSE(none.expired());
  EXPECT_FALSE(negative.expired());
  EXPECT_NO_THROW(none.check());
}

}  // namespace
}  // namespace gridlock
