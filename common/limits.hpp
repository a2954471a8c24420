// Limits shared by every long computation: a wall-clock deadline and a
// process-wide stop request.
//
// How to use (library code):
//   Deadline d(seconds);          // seconds <= 0: no time limit
//   for (...) { d.check(); ... }  // throws LimitReached when the time is up
//                                 // or a stop was requested (SIGINT/SIGTERM)
// Callers catch LimitReached and report UNKNOWN (or "interrupted" when
// stop_requested() is true). Deadline::check reads the clock on every call
// (a vDSO call, ~20 ns): call it once per unit of real work (a search node,
// a constraint pair), not in the tightest inner loop.
//
// The stop request is set only by the command line's signal handler
// (tools/cli_common.hpp, install_stop_handlers); library code only reads it,
// so tests and library users never see it set.
#pragma once

#include <atomic>

#include "common/clock.hpp"

namespace gridlock {

// Thrown by Deadline::check (and by SearchBudget, solver/internal/search.hpp).
struct LimitReached {};

// The signal number that asked the process to stop, or 0. Lock-free, so a
// signal handler may store into it.
inline std::atomic<int>& stop_signal() {
  static std::atomic<int> s{0};
  return s;
}
inline bool stop_requested() { return stop_signal().load(std::memory_order_relaxed) != 0; }

class Deadline {
 public:
  // No time limit (stop requests still end check()).
  Deadline() = default;
  // A limit of `seconds` from now; seconds <= 0 means none.
  explicit Deadline(double seconds) : seconds_(seconds) {}

  // Seconds since construction (common/clock.hpp).
  double elapsed() const { return clock_.seconds(); }
  double limit() const { return seconds_; }
  // True once the limit has passed or a stop was requested.
  bool expired() const { return stop_requested() || (seconds_ > 0 && elapsed() > seconds_); }
  // Throws LimitReached when expired().
  void check() const {
    if (expired()) throw LimitReached{};
  }

 private:
  Stopwatch clock_;
  double seconds_ = 0;
};

}  // namespace gridlock
