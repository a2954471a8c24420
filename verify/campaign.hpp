// Verification campaigns: the loops and tallies behind `gridlock fuzz` (many
// drawn formulas) and `gridlock verify` (many given formulas), docs/verify.md.
//
// A campaign takes a plain option struct, calls verify_formula on each item
// of its shard, counts the answers and reports through callbacks (progress,
// a disagreement, a shrunk finding) and its returned tally. It never prints
// and never exits: the command line (tools/) turns events and tallies into
// text, JSON and exit codes. Between items it polls stop_requested()
// (common/limits.hpp); an item cut short by a stop is not counted, and the
// tally comes back marked interrupted.
//
// Items run on `jobs` worker threads (common/internal/ordered_pool.hpp), each with its
// own Verifier; every event is called on the calling thread, in item order,
// so events, tallies and findings are the same for every number of jobs.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "cnf/formula.hpp"
#include "verify/fuzz.hpp"
#include "verify/shrink.hpp"
#include "verify/verify.hpp"

namespace gridlock {

// The items i of a campaign with i % n == k (0 <= k < n).
struct Shard {
  uint64_t k = 0, n = 1;
  bool has(uint64_t i) const { return i % n == k; }
  std::string str() const { return std::to_string(k) + "/" + std::to_string(n); }
};

// --- fuzz: formulas drawn from a seed -----------------------------------------

struct FuzzCampaign {
  FuzzParams formulas;   // formula i is fuzz_formula(formulas, i)
  VerifyOptions verify;  // how each formula is checked (and its shrunk form)
  uint64_t first = 0;    // indices first, first + step, ... below last
  uint64_t last = 1000;
  uint64_t step = 1;        // the shard count (first is the shard's own index)
  double seconds = 0;       // stop after this many seconds (0: no limit); the
                            // last formula's solver gets only what is left
  bool keep_going = false;  // false: stop after the first disagreement
  unsigned jobs = 1;        // worker threads (formulas checked and shrunk at once)
};

// A disagreement, shrunk (verify/fuzz.hpp shrink_disagreement).
struct FuzzFinding {
  uint64_t index = 0;
  std::string problem;  // what the shrunk formula's verify found
  Formula original, shrunk;
  ShrinkStats shrink;
};

struct FuzzTally {
  uint64_t formulas = 0, sat = 0, unsat = 0;
  uint64_t unknown = 0;       // agreeing formulas on which an exact solver hit a limit
  uint64_t certificates = 0;  // certificates checked and valid
  uint64_t no_certified = 0;  // of them: NO certificates (certify/) accepted
  uint64_t disagreements = 0;
  double seconds = 0;  // since the campaign started
  bool interrupted = false;
  std::vector<FuzzFinding> findings;  // each shrunk disagreement, in index order
};

struct FuzzEvents {
  // Formula `index` disagrees (r: its verify result); shrinking starts next.
  std::function<void(uint64_t index, const VerifyResult& r)> disagreement;
  // A disagreement shrunk and verified again (shrunk: that result, whose
  // certificates and instances a reproducer needs). Called before the
  // finding is counted in the tally's findings.
  std::function<void(const FuzzFinding& f, const VerifyResult& shrunk)> finding;
  // After each formula counted (tally.seconds up to date).
  std::function<void(const FuzzTally& t)> progress;
};

// Runs the campaign. Deterministic apart from times: the same campaign gives
// the same counts and findings whatever the machine, given no time limits
// are hit. A disagreement cut short by a stop while shrinking is counted but
// has no finding (no reproducer rather than a wrong one).
FuzzTally run_fuzz_campaign(const FuzzCampaign& c, const FuzzEvents& events = {});

// --- verify: given formulas ---------------------------------------------------

// How one formula's check ended: everything agrees, agrees but an exact
// solver hit a limit, or something disagrees.
enum class FormulaStatus { Agree, Unknown, Disagree };
const char* formula_status_name(FormulaStatus s);  // "agree", "unknown", "DISAGREE"

struct VerifyCampaign {
  VerifyOptions verify;
  Shard shard;              // formulas i (in input order) with shard.has(i)
  std::string reproducers;  // folder for reproducers (one subfolder per
                            // disagreement, named by formula_stem); "" = none
  unsigned jobs = 1;        // worker threads (formulas checked at once)
};

struct VerifyTally {
  size_t formulas = 0, sat = 0, unsat = 0;
  size_t agree = 0, unknown = 0, disagree = 0;
  size_t certificates = 0;  // certificates checked and valid
  size_t no_certified = 0;  // of them: NO certificates (certify/) accepted
  size_t no_rejected = 0;   // discrete NOs whose certificate was missing or rejected
  double ms = 0;            // the formulas' own times (sat, compile, solvers)
  bool interrupted = false;
  // Disagreements whose reproducer could not be written: (formula index,
  // the write's Diagnostic). The command reports them (the finding in full
  // on stderr) and fails with the first Diagnostic.
  std::vector<std::pair<size_t, Diagnostic>> unsaved;
};

struct VerifyEvents {
  // Formula i is the next to be counted: the campaign waits for it (the
  // command line names it as the activity in progress, for an out-of-memory
  // report).
  std::function<void(size_t i)> start;
  // Formula i checked and counted. For a disagreement with a reproducer
  // folder, r.problem ends with " (reproducer: DIR)", or with
  // " (reproducer NOT written: DIAGNOSTIC)" when writing it failed.
  std::function<void(size_t i, const VerifyResult& r, FormulaStatus s)> result;
};

// Checks formulas[i] (named names[i]) for each i of the shard, in order.
// Requires names.size() == formulas.size(). Throws std::runtime_error if a
// reproducer cannot be written.
VerifyTally run_verify_campaign(const std::vector<Formula>& formulas, const std::vector<std::string>& names,
                                const VerifyCampaign& c, const VerifyEvents& events = {});

// The name a formula file gives its rows, reproducers and pictures: the
// file's stem ("uf20-01" for "dir/uf20-01.cnf"), "stdin" for "-".
std::string formula_stem(const std::string& path);

}  // namespace gridlock
