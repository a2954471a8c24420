// Twin of the instance builder on compiled formulas: thousands of seeded
// random formulas compiled, every instance written as .grid text into one
// running digest that must equal the digest written by the builder before it
// was made allocation-free (main at a0cc354), and every index of the
// instance (cells, adjacency, operations of nodes, names) checked against a
// naive rebuild from its lists.
#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <string>
#include <utility>

#include "cnf/dimacs.hpp"
#include "gadgets/mutation.hpp"
#include "lattice/grid_format.hpp"
#include "reductions/compile.hpp"
#include "support/cnf_testing.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

uint64_t fnv1a(uint64_t h, const std::string& s) {
  for (char ch : s) h = (h ^ static_cast<unsigned char>(ch)) * 0x100000001B3ull;
  return h;
}

// Every derived table of inst against a rebuild from cells, edges, ops and
// couplings with std::map; names that are not there must not be found.
void expect_indexes_match(const Instance& inst) {
  std::map<std::pair<int64_t, int64_t>, NodeId> at;
  for (NodeId w = 0; w < inst.num_nodes(); ++w) at[{inst.cells()[w].x, inst.cells()[w].y}] = w;
  ASSERT_EQ(at.size(), inst.num_nodes());
  for (const auto& [c, w] : at) ASSERT_EQ(inst.node_at({c.first, c.second}), w);
  ASSERT_EQ(inst.node_at({-1000, -1000}), kNone);
  std::map<std::pair<NodeId, int>, std::pair<NodeId, uint32_t>> nb;
  for (uint32_t e = 0; e < inst.edges().size(); ++e) {
    const Edge& ed = inst.edges()[e];
    auto d = dir_between(inst.cells()[ed.a], inst.cells()[ed.b]);
    ASSERT_TRUE(d.has_value());
    nb[{ed.a, static_cast<int>(*d)}] = {ed.b, e};
    nb[{ed.b, static_cast<int>(opposite(*d))}] = {ed.a, e};
  }
  std::map<NodeId, OpId> op_of;
  for (OpId k = 0; k < inst.ops().size(); ++k) {
    const Operation& op = inst.ops()[k];
    op_of[op.u] = k;
    if (op.v != kNone) op_of[op.v] = k;
    ASSERT_EQ(inst.find_op(op.name), k);
    ASSERT_EQ(inst.find_op(op.name + "#"), kNone);
    ASSERT_LT(op.coupling, inst.couplings().size());
  }
  for (NodeId w = 0; w < inst.num_nodes(); ++w) {
    for (int d = 0; d < 4; ++d) {
      auto it = nb.find({w, d});
      ASSERT_EQ(inst.neighbour(w, static_cast<Dir>(d)), it == nb.end() ? kNone : it->second.first);
      ASSERT_EQ(inst.edge_index(w, static_cast<Dir>(d)), it == nb.end() ? kNone : it->second.second);
    }
    auto it = op_of.find(w);
    ASSERT_EQ(inst.op_of_node(w), it == op_of.end() ? kNone : it->second);
  }
  for (CouplingId q = 0; q < inst.couplings().size(); ++q) {
    ASSERT_EQ(inst.find_coupling(inst.couplings()[q].name), q);
    ASSERT_EQ(inst.find_coupling(inst.couplings()[q].name + "'x"), kNone);
    for (OpId k : inst.couplings()[q].ops) ASSERT_EQ(inst.ops()[k].coupling, q);
  }
}

// 2 000 formulas of 1-7 variables, 0-12 clauses of 1-3 literals (repeated
// literals in a third of them), a random mutation in every fourth, the
// continuous reduction in every third. Not scaled: the digest counts them all.
TEST(BuildTwin, CompiledInstancesAreTheOldBuildersByteForByte) {
  const uint64_t seed = 24700;
  Rng rng(seed);
  const std::vector<Mutation> mutations = all_mutations();
  uint64_t digest = 0xCBF29CE484222325ull;
  for (int t = 0; t < 2000; ++t) {
    const int n = static_cast<int>(rng.between(1, 7)), m = static_cast<int>(rng.between(0, 12));
    Formula f = test::random_cnf(rng, n, m, 1, 3, rng.below(3) == 0);
    const Mutation mu = rng.below(4) == 0 ? mutations[rng.below(mutations.size())] : Mutation::None;
    const TimeModel model = rng.below(3) == 0 ? TimeModel::Continuous : TimeModel::Discrete;
    SCOPED_TRACE("seed " + std::to_string(seed) + ", formula " + std::to_string(t) + ":\n" + to_dimacs(f));
    CompiledFormula c = compile_formula(f, mu, model);
    std::ostringstream text;
    write_instance(text, c.instance);
    digest = fnv1a(digest, text.str());
    if (t % 4 == 0) expect_indexes_match(c.instance);
    if (HasFatalFailure()) return;
  }
  // A regression pin, not a twin: a deliberate change of the compiler's
  // output or of the .grid writer changes it; review the change, then
  // update the constant to the digest printed here.
  EXPECT_EQ(digest, 0x25E8A34398BD8154ull) << "digest 0x" << std::hex << digest;
}

}  // namespace
}  // namespace gridlock
