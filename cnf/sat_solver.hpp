// SAT solving through CaDiCaL, linked as a library. This header does not
// include CaDiCaL: cnf/sat_solver.cpp is the only file that does, so the
// solver can be replaced (or pinned) in one place.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cnf/formula.hpp"
#include "common/verdict.hpp"

namespace gridlock {

// Limits of one solve call; a limit that is hit gives Verdict::Unknown.
struct SatLimits {
  int64_t conflicts = -1;  // CaDiCaL conflict limit; < 0 = none (values above INT_MAX are capped)
  double seconds = -1;     // wall-clock limit; <= 0 = none
};

struct SatResult {
  Verdict status = Verdict::Unknown;  // Yes = satisfiable, No = unsatisfiable
  std::vector<bool> model;            // Yes only: indexed 1..num_vars (model[0] unused)
  double seconds = 0;                 // wall-clock time of the call
};

// "SATISFIABLE", "UNSATISFIABLE", "UNKNOWN" (the DIMACS status words).
const char* sat_status_name(Verdict v);

// Solves f with CaDiCaL. Requires validate(f) empty (throws
// std::invalid_argument otherwise). A Sat model is checked with satisfies()
// before it is returned; if CaDiCaL ever gives a wrong model, throws
// std::logic_error (a bug to report, never a silent wrong answer).
// Variables that occur in no clause get the value CaDiCaL gives them.
// Time: whatever the formula needs, bounded by the limits.
SatResult solve_sat(const Formula& f, const SatLimits& limits = {});

// "CaDiCaL 1.5.3" (for comments in tool output).
std::string sat_solver_name();

}  // namespace gridlock
