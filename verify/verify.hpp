// End-to-end verification of the reduction on one formula (docs/verify.md).
//
// For a CNF formula F: answer "is F satisfiable?" three ways and compare.
//  1. CaDiCaL on F (its model is checked against F).
//  2. If F is not LSAT<=3, reduce it with to-lsat to G (else, or with
//     VerifyOptions::direct, G = F); compile
//     G into a lattice instance I; the exact discrete solver on I.
//  3. The linear-time gap checker on I (continuous model): every compiled
//     instance is expected to be YES (paper: continuous time is easy), and
//     its witness "everything at time 0" is run through the simulator.
// Certificates are checked both ways: F's model -> G's assignment -> a
// schedule of I -> the simulator; the solver's schedule (already replayed by
// the simulator inside the solver) -> an assignment of G -> of F -> F.
//
// The continuous model (VerifyOptions::model Continuous or Both): G is also
// compiled for continuous time (compile_formula with TimeModel::
// Continuous) into I', and the exact continuous solver (solver/continuous.hpp)
// decides I'. Expected: its answer is CaDiCaL's. Certificates: F's model ->
// start times of I' (times_from_assignment) -> the simulator; the solver's
// start times -> the simulator again -> an assignment (assignment_from_times)
// -> of F -> F.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cnf/formula.hpp"
#include "common/diagnostic.hpp"
#include "common/verdict.hpp"
#include "gadgets/mutation.hpp"
#include "lattice/instance.hpp"
#include "reductions/compile.hpp"

namespace gridlock {

// Which reductions verify checks (VerifyOptions::models, a TimeModels of
// lattice/time_model.hpp): the discrete one (exact discrete solver and gap
// checker), the continuous one (exact continuous solver), or both.

struct VerifyOptions {
  TimeModels models = TimeModels::only(TimeModel::Discrete);
  double solve_seconds = 60;           // limit of each exact solver (then UNKNOWN)
  uint64_t max_states = 0;             // limit of the exact solver; 0 = none
  Mutation mutation = Mutation::None;  // test only: compile with a broken gadget
  // Compile F itself, not its LSAT<=3 form (G = F; couplings may then have
  // more than 3 operations, which the reduction's correctness does not need):
  // small formulas stay small instances. Formulas with an empty clause still
  // go through to-lsat.
  bool direct = false;
  // With every NO of an exact solver (discrete or continuous), ask it for a
  // NO certificate (solver/no_certificate.hpp) and check it with the
  // independent checker (certify/certify.hpp); a missing or rejected
  // certificate is a problem.
  bool certify = true;
};

// A certificate check: not applicable, checked and valid, checked and INVALID.
enum class Check { None, Valid, Invalid };

struct VerifyResult {
  std::string name;
  Formula source, lsat;      // F and G
  bool reduced = false;      // G came from to-lsat
  CompiledFormula compiled;  // G compiled (with the mutation, if any): the instance checked
  const Instance& instance() const { return compiled.instance; }
  size_t nodes = 0, ops = 0, couplings = 0, max_coupling = 0;
  Verdict sat = Verdict::Unknown, discrete = Verdict::Unknown, continuous = Verdict::Unknown;
  Check sat_witness = Check::None;                         // F's model -> schedule -> simulator
  Check solver_witness = Check::None;                      // solver's schedule -> assignment -> F
  Check gaps_witness = Check::None;                        // gaps YES: all couplings at time 0 -> simulator
  Check no_certificate = Check::None;                      // discrete NO: its certificate -> certify
  std::string certificate;                                 // that certificate (kept for reproducers)
  std::string certificate_issue;                           // why no_certificate is Invalid
  double ms_certify = 0;                                   // time of the independent check
  std::vector<std::string> sat_schedule, solver_schedule;  // coupling names
  // The continuous reduction (when VerifyOptions::model asks for it).
  bool ran_discrete = false, ran_continuous = false;
  CompiledFormula compiled_continuous;                 // G compiled for continuous time
  Verdict continuous_solver = Verdict::Unknown;        // the exact continuous solver on it
  Check csat_witness = Check::None;                    // F's model -> start times -> simulator
  Check csolver_witness = Check::None;                 // solver's start times -> simulator -> assignment -> F
  std::string csolver_issue;                           // why csolver_witness is Invalid
  Check cno_certificate = Check::None;                 // continuous NO: its certificate -> certify
  std::string ccertificate, ccertificate_issue;        // that certificate; why cno_certificate is Invalid
  std::vector<std::string> csat_times, csolver_times;  // "NAME TIME" lines
  size_t cnodes = 0;
  double ms_csolve = 0;
  uint64_t csolver_conflicts = 0;
  double ms_sat = 0, ms_compile = 0, ms_solve = 0, ms_gaps = 0;
  uint64_t solver_states = 0;
  bool agree = false;   // everything consistent (UNKNOWN is not a disagreement)
  std::string problem;  // what disagreed, if anything
  // Number of certificates checked and valid (for the table).
  int witnesses_checked() const;
  // Some exact solver that ran hit a limit (UNKNOWN).
  bool solver_unknown() const {
    return (ran_discrete && discrete == Verdict::Unknown) || (ran_continuous && continuous_solver == Verdict::Unknown);
  }
};

// Runs the whole check. Never throws for a valid formula (validate(f)
// empty) with clauses of any length, empty ones included (they go through
// to-lsat); limits give UNKNOWN. Time: CaDiCaL + O(size) compile + the
// solver (exponential worst case, bounded by the limits) + simulator runs.
VerifyResult verify_formula(const Formula& f, const std::string& name, const VerifyOptions& opt);

class Simulator;

// The same check, for many formulas in a row (a fuzz campaign, a folder of
// formulas): one Verifier keeps the simulator's work arrays from formula to
// formula instead of allocating them again for each. verify(f, name, opt)
// returns exactly what verify_formula(f, name, opt) returns. Not thread-safe:
// one Verifier per thread.
class Verifier {
 public:
  Verifier();
  ~Verifier();
  Verifier(Verifier&&) noexcept;
  Verifier& operator=(Verifier&&) noexcept;
  Verifier(const Verifier&) = delete;
  Verifier& operator=(const Verifier&) = delete;

  VerifyResult verify(const Formula& f, const std::string& name, const VerifyOptions& opt);

 private:
  std::unique_ptr<Simulator> sim_;  // rebound to each formula's instance
};

// Writes a reproducer for r into dir (created, with parents): formula.cnf,
// lsat.cnf, instance.grid, sat-schedule.txt, solver-schedule.txt, README.txt
// saying what disagreed, and run.sh replaying it with `gridlock verify`.
// A file that cannot be written (or a folder that cannot be created) is the
// returned Diagnostic naming it ("DIR/FILE: write failed: REASON"); files
// written before it stay (each one whole: common/internal/atomic_file.hpp).
MaybeError write_reproducer(const VerifyResult& r, const std::string& dir, const VerifyOptions& opt);

}  // namespace gridlock
