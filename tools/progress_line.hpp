// The command line's one progress printer: libraries report progress
// through callbacks (verify/campaign.hpp's events, SolveOptions::on_progress,
// find_collision's on_progress)
// and never draw; the subcommands turn those reports into this line.
#pragma once

#include <string>

#include "collide/collide.hpp"
#include "solver/solve.hpp"

namespace gridlock::cli {

// One line of progress on standard error, redrawn in place, when standard
// error is a terminal (and enabled); nothing otherwise.
class ProgressLine {
 public:
  explicit ProgressLine(bool enabled);
  bool enabled() const { return enabled_; }
  // Redraws the line (at most twice a second unless now).
  void show(const std::string& text, bool now = false);
  // Erases the line, so that other output starts on a clean line.
  void clear() const;

 private:
  bool enabled_;
  double last_ = -1;
};

// "solve: 1200 states, depth 14, 2400 states/s, 0.5 s", or for an activity
// "solve: WHAT, 0.5 s". O(1).
std::string solve_progress_text(const SolveProgress& p);

// A SolveOptions::on_progress that draws on line (erased at the last
// report). line must outlive the solve.
std::function<void(const SolveProgress&)> solve_progress_to(ProgressLine& line);

// "collide: pairwise-zonotope, 1200 of 5000 source nodes (24 %), 3.1 s". O(1).
std::string collide_progress_text(const CollideProgress& p);

// A find_collision on_progress that draws on line; a step's last report
// (done == total) erases it. line must outlive the call.
CollideProgressFn collide_progress_to(ProgressLine& line);

}  // namespace gridlock::cli
