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

}  // namespace gridlock::cli
