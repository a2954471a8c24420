// The linear-time continuous checker against the Simulator running every
// coupling at once; the row order against a comparison sort; the collision
// constraints against the Simulator on random orders; the pair builder
// against its per-face twin; the interned coefficient rows against a map.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <set>
#include <tuple>

#include "common/random.hpp"
#include "lattice/prepared.hpp"
#include "lattice/random_instance.hpp"
#include "lattice/row_order.hpp"
#include "lattice/simulate.hpp"
#include "reductions/compile.hpp"
#include "solver/gaps.hpp"
#include "solver/internal/constraints.hpp"
#include "support/cnf_testing.hpp"
#include "support/reference_constraints.hpp"
#include "support/reference_solver.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

RandomInstanceParams horizontal_params(uint64_t seed) {
  Rng rng(seed * 0x9E3779B97F4A7C15ULL + 7);
  RandomInstanceParams p;
  p.horizontal_only = true;
  p.nodes = 2 + static_cast<uint32_t>(rng.below(40));
  p.ops = static_cast<uint32_t>(rng.below(p.nodes + 1));
  p.max_coupling = 1 + static_cast<uint32_t>(rng.below(4));
  p.extra_edge_percent = rng.below(2) ? static_cast<uint32_t>(rng.below(60)) : 0;
  p.allow_grow = rng.below(4) != 0;
  p.allow_contract = rng.below(4) != 0;
  p.path_shape = rng.below(5) == 0;
  p.spread = static_cast<uint32_t>(rng.below(3));
  return p;
}

TEST(Gaps, AgreesWithAllAtOnceSimulation) {
  const uint64_t base = test::base_seed(7000);
  const int count = test::scaled(4000);
  int yes = 0, no_gap = 0, no_cycle = 0;
  for (int i = 0; i < count; ++i) {
    uint64_t seed = base + static_cast<uint64_t>(i);
    Instance inst = random_instance(horizontal_params(seed), seed);
    ASSERT_TRUE(inst.horizontal_only());
    GapVerdict v = check_gaps(inst);
    bool sim_ok = test::reference_all_at_once(inst);
    ASSERT_EQ(v.collision_free, sim_ok) << "seed " << seed << ": " << describe_gap_verdict(inst, v);
    if (v.collision_free) {
      ++yes;
      continue;
    }
    if (v.reason == GapVerdict::Reason::Gap) {
      ++no_gap;
      // The reported gap: consecutive nodes of one row, negative at the end,
      // and the changes add up.
      const auto& cells = inst.cells();
      EXPECT_EQ(cells[v.left].y, v.row);
      EXPECT_EQ(cells[v.right].y, v.row);
      EXPECT_EQ(v.initial_size, cells[v.right].x - cells[v.left].x - 1);
      EXPECT_LT(v.final_size, 0);
      int64_t sum = v.initial_size;
      for (const GapChange& c : v.changes) sum += c.delta;
      EXPECT_EQ(sum, v.final_size) << "seed " << seed << ": " << describe_gap_verdict(inst, v);
    } else {
      ++no_cycle;
      EXPECT_NE(v.mismatch, 0);
      EXPECT_GE(v.cycle.size(), 4u);
    }
  }
  EXPECT_GT(yes, 0);
  EXPECT_GT(no_gap, 0);
  EXPECT_GT(no_cycle, 0);
  std::printf("[ gaps ] %d instances: %d YES, %d NO by a gap, %d NO by a cycle (seed %llu)\n", count, yes, no_gap,
              no_cycle, static_cast<unsigned long long>(base));
}

TEST(Gaps, RejectsVerticalInstances) {
  RandomInstanceParams p;
  p.nodes = 10;
  p.ops = 5;
  for (uint64_t seed = 1; seed < 100; ++seed) {
    Instance inst = random_instance(p, seed);
    if (inst.horizontal_only()) continue;
    EXPECT_THROW(check_gaps(inst), std::invalid_argument);
    return;
  }
  FAIL() << "no vertical instance drawn";
}

// Shapes wider and taller than one radix digit (2^11), at both ends of the
// coordinate range, added in a shuffled order: several passes, and keys
// shifted from the most negative coordinates.
TEST(RowOrder, WideShapesAtTheCoordinateLimits) {
  const uint64_t base = test::base_seed(8100);
  for (int i = 0; i < test::scaled(6); ++i) {
    const uint64_t seed = base + static_cast<uint64_t>(i);
    Rng rng(seed);
    const int64_t w = rng.between(1, 5000), h = rng.between(1, 5000);
    const int64_t x0 = i % 2 == 0 ? -kMaxCoordinate : kMaxCoordinate - w;
    const int64_t y0 = i % 3 == 0 ? -kMaxCoordinate : kMaxCoordinate - h;
    std::vector<Vec2> cells;  // an L: a row of w cells and a column of h
    for (int64_t x = 0; x < w; ++x) cells.push_back({x0 + x, y0});
    for (int64_t y = 1; y < h; ++y) cells.push_back({x0, y0 + y});
    rng.shuffle(cells);
    InstanceBuilder b;
    for (Vec2 c : cells) ASSERT_FALSE(b.add_node(c)) << "seed " << seed;
    for (int64_t x = 1; x < w; ++x) ASSERT_FALSE(b.add_edge({x0 + x - 1, y0}, {x0 + x, y0}));
    for (int64_t y = 1; y < h; ++y) ASSERT_FALSE(b.add_edge({x0, y0 + y - 1}, {x0, y0 + y}));
    Instance inst;
    ASSERT_FALSE(b.finish(inst)) << "seed " << seed;
    std::vector<NodeId> want(inst.num_nodes());
    std::iota(want.begin(), want.end(), 0);
    const auto& c = inst.cells();
    std::sort(want.begin(), want.end(),
              [&](NodeId a, NodeId d) { return c[a].y != c[d].y ? c[a].y < c[d].y : c[a].x < c[d].x; });
    ASSERT_EQ(nodes_by_row(inst), want) << "seed " << seed << " (" << w << " x " << h << ")";
  }
}

TEST(RowOrder, MatchesComparisonSort) {
  const uint64_t base = test::base_seed(8000);
  for (int i = 0; i < test::scaled(300); ++i) {
    RandomInstanceParams p;
    p.nodes = 1 + static_cast<uint32_t>(i % 200);
    p.spread = static_cast<uint32_t>(i % 4);
    Instance inst = random_instance(p, base + static_cast<uint64_t>(i));
    std::vector<NodeId> got = nodes_by_row(inst);
    std::vector<NodeId> want(inst.num_nodes());
    std::iota(want.begin(), want.end(), 0);
    const auto& c = inst.cells();
    std::sort(want.begin(), want.end(),
              [&](NodeId a, NodeId b) { return c[a].y != c[b].y ? c[a].y < c[b].y : c[a].x < c[b].x; });
    ASSERT_EQ(got, want) << "seed " << base + static_cast<uint64_t>(i);
    size_t total = 0;
    for (const RowRun& r : row_runs(inst, got)) {
      ASSERT_LT(r.begin, r.end);
      for (uint32_t j = r.begin; j < r.end; ++j) EXPECT_EQ(c[got[j]].y, c[got[r.begin]].y);
      total += r.end - r.begin;
    }
    EXPECT_EQ(total, inst.num_nodes());
  }
}

// The constraint systems (gap and pair) replay random orders exactly as the
// Simulator does: same verdict, and the failing step is the simulator's.
TEST(Constraints, ReplayAgreesWithSimulator) {
  const uint64_t base = test::base_seed(9000);
  int collide = 0, clean = 0;
  for (int i = 0; i < test::scaled(3000); ++i) {
    uint64_t seed = base + static_cast<uint64_t>(i);
    Rng rng(seed * 31 + 5);
    RandomInstanceParams p;
    p.nodes = 3 + static_cast<uint32_t>(rng.below(30));
    p.ops = 1 + static_cast<uint32_t>(rng.below(12));
    p.max_coupling = 1 + static_cast<uint32_t>(rng.below(3));
    p.extra_edge_percent = rng.below(3) == 0 ? 30 : 0;
    p.horizontal_only = rng.below(2) == 0;
    p.spread = static_cast<uint32_t>(rng.below(3));
    Instance inst = random_instance(p, seed);
    FaceNets faces = FaceNets::build(inst);
    if (std::any_of(faces.coupling_breaks_cycle.begin(), faces.coupling_breaks_cycle.end(), [](char b) { return b; }))
      continue;  // the systems do not model cycle collisions (the solver checks them first)
    SpanningTree tree = SpanningTree::build(inst);
    std::vector<ConstraintSystem> systems;
    systems.push_back(build_pair_constraints(inst, tree));
    if (inst.horizontal_only()) systems.push_back(build_gap_constraints(inst, tree));
    std::vector<CouplingId> order(inst.couplings().size());
    std::iota(order.begin(), order.end(), 0);
    rng.shuffle(order);
    Simulator sim(inst);
    SimResult r = sim.run_order(order);
    for (const ConstraintSystem& sys : systems) {
      ReplayResult rr = replay_order(sys, order);
      ASSERT_EQ(rr.failed_step < order.size(), r.collision.has_value())
          << "seed " << seed << (sys.kind == ConstraintKind::Gaps ? " gaps" : " pairs");
      if (r.collision) {
        // The simulator reports the first collision; step i runs over [i, i+1].
        EXPECT_EQ(Rational(static_cast<int64_t>(rr.failed_step)) <= r.collision->time, true) << "seed " << seed;
        EXPECT_LT(r.collision->time, Rational(static_cast<int64_t>(rr.failed_step) + 1)) << "seed " << seed;
      }
    }
    (r.collision ? collide : clean) += 1;
  }
  EXPECT_GT(collide, 0);
  EXPECT_GT(clean, 0);
}

// build_pair_constraints (one tree walk per pair, a box scan over sorted
// cells, O(1) operation counts) gives exactly the constraints of its
// per-face twin (every pair, a walk per face): the same pairs, forms, bases
// and coefficients. Small random instances of every shape, and family
// instances with long paths (sparse, path) so that the scan box and the
// walks are large.
TEST(Constraints, PairBuilderMatchesPerFaceTwin) {
  const uint64_t base = test::base_seed(9400);
  int compared = 0, constraints = 0;
  for (int i = 0; i < test::scaled(2000); ++i) {
    const uint64_t seed = base + static_cast<uint64_t>(i);
    Rng rng(seed * 131 + 9);
    Instance inst;
    if (i % 4 == 3) {
      RandomFamilyParams f;
      f.family = static_cast<ShapeFamily>(rng.below(5));
      f.couplings = 5 + static_cast<uint32_t>(rng.below(40));
      f.max_coupling = 1 + static_cast<uint32_t>(rng.below(3));
      inst = random_family_instance(f, seed);
    } else {
      RandomInstanceParams p;
      p.nodes = 2 + static_cast<uint32_t>(rng.below(40));
      p.ops = static_cast<uint32_t>(rng.below(p.nodes / 2 + 2));
      p.max_coupling = 1 + static_cast<uint32_t>(rng.below(4));
      p.extra_edge_percent = rng.below(3) == 0 ? static_cast<uint32_t>(rng.below(60)) : 0;
      p.path_shape = rng.below(4) == 0;
      p.spread = static_cast<uint32_t>(rng.below(3));
      inst = random_instance(p, seed);
    }
    const FaceNets faces = FaceNets::build(inst);
    if (std::any_of(faces.coupling_breaks_cycle.begin(), faces.coupling_breaks_cycle.end(), [](char b) { return b; }))
      continue;  // the builder requires it
    const SpanningTree tree = SpanningTree::build(inst);
    const ConstraintSystem fast = build_pair_constraints(inst, tree);
    const ConstraintSystem twin = test::reference_pair_constraints(inst, tree);
    std::map<std::pair<uint32_t, uint32_t>, const CollisionConstraint*> by_pair;
    for (const CollisionConstraint& c : fast.constraints) {
      ASSERT_LT(c.region_a, c.region_b) << "seed " << seed;
      ASSERT_TRUE(by_pair.emplace(std::make_pair(c.region_a, c.region_b), &c).second) << "seed " << seed;
    }
    ASSERT_EQ(fast.constraints.size(), twin.constraints.size()) << "seed " << seed;
    for (const CollisionConstraint& t : twin.constraints) {
      auto it = by_pair.find({t.region_a, t.region_b});
      ASSERT_NE(it, by_pair.end()) << "seed " << seed << ": pair " << t.region_a << "," << t.region_b << " missing";
      const CollisionConstraint& c = *it->second;
      EXPECT_EQ(std::make_tuple(c.num_forms, c.form_index, c.base, c.rel, c.coef()),
                std::make_tuple(t.num_forms, t.form_index, t.base, t.rel, t.coef()))
          << "seed " << seed << ": pair " << t.region_a << "," << t.region_b;
    }
    ++compared;
    constraints += static_cast<int>(twin.constraints.size());
  }
  EXPECT_GT(compared, test::scaled(2000) / 2);
  EXPECT_GT(constraints, compared);
  std::printf("[ twin ] %d instances, %d constraints (seed %llu)\n", compared, constraints,
              static_cast<unsigned long long>(base));
}

// With stop_at_refuting the builder returns a prefix of the full system
// (the same constraints in the same order) ending at a constraint that only
// one coupling moves and whose step collides from its base values; without
// such a constraint, the whole system. Every stopped instance is NO by the
// brute-force twin (every order through the simulator) when it is small
// enough, and by the states engine on the full system otherwise.
// The interned coefficient rows against a std::map: equal rows give one
// pointer, distinct rows distinct ones, and every stored row keeps its values
// while the table grows (rows of 1-8 values drawn from a small range, so
// that most repeat).
TEST(Constraints, CoefRowsInternLikeAMap) {
  const uint64_t seed = test::base_seed(24810);
  Rng rng(seed);
  CoefRows table;
  std::map<std::vector<int64_t>, const int64_t*> twin;
  std::vector<std::pair<std::vector<int64_t>, const int64_t*>> seen;
  for (int i = 0; i < test::scaled(20000); ++i) {
    std::vector<int64_t> row(1 + rng.below(8));
    for (auto& v : row) v = static_cast<int64_t>(rng.below(5)) - 2;
    if (rng.below(50) == 0) row[0] = static_cast<int64_t>(rng.next());  // a rare large value
    const int64_t* p = table.intern(row.data(), static_cast<uint32_t>(row.size()));
    auto [it, added] = twin.emplace(row, p);
    ASSERT_EQ(it->second, p) << "seed " << seed << " row " << i << ": an equal row got another pointer";
    if (i % 7 == 0) seen.emplace_back(row, p);
  }
  ASSERT_EQ(table.size(), twin.size()) << "seed " << seed;
  std::set<const int64_t*> distinct;
  for (const auto& [row, p] : twin) distinct.insert(p);
  EXPECT_EQ(distinct.size(), twin.size()) << "seed " << seed << ": distinct rows share a pointer";
  for (const auto& [row, p] : seen) ASSERT_TRUE(std::equal(row.begin(), row.end(), p)) << "seed " << seed;
}

// Built systems keep one table for all their constraints, with each distinct
// row once (gap systems of horizontal instances, pair systems of any).
TEST(Constraints, BuiltSystemsShareOneTableOfDistinctRows) {
  const uint64_t base = test::base_seed(24820);
  int checked = 0;
  for (int i = 0; i < test::scaled(1500); ++i) {
    const uint64_t seed = base + static_cast<uint64_t>(i);
    const Instance inst = random_instance(horizontal_params(seed), seed);
    const FaceNets faces = FaceNets::build(inst);
    if (std::any_of(faces.coupling_breaks_cycle.begin(), faces.coupling_breaks_cycle.end(), [](char b) { return b; }))
      continue;
    const SpanningTree tree = SpanningTree::build(inst);
    for (const ConstraintSystem& sys : {build_gap_constraints(inst, tree), build_pair_constraints(inst, tree)}) {
      if (sys.constraints.empty()) continue;
      const CoefRows* table = sys.constraints[0].rows.get();
      std::set<std::vector<int64_t>> rows;
      for (const CollisionConstraint& c : sys.constraints) {
        ASSERT_EQ(c.rows.get(), table) << "seed " << seed;
        ASSERT_EQ(c.coef_rows.size(), c.rel.size()) << "seed " << seed;
        for (size_t j = 0; j < c.rel.size(); ++j) rows.emplace(c.coef_of(j), c.coef_of(j) + c.num_forms);
      }
      ASSERT_EQ(table->size(), rows.size()) << "seed " << seed;
      ++checked;
    }
  }
  EXPECT_GT(checked, test::scaled(1500) / 2) << "too few non-empty systems";
}

// The flat per-coupling index against per-coupling lists filled in
// constraint order (what it replaced), on the pair systems of random shapes.
TEST(Constraints, CouplingIndexMatchesPerCouplingLists) {
  const uint64_t base = test::base_seed(24830);
  size_t entries = 0;
  for (int i = 0; i < test::scaled(1500); ++i) {
    const uint64_t seed = base + static_cast<uint64_t>(i);
    RandomFamilyParams f;
    f.family = static_cast<ShapeFamily>(i % 5);
    f.couplings = 3 + static_cast<uint32_t>(i % 30);
    const Instance inst = random_family_instance(f, seed);
    const FaceNets faces = FaceNets::build(inst);
    if (std::any_of(faces.coupling_breaks_cycle.begin(), faces.coupling_breaks_cycle.end(), [](char b) { return b; }))
      continue;
    const ConstraintSystem sys = build_pair_constraints(inst, SpanningTree::build(inst));
    std::vector<std::vector<CouplingIndex::Entry>> lists(sys.num_couplings);
    for (uint32_t ci = 0; ci < sys.constraints.size(); ++ci)
      for (uint32_t j = 0; j < sys.constraints[ci].rel.size(); ++j)
        lists[sys.constraints[ci].rel[j]].push_back({ci, j});
    ASSERT_EQ(sys.of_coupling.size(), lists.size()) << "seed " << seed;
    for (size_t q = 0; q < lists.size(); ++q) {
      const auto got = sys.of_coupling[q];
      ASSERT_TRUE(std::equal(got.begin(), got.end(), lists[q].begin(), lists[q].end()))
          << "seed " << seed << " q " << q;
      entries += got.size();
    }
  }
  EXPECT_GT(entries, size_t{1000});
}

TEST(Constraints, StopAtRefutingIsAPrefixThatRefutes) {
  const uint64_t base = test::base_seed(9600);
  int stopped = 0, whole = 0, by_twin = 0;
  for (int i = 0; i < test::scaled(1500); ++i) {
    const uint64_t seed = base + static_cast<uint64_t>(i);
    Rng rng(seed * 17 + 3);
    RandomInstanceParams p;
    p.nodes = 3 + static_cast<uint32_t>(rng.below(40));
    p.ops = 1 + static_cast<uint32_t>(rng.below(p.nodes / 2 + 2));
    p.max_coupling = 1 + static_cast<uint32_t>(rng.below(3));
    p.extra_edge_percent = rng.below(3) == 0 ? static_cast<uint32_t>(rng.below(60)) : 0;
    p.spread = static_cast<uint32_t>(rng.below(3));
    const Instance inst = random_instance(p, seed);
    const FaceNets faces = FaceNets::build(inst);
    if (std::any_of(faces.coupling_breaks_cycle.begin(), faces.coupling_breaks_cycle.end(), [](char b) { return b; }))
      continue;
    const SpanningTree tree = SpanningTree::build(inst);
    const ConstraintSystem full = build_pair_constraints(inst, tree);
    const ConstraintSystem stop = build_pair_constraints(inst, tree, nullptr, true);
    EXPECT_EQ(full.refuting, kNone);
    ASSERT_LE(stop.constraints.size(), full.constraints.size()) << "seed " << seed;
    for (size_t k = 0; k < stop.constraints.size(); ++k) {
      const CollisionConstraint& a = stop.constraints[k];
      const CollisionConstraint& b = full.constraints[k];
      ASSERT_EQ(std::make_tuple(a.region_a, a.region_b, a.base, a.rel, a.coef(), a.form_index),
                std::make_tuple(b.region_a, b.region_b, b.base, b.rel, b.coef(), b.form_index))
          << "seed " << seed << " constraint " << k;
    }
    if (stop.refuting == kNone) {
      EXPECT_EQ(stop.constraints.size(), full.constraints.size()) << "seed " << seed;
      ++whole;
      continue;
    }
    ++stopped;
    ASSERT_EQ(stop.refuting + size_t{1}, stop.constraints.size()) << "seed " << seed;
    const CollisionConstraint& r = stop.constraints[stop.refuting];
    ASSERT_EQ(r.rel.size(), 1u) << "seed " << seed;
    EXPECT_TRUE(step_collides(r.base.data(), r.coef_of(0), r.num_forms)) << "seed " << seed;
    // No earlier constraint qualifies (the stop is at the first).
    for (size_t k = 0; k < stop.refuting; ++k) {
      const CollisionConstraint& c = stop.constraints[k];
      EXPECT_FALSE(c.rel.size() == 1 && step_collides(c.base.data(), c.coef_of(0), c.num_forms))
          << "seed " << seed << " constraint " << k;
    }
    if (inst.couplings().size() <= 6) {
      EXPECT_FALSE(test::reference_solve(inst).has_value()) << "seed " << seed;
      ++by_twin;
    }
  }
  EXPECT_GT(stopped, 50);
  EXPECT_GT(whole, 50);
  EXPECT_GT(by_twin, 20);
  std::printf("[ stop ] %d stopped (%d checked by every order), %d whole (seed %llu)\n", stopped, by_twin, whole,
              static_cast<unsigned long long>(base));
}

// Twin of the shared row order: the gap checker and the gap constraints from
// a PreparedInstance (its rows, runs and tree, built once) against the same
// functions from the bare Instance (which sort the rows and build the tree
// themselves), field for field, on seeded random horizontal instances and,
// one case in four, compiled random formulas (verify's case).
Instance prepared_twin_case(uint64_t seed, int i) {
  if (i % 4 != 3) return random_instance(horizontal_params(seed), seed);
  Rng rng(seed);
  const int n = static_cast<int>(rng.between(1, 6)), m = static_cast<int>(rng.between(1, 12));
  return compile_formula(test::random_cnf(rng, n, m, 1, 3, rng.below(3) == 0)).instance;
}

auto verdict_fields(const GapVerdict& v) {
  std::vector<std::pair<OpId, int64_t>> changes;
  for (const GapChange& c : v.changes) changes.emplace_back(c.op, c.delta);
  return std::make_tuple(v.collision_free, static_cast<int>(v.reason), v.row, v.left, v.right, v.initial_size,
                         v.final_size, changes, v.cycle, v.mismatch, v.gaps_checked, v.negative_gaps, v.cycles_checked,
                         v.open_cycles);
}

auto system_fields(const ConstraintSystem& s) {
  std::vector<std::tuple<uint32_t, uint32_t, uint32_t, std::vector<int64_t>, std::vector<CouplingId>,
                         std::vector<int64_t>, std::vector<uint8_t>>>
      cs;
  for (const CollisionConstraint& c : s.constraints)
    cs.emplace_back(c.region_a, c.region_b, c.num_forms, c.base, c.rel, c.coef(), c.form_index);
  std::vector<std::vector<std::pair<uint32_t, uint32_t>>> index(s.num_couplings);
  for (size_t q = 0; q < s.num_couplings; ++q)
    for (const auto& [ci, j] : s.of_coupling[q]) index[q].emplace_back(ci, j);
  return std::make_tuple(static_cast<int>(s.kind), s.num_couplings, s.candidate_pairs, s.refuting, index, cs);
}

TEST(PreparedRowsTwin, GapCheckerAndConstraintsAgreeWithTheInstancePath) {
  const uint64_t base = 24800;  // not scaled: the counts below are asserted
  int gaps = 0, cycles = 0, clean = 0, systems = 0;
  for (int i = 0; i < 4000; ++i) {
    const uint64_t seed = base + static_cast<uint64_t>(i);
    const Instance inst = prepared_twin_case(seed, i);
    ASSERT_TRUE(inst.horizontal_only()) << "seed " << seed;
    const PreparedInstance prep(inst);
    const std::vector<NodeId> rows = nodes_by_row(inst);
    ASSERT_EQ(prep.rows, rows) << "seed " << seed;
    std::vector<std::pair<uint32_t, uint32_t>> runs, prep_runs;
    for (const RowRun& r : row_runs(inst, rows)) runs.emplace_back(r.begin, r.end);
    for (const RowRun& r : prep.runs) prep_runs.emplace_back(r.begin, r.end);
    ASSERT_EQ(prep_runs, runs) << "seed " << seed;
    const GapVerdict v = check_gaps(inst);
    ASSERT_EQ(verdict_fields(check_gaps(prep)), verdict_fields(v)) << "seed " << seed;
    (v.reason == GapVerdict::Reason::Gap ? gaps : v.reason == GapVerdict::Reason::Cycle ? cycles : clean) += 1;
    if (std::any_of(prep.faces.coupling_breaks_cycle.begin(), prep.faces.coupling_breaks_cycle.end(),
                    [](char b) { return b != 0; }))
      continue;  // the gap constraints require no coupling breaking a cycle
    ++systems;
    ASSERT_EQ(system_fields(build_gap_constraints(prep)),
              system_fields(build_gap_constraints(inst, SpanningTree::build(inst))))
        << "seed " << seed;
  }
  EXPECT_GT(gaps, 100);
  EXPECT_GT(cycles, 20);
  EXPECT_GT(clean, 100);
  EXPECT_GT(systems, 1000);
}

}  // namespace
}  // namespace gridlock
