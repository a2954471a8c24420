// A labelled benchmark set of lattice instances, each answer certified: the
// generation behind `gridlock gen-instances` (docs/verify.md).
//
// Each formula (given, random 3-SAT at the threshold, random LSAT<=3) is
// decided by CaDiCaL, reduced with to-lsat and compiled for each model. YES
// is certified by a witness the exact simulator has accepted (the lifted
// model as a schedule, or as start times in the continuous model), NO by
// CaDiCaL's UNSAT of the source formula (the reduction preserves
// satisfiability: docs/gadgets.md; verify and fuzz test it) and, in the
// discrete model, by the solver's NO certificate, which certify/ has
// accepted (NAME.nocert; `gridlock certify` checks it without the solvers).
//
// make_instance_set never prints, never exits and writes no file itself: it
// hands each file (name and text, in a safe order) to a callback, and
// returns the set's records; the command line writes the files atomically
// and the manifest last. Between formulas it polls stop_requested()
// (common/limits.hpp): the set is then partial and marked interrupted.
// Formulas are labelled and compiled on plan.jobs worker threads
// (common/internal/ordered_pool.hpp); every event, the callback writes included, is
// called on the calling thread in set order, so files, events and tally
// are the same for every number of jobs.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "cnf/formula.hpp"
#include "reductions/compile.hpp"
#include "verify/campaign.hpp"

namespace gridlock {

// A formula of the set: its file stem, how it was made, its seed (0: given).
struct SetFormula {
  std::string name, origin;
  Formula formula;
  uint64_t seed = 0;
};

// Random formula j (0-based) of a kind, "threshold" (3-SAT, m = n * 4.26)
// or "lsat" (LSAT<=3, clauses of 1 to 3 literals), named KIND-(j+1). Its
// seed is fuzz_formula_seed(seed, j) (plus 10^9 for lsat). Deterministic.
SetFormula random_set_formula(const std::string& kind, uint64_t seed, int vars, uint64_t j);

struct InstanceSetPlan {
  std::vector<SetFormula> given;    // first in the set, in this order
  uint64_t seed = 1;                // of the random formulas
  int vars = 12;                    // variables of each random formula
  int threshold = 10, lsat = 10;    // random formulas of each kind
  int want_yes = -1, want_no = -1;  // keep only this many YES / NO random ones; -1: all
  double sat_seconds = 60;          // CaDiCaL's limit per formula; undecided ones are skipped
  Shard shard;                      // instances i (given, threshold, lsat) with shard.has(i); not with want_*
  std::vector<TimeModel> models = {TimeModel::Discrete};  // 1 or 2, compiled in this order
  // Discrete NO instances: the exact solver's NO certificate (docs/certificates.md),
  // checked by certify/ and written as NAME.nocert. A NO the solver does not
  // settle within solve_seconds (0: no limit) gets none (the manifest names none).
  bool no_certificates = true;
  double solve_seconds = 60;
  unsigned jobs = 1;  // worker threads labelling formulas at once (the set is the same for every count)
  bool mix() const { return want_yes >= 0 || want_no >= 0; }
  // Formulas the plan asks for (without want_*).
  size_t planned() const { return given.size() + static_cast<size_t>(threshold) + static_cast<size_t>(lsat); }
};

// One instance of the set (a manifest entry).
struct SetInstance {
  uint64_t index = 0;  // position of its formula in the unsharded set
  std::string name;    // NAME: files NAME.grid and NAME.schedule / NAME.times
  TimeModel model = TimeModel::Discrete;
  std::string formula_file, instance_file;
  std::string origin;
  uint64_t seed = 0;
  int variables = 0, lsat_variables = 0;
  size_t clauses = 0, lsat_clauses = 0;
  size_t nodes = 0, operations = 0, couplings = 0, max_coupling = 0;
  bool yes = false;
  std::string certificate_file;     // YES: the witness (NAME.schedule or NAME.times); NO: ""
  std::string no_certificate_file;  // NO: NAME.nocert, checked by certify/; "" if none
  std::string solver_check;         // continuous NO: "NO" (the continuous solver proved it) or "UNKNOWN"
};

struct InstanceSetTally {
  int yes = 0, no = 0;  // formulas kept, by answer
  int skipped = 0;      // formulas CaDiCaL did not decide in time
  std::vector<SetInstance> instances;
  bool interrupted = false;
  // With want_*: fewer formulas of an answer than asked for were found.
  bool short_of(const InstanceSetPlan& p) const {
    return p.mix() && ((p.want_yes >= 0 && yes < p.want_yes) || (p.want_no >= 0 && no < p.want_no));
  }
};

struct InstanceSetEvents {
  // The set waits for this formula's label (t: the set so far); then it
  // has it (not called when a stop cuts the labelling short).
  std::function<void(const std::string& name, const InstanceSetTally& t)> labelling;
  std::function<void()> labelled;
  // CaDiCaL did not decide this formula in time: not in the set.
  std::function<void(const std::string& name)> skipped;
  // Required: stores file (a name inside the set's folder) with this text.
  // Called in a safe order: a formula, then for each instance its witness
  // and then its .grid, so a .grid always has its formula and witness.
  std::function<void(const std::string& file, const std::string& text)> write;
  // An instance whose files are stored.
  std::function<void(const SetInstance& e)> instance;
};

// Makes the set. Throws std::logic_error if a lifted witness collides (the
// reduction would be wrong there), and whatever events.write throws.
InstanceSetTally make_instance_set(const InstanceSetPlan& plan, const InstanceSetEvents& events);

}  // namespace gridlock
