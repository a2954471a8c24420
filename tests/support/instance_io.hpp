// Reading instances in tests: from a string, or from examples/instances/;
// and rebuilding one with x and y swapped or every operation in one
// coupling. A reader or builder error fails the current test (EXPECT) and
// returns what was read or built.
#pragma once

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "lattice/grid_format.hpp"

namespace gridlock::test {

inline Instance parse_instance(const std::string& text) {
  Instance inst;
  std::istringstream in(text);
  auto err = read_instance(in, "test.grid", inst);
  EXPECT_FALSE(err) << err->str();
  return inst;
}

inline Instance load_example(const std::string& name) {
  Instance inst;
  auto err = read_instance_file(std::string(GRIDLOCK_SOURCE_DIR) + "/examples/instances/" + name, inst);
  EXPECT_FALSE(err) << err->str();
  return inst;
}

// The .grid text of a row of n nodes along y = 0 (n >= 2) with an
// expansion "e<x>" (+x) at every even x < n - 1, in couplings "Q<x>" of
// `group` consecutive expansions (x: the first one's; 0: one coupling
// "all"). NO in every schedule: expansions only push apart.
inline std::string expansion_row_grid(int n, int group) {
  std::string nodes, edges, ops, couplings;
  int count = 0, coupled = 0;
  for (int x = 0; x < n; ++x) nodes += "n " + std::to_string(x) + " 0\n";
  for (int x = 0; x + 1 < n; ++x) edges += "e " + std::to_string(x) + " 0 " + std::to_string(x + 1) + " 0\n";
  for (int x = 0; x + 1 < n; x += 2, ++count) {
    ops += "o e" + std::to_string(x) + " expand " + std::to_string(x) + " 0 +x\n";
    if (count == 0 || (group > 0 && count % group == 0)) {
      couplings += (count == 0 ? "q " : "\nq ") + (group == 0 ? std::string("all") : "Q" + std::to_string(x));
      ++coupled;
    }
    couplings += " e" + std::to_string(x);
  }
  return "p grid " + std::to_string(n) + " " + std::to_string(n - 1) + " " + std::to_string(count) + " " +
         std::to_string(coupled) + "\n" + nodes + edges + ops + couplings + "\n";
}

// The same shape and operations; with `transpose`, x and y swapped (cells
// and directions: a horizontal-only instance becomes a vertical-only one);
// with `mirror_y`, then y negated (+y and -y swapped: a cut along x - y
// becomes one along x + y); with `one_coupling`, every operation in one
// coupling "Q", else the instance's couplings.
inline Instance rebuilt(const Instance& inst, bool transpose, bool one_coupling, bool mirror_y = false) {
  auto cell = [&](NodeId w) {
    Vec2 c = inst.cells()[w];
    if (transpose) c = Vec2{c.y, c.x};
    if (mirror_y) c.y = -c.y;
    return c;
  };
  auto dir = [&](Dir d) {
    if (transpose) d = d == Dir::PosX ? Dir::PosY : d == Dir::PosY ? Dir::PosX : d == Dir::NegX ? Dir::NegY : Dir::NegX;
    if (mirror_y && (d == Dir::PosY || d == Dir::NegY)) d = d == Dir::PosY ? Dir::NegY : Dir::PosY;
    return d;
  };
  InstanceBuilder b;
  for (NodeId w = 0; w < inst.num_nodes(); ++w) EXPECT_FALSE(b.add_node(cell(w)));
  for (const Edge& e : inst.edges()) EXPECT_FALSE(b.add_edge(cell(e.a), cell(e.b)));
  std::vector<std::string> all;
  for (const Operation& op : inst.ops()) {
    EXPECT_FALSE(b.add_op(op.name, op.kind, cell(op.u), dir(op.dir)));
    all.push_back(op.name);
  }
  if (one_coupling && !all.empty()) {
    EXPECT_FALSE(b.add_coupling("Q", all));
  }
  if (!one_coupling)
    for (const Coupling& c : inst.couplings()) {
      if (c.ops.size() < 2) continue;  // singletons are implicit
      std::vector<std::string> names;
      for (OpId k : c.ops) names.push_back(inst.ops()[k].name);
      EXPECT_FALSE(b.add_coupling(c.name, names));
    }
  if (inst.has_explicit_anchor()) {
    EXPECT_FALSE(b.set_anchor(cell(inst.anchor())));
  }
  Instance out;
  EXPECT_FALSE(b.finish(out));
  return out;
}

}  // namespace gridlock::test
