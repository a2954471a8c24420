#include "solver/planted.hpp"

#include <stdexcept>

#include "common/random.hpp"
#include "lattice/prepared.hpp"
#include "solver/internal/constraints.hpp"

namespace gridlock {
namespace {

// The instance with only the couplings marked in keep (same shape and anchor).
Instance restrict_to(const Instance& inst, const std::vector<char>& keep) {
  InstanceBuilder b;
  for (const Vec2& c : inst.cells()) b.add_node(c);
  for (const Edge& e : inst.edges()) b.add_edge(inst.cells()[e.a], inst.cells()[e.b]);
  if (inst.has_explicit_anchor()) b.set_anchor(inst.cells()[inst.anchor()]);
  for (CouplingId q = 0; q < inst.couplings().size(); ++q) {
    if (!keep[q]) continue;
    const Coupling& cq = inst.couplings()[q];
    std::vector<std::string> names;
    for (OpId o : cq.ops) {
      const Operation& op = inst.ops()[o];
      if (auto err = b.add_op(op.name, op.kind, inst.cells()[op.u], op.dir))
        throw std::logic_error("plant_schedule: " + *err);
      names.push_back(op.name);
    }
    if (names.size() > 1 || names[0] != cq.name)
      if (auto err = b.add_coupling(cq.name, names)) throw std::logic_error("plant_schedule: " + *err);
  }
  Instance out;
  if (auto err = b.finish(out)) throw std::logic_error("plant_schedule: " + err->message);
  return out;
}

}  // namespace

PlantedInstance plant_schedule(const Instance& inst, uint64_t seed, size_t max_couplings) {
  const PreparedInstance prep(inst);
  const size_t k = inst.couplings().size();
  std::vector<CouplingId> order;
  for (CouplingId q = 0; q < k; ++q)
    if (!prep.faces.coupling_breaks_cycle[q]) order.push_back(q);
  const ConstraintSystem sys = build_pair_constraints(prep);
  Rng rng(seed * 0x9E3779B97F4A7C15ULL + 0x5EED);
  rng.shuffle(order);
  std::vector<std::vector<int64_t>> cur(sys.constraints.size());
  for (size_t ci = 0; ci < cur.size(); ++ci) cur[ci] = sys.constraints[ci].base;
  std::vector<char> keep(k, 0);
  PlantedInstance out;
  for (CouplingId q : order) {
    if (max_couplings != 0 && out.hidden_order.size() == max_couplings) break;
    bool collides = false;
    for (auto [ci, j] : sys.of_coupling[q]) {
      const CollisionConstraint& c = sys.constraints[ci];
      if (step_collides(cur[ci].data(), c.coef_of(j), c.num_forms)) collides = true;
    }
    if (collides) continue;
    keep[q] = 1;
    out.hidden_order.push_back(inst.couplings()[q].name);
    for (auto [ci, j] : sys.of_coupling[q])
      for (uint32_t i = 0; i < sys.constraints[ci].num_forms; ++i) cur[ci][i] += sys.constraints[ci].coef_of(j)[i];
  }
  out.dropped = k - out.hidden_order.size();
  out.instance = restrict_to(inst, keep);
  return out;
}

PlantedInstance planted_family_instance(const RandomFamilyParams& f, uint64_t seed) {
  PlantedInstance best;
  for (uint32_t factor = 2; factor <= 4; factor *= 2) {
    RandomFamilyParams g = f;
    g.couplings = f.couplings * factor;
    PlantedInstance p = plant_schedule(random_family_instance(g, seed), seed, f.couplings);
    const bool enough = p.hidden_order.size() >= f.couplings;
    if (p.hidden_order.size() > best.hidden_order.size()) best = std::move(p);
    if (enough) break;
  }
  return best;
}

}  // namespace gridlock
