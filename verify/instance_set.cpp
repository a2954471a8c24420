#include "verify/instance_set.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "certify/certify.hpp"
#include "cnf/dimacs.hpp"
#include "cnf/generate.hpp"
#include "cnf/sat_solver.hpp"
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

class SetMaker {
 public:
  SetMaker(const InstanceSetPlan& plan, const InstanceSetEvents& events) : plan_(plan), ev_(events) {}

  // Labels one formula and stores its instances; false if it is not in the
  // set (skipped, stopped, or not wanted by want_*).
  bool label(const SetFormula& s, bool random, uint64_t index) {
    if (ev_.labelling) ev_.labelling(s.name, tally_);
    SatLimits limits;
    limits.seconds = plan_.sat_seconds;
    SatResult sat = solve_sat(s.formula, limits);
    if (ev_.labelled) ev_.labelled();
    if (stop_requested()) return false;
    if (sat.status == Verdict::Unknown) {
      ++tally_.skipped;
      if (ev_.skipped) ev_.skipped(s.name);
      return false;
    }
    const bool yes = sat.status == Verdict::Yes;
    if (random && plan_.mix() &&
        ((yes && plan_.want_yes >= 0 && tally_.yes >= plan_.want_yes) ||
         (!yes && plan_.want_no >= 0 && tally_.no >= plan_.want_no)))
      return false;
    LsatReduction red = reduce_to_lsat(s.formula);
    ev_.write(s.name + ".cnf", to_dimacs(s.formula));  // the formula before its instances
    for (ReductionModel model : plan_.models) store(s, red, sat, model, index);
    (yes ? tally_.yes : tally_.no) += 1;
    return true;
  }

  // Draws the random formulas of a kind (count of them, or with want_*
  // until the counts are met), whose set indices start at offset.
  void draw(const std::string& kind, int count, uint64_t offset) {
    int made = 0;
    const int limit = plan_.mix() ? 100 * std::max(count, 1) : count;  // attempts
    for (int j = 0; j < limit && made < count && !stop_requested(); ++j) {
      const uint64_t jj = static_cast<uint64_t>(j);
      if (!plan_.shard.has(offset + jj)) continue;
      made += label(random_set_formula(kind, plan_.seed, plan_.vars, jj), true, offset + jj);
    }
  }

  InstanceSetTally& tally() { return tally_; }

 private:
  void store(const SetFormula& s, const LsatReduction& red, const SatResult& sat, ReductionModel model,
             uint64_t index) {
    const bool cont = model == ReductionModel::Continuous;
    SetInstance e;
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
      ev_.write(e.certificate_file, certified_witness(c, red.lift_to_target(sat.model), cont, e.name));
    }
    if (!e.yes && !cont && plan_.no_certificates) write_no_certificate(c.instance, e);
    if (!e.yes && cont && plan_.no_certificates) confirm_continuous_no(c.instance, e);
    std::ostringstream grid;
    write_instance(grid, c.instance,
                   {e.name + ": " + s.origin, std::string("model: ") + reduction_model_name(model),
                    std::string("answer: ") + (e.yes ? "YES" : "NO")});
    ev_.write(e.instance_file, grid.str());
    tally_.instances.push_back(e);
    if (ev_.instance) ev_.instance(tally_.instances.back());
  }

  // The solver's NO certificate, checked by the independent checker, as
  // NAME.nocert. None if the solver hits plan_.solve_seconds.
  void write_no_certificate(const Instance& inst, SetInstance& e) {
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
    ev_.write(e.no_certificate_file, cs.certificate);
  }

  // The exact continuous solver must prove the label too, within
  // plan_.solve_seconds (e.solver_check says whether it did), and its NO
  // certificate, checked by the independent checker, becomes NAME.nocert.
  void confirm_continuous_no(const Instance& inst, SetInstance& e) {
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
    ev_.write(e.no_certificate_file, cc.certificate);
  }

  const InstanceSetPlan& plan_;
  const InstanceSetEvents& ev_;
  InstanceSetTally tally_;
};

}  // namespace

InstanceSetTally make_instance_set(const InstanceSetPlan& plan, const InstanceSetEvents& events) {
  SetMaker maker(plan, events);
  for (size_t i = 0; i < plan.given.size() && !stop_requested(); ++i)
    if (plan.shard.has(i)) maker.label(plan.given[i], false, i);
  maker.draw("threshold", plan.threshold, plan.given.size());
  maker.draw("lsat", plan.lsat, plan.given.size() + static_cast<uint64_t>(plan.threshold));
  maker.tally().interrupted = stop_requested();
  return maker.tally();
}

}  // namespace gridlock
