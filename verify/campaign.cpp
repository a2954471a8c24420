#include "verify/campaign.hpp"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <utility>

#include "common/assert.hpp"
#include "common/limits.hpp"

namespace gridlock {

namespace {

// Checks formula i of a fuzz campaign and counts it; false when the campaign
// ends here (a stop request, or a disagreement without keep_going).
// One Verifier serves the whole campaign (its simulator's arrays are kept).
bool fuzz_one(const FuzzCampaign& c, uint64_t i, const Deadline& clock, const FuzzEvents& ev, Verifier& verifier,
              FuzzTally& t) {
  Formula f = fuzz_formula(c.formulas, i);
  VerifyOptions vi = c.verify;  // the time limit bounds the campaign: the last formula gets what is left
  if (c.seconds > 0) vi.solve_seconds = std::min(c.verify.solve_seconds, std::max(c.seconds - clock.elapsed(), 0.001));
  VerifyResult r = verifier.verify(f, "formula " + std::to_string(i), vi);
  if (stop_requested()) return false;  // answers may be cut short: the formula is not counted
  ++t.formulas;
  t.sat += r.sat == Verdict::Yes;
  t.unsat += r.sat == Verdict::No;
  t.unknown += r.agree && r.solver_unknown();
  t.certificates += static_cast<uint64_t>(r.witnesses_checked());
  t.no_certified += (r.no_certificate == Check::Valid) + (r.cno_certificate == Check::Valid);
  if (r.agree) return true;
  ++t.disagreements;
  if (ev.disagreement) ev.disagreement(i, r);
  FuzzFinding found;
  found.index = i;
  found.shrunk = shrink_disagreement(f, c.verify, &found.shrink);
  if (stop_requested()) return false;  // shrinking cut short: no reproducer rather than a wrong one
  VerifyResult rs = verifier.verify(found.shrunk, "shrunk formula " + std::to_string(i), c.verify);
  found.problem = rs.problem;
  found.original = std::move(f);
  if (ev.finding) ev.finding(found, rs);
  t.findings.push_back(std::move(found));
  return c.keep_going;
}

// Counts one checked formula into t and says how it ended.
FormulaStatus count(const VerifyResult& r, VerifyTally& t) {
  ++t.formulas;
  t.certificates += static_cast<size_t>(r.witnesses_checked());
  t.no_certified += (r.no_certificate == Check::Valid) + (r.cno_certificate == Check::Valid);
  t.no_rejected += (r.no_certificate == Check::Invalid) + (r.cno_certificate == Check::Invalid);
  t.sat += r.sat == Verdict::Yes;
  t.unsat += r.sat == Verdict::No;
  t.ms += r.ms_sat + r.ms_compile + r.ms_solve + r.ms_gaps + r.ms_csolve + r.ms_certify;
  if (!r.agree) {
    ++t.disagree;
    return FormulaStatus::Disagree;
  }
  if (r.solver_unknown()) {
    ++t.unknown;
    return FormulaStatus::Unknown;
  }
  ++t.agree;
  return FormulaStatus::Agree;
}

}  // namespace

FuzzTally run_fuzz_campaign(const FuzzCampaign& c, const FuzzEvents& events) {
  const Deadline clock;  // no limit: only its clock is used
  FuzzTally t;
  Verifier verifier;
  for (uint64_t i = c.first; i < c.last && !stop_requested(); i += c.step) {
    if (c.seconds > 0 && clock.elapsed() >= c.seconds) break;
    if (!fuzz_one(c, i, clock, events, verifier, t)) break;
    if (i > UINT64_MAX - c.step) break;
    t.seconds = clock.elapsed();
    if (events.progress) events.progress(t);
  }
  t.seconds = clock.elapsed();
  t.interrupted = stop_requested();
  return t;
}

const char* formula_status_name(FormulaStatus s) {
  switch (s) {
    case FormulaStatus::Agree: return "agree";
    case FormulaStatus::Unknown: return "unknown";
    case FormulaStatus::Disagree: break;
  }
  return "DISAGREE";
}

std::string formula_stem(const std::string& path) {
  return path == "-" ? "stdin" : std::filesystem::path(path).stem().string();
}

VerifyTally run_verify_campaign(const std::vector<Formula>& formulas, const std::vector<std::string>& names,
                                const VerifyCampaign& c, const VerifyEvents& events) {
  GRIDLOCK_ASSERT(names.size() == formulas.size(), "run_verify_campaign needs one name per formula");
  VerifyTally t;
  Verifier verifier;  // one for all formulas: its simulator's arrays are kept
  for (size_t i = 0; i < formulas.size() && !stop_requested(); ++i) {
    if (!c.shard.has(i)) continue;
    if (events.start) events.start(i);
    VerifyResult r = verifier.verify(formulas[i], names[i], c.verify);
    if (stop_requested()) break;  // its answers may be cut short: not counted
    const FormulaStatus s = count(r, t);
    if (s == FormulaStatus::Disagree && !c.reproducers.empty()) {
      const std::string dir = c.reproducers + "/" + formula_stem(names[i]);
      if (auto err = write_reproducer(r, dir, c.verify)) {
        r.problem += " (reproducer NOT written: " + err->str() + ")";
        t.unsaved.emplace_back(i, *err);
      } else {
        r.problem += " (reproducer: " + dir + ")";
      }
    }
    if (events.result) events.result(i, r, s);
  }
  t.interrupted = stop_requested();
  return t;
}

}  // namespace gridlock
