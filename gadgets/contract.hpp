// Gadget contracts: which states of a gadget's own operations collide.
//
// Every gadget of the reduction is a small tree with horizontal expansions
// only. Nodes never leave their rows, so a collision is a gap (the empty
// cells between two consecutive nodes of a row) going negative (docs/model.md,
// "Consequences worth testing"). A gap's size after a set S of operations is
//   size + sum over the operations k on the tree path between its two nodes
//          of sign(k) * [k in S],      sign = +1 widens, -1 narrows.
// In the discrete model sizes change linearly while a coupling runs, so an
// order collides iff some prefix (set of couplings done) leaves a negative
// gap. The contract of a gadget lists the gaps whose size can change; every
// other gap of the gadget keeps its size or only widens (checked by tests).
#pragma once

#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace gridlock {

struct GapTerm {
  std::string op;  // operation name
  int sign = 0;    // +1 widens the gap, -1 narrows it
};

struct GapSpec {
  int64_t size = 0;            // empty cells at the start
  std::vector<GapTerm> terms;  // the operations on the path between its nodes
  // The size after the operations in `done`. O(terms).
  int64_t size_after(const std::set<std::string>& done) const {
    int64_t s = size;
    for (const GapTerm& t : terms) s += done.count(t.op) ? t.sign : 0;
    return s;
  }
};

struct GadgetContract {
  std::vector<GapSpec> gaps;
  // True iff the state `done` has a negative gap: any order of the gadget's
  // operations collides iff one of its prefixes is such a state. O(total terms).
  bool collides(const std::set<std::string>& done) const {
    for (const GapSpec& g : gaps)
      if (g.size_after(done) < 0) return true;
    return false;
  }
  // "1 - x1.T - x1.F + x1.z >= 0; ..." for docs and messages.
  std::string str() const;
};

// Where a gadget was drawn: its rows and the node the compiler joins to the
// spine. Every node of the gadget lies in rows bottom_row..top_row, at x >= 0,
// and the leftmost node of each of its rows is joined to the attach node
// (0, attach_row) by plain edges only, so the gap between the spine and the
// gadget never changes.
struct GadgetPlacement {
  int64_t bottom_row = 0, top_row = 0, attach_row = 0;
  GadgetContract contract;
};

}  // namespace gridlock
