// Gadget contracts: which states of a gadget's own operations collide.
//
// Every gadget of the discrete reduction is a small tree with horizontal
// expansions only (the separation gadget of the continuous reduction adds a
// vertical one and a contract of its own kind, Separation below). Nodes never leave their rows, so a collision is a gap
// (the empty cells between two consecutive nodes of a row) going negative (docs/model.md, "Consequences worth
// testing"). A gap's size after a set S of operations is
//   size + sum over the operations k on the tree path between its two nodes
//          of sign(k) * [k in S],      sign = +1 widens, -1 narrows.
// In the discrete model sizes change linearly while a coupling runs, so an
// order collides iff some prefix (set of couplings done) leaves a negative
// gap. The contract of a gadget lists the gaps whose size can change; every
// other gap of the gadget keeps its size or only widens (checked by tests).
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "lattice/rational.hpp"

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

// The separation gadget's promise (gadgets/internal/separation_gadget.hpp): in
// continuous time, collision-free iff t_second >= t_first + 1 (second starts
// no earlier than first has finished); in discrete time (one coupling at a
// time) iff first runs before second.
struct Separation {
  std::string first, second;  // operation names
};

struct GadgetContract {
  std::vector<GapSpec> gaps;
  std::vector<Separation> separations;
  // True iff the state `done` has a negative gap, or a separation's second
  // operation is done and its first is not: any order of the gadget's
  // operations collides iff one of its prefixes is such a state. O(total terms).
  bool collides(const std::set<std::string>& done) const {
    for (const GapSpec& g : gaps)
      if (g.size_after(done) < 0) return true;
    for (const Separation& s : separations)
      if (done.count(s.second) && !done.count(s.first)) return true;
    return false;
  }
  // The continuous model: operation k runs over [start(k), start(k) + 1] with
  // progress p_k(t) = clamp(t - start(k), 0, 1). True iff some gap
  // size + sum sign * p_k(t) is negative at some moment t, or some separation
  // has start(second) < start(first) + 1. Exact: a gap's size is piecewise
  // linear in t with breakpoints at the start(k) and start(k) + 1, so its
  // minimum is taken at one of them (and negative there iff negative on an
  // open interval around it). Requires a start time for every operation
  // named in the contract (throws std::invalid_argument otherwise).
  // O(terms^2) per gap.
  bool collides_continuous(const std::map<std::string, Rational>& start) const;
  // "1 - x1.T - x1.F + x1.z >= 0; ...; z1 >= y1 + 1" for docs and messages
  // (a separation reads "t(second) >= t(first) + 1").
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
