#include "support/reference_constraints.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "solver/internal/op_tree.hpp"

namespace gridlock::test {

namespace {

// coupling -> coefficient, zeros dropped (a std::map keeps it sorted).
struct Form {
  int64_t base = 0;
  std::map<CouplingId, int64_t> coef;
  void add(CouplingId q, int64_t c) {
    if ((coef[q] += c) == 0) coef.erase(q);
  }
};

Form minus(const Form& a, const Form& b) {
  Form r = a;
  r.base = a.base - b.base;
  for (const auto& [q, c] : b.coef) r.add(q, -c);
  return r;
}

// Face f of region r relative to node P: base + the walk from P to the
// face's reference node along f's axis, plus the growth term.
Form face_form(const Instance& inst, const Regions& regions, const OpTree& ot, uint32_t r, int f, NodeId P) {
  const RegionShape& sh = regions.shapes[r];
  Form out;
  out.base = sh.base[f];
  ot.for_each_op_on_path(P, sh.ref[f], [&](OpId k, int sign) {
    const Vec2 v = ot.child_vector(k);
    const int64_t d = f < 2 ? v.x : v.y;
    if (d != 0) out.add(inst.ops()[k].coupling, sign * d);
  });
  if (sh.grow_op != kNone && f == sh.grow_face) out.add(inst.ops()[sh.grow_op].coupling, sh.grow_sign);
  return out;
}

// The node whose displacement moves the region's box (constraints.cpp).
NodeId main_node(const Instance& inst, const RegionShape& sh) {
  if (sh.kind != RegionKind::Node) return inst.ops()[sh.id].u;
  const OpId k = inst.op_of_node(sh.id);
  const bool contracting_v = k != kNone && inst.ops()[k].kind == OpKind::Contract && inst.ops()[k].v == sh.id;
  return contracting_v ? inst.ops()[k].u : sh.id;
}

Vec2 base_cell(const Instance& inst, const RegionShape& sh) {
  if (sh.kind == RegionKind::Node) return inst.cells()[sh.id];
  const Operation& op = inst.ops()[sh.id];
  return inst.cells()[op.u] + unit(op.dir);
}

}  // namespace

ConstraintSystem reference_pair_constraints(const Instance& inst, const SpanningTree& tree) {
  const Regions regions = Regions::build(inst);
  const OpTree ot(inst, tree);
  ConstraintSystem sys;
  sys.kind = ConstraintKind::Pairs;
  sys.num_couplings = inst.couplings().size();
  const auto nr = static_cast<uint32_t>(regions.size());
  for (uint32_t a = 0; a < nr; ++a)
    for (uint32_t b = a + 1; b < nr; ++b) {
      const RegionShape& sa = regions.shapes[a];
      const RegionShape& sb = regions.shapes[b];
      const NodeId ma = main_node(inst, sa), mb = main_node(inst, sb);
      int64_t H = 0, V = 0;
      ot.for_each_op_on_path(ma, mb, [&](OpId k, int) { (is_horizontal(inst.ops()[k].dir) ? H : V) += 1; });
      const Vec2 d = base_cell(inst, sa) - base_cell(inst, sb);
      if (std::abs(d.x) > H || std::abs(d.y) > V) continue;
      Form fa[4], fb[4];
      for (int f = 0; f < 4; ++f)
        fa[f] = face_form(inst, regions, ot, a, f, ma), fb[f] = face_form(inst, regions, ot, b, f, ma);
      const Form forms[8] = {minus(fa[1], fb[0]), minus(fb[1], fa[0]), minus(fa[3], fb[2]), minus(fb[3], fa[2]),
                             minus(fa[1], fa[0]), minus(fb[1], fb[0]), minus(fa[3], fa[2]), minus(fb[3], fb[2])};
      bool never = false;
      for (const Form& f : forms) {
        int64_t mx = f.base;
        for (const auto& [q, c] : f.coef) mx += std::max<int64_t>(c, 0);
        never = never || mx <= 0;
      }
      if (never) continue;
      CollisionConstraint c;
      c.region_a = a;
      c.region_b = b;
      std::map<CouplingId, std::vector<int64_t>> by_coupling;  // per coupling: its coefficient in each kept form
      for (uint8_t i = 0; i < 8; ++i) {
        if (forms[i].coef.empty()) continue;
        c.form_index.push_back(i);
        c.base.push_back(forms[i].base);
      }
      c.num_forms = static_cast<uint32_t>(c.form_index.size());
      if (c.num_forms == 0) throw std::logic_error("reference: a permanent overlap");
      for (uint32_t i = 0; i < c.num_forms; ++i)
        for (const auto& [q, v] : forms[c.form_index[i]].coef) {
          auto& row = by_coupling[q];
          row.resize(c.num_forms, 0);
          row[i] = v;
        }
      std::vector<int64_t> coef;
      for (const auto& [q, row] : by_coupling) {
        c.rel.push_back(q);
        coef.insert(coef.end(), row.begin(), row.end());
      }
      c.set_coef(coef);
      sys.constraints.push_back(std::move(c));
    }
  sys.index();
  return sys;
}

}  // namespace gridlock::test
