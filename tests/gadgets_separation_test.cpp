// The separation gadget (gadgets/internal/separation_gadget.hpp) and the continuous
// contracts of every gadget.
//
// Separation: its contract "collision-free iff t_b >= t_a + 1" quantifies
// over every real delta = t_b - t_a. The proof (docs/gadgets.md, "Why
// finitely many deltas suffice") shows that for a tree whose only operations
// are one horizontal and one vertical expansion, the set of colliding deltas
// is a finite union of intervals whose endpoints lie in {-1, 0, 1}. So the
// verdict is constant on (-inf,-1), (-1,0), (0,1), (1,inf), and the exact
// simulator on the three breakpoints and one delta inside each of the four
// open intervals decides the contract for every real delta. The test checks
// the premises of that argument on the drawn instance, then those seven
// deltas, then (as a cross-check, not part of the proof) deltas approaching
// the breakpoints from both sides: 1 - 1/2^k, 1 + 1/2^k, ...
//
// Every other gadget: the continuous contract (GadgetContract::
// collides_continuous, exact) against the simulator on every start-time
// vector of a rational grid.
#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <set>

#include "gadgets/internal/canvas.hpp"
#include "gadgets/internal/clause_gadget.hpp"
#include "gadgets/internal/gap_gadget.hpp"
#include "gadgets/internal/order_gadget.hpp"
#include "gadgets/internal/separation_gadget.hpp"
#include "gadgets/internal/variable_gadget.hpp"
#include "lattice/simulate.hpp"

namespace gridlock {
namespace {

struct Drawn {
  Instance inst;
  GadgetContract contract;
};

Drawn draw(const std::function<GadgetPlacement(Canvas&)>& place) {
  Canvas canvas;
  GadgetPlacement p = place(canvas);
  return {canvas.build(), p.contract};
}

// Runs the gadget (each operation its own coupling) with the given start
// times per operation name.
std::optional<Collision> run(const Instance& inst, const std::map<std::string, Rational>& start) {
  Schedule s;
  s.start.resize(inst.couplings().size());
  for (CouplingId q = 0; q < inst.couplings().size(); ++q) s.start[q] = start.at(inst.couplings()[q].name);
  return Simulator(inst).run(s).collision;
}

std::string str(const Rational& r) {
  return std::to_string(r.num()) + (r.den() == 1 ? "" : "/" + std::to_string(r.den()));
}

TEST(SeparationGadget, PremisesOfTheExactArgument) {
  Drawn d = draw([](Canvas& c) { return place_separation_gadget(c, 0, "a", "b"); });
  const Instance& inst = d.inst;
  EXPECT_EQ(inst.num_nodes(), 8u);
  EXPECT_EQ(inst.edges().size(), inst.num_nodes() - 1);  // connected (builder) and a tree: no cycle collisions
  ASSERT_EQ(inst.ops().size(), 2u);
  const Operation& a = inst.ops()[inst.find_op("a")];
  const Operation& b = inst.ops()[inst.find_op("b")];
  EXPECT_EQ(a.kind, OpKind::Expand);
  EXPECT_EQ(b.kind, OpKind::Expand);
  EXPECT_FALSE(is_horizontal(a.dir));  // every x-coordinate depends on p_b only,
  EXPECT_TRUE(is_horizontal(b.dir));   // every y-coordinate on p_a only
  ASSERT_EQ(d.contract.separations.size(), 1u);
  EXPECT_EQ(d.contract.separations[0].first, "a");
  EXPECT_EQ(d.contract.separations[0].second, "b");
  EXPECT_TRUE(d.contract.gaps.empty());
  EXPECT_EQ(d.contract.str(), "t(b) >= t(a) + 1");
  // Discrete: a then b is fine, b then a collides (one coupling at a time).
  Simulator sim(inst);
  const CouplingId qa = inst.find_coupling("a"), qb = inst.find_coupling("b");
  EXPECT_FALSE(sim.run_order({qa, qb}).collision);
  EXPECT_TRUE(sim.run_order({qb, qa}).collision);
}

TEST(SeparationGadget, ContractHoldsForEveryRealDelta) {
  Drawn d = draw([](Canvas& c) { return place_separation_gadget(c, 0, "a", "b"); });
  // The breakpoints and one point inside each open interval between them:
  // by the argument above, this decides every real delta.
  const std::vector<Rational> proof = {Rational(-2),   Rational(-1), Rational(-1, 2), Rational(0),
                                       Rational(1, 2), Rational(1),  Rational(2)};
  // The answer does not depend on t_a (only relative motion matters): try two.
  for (const Rational& ta : {Rational(0), Rational(5, 3)}) {
    for (const Rational& delta : proof) {
      const Rational tb = ta + delta;
      auto col = run(d.inst, {{"a", ta}, {"b", tb}});
      const bool expect = delta < Rational(1);
      EXPECT_EQ(col.has_value(), expect) << "t_a " << str(ta) << " delta " << str(delta);
      EXPECT_EQ(d.contract.collides_continuous({{"a", ta}, {"b", tb}}), expect);
      if (col) {
        // Y and X share area while t_b < t < t_a + 1: from t_b on.
        EXPECT_EQ(col->time, tb) << "delta " << str(delta);
        EXPECT_EQ(col->kind, Collision::Kind::Node);
      }
    }
  }
  // Cross-checks approaching every breakpoint from both sides.
  for (int k = 1; k <= 20; ++k) {
    const Rational e(1, int64_t{1} << k);
    for (const Rational& base : {Rational(-1), Rational(0), Rational(1)})
      for (const Rational& delta : {base - e, base + e}) {
        auto col = run(d.inst, {{"a", Rational(0)}, {"b", delta}});
        EXPECT_EQ(col.has_value(), delta < Rational(1)) << "delta " << str(delta);
      }
  }
  // Far away on both sides.
  EXPECT_TRUE(run(d.inst, {{"a", Rational(1000)}, {"b", Rational(0)}}));
  EXPECT_FALSE(run(d.inst, {{"a", Rational(0)}, {"b", Rational(1000)}}));
}

TEST(SeparationGadget, LooseMutationNeverCollides) {
  Drawn d = draw([](Canvas& c) { return place_separation_gadget(c, 0, "a", "b", Mutation::SeparationLoose); });
  EXPECT_TRUE(d.contract.separations.empty());
  for (const Rational& delta :
       {Rational(-2), Rational(-1), Rational(-1, 2), Rational(0), Rational(1, 2), Rational(1), Rational(2)}) {
    EXPECT_FALSE(run(d.inst, {{"a", Rational(0)}, {"b", delta}})) << "delta " << str(delta);
    EXPECT_FALSE(d.contract.collides_continuous({{"a", Rational(0)}, {"b", delta}}));
  }
}

// Every start-time vector with entries in {0, 1/step, ..., span} for the
// gadget's operations: the simulator collides iff the continuous contract
// says so. Returns the number of colliding vectors.
int check_start_grid(const Drawn& d, int step, int span) {
  std::vector<std::string> ops;
  for (const Operation& op : d.inst.ops()) ops.push_back(op.name);
  const int values = step * span + 1;
  std::vector<int> idx(ops.size(), 0);
  int colliding = 0;
  for (;;) {
    std::map<std::string, Rational> start;
    std::string where;
    for (size_t i = 0; i < ops.size(); ++i) {
      start[ops[i]] = Rational(idx[i], step);
      where += ops[i] + "=" + str(start[ops[i]]) + " ";
    }
    const bool got = run(d.inst, start).has_value();
    EXPECT_EQ(got, d.contract.collides_continuous(start)) << where << "; contract " << d.contract.str();
    colliding += got;
    size_t i = 0;
    while (i < idx.size() && ++idx[i] == values) idx[i++] = 0;
    if (i == idx.size()) break;
  }
  return colliding;
}

TEST(ContinuousContracts, EveryGadgetOnARationalGrid) {
  // Thirds and halves over [0, 2]: every relative order of the starts and
  // ends, and fractional overlaps of both parities.
  Drawn var = draw([](Canvas& c) { return place_variable_gadget(c, 0, {"T", "F", "y", "z"}); });
  EXPECT_GT(check_start_grid(var, 3, 2), 0);
  EXPECT_GT(check_start_grid(var, 2, 2), 0);
  for (size_t k = 1; k <= 3; ++k) {
    std::vector<std::string> lits;
    for (size_t i = 1; i <= k; ++i) lits.push_back("l" + std::to_string(i));
    Drawn cl = draw([&](Canvas& c) { return place_clause_gadget(c, 0, lits, "u"); });
    SCOPED_TRACE("clause k=" + std::to_string(k));
    EXPECT_GT(check_start_grid(cl, 3, 2), 0);
  }
  Drawn ord = draw([](Canvas& c) { return place_order_gadget(c, 0, "a", "b"); });
  EXPECT_GT(check_start_grid(ord, 6, 3), 0);
  Drawn sep = draw([](Canvas& c) { return place_separation_gadget(c, 0, "a", "b"); });
  EXPECT_GT(check_start_grid(sep, 6, 3), 0);
  for (Mutation m : all_mutations()) {
    SCOPED_TRACE(mutation_name(m));
    check_start_grid(draw([&](Canvas& c) { return place_variable_gadget(c, 0, {"T", "F", "y", "z"}, m); }), 2, 2);
    check_start_grid(draw([&](Canvas& c) { return place_clause_gadget(c, 0, {"p", "q", "r"}, "u", m); }), 2, 2);
    check_start_grid(draw([&](Canvas& c) { return place_order_gadget(c, 0, "a", "b", m); }), 4, 2);
    check_start_grid(draw([&](Canvas& c) { return place_separation_gadget(c, 0, "a", "b", m); }), 4, 2);
  }
}

TEST(ContinuousContracts, GapGadgetFamily) {
  for (int64_t gap = 0; gap <= 2; ++gap)
    for (int nw = 0; nw <= 2; ++nw)
      for (int nn = 0; nn <= 2; ++nn) {
        if (nw + nn == 0 || nw + nn > 3) continue;
        GapGadgetSpec spec;
        spec.gap = gap;
        for (int i = 0; i < nw; ++i) spec.widen.push_back("w" + std::to_string(i));
        for (int i = 0; i < nn; ++i) spec.narrow.push_back("n" + std::to_string(i));
        SCOPED_TRACE("gap " + std::to_string(gap) + " widen " + std::to_string(nw) + " narrow " + std::to_string(nn));
        check_start_grid(draw([&](Canvas& c) { return place_gap_gadget(c, 0, spec); }), 3, 2);
      }
}

}  // namespace
}  // namespace gridlock
