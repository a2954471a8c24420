// FaceNets::build (lattice/motion.hpp) against a naive twin written here:
// the same face walks (the first edge clockwise from the way back), every
// walk kept with its steps summed in a std::map, then the walks whose sums
// are all zero dropped. Seeded random shapes with cycles, operations of
// every kind in couplings of up to four; a failure prints the seed
// (GRIDLOCK_TEST_SEED replays).

#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "common/random.hpp"
#include "lattice/motion.hpp"
#include "lattice/random_instance.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

struct NaiveFace {
  std::vector<NodeId> walk;
  std::vector<std::pair<CouplingId, Vec2>> nets;
};

// Every face walk, in the order of its first half-edge (node, then
// direction), with its non-zero sums per coupling; walks with none dropped.
std::vector<NaiveFace> naive_faces(const Instance& inst) {
  std::vector<NaiveFace> out;
  std::map<std::pair<NodeId, int>, bool> used;
  for (NodeId w0 = 0; w0 < inst.num_nodes(); ++w0)
    for (int d0 = 0; d0 < 4; ++d0) {
      if (inst.neighbour(w0, static_cast<Dir>(d0)) == kNone || used[{w0, d0}]) continue;
      NaiveFace face;
      std::map<CouplingId, Vec2> sum;
      NodeId w = w0;
      int d = d0;
      while (!used[{w, d}]) {
        used[{w, d}] = true;
        face.walk.push_back(w);
        const NodeId x = inst.neighbour(w, static_cast<Dir>(d));
        const OpId k = inst.edges()[inst.edge_index(w, static_cast<Dir>(d))].op;
        if (k != kNone) {
          const Operation& op = inst.ops()[k];
          const Vec2 step = unit(static_cast<Dir>(d));
          sum[op.coupling] += op.kind == OpKind::Contract ? Vec2{-step.x, -step.y} : step;
        }
        int next = (d + 2) % 4;
        for (int turn = 1; turn <= 4; ++turn)
          if (inst.neighbour(x, static_cast<Dir>((d + 2 + 4 - turn) % 4)) != kNone) {
            next = (d + 2 + 4 - turn) % 4;
            break;
          }
        w = x;
        d = next;
      }
      for (const auto& [q, v] : sum)
        if (!v.is_zero()) face.nets.emplace_back(q, v);
      if (!face.nets.empty()) out.push_back(face);
    }
  return out;
}

TEST(FaceNets, AgreesWithANaiveSumOnRandomShapes) {
  const uint64_t base = test::base_seed(9100);
  const int runs = test::scaled(2000);
  size_t kept = 0;
  for (int run = 0; run < runs; ++run) {
    const uint64_t seed = base + static_cast<uint64_t>(run);
    Rng rng(seed);
    RandomInstanceParams p;
    p.nodes = 4 + static_cast<uint32_t>(rng.below(60));
    p.ops = 1 + static_cast<uint32_t>(rng.below(p.nodes));
    p.max_coupling = 1 + static_cast<uint32_t>(rng.below(4));
    p.extra_edge_percent = static_cast<uint32_t>(rng.below(100));
    p.spread = static_cast<uint32_t>(rng.below(3));
    const Instance inst = random_instance(p, seed);
    const FaceNets F = FaceNets::build(inst);
    const std::vector<NaiveFace> twin = naive_faces(inst);
    ASSERT_EQ(F.faces.size(), twin.size()) << "seed " << seed;
    std::vector<char> breaks(inst.couplings().size(), 0);
    for (size_t i = 0; i < twin.size(); ++i) {
      EXPECT_EQ(F.faces[i].walk, twin[i].walk) << "seed " << seed << " face " << i;
      ASSERT_EQ(F.faces[i].nets.size(), twin[i].nets.size()) << "seed " << seed << " face " << i;
      for (size_t j = 0; j < twin[i].nets.size(); ++j) {
        EXPECT_EQ(F.faces[i].nets[j].first, twin[i].nets[j].first) << "seed " << seed << " face " << i;
        EXPECT_TRUE(F.faces[i].nets[j].second == twin[i].nets[j].second) << "seed " << seed << " face " << i;
        breaks[twin[i].nets[j].first] = 1;
      }
    }
    EXPECT_EQ(F.coupling_breaks_cycle, breaks) << "seed " << seed;
    kept += twin.size();
  }
  // Not vacuous: the random shapes have faces with non-zero nets.
  EXPECT_GT(kept, static_cast<size_t>(runs) / 4);
}

}  // namespace
}  // namespace gridlock
