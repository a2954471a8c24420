#include "tools/progress_line.hpp"

#include <unistd.h>

#include <cstdio>
#include <iostream>

#include "common/clock.hpp"

namespace gridlock::cli {

ProgressLine::ProgressLine(bool enabled) : enabled_(enabled && isatty(STDERR_FILENO)) {}

void ProgressLine::show(const std::string& text, bool now) {
  if (!enabled_) return;
  const double t = monotonic_seconds();
  if (!now && last_ >= 0 && t - last_ < 0.5) return;
  last_ = t;
  std::cerr << "\r\033[K" << text << std::flush;
}

void ProgressLine::clear() const {
  if (enabled_) std::cerr << "\r\033[K" << std::flush;
}

std::string solve_progress_text(const SolveProgress& p) {
  char buf[160];
  if (p.activity) std::snprintf(buf, sizeof buf, "solve: %s, %.1f s", p.activity, p.seconds);
  else
    std::snprintf(buf, sizeof buf, "solve: %llu states, depth %zu, %.0f states/s, %.1f s",
                  static_cast<unsigned long long>(p.states), p.depth,
                  p.seconds > 0 ? static_cast<double>(p.states) / p.seconds : 0.0, p.seconds);
  return buf;
}

std::function<void(const SolveProgress&)> solve_progress_to(ProgressLine& line) {
  return [&line](const SolveProgress& p) {
    if (p.finished) line.clear();
    else line.show(solve_progress_text(p), true);  // the solver already reports at most twice a second
  };
}

std::string collide_progress_text(const CollideProgress& p) {
  const bool bands = p.step == "single-coupling";
  char buf[200];
  std::snprintf(buf, sizeof buf, "collide: %s, %llu of %llu %s (%.0f %%), %.1f s", p.step.c_str(),
                static_cast<unsigned long long>(p.done), static_cast<unsigned long long>(p.total),
                bands ? "column bands" : "source nodes",
                p.total > 0 ? 100.0 * static_cast<double>(p.done) / static_cast<double>(p.total) : 100.0, p.seconds);
  return buf;
}

CollideProgressFn collide_progress_to(ProgressLine& line) {
  return [&line](const CollideProgress& p) {
    if (p.done >= p.total) line.clear();
    else line.show(collide_progress_text(p), true);  // find_collision already reports at most four times a second
  };
}

}  // namespace gridlock::cli
