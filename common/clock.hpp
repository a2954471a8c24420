// The one monotonic clock of the project: std::chrono::steady_clock, which
// never goes back when the system's wall clock is set. Deadlines
// (common/limits.hpp), the SAT adapter's time (cnf/sat_solver.cpp), verify's
// per-step times (verify/verify.cpp) and the command line's progress rate
// (tools/campaign_cli.cpp) read it through here.
#pragma once

#include <chrono>

namespace gridlock {

// Seconds since a fixed, arbitrary origin (the same for the whole process):
// only differences mean anything. O(1) (one vDSO call, ~20 ns).
inline double monotonic_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Time elapsed since construction or the last restart(). O(1) per call.
class Stopwatch {
 public:
  using Clock = std::chrono::steady_clock;
  Stopwatch() : start_(Clock::now()) {}
  void restart() { start_ = Clock::now(); }
  double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
  double milliseconds() const { return std::chrono::duration<double, std::milli>(Clock::now() - start_).count(); }

 private:
  Clock::time_point start_;
};

}  // namespace gridlock
