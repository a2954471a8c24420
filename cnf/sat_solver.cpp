// The CaDiCaL adapter (with cnf/incremental_sat.cpp, the only files that include cadical.hpp).
#include "cnf/sat_solver.hpp"

#include <cadical.hpp>

#include <algorithm>
#include <climits>
#include <stdexcept>

#include "common/limits.hpp"

namespace gridlock {

namespace {

// CaDiCaL polls its terminator regularly during search; this one ends the
// search when the common deadline expires: its time limit or a stop request
// (common/limits.hpp).
class SatDeadline : public CaDiCaL::Terminator {
 public:
  explicit SatDeadline(const Deadline& deadline) : deadline_(deadline) {}
  bool terminate() override { return deadline_.expired(); }

 private:
  const Deadline& deadline_;
};

}  // namespace

const char* sat_status_name(Verdict s) {
  switch (s) {
    case Verdict::Yes: return "SATISFIABLE";
    case Verdict::No: return "UNSATISFIABLE";
    case Verdict::Unknown: return "UNKNOWN";
  }
  return "UNKNOWN";
}

std::string sat_solver_name() { return std::string("CaDiCaL ") + CaDiCaL::Solver::version(); }

SatResult solve_sat(const Formula& f, const SatLimits& limits) {
  if (std::string bad = validate(f); !bad.empty()) throw std::invalid_argument("solve_sat: " + bad);
  const Deadline limit(limits.seconds);  // <= 0: none
  SatResult res;
  CaDiCaL::Solver solver;
  // CaDiCaL writes some messages ("c found falsified original clause") to
  // standard output even by default; a library must not touch our output.
  solver.set("quiet", 1);
  // Make every declared variable known to the solver, so that val() is
  // defined for variables that occur in no clause too.
  if (f.num_vars > 0) solver.reserve(f.num_vars);
  for (const auto& clause : f.clauses) {
    for (int lit : clause) solver.add(lit);
    solver.add(0);
  }
  if (limits.conflicts >= 0) solver.limit("conflicts", static_cast<int>(std::min<int64_t>(limits.conflicts, INT_MAX)));
  SatDeadline deadline(limit);
  solver.connect_terminator(&deadline);
  const int code = solver.solve();
  solver.disconnect_terminator();
  res.status = code == 10 ? Verdict::Yes : code == 20 ? Verdict::No : Verdict::Unknown;
  if (res.status == Verdict::Yes) {
    res.model.assign(static_cast<size_t>(f.num_vars) + 1, false);
    for (int v = 1; v <= f.num_vars; ++v) res.model[static_cast<size_t>(v)] = solver.val(v) > 0;
    long bad = first_falsified_clause(f, res.model);
    if (bad >= 0)
      throw std::logic_error(sat_solver_name() + " returned a model that falsifies clause " + std::to_string(bad + 1));
  }
  res.seconds = limit.elapsed();
  return res;
}

}  // namespace gridlock
