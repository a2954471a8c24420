#include "solver/solve.hpp"

#include <optional>
#include <stdexcept>

#include "lattice/motion.hpp"
#include "lattice/simulate.hpp"
#include "solver/internal/constraints.hpp"
#include "solver/internal/search.hpp"

namespace gridlock {

namespace {

// Never a silent wrong answer: a YES order must be a permutation that the
// constraint system and the exact simulator both accept (else logic_error).
// A limit during the simulation turns the answer into Unknown.
void confirm_yes(const PreparedInstance& prep, const ConstraintSystem& sys, SearchBudget& budget, Simulator* replay,
                 SolveResult& res) {
  const Instance& inst = prep.inst;
  std::vector<char> seen(inst.couplings().size(), 0);
  if (res.order.size() != seen.size()) throw std::logic_error("solver returned an incomplete order");
  for (CouplingId q : res.order) {
    if (q >= seen.size() || seen[q]) throw std::logic_error("solver returned an order that is not a permutation");
    seen[q] = 1;
  }
  if (replay_order(sys, res.order).failed_step != res.order.size())
    throw std::logic_error("solver returned an order its own constraints reject");
  std::optional<Simulator> own;
  if (!replay || &replay->prepared() != &prep) replay = &own.emplace(prep);
  Simulator& sim = *replay;
  sim.set_deadline(&budget.deadline());  // --timeout covers the final check too
  SimResult check;
  try {
    check = sim.run_order(res.order);
  } catch (const LimitReached&) {
    sim.set_deadline(nullptr);
    res.status = Verdict::Unknown;
    res.order.clear();
    return;
  }
  sim.set_deadline(nullptr);
  if (check.collision)
    throw std::logic_error("solver returned an order that collides in the simulator: " +
                           describe(inst, sim.regions(), *check.collision));
}

}  // namespace

SolveResult solve_discrete(const Instance& inst, const SolveOptions& opt) {
  const PreparedInstance prep(inst);
  return solve_discrete(prep, opt);
}

SolveResult solve_discrete(const PreparedInstance& prep, const SolveOptions& opt, Simulator* replay) {
  std::optional<ConstraintSystem> kept;
  return solve_discrete_kept(prep, opt, replay, kept);
}

SolveResult solve_discrete_kept(const PreparedInstance& prep, const SolveOptions& opt, Simulator* replay,
                                std::optional<ConstraintSystem>& kept) {
  const Instance& inst = prep.inst;
  SearchBudget budget(opt);
  SolveResult res;
  const bool horizontal = inst.horizontal_only();
  using Engine = SolveOptions::Engine;
  if (opt.engine == Engine::Precedence && !horizontal)
    throw std::invalid_argument("the precedence search needs a horizontal-only instance");
  if (opt.engine == Engine::Sat && !horizontal)
    throw std::invalid_argument("the SAT engine needs a horizontal-only instance");

  // A coupling that breaks a cycle collides whenever it runs.
  const FaceNets& faces = prep.faces;
  for (CouplingId q = 0; q < inst.couplings().size(); ++q)
    if (faces.coupling_breaks_cycle[q]) {
      res.status = Verdict::No;
      res.cycle_breaker = q;
      res.stats.engine = "cycle";
      res.stats.seconds = budget.elapsed();
      return res;
    }

  const Engine engine = opt.engine != Engine::Auto ? opt.engine : horizontal ? Engine::Sat : Engine::Pairs;
  res.stats.engine = engine == Engine::Precedence ? "precedence"
                     : engine == Engine::Sat      ? "sat"
                     : engine == Engine::Pairs    ? "pairs"
                                                  : "states";
  static const ConstraintSystem kNoSystem;
  const ConstraintSystem* built = kept ? &*kept : &kNoSystem;  // replay_order below reads it
  try {
    budget.check();
    if (!kept)
      built = &kept.emplace(horizontal ? build_gap_constraints(prep, &budget.deadline())
                                       : build_pair_constraints(prep, &budget.deadline(), /*stop_at_refuting=*/true));
    const ConstraintSystem& sys = *built;
    res.stats.constraints = sys.constraints.size();
    if (sys.refuting != kNone) {
      const CollisionConstraint& c = sys.constraints[sys.refuting];
      res.status = Verdict::No;
      res.lone_collider = c.rel[0];
      res.lone_pair = constraint_label(inst, prep.regions, c);
      res.stats.seconds = budget.elapsed();
      budget.clear_progress();
      return res;
    }
    SearchOutcome out = engine == Engine::Precedence ? search_precedence(sys, budget, res.stats, opt.precedence_hooks)
                        : engine == Engine::Sat      ? search_sat(sys, budget, res.stats)
                        : engine == Engine::Pairs    ? search_pairs(sys, budget, res.stats)
                                                     : search_states(sys, budget, res.stats);
    res.status = out.status;
    res.order = std::move(out.order);
  } catch (const LimitReached&) {
    res.status = Verdict::Unknown;
    res.order.clear();
  }
  budget.clear_progress();

  if (res.status == Verdict::Yes) confirm_yes(prep, *built, budget, replay, res);
  res.stats.seconds = budget.elapsed();
  return res;
}

}  // namespace gridlock
