// Every gadget's contract, checked exhaustively against the exact simulator:
// for every order of the gadget's own operations (each its own coupling),
// the simulator finds a collision iff some prefix of the order leaves a gap
// of the contract negative. Also: the contracts say what the paper's proof
// needs, every gadget runs collision-free with everything at once
// (continuous model), and every mutation really changes the contract.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <set>

#include "gadgets/internal/canvas.hpp"
#include "gadgets/internal/clause_gadget.hpp"
#include "gadgets/internal/gap_gadget.hpp"
#include "gadgets/internal/order_gadget.hpp"
#include "gadgets/internal/separation_gadget.hpp"
#include "gadgets/internal/variable_gadget.hpp"
#include "lattice/simulate.hpp"
#include "solver/gaps.hpp"

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

// Checks the contract against the simulator over every order; returns the
// number of orders that collide.
int check_every_order(const Drawn& d) {
  const Instance& inst = d.inst;
  std::vector<CouplingId> order(inst.couplings().size());
  for (CouplingId q = 0; q < order.size(); ++q) order[q] = q;
  Simulator sim(inst);
  int colliding = 0;
  do {
    std::set<std::string> done;
    bool expect = false;
    std::string names;
    for (CouplingId q : order) {
      for (OpId op : inst.couplings()[q].ops) done.insert(inst.ops()[op].name);
      expect = expect || d.contract.collides(done);
      names += inst.couplings()[q].name + " ";
    }
    bool got = sim.run_order(order).collision.has_value();
    EXPECT_EQ(got, expect) << "order " << names << "; contract " << d.contract.str();
    colliding += got;
  } while (std::next_permutation(order.begin(), order.end()));
  return colliding;
}

bool all_at_once_collides(const Instance& inst) {
  Schedule s;
  s.start.assign(inst.couplings().size(), Rational(0));
  return Simulator(inst).run(s).collision.has_value();
}

VariableOps var_ops() { return {"T", "F", "y", "z"}; }

TEST(GadgetContract, VariableGadget) {
  Drawn d = draw([](Canvas& c) { return place_variable_gadget(c, 0, var_ops()); });
  EXPECT_EQ(d.inst.num_nodes(), 17u);
  EXPECT_TRUE(d.inst.horizontal_only());
  // The paper's words, as a predicate on the set done.
  for (int mask = 0; mask < 16; ++mask) {
    std::set<std::string> done;
    bool t = mask & 1, f = mask & 2, y = mask & 4, z = mask & 8;
    if (t) done.insert("T");
    if (f) done.insert("F");
    if (y) done.insert("y");
    if (z) done.insert("z");
    EXPECT_EQ(d.contract.collides(done), (t && f && !z) || (y && !t && !f)) << "mask " << mask;
  }
  EXPECT_GT(check_every_order(d), 0);
  EXPECT_FALSE(all_at_once_collides(d.inst));
  EXPECT_TRUE(check_gaps(d.inst).collision_free);
}

TEST(GadgetContract, ClauseGadgets) {
  for (size_t k = 1; k <= 4; ++k) {
    std::vector<std::string> lits;
    for (size_t i = 1; i <= k; ++i) lits.push_back("l" + std::to_string(i));
    Drawn d = draw([&](Canvas& c) { return place_clause_gadget(c, 0, lits, "u"); });
    EXPECT_EQ(d.inst.num_nodes(), 5 * k + 1);
    // Collides iff all literal operations are done and u is not.
    for (uint32_t mask = 0; mask < (1u << (k + 1)); ++mask) {
      std::set<std::string> done;
      for (size_t i = 0; i < k; ++i)
        if (mask >> i & 1) done.insert(lits[i]);
      bool u = mask >> k & 1;
      if (u) done.insert("u");
      EXPECT_EQ(d.contract.collides(done), done.size() == k && !u) << "k " << k << " mask " << mask;
    }
    EXPECT_GT(check_every_order(d), 0);
    EXPECT_FALSE(all_at_once_collides(d.inst));
  }
}

TEST(GadgetContract, OrderGadget) {
  Drawn d = draw([](Canvas& c) { return place_order_gadget(c, 0, "a", "b"); });
  EXPECT_EQ(d.inst.num_nodes(), 6u);
  EXPECT_TRUE(d.contract.collides({"b"}));
  EXPECT_FALSE(d.contract.collides({"a"}));
  EXPECT_FALSE(d.contract.collides({"a", "b"}));
  EXPECT_EQ(check_every_order(d), 1);  // exactly "b a"
  EXPECT_FALSE(all_at_once_collides(d.inst));
}

TEST(GadgetContract, GapGadgetFamily) {
  // Every small combination of gap, widening and narrowing operations.
  for (int64_t gap = 0; gap <= 2; ++gap)
    for (int nw = 0; nw <= 2; ++nw)
      for (int nn = 0; nn <= 3; ++nn) {
        GapGadgetSpec spec;
        spec.gap = gap;
        for (int i = 0; i < nw; ++i) spec.widen.push_back("w" + std::to_string(i));
        for (int i = 0; i < nn; ++i) spec.narrow.push_back("n" + std::to_string(i));
        if (nw + nn == 0) continue;
        SCOPED_TRACE("gap " + std::to_string(gap) + " widen " + std::to_string(nw) + " narrow " + std::to_string(nn));
        Drawn d = draw([&](Canvas& c) { return place_gap_gadget(c, 0, spec); });
        check_every_order(d);
        EXPECT_EQ(all_at_once_collides(d.inst), gap + nw - nn < 0);
      }
}

TEST(GadgetContract, GadgetsPlacedAnywhereBehaveTheSame) {
  // Rows are relative: a gadget drawn at another row has the same verdicts.
  Drawn d = draw([](Canvas& c) { return place_variable_gadget(c, -7, var_ops()); });
  check_every_order(d);
  Drawn e = draw([](Canvas& c) { return place_clause_gadget(c, 1000, {"p", "q", "r"}, "u"); });
  check_every_order(e);
}

TEST(GadgetContract, EveryMutationChangesItsGadget) {
  // The broken gadgets still match their own (changed) contracts, and each
  // changed contract differs from the original on some state.
  struct Case {
    Mutation m;
    std::function<GadgetPlacement(Canvas&, Mutation)> place;
  };
  std::vector<Case> cases = {
      {Mutation::VariableLooseY, [](Canvas& c, Mutation m) { return place_variable_gadget(c, 0, var_ops(), m); }},
      {Mutation::ClauseLoose,
       [](Canvas& c, Mutation m) {
         return place_clause_gadget(c, 0, {"p", "q", "r"}, "u", m);
       }},
      {Mutation::ClauseTight,
       [](Canvas& c, Mutation m) {
         return place_clause_gadget(c, 0, {"p", "q", "r"}, "u", m);
       }},
      {Mutation::OrderLoose, [](Canvas& c, Mutation m) { return place_order_gadget(c, 0, "a", "b", m); }},
      {Mutation::OrderDropRelease, [](Canvas& c, Mutation m) { return place_order_gadget(c, 0, "a", "b", m); }},
      {Mutation::SeparationLoose, [](Canvas& c, Mutation m) { return place_separation_gadget(c, 0, "a", "b", m); }},
  };
  ASSERT_EQ(cases.size(), all_mutations().size());
  for (const Case& k : cases) {
    SCOPED_TRACE(mutation_name(k.m));
    Drawn good = draw([&](Canvas& c) { return k.place(c, Mutation::None); });
    Drawn bad = draw([&](Canvas& c) { return k.place(c, k.m); });
    check_every_order(bad);
    std::vector<std::string> ops;
    for (const Operation& op : good.inst.ops()) ops.push_back(op.name);
    bool differs = false;
    for (uint32_t mask = 0; mask < (1u << ops.size()); ++mask) {
      std::set<std::string> done;
      for (size_t i = 0; i < ops.size(); ++i)
        if (mask >> i & 1) done.insert(ops[i]);
      differs = differs || good.contract.collides(done) != bad.contract.collides(done);
    }
    EXPECT_TRUE(differs);
  }
}

}  // namespace
}  // namespace gridlock
