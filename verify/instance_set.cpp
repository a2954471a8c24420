#include "verify/instance_set.hpp"

#include <algorithm>
#include <atomic>
#include <functional>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "certify/certify.hpp"
#include "cnf/dimacs.hpp"
#include "cnf/generate.hpp"
#include "cnf/sat_solver.hpp"
#include "common/assert.hpp"
#include "common/internal/ordered_pool.hpp"
#include "common/limits.hpp"
#include "lattice/grid_format.hpp"
#include "lattice/simulate.hpp"
#include "reductions/to_lsat.hpp"
#include "solver/continuous.hpp"
#include "solver/no_certificate.hpp"
#include "verify/fuzz.hpp"

namespace gridlock {

SetFormula random_set_formula(const std::string& kind, uint64_t seed, int vars, uint64_t j) {
  SetFormula s;
  s.seed = fuzz_formula_seed(seed, j + (kind == "lsat" ? 1'000'000'000ull : 0));
  if (kind == "threshold") {
    KSatParams k;
    k.n = vars;
    k.m = clauses_for_ratio(vars, 4.26);
    k.seed = s.seed;
    s.formula = random_ksat(k);
    s.origin = "random 3-SAT, n=" + std::to_string(vars) + ", m=" + std::to_string(k.m) + " (ratio 4.26)";
  } else {
    LsatParams l;
    l.n = vars;
    l.min_len = 1;
    l.max_len = 3;
    l.m = lsat_max_clauses(vars, 1);
    l.seed = s.seed;
    s.formula = random_lsat(l);
    s.origin = "random LSAT<=3, n=" + std::to_string(vars) + ", m=" + std::to_string(l.m);
  }
  s.name = kind + "-" + std::to_string(j + 1);
  return s;
}

namespace {

// The witness of a YES instance, checked by the simulator: the lifted model
// as an order of the couplings (NAME per line), or in the continuous model
// as start times (NAME TIME per line).
std::string certified_witness(const CompiledFormula& c, const std::vector<bool>& assignment, bool continuous,
                              const std::string& name) {
  Simulator sim(c.instance);
  std::string text;
  const auto& couplings = c.instance.couplings();
  if (continuous) {
    Schedule times = times_from_assignment(c, assignment);
    if (sim.run(times).collision)
      throw std::logic_error("the lifted start times of " + name + " collide: the reduction is wrong here");
    for (CouplingId q = 0; q < couplings.size(); ++q) text += couplings[q].name + " " + times.start[q].str() + "\n";
  } else {
    std::vector<CouplingId> order = schedule_from_assignment(c, assignment);
    if (sim.run_order(order).collision)
      throw std::logic_error("the lifted schedule of " + name + " collides: the reduction is wrong here");
    for (CouplingId q : order) text += couplings[q].name + "\n";
  }
  return text;
}

// One instance of a labelled formula, ready to store: its entry and its
// files (witness and NO certificate first, the .grid last).
struct ReadyInstance {
  SetInstance entry;
  std::vector<std::pair<std::string, std::string>> files;
};

// What a worker makes of one formula: CaDiCaL's label and, unless the
// formula is skipped or surely unwanted, its instances.
struct LabelledFormula {
  Verdict status = Verdict::Unknown;
  std::string name, formula_text;
  std::vector<ReadyInstance> instances;  // empty when skipped or unwanted
};

// The labelling of one formula, the workers' part (common/internal/ordered_pool.hpp):
// pure but for the kept counts, which it only reads as a hint (they grow
// only, so a formula of an answer already full when the worker looks is
// unwanted when its turn comes too, and is not compiled).
class FormulaLabeller {
 public:
  FormulaLabeller(const InstanceSetPlan& plan, const std::atomic<int>& yes_kept, const std::atomic<int>& no_kept)
      : plan_(plan), yes_kept_(yes_kept), no_kept_(no_kept) {}

  // Nullopt when a stop request may have cut the labelling short.
  std::optional<LabelledFormula> label(const SetFormula& s, bool random, uint64_t index) const {
    LabelledFormula out;
    out.name = s.name;
    SatLimits limits;
    limits.seconds = plan_.sat_seconds;
    SatResult sat = solve_sat(s.formula, limits);
    if (stop_requested()) return std::nullopt;
    out.status = sat.status;
    if (sat.status == Verdict::Unknown) return out;
    const bool yes = sat.status == Verdict::Yes;
    if (random && plan_.mix() && surely_unwanted(yes)) return out;
    LsatReduction red = reduce_to_lsat(s.formula);
    out.formula_text = to_dimacs(s.formula);
    for (TimeModel model : plan_.models) out.instances.push_back(make(s, red, sat, model, index));
    if (stop_requested()) return std::nullopt;
    return out;
  }

 private:
  bool surely_unwanted(bool yes) const {
    return yes ? plan_.want_yes >= 0 && yes_kept_.load(std::memory_order_relaxed) >= plan_.want_yes
               : plan_.want_no >= 0 && no_kept_.load(std::memory_order_relaxed) >= plan_.want_no;
  }

  ReadyInstance make(const SetFormula& s, const LsatReduction& red, const SatResult& sat, TimeModel model,
                     uint64_t index) const {
    const bool cont = model == TimeModel::Continuous;
    ReadyInstance ready;
    SetInstance& e = ready.entry;
    e.index = index;
    e.name = s.name + (cont && plan_.models.size() == 2 ? "-continuous" : "");  // both models: a suffix
    e.model = model;
    e.formula_file = s.name + ".cnf";
    e.instance_file = e.name + ".grid";
    e.origin = s.origin;
    e.seed = s.seed;
    e.variables = s.formula.num_vars;
    e.clauses = s.formula.clauses.size();
    e.lsat_variables = red.output().num_vars;
    e.lsat_clauses = red.output().clauses.size();
    CompiledFormula c = compile_formula(red.output(), Mutation::None, model);
    e.nodes = c.stats.nodes;
    e.operations = c.stats.ops;
    e.couplings = c.stats.couplings;
    e.max_coupling = c.stats.max_coupling;
    e.yes = sat.status == Verdict::Yes;
    if (e.yes) {
      e.certificate_file = e.name + (cont ? ".times" : ".schedule");
      ready.files.emplace_back(e.certificate_file, certified_witness(c, red.lift_to_target(sat.model), cont, e.name));
    }
    if (!e.yes && !cont && plan_.no_certificates) write_no_certificate(c.instance, ready);
    if (!e.yes && cont && plan_.no_certificates) confirm_continuous_no(c.instance, ready);
    std::ostringstream grid;
    write_instance(grid, c.instance,
                   {e.name + ": " + s.origin, std::string("model: ") + time_model_name(model),
                    std::string("answer: ") + (e.yes ? "YES" : "NO")});
    ready.files.emplace_back(e.instance_file, grid.str());
    return ready;
  }

  // The solver's NO certificate, checked by the independent checker, as
  // NAME.nocert. None if the solver hits plan_.solve_seconds.
  void write_no_certificate(const Instance& inst, ReadyInstance& ready) const {
    SetInstance& e = ready.entry;
    const PreparedInstance prep(inst);
    SolveOptions opt;
    opt.seconds = plan_.solve_seconds;
    const CertifiedSolve cs = solve_discrete_certified(prep, opt);
    if (cs.result.status == Verdict::Unknown) return;
    if (cs.result.status != Verdict::No)
      throw std::logic_error(e.name + ": the exact solver finds a schedule for an unsatisfiable formula");
    const CertifyResult r = certify(inst, cs.certificate, "discrete");
    if (!r.proved) throw std::logic_error(e.name + ": the NO certificate is rejected: " + r.reason);
    e.no_certificate_file = e.name + ".nocert";
    ready.files.emplace_back(e.no_certificate_file, cs.certificate);
  }

  // The exact continuous solver must prove the label too, within
  // plan_.solve_seconds (e.solver_check says whether it did), and its NO
  // certificate, checked by the independent checker, becomes NAME.nocert.
  void confirm_continuous_no(const Instance& inst, ReadyInstance& ready) const {
    SetInstance& e = ready.entry;
    SolveOptions opt;
    opt.seconds = plan_.solve_seconds;
    const CertifiedContinuous cc = solve_continuous_certified(inst, opt);
    if (cc.result.status == Verdict::Yes)
      throw std::logic_error(e.name + ": the exact continuous solver finds start times for an unsatisfiable formula");
    e.solver_check = cc.result.status == Verdict::No ? "NO" : "UNKNOWN";
    if (cc.certificate.empty()) return;
    const CertifyResult r = certify(inst, cc.certificate, "continuous");
    if (!r.proved) throw std::logic_error(e.name + ": the continuous NO certificate is rejected: " + r.reason);
    e.no_certificate_file = e.name + ".nocert";
    ready.files.emplace_back(e.no_certificate_file, cc.certificate);
  }

  const InstanceSetPlan& plan_;
  const std::atomic<int>& yes_kept_;
  const std::atomic<int>& no_kept_;
};

// The set being made: formulas labelled on plan.jobs workers, stored (files
// written, tally counted, events called) on the calling thread in set order.
class SetMaker {
 public:
  SetMaker(const InstanceSetPlan& plan, const InstanceSetEvents& events)
      : plan_(plan), ev_(events), labeller_(plan, yes_kept_, no_kept_) {}

  // Labels the formulas formula(j) for j in js, in order (name(j): the
  // formula's name, for the progress line), storing those in the set; with
  // limit > 0, until that many are stored.
  template <class Formulas, class Names>
  void run(const std::vector<uint64_t>& js, Formulas formula, Names name, bool random, uint64_t offset, int limit) {
    int made = 0;
    auto work = [&](uint64_t k, unsigned) { return labeller_.label(formula(js[k]), random, offset + js[k]); };
    auto take = [&](uint64_t, LabelledFormula& l) {
      made += store(l, random);
      return limit <= 0 || made < limit;
    };
    std::function<void(uint64_t)> before;
    if (ev_.labelling) before = [&](uint64_t k) { ev_.labelling(name(js[k]), tally_); };
    run_in_order(plan_.jobs, js.size(), work, take, before);
  }

  InstanceSetTally& tally() { return tally_; }

 private:
  // Stores a labelled formula; false if it is not in the set (skipped, or
  // not wanted by want_*).
  bool store(const LabelledFormula& l, bool random) {
    if (ev_.labelled) ev_.labelled();
    if (l.status == Verdict::Unknown) {
      ++tally_.skipped;
      if (ev_.skipped) ev_.skipped(l.name);
      return false;
    }
    const bool yes = l.status == Verdict::Yes;
    if (random && plan_.mix() &&
        ((yes && plan_.want_yes >= 0 && tally_.yes >= plan_.want_yes) ||
         (!yes && plan_.want_no >= 0 && tally_.no >= plan_.want_no)))
      return false;
    GRIDLOCK_ASSERT(l.instances.size() == plan_.models.size(), "a wanted formula comes with its instances");
    ev_.write(l.name + ".cnf", l.formula_text);  // the formula before its instances
    for (const ReadyInstance& ready : l.instances) {
      for (const auto& [file, text] : ready.files) ev_.write(file, text);
      tally_.instances.push_back(ready.entry);
      if (ev_.instance) ev_.instance(tally_.instances.back());
    }
    (yes ? tally_.yes : tally_.no) += 1;
    (yes ? yes_kept_ : no_kept_).store(yes ? tally_.yes : tally_.no, std::memory_order_relaxed);
    return true;
  }

  const InstanceSetPlan& plan_;
  const InstanceSetEvents& ev_;
  std::atomic<int> yes_kept_{0}, no_kept_{0};  // tally_'s counts, for the workers' hint
  FormulaLabeller labeller_;
  InstanceSetTally tally_;
};

}  // namespace

InstanceSetTally make_instance_set(const InstanceSetPlan& plan, const InstanceSetEvents& events) {
  SetMaker maker(plan, events);
  std::vector<uint64_t> given;
  for (uint64_t i = 0; i < plan.given.size(); ++i)
    if (plan.shard.has(i)) given.push_back(i);
  maker.run(
      given, [&](uint64_t i) -> const SetFormula& { return plan.given[i]; },
      [&](uint64_t i) { return plan.given[i].name; }, false, 0, 0);
  // The random formulas of a kind: count of them, or with want_* drawn
  // until the counts are met (at most 100 * count attempts).
  auto draw = [&](const std::string& kind, int count, uint64_t offset) {
    if (count <= 0 || stop_requested()) return;
    const uint64_t attempts = static_cast<uint64_t>(plan.mix() ? 100 * std::max(count, 1) : count);
    std::vector<uint64_t> js;
    for (uint64_t j = 0; j < attempts; ++j)
      if (plan.shard.has(offset + j)) js.push_back(j);
    maker.run(
        js, [&](uint64_t j) { return random_set_formula(kind, plan.seed, plan.vars, j); },
        [&](uint64_t j) { return kind + "-" + std::to_string(j + 1); }, true, offset, count);
  };
  if (!stop_requested()) draw("threshold", plan.threshold, plan.given.size());
  draw("lsat", plan.lsat, plan.given.size() + static_cast<uint64_t>(plan.threshold));
  maker.tally().interrupted = stop_requested();
  return maker.tally();
}

}  // namespace gridlock
