// Schedules: when each coupling runs (docs/model.md, "Couplings and schedules").
//
// Discrete: an order of all couplings; the i-th (from 0) runs over [i, i+1].
// Continuous: a rational start time t_q per coupling; q runs over [t_q, t_q+1].
// Both are stored as start times, so one simulator serves both models.
#pragma once

#include <string>
#include <vector>

#include "common/diagnostic.hpp"
#include "lattice/instance.hpp"
#include "lattice/rational.hpp"

namespace gridlock {

// Start times are bounded so that the simulator's scaled integers fit 64 bits.
inline constexpr int64_t kMaxStartTime = int64_t{1} << 30;    // |t| <= 2^30
inline constexpr int64_t kMaxDenominator = int64_t{1} << 20;  // lcm of denominators

struct Schedule {
  std::vector<Rational> start;    // per coupling id
  std::vector<CouplingId> order;  // set iff the schedule is discrete
  bool discrete() const { return !order.empty() || start.empty(); }
};

// Requires order to be a permutation of all coupling ids (GRIDLOCK_ASSERT).
Schedule schedule_from_order(const std::vector<CouplingId>& order);

// Turns coupling names into an order. Every coupling must be named exactly
// once; errors name `source`:`line` and the offending or missing name.
MaybeError parse_order(const Instance& inst, const std::vector<std::string>& names, const std::string& source,
                       long line, std::vector<CouplingId>& order);
// Reads an order from a file ("-": stdin): whitespace-separated names; lines
// starting with "c" or "#" are comments, an "s" line is skipped and a leading
// "v" is dropped, so the output of `gridlock solve` can be read back.
MaybeError read_order_file(const Instance& inst, const std::string& path, std::vector<CouplingId>& order);
// Reads start times: one line "NAME TIME" per coupling, TIME an integer or
// a fraction a/b; comments as above (an "s" line is skipped and a leading
// "v" dropped, so the output of `gridlock collide` and `gridlock gaps` can be
// read back). Checks the bounds above.
MaybeError read_times_file(const Instance& inst, const std::string& path, Schedule& out);
// Checks the bounds of kMaxStartTime / kMaxDenominator for a schedule built
// in code; returns a message or nullopt.
std::optional<std::string> check_schedule_bounds(const Instance& inst, const Schedule& s);

}  // namespace gridlock
