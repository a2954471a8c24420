#include "verify/campaign.hpp"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <utility>

#include "common/assert.hpp"
#include "common/internal/ordered_pool.hpp"
#include "common/limits.hpp"

namespace gridlock {

namespace {

// What a worker finds for one fuzz formula: its verify result and, for a
// disagreement, the shrunk finding and the shrunk formula's verify result.
struct FuzzItem {
  uint64_t index = 0;
  VerifyResult r;
  std::optional<FuzzFinding> found;  // none when a stop cut the shrinking short
  VerifyResult shrunk;
};

// An agreeing formula's result is only counted: its formulas, instances,
// schedules and certificate are freed here, in the worker that made them,
// rather than by the thread that counts every worker's results.
void release_instances(VerifyResult& r) {
  r.source = Formula{};
  r.lsat = Formula{};
  r.compiled = CompiledFormula{};
  r.compiled_continuous = CompiledFormula{};
  r.certificate = std::string{};
  r.sat_schedule = r.solver_schedule = r.csat_times = r.csolver_times = std::vector<std::string>{};
}

// Checks formula i (and shrinks it if it disagrees) with the worker's own
// Verifier. Nullopt when the campaign's time is up before it starts, or when
// a stop request may have cut its answers short (then it is not counted).
std::optional<FuzzItem> check_fuzz_formula(const FuzzCampaign& c, uint64_t i, const Deadline& clock,
                                           Verifier& verifier) {
  if (c.seconds > 0 && clock.elapsed() >= c.seconds) return std::nullopt;
  FuzzItem item;
  item.index = i;
  Formula f = fuzz_formula(c.formulas, i);
  VerifyOptions vi = c.verify;  // the time limit bounds the campaign: the last formula gets what is left
  if (c.seconds > 0) vi.solve_seconds = std::min(c.verify.solve_seconds, std::max(c.seconds - clock.elapsed(), 0.001));
  item.r = verifier.verify(f, "formula " + std::to_string(i), vi);
  if (stop_requested()) return std::nullopt;
  if (item.r.agree) {
    release_instances(item.r);
    return item;
  }
  FuzzFinding found;
  found.index = i;
  found.shrunk = shrink_disagreement(f, c.verify, &found.shrink);
  if (stop_requested()) return item;  // shrinking cut short: no reproducer rather than a wrong one
  item.shrunk = verifier.verify(found.shrunk, "shrunk formula " + std::to_string(i), c.verify);
  found.problem = item.shrunk.problem;
  found.original = std::move(f);
  item.found = std::move(found);
  return item;
}

// Counts a checked formula and reports it; false when the campaign ends
// here (a disagreement without keep_going, or one whose shrinking a stop cut
// short).
bool count_fuzz_formula(const FuzzCampaign& c, FuzzItem& item, const FuzzEvents& ev, FuzzTally& t) {
  const VerifyResult& r = item.r;
  ++t.formulas;
  t.sat += r.sat == Verdict::Yes;
  t.unsat += r.sat == Verdict::No;
  t.unknown += r.agree && r.solver_unknown();
  t.certificates += static_cast<uint64_t>(r.witnesses_checked());
  t.no_certified += (r.no_certificate == Check::Valid) + (r.cno_certificate == Check::Valid);
  if (r.agree) return true;
  ++t.disagreements;
  if (ev.disagreement) ev.disagreement(item.index, r);
  if (!item.found) return false;
  if (ev.finding) ev.finding(*item.found, item.shrunk);
  t.findings.push_back(std::move(*item.found));
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
  GRIDLOCK_ASSERT(c.step > 0, "a fuzz campaign needs a step");
  const uint64_t count = c.first < c.last ? (c.last - c.first - 1) / c.step + 1 : 0;
  std::vector<Verifier> verifiers(std::max(c.jobs, 1u));  // one per worker: its simulator's arrays are kept
  run_in_order(
      c.jobs, count,
      [&](uint64_t k, unsigned w) { return check_fuzz_formula(c, c.first + k * c.step, clock, verifiers[w]); },
      [&](uint64_t, FuzzItem& item) {
        if (!count_fuzz_formula(c, item, events, t)) return false;
        t.seconds = clock.elapsed();
        if (events.progress) events.progress(t);
        return true;
      });
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
  std::vector<size_t> items;  // the shard's formulas, in input order
  for (size_t i = 0; i < formulas.size(); ++i)
    if (c.shard.has(i)) items.push_back(i);
  std::vector<Verifier> verifiers(std::max(c.jobs, 1u));  // one per worker: its simulator's arrays are kept
  auto check = [&](uint64_t k, unsigned w) -> std::optional<VerifyResult> {
    const size_t i = items[k];
    VerifyResult r = verifiers[w].verify(formulas[i], names[i], c.verify);
    if (stop_requested()) return std::nullopt;  // its answers may be cut short: not counted
    return r;
  };
  auto take = [&](uint64_t k, VerifyResult& r) {
    const size_t i = items[k];
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
    return true;
  };
  std::function<void(uint64_t)> before;
  if (events.start) before = [&](uint64_t k) { events.start(items[k]); };
  run_in_order(c.jobs, items.size(), check, take, before);
  t.interrupted = stop_requested();
  return t;
}

}  // namespace gridlock
