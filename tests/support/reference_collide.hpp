// Brute-force twins for Colliding Schedule (collide/collide.hpp), for tiny
// instances only.
//
// Discrete: every order of the couplings through the exact Simulator.
// Continuous: (a) every order as start times 0, 1, 2, ... through the
// Simulator (finds every cycle collision and many node collisions), then
// (b) for every pair of regions, the exact feasibility of its eight strict
// inequalities over the whole cube of progresses p in [0,1]^k by vertex
// enumeration: the closed polytope {g >= 0, 0 <= p <= 1} has non-empty
// strict interior iff the centroid of its vertices satisfies every g > 0.
// The faces are written again from docs/model.md's words (not from the solver's
// RegionForm), on a depth-first tree of the instance's own edges.
#pragma once

#include <optional>
#include <vector>

#include "collide/internal/collide_pairs.hpp"
#include "lattice/instance.hpp"
#include "lattice/rational.hpp"
#include "lattice/schedule.hpp"

namespace gridlock::test {

struct BruteAnswer {
  bool collides = false;
  std::optional<Schedule> schedule;  // a colliding schedule, when one was built
  bool from_pair_test = false;       // (continuous) found by (b), not by simulation
};

// k! simulations. Requires at most 8 couplings.
BruteAnswer brute_discrete(const Instance& inst);
// Requires at most 5 couplings.
BruteAnswer brute_continuous(const Instance& inst);

// Depth-first spanning tree from node 0 over the instance's own edges:
// disp[w][q] = net vector of coupling q on the tree path 0 -> w (at full
// progress); tree_edge[e] = 1 for the edges used.
struct CouplingDisplacements {
  std::vector<std::vector<Vec2>> disp;
  std::vector<char> tree_edge;
};
CouplingDisplacements coupling_displacements(const Instance& inst);
// The vector by which the far side of edge e moves relative to node `from`
// at full progress (zero without an operation).
Vec2 edge_vector(const Instance& inst, uint32_t e, NodeId from);

// One pair of region forms (collide/internal/collide_pairs.hpp) with the path's nets,
// couplings numbered below nq: continuous by vertex enumeration over the
// cube; discrete by every done set S and running coupling q, each a vertex
// enumeration in the one variable s.
bool brute_pair_continuous(const RegionForm& A, const RegionForm& B, const PathNets& nets, size_t nq);
bool brute_pair_discrete(const RegionForm& A, const RegionForm& B, const PathNets& nets, size_t nq);

}  // namespace gridlock::test
