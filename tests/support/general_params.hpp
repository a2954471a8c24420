// Small seeded random instances with operations in all four directions,
// for the NO-certificate tests (kind pairs, kind bounds): 5-14 nodes,
// 3 to 2 + op_kinds operations, couplings of 1-3 operations, 2 to
// 1 + coupling_kinds couplings, some with extra edges (faces), three
// spreads. The counts cycle with the seed so a run covers every size.
#pragma once

#include <cstdint>

#include "lattice/random_instance.hpp"

namespace gridlock::test {

inline RandomInstanceParams general_params(uint64_t seed, uint32_t op_kinds, uint32_t coupling_kinds) {
  RandomInstanceParams p;
  p.nodes = 5 + static_cast<uint32_t>(seed % 10);
  p.ops = 3 + static_cast<uint32_t>(seed % op_kinds);
  p.max_coupling = 1 + static_cast<uint32_t>(seed % 3);
  p.couplings = 2 + static_cast<uint32_t>(seed % coupling_kinds);
  p.extra_edge_percent = static_cast<uint32_t>(seed % 3) * 20;
  p.spread = static_cast<uint32_t>(seed % 3);
  return p;
}

}  // namespace gridlock::test
