// Planted schedules: a YES instance cut from any instance, for benchmarks
// whose answers should not all be NO (random shapes of hundreds of
// couplings almost always hold a local conflict somewhere).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "lattice/instance.hpp"
#include "lattice/random_instance.hpp"

namespace gridlock {

struct PlantedInstance {
  Instance instance;
  std::vector<std::string> hidden_order;  // coupling names: a collision-free order of all of them
  size_t dropped = 0;                     // couplings of the input left out
};

// Drops every coupling that breaks a cycle, draws a random order of the
// rest (seeded), and walks it keeping a coupling iff its step does not
// collide after the couplings kept so far (the exact step test on the input's
// pair constraints); stops after `max_couplings` kept (0: no limit). The
// result has the input's shape and the kept couplings' operations only, and
// hidden_order is collision-free on it. Why exact: dropping couplings only
// removes terms from the pair forms, so the input's constraint system,
// restricted to the kept couplings, describes the result (pairs it left out
// still never overlap), and a step depends only on the couplings done before
// it. O(pair constraints + sum over the order of the steps' constraints).
PlantedInstance plant_schedule(const Instance& inst, uint64_t seed, size_t max_couplings = 0);

// A planted instance of the family with at most f.couplings couplings:
// random_family_instance with 2, then (if too few are kept) 4 times the
// couplings, planted with at most f.couplings kept; the larger result is
// returned. Compact shapes keep few (a tree blob about a tenth: most
// expansions there push a subtree into an unjoined neighbour), sparse
// shapes most. Deterministic in (f, seed).
PlantedInstance planted_family_instance(const RandomFamilyParams& f, uint64_t seed);

}  // namespace gridlock
