#include "collide/collide.hpp"

#include <algorithm>
#include <functional>
#include <stdexcept>
#include <string>

#include "collide/internal/collide_pairs.hpp"
#include "collide/internal/collide_tree.hpp"
#include "collide/single_coupling.hpp"
#include "common/clock.hpp"

namespace gridlock {

namespace {

// An order: `first` (in the given order, without repeats), then every other
// coupling by id.
std::vector<CouplingId> order_starting_with(const Instance& inst, const std::vector<CouplingId>& first) {
  std::vector<char> used(inst.couplings().size(), 0);
  std::vector<CouplingId> order;
  for (CouplingId q : first)
    if (!used[q]) used[q] = 1, order.push_back(q);
  for (CouplingId q = 0; q < used.size(); ++q)
    if (!used[q]) order.push_back(q);
  return order;
}

bool all_singletons(const Instance& inst) {
  for (const Coupling& c : inst.couplings())
    if (c.ops.size() != 1) return false;
  return true;
}

// res completed as a collision with witness s, which the simulator must
// confirm (logic_error otherwise).
CollideResult finish_with(CollideResult& res, Simulator& sim, Schedule s) {
  res.collides = true;
  res.witness = std::move(s);
  SimResult run = sim.run(res.witness);
  if (!run.collision)
    throw std::logic_error("collide (" + res.algorithm + "): the witness schedule does not collide in the simulator");
  res.simulated = run.collision;
  return res;
}

// A one-coupling YES that names its first collision (the one-axis test and
// the sweep do, docs/collide.md): the simulator's configuration at a
// moment inside the pair's overlap confirms that the witness collides
// (logic_error otherwise). O(n) where simulating this motion costs up to
// Theta(n^2) (a row whose expansions share the coupling; the diagonal
// sweep's broad phase).
CollideResult finish_named(CollideResult& res, const Instance& inst, const SingleCouplingAnswer& ans) {
  res.collides = true;
  res.witness = schedule_from_order({0});
  const std::vector<RectQ> at = configuration_at(inst, res.witness, *ans.during);
  const RectQ &A = at[ans.pair->a], &B = at[ans.pair->b];
  if (!(std::max(A.xlo, B.xlo) < std::min(A.xhi, B.xhi) && std::max(A.ylo, B.ylo) < std::min(A.yhi, B.yhi)))
    throw std::logic_error("collide (" + res.algorithm + "): the predicted pair does not overlap at time " +
                           ans.during->str() + " in the simulator's configuration");
  Collision c;
  c.kind = Collision::Kind::Node;
  c.time = *ans.first;
  c.a = ans.pair->a, c.b = ans.pair->b;
  c.moving = {0};
  res.simulated = c;
  res.checked_at = ans.during;
  return res;
}

// Turns a step's (done, total) into at most four CollideProgress reports a
// second, plus every report with done == total.
class Reporter {
 public:
  explicit Reporter(const CollideProgressFn& fn) : fn_(fn) {}
  // The (done, total) callback of one step; empty without a listener.
  std::function<void(uint64_t, uint64_t)> step(const std::string& name) {
    if (!fn_) return {};
    return [this, name](uint64_t done, uint64_t total) { report(name, done, total); };
  }
  void report(const std::string& name, uint64_t done, uint64_t total) {
    if (!fn_) return;
    const double t = clock_.seconds();
    if (done < total && last_ >= 0 && t - last_ < 0.25) return;
    last_ = t;
    fn_(CollideProgress{name, done, total, t});
  }

 private:
  const CollideProgressFn& fn_;
  Stopwatch clock_;
  double last_ = -1;
};

// Step 3, no couplings: the centroid algorithm (or, for TreePairwise, its
// all-pairs twin naming the pair and the centroid run giving the witness).
CollideResult tree_step(const Instance& inst, Simulator& sim, CollideMethod method, CollideResult& res,
                        const Deadline* deadline) {
  std::optional<TreeCollision> tc;
  if (method == CollideMethod::TreePairwise) {
    res.algorithm = "tree-pairwise";
    res.complexity = "O(n^2)";
    tc = tree_collision_pairwise(inst, sim.tree(), sim.regions(), deadline);
  } else {
    res.algorithm = "tree-centroid";
    res.complexity = "O(n log^2 n)";
    TreeStats ts;
    tc = tree_collision(inst, sim.tree(), sim.regions(), &ts);
    res.stats.levels = ts.levels;
    res.stats.rectangles = ts.rectangles;
  }
  if (!tc) return res;
  res.region_a = tc->a, res.region_b = tc->b;
  if (method == CollideMethod::TreePairwise) {
    // The twin only names the pair; the witness comes from the centroid run.
    auto again = tree_collision(inst, sim.tree(), sim.regions());
    if (!again) throw std::logic_error("collide: the tree twins disagree");
    tc = again;
  }
  std::vector<CouplingId> first;
  for (OpId k : tc->done) first.push_back(inst.ops()[k].coupling);
  return finish_with(res, sim, schedule_from_order(order_starting_with(inst, first)));
}

// The continuous witness for progresses p at time 1: q starts at 1 - p_q;
// the nq couplings that do not move the pair start after time 1.
Schedule schedule_reaching(size_t nq, const std::vector<std::pair<CouplingId, Rational>>& progress) {
  Schedule s;
  s.start.assign(nq, Rational(0));
  std::vector<char> set(nq, 0);
  for (const auto& [q, p] : progress) s.start[q] = Rational(1) - p, set[q] = 1;
  int64_t later = 2;
  for (CouplingId q = 0; q < nq; ++q)
    if (!set[q]) s.start[q] = Rational(later++);
  return s;
}

// How the continuous model decides all pairs: couplings of at most 3
// operations give at most 6 non-axis directions, so the support table is
// O(1) per step and pair (proven O(n^2), and faster by a constant); larger
// couplings take the paper's angle tree, O(n^2 log^2 n) (docs/collide.md,
// "The angle tree").
struct ContinuousPairs {
  ZonotopeTest ztest;
  const char* algorithm;
  const char* complexity;
};
ContinuousPairs continuous_pairs(const Instance& inst) {
  size_t largest = 0;
  for (const Coupling& c : inst.couplings()) largest = std::max(largest, c.ops.size());
  if (largest > 3)
    return {ZonotopeTest::AngleTree, "pairwise-angle-tree",
            "O(n^2 log^2 n) (AVL tree sorted by angle, one fan search per pair)"};
  return {ZonotopeTest::Incremental, "pairwise-zonotope",
          "O(n^2) (couplings of <= 3 operations: <= 6 directions in the support table)"};
}

const char* const kSubsetSumComplexity =
    "O(n^2 (c^2 A + c L^2)) <= O(n^(16/3)) for c distinct vectors, grid area A, L operations per path";

void add_pair_stats(CollideResult& res, const PairwiseStats& ps) {
  res.stats.pairs += ps.pairs;
  res.stats.full_tests += ps.full_tests;
}

// A discrete collision found by the pair tests, as an order: the done
// set, then the running coupling, then the rest.
CollideResult finish_discrete(CollideResult& res, Simulator& sim, const Instance& inst, const PairCollision& pc) {
  res.region_a = pc.a, res.region_b = pc.b;
  std::vector<CouplingId> first = pc.witness.done;
  if (pc.witness.running != kNone) first.push_back(pc.witness.running);
  return finish_with(res, sim, schedule_from_order(order_starting_with(inst, first)));
}

// The continuous pair tests that decide an instance with couplings under
// Auto: on one axis only the group pairs (one_axis_group_pairs, O(n) pairs,
// O(n sqrt n) steps of the ends), else every pair (continuous_pairs). Sets
// res's algorithm and complexity.
std::optional<PairCollision> continuous_decider(const Instance& inst, Simulator& sim, CollideResult& res,
                                                const Deadline* deadline, Reporter& progress) {
  PairwiseStats ps;
  std::optional<PairCollision> pc;
  if (auto groups = one_axis_group_pairs(inst, sim.regions())) {
    res.algorithm = "one-axis-groups";
    res.complexity = "O(n log n + n sqrt n) (one axis: O(n) group pairs, ends walked in Mo's order)";
    pc = listed_pairs_collision(inst, sim.tree(), sim.regions(), TimeModel::Continuous, *groups, &ps, deadline);
  } else {
    const ContinuousPairs cp = continuous_pairs(inst);
    res.algorithm = cp.algorithm;
    res.complexity = cp.complexity;
    pc = pairwise_collision(inst, sim.tree(), sim.regions(), TimeModel::Continuous, &ps, deadline, cp.ztest,
                            progress.step(res.algorithm));
    if (!pc) progress.report(res.algorithm, inst.num_nodes(), inst.num_nodes());
  }
  add_pair_stats(res, ps);
  return pc;
}

// Steps 4/5, couplings: all pairs, exact per-pair tests in the model's
// sense (the continuous tests, or the discrete subset sums); continuous
// under Auto, continuous_decider.
CollideResult pairwise_step(const Instance& inst, Simulator& sim, TimeModel model, CollideMethod method,
                            CollideResult& res, const Deadline* deadline, Reporter& progress) {
  if (model == TimeModel::Continuous && method == CollideMethod::Auto) {
    auto pc = continuous_decider(inst, sim, res, deadline, progress);
    if (!pc) return res;
    res.region_a = pc->a, res.region_b = pc->b;
    return finish_with(res, sim, schedule_reaching(inst.couplings().size(), pc->witness.progress));
  }
  PairwiseStats ps;
  const ContinuousPairs cp = continuous_pairs(inst);
  if (model == TimeModel::Continuous) {
    res.algorithm = cp.algorithm;
    res.complexity = cp.complexity;
  } else {
    res.algorithm = "pairwise-subset-sum";
    res.complexity = kSubsetSumComplexity;
  }
  auto pc = pairwise_collision(inst, sim.tree(), sim.regions(), model, &ps, deadline,
                               model == TimeModel::Continuous ? cp.ztest : ZonotopeTest::Incremental,
                               progress.step(res.algorithm));
  add_pair_stats(res, ps);
  if (!pc) {
    progress.report(res.algorithm, inst.num_nodes(), inst.num_nodes());
    return res;
  }
  if (model == TimeModel::Discrete) return finish_discrete(res, sim, inst, *pc);
  res.region_a = pc->a, res.region_b = pc->b;
  return finish_with(res, sim, schedule_reaching(inst.couplings().size(), pc->witness.progress));
}

// Step 5 under Auto: the discrete answer is the continuous one (proven:
// docs/collide.md, "Colliding Schedule: the models agree"), so the
// continuous pair tests decide it, and a NO costs what it costs there.
// After a YES on regions (a, b) the discrete witness is searched from the
// nodes that the faces of a and b follow only (the proof's colliding pair
// has one of them: O(n) pairs by subset sums); all pairs only if that finds nothing
// (counted in witness_fallbacks; never seen). If even all pairs find
// nothing, the exact discrete answer NO is returned: the theorem would be
// wrong on this instance, and collide_no_certificate says so.
CollideResult discrete_by_continuous_step(const Instance& inst, Simulator& sim, CollideResult& res,
                                          const Deadline* deadline, Reporter& progress) {
  auto pc = continuous_decider(inst, sim, res, deadline, progress);
  const std::string decided_in = res.complexity;
  res.complexity += "; the discrete answer is the continuous one (the models agree)";
  if (!pc) return res;
  res.algorithm += "+subset-sum";
  res.complexity = decided_in +
                   ", then the discrete witness by subset sums from the pair's nodes: O(n (c^2 A + c L^2))";
  const std::vector<uint32_t> around{pc->a, pc->b};
  PairwiseStats ws;
  auto dc = pairwise_collision(inst, sim.tree(), sim.regions(), TimeModel::Discrete, &ws, deadline,
                               ZonotopeTest::Incremental, progress.step("subset-sum-witness"), {}, &around);
  add_pair_stats(res, ws);
  if (!dc) {
    ++res.stats.witness_fallbacks;
    res.algorithm = "pairwise-subset-sum";
    res.complexity = kSubsetSumComplexity;
    PairwiseStats all;
    dc = pairwise_collision(inst, sim.tree(), sim.regions(), TimeModel::Discrete, &all, deadline,
                            ZonotopeTest::Incremental, progress.step(res.algorithm));
    add_pair_stats(res, all);
    if (!dc) return res;
  }
  return finish_discrete(res, sim, inst, *dc);
}

// The algorithm and bound of a fixed-axis answer: one group keeping an
// order, or several separated groups.
void name_fixed_axis(const FixedAxisAnswer& fixed, CollideResult& res) {
  if (fixed.groups == 1) {
    res.algorithm = "single-coupling-fixed-axis";
    res.complexity =
        "O(n log n) (the faces of one axis keep their order: one sweep along it; a YES bisects for its first "
        "moment)";
    return;
  }
  res.algorithm = "single-coupling-separated";
  res.complexity = "O(n log n) per level of cuts (" + std::to_string(fixed.groups) +
                   " groups that never meet, each keeping the order of one axis: one sweep each; a YES bisects "
                   "for its first moment)";
}

// 2. One coupling (Auto): the one schedule, decided as find_collision's
// comment says; res is filled and returned.
CollideResult single_coupling_step(const Instance& inst, Simulator& sim, CollideResult& res, const Deadline* deadline,
                                   Reporter& progress) {
  std::optional<SingleCouplingAnswer> answer = single_coupling_one_axis(inst, sim.tree(), sim.regions(),
                                                                        &res.stats.pair_tests);
  SingleCouplingStats st;
  if (answer) {
    res.algorithm = "single-coupling-one-axis";
    res.complexity = "O(n log n) (one axis: neighbours in each row at t = 0)";
  } else if (std::optional<FixedAxisAnswer> fixed = single_coupling_fixed_axis(inst, sim.tree(), sim.regions(),
                                                                               deadline)) {
    name_fixed_axis(*fixed, res);
    res.stats.pair_tests = fixed->tests;
    answer = fixed->answer;
  } else if (std::optional<TimeSlabAnswer> slabs = single_coupling_time_slabs(inst, sim.tree(), sim.regions(),
                                                                              deadline)) {
    res.algorithm = "single-coupling-time-slabs";
    res.complexity = "O(W log n) (pieces no cut separates over (0, 1), cut over " + std::to_string(slabs->slabs) +
                     " time slabs down to 2^-" + std::to_string(slabs->finest) + " into " +
                     std::to_string(slabs->groups) + " groups, W = " + std::to_string(slabs->work) +
                     " members placed; a YES bisects for its first moment)";
    res.stats.pair_tests = slabs->tests;
    answer = slabs->answer;
  } else if (std::optional<MotionClassAnswer> classes = single_coupling_motion_classes(inst, sim.tree(), sim.regions(),
                                                                                       deadline)) {
    res.algorithm = "single-coupling-motion-classes";
    res.complexity = "O(k n log n) (a piece no cut separates, in k motion classes: " +
                     std::to_string(classes->classes) +
                     "; one strip query per class pair and strip; a YES bisects for its first moment)";
    res.stats.pair_tests = classes->tests;
    answer = classes->answer;
  } else {
    res.algorithm = "single-coupling";
    res.complexity = "O(n + mu log mu), mu = total motion (sum of |speeds|)";
    answer = single_coupling_sweep(inst, sim.tree(), sim.regions(), &st, deadline, kSingleCouplingBandItems,
                                   progress.step(res.algorithm));
    res.stats.cell_items = st.items;
    res.stats.pair_tests = st.tests;
  }
  const SingleCouplingAnswer& ans = *answer;
  if (!ans.collides) {
    if (st.bands) progress.report(res.algorithm, st.bands, st.bands);
    return res;
  }
  if (ans.pair) res.region_a = ans.pair->a, res.region_b = ans.pair->b;
  if (ans.first) return finish_named(res, inst, ans);
  finish_with(res, sim, schedule_from_order({0}));
  if (!ans.pair && res.simulated->kind == Collision::Kind::Node)  // decided by packing: the simulator names the pair
    res.region_a = res.simulated->a, res.region_b = res.simulated->b;
  return res;
}

}  // namespace

CollideResult find_collision(const Instance& inst, TimeModel model, CollideMethod method, const Deadline* deadline,
                             const CollideProgressFn& on_progress) {
  const PreparedInstance prep(inst);
  return find_collision(prep, model, method, deadline, on_progress);
}

CollideResult find_collision(const PreparedInstance& prep, TimeModel model, CollideMethod method,
                             const Deadline* deadline, const CollideProgressFn& on_progress) {
  Reporter progress(on_progress);
  const Instance& inst = prep.inst;
  CollideResult res;
  Simulator sim(prep);
  sim.set_deadline(deadline);
  const size_t nq = inst.couplings().size();

  if (nq == 0) {
    res.algorithm = "no-operations";
    res.complexity = "O(1)";
    return res;
  }

  // 1. Cycle collisions: a coupling with a non-zero net around a face walk.
  const FaceNets& faces = sim.faces();
  if (!faces.faces.empty()) {
    const auto& f = faces.faces.front();
    res.algorithm = "cycle";
    res.complexity = "O(n + e log e)";
    res.cycle = f.walk;
    return finish_with(res, sim, schedule_from_order(order_starting_with(inst, {f.nets.front().first})));
  }

  // 2. One coupling: one schedule in both models, decided by one sort per
  // row when every operation is on one axis (O(n log n)), by one sweep
  // along an axis whose faces keep their order (O(n log n) for a NO; a
  // YES bisects for its first moment), else by the space-time cell sweep
  // (single_coupling.hpp); a piece that keeps neither order and has no
  // cut is split into time slabs, over which it may have cuts, else
  // decided by motion classes when they cost no more than the motion.
  // All YES name the first collision, checked at one moment; a YES of
  // the cell sweep's packing bound names none and is simulated.
  if (method == CollideMethod::Auto && nq == 1) return single_coupling_step(inst, sim, res, deadline, progress);

  // 3. No couplings: the centroid algorithm (or its all-pairs twin).
  bool tree_ok = all_singletons(inst);
  if ((method == CollideMethod::Tree || method == CollideMethod::TreePairwise) && !tree_ok)
    throw std::invalid_argument("collide: the tree algorithm needs an instance without couplings");
  if (method == CollideMethod::Tree || method == CollideMethod::TreePairwise ||
      (method == CollideMethod::Auto && tree_ok))
    return tree_step(inst, sim, method, res, deadline);

  // 4./5. Couplings: all pairs, exact per-pair tests (Auto, discrete: the
  // continuous tests decide, the subset sums give the witness).
  if (model == TimeModel::Discrete && method == CollideMethod::Auto)
    return discrete_by_continuous_step(inst, sim, res, deadline, progress);
  return pairwise_step(inst, sim, model, method, res, deadline, progress);
}

}  // namespace gridlock
