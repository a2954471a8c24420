#include "lattice/animation.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace gridlock {

namespace {

Rational clamp01(const Rational& p) { return p < Rational(0) ? Rational(0) : p > Rational(1) ? Rational(1) : p; }

}  // namespace

size_t Animation::keyframes() const {
  size_t k = 0;
  for (const auto& p : parts) k += p.key_event.size();
  return k;
}

Rational collision_draw_time(const Schedule& s, const Collision& c) {
  Rational next = c.time + Rational(1);
  for (const Rational& t : s.start)
    for (const Rational& e : {t, t + Rational(1)})
      if (c.time < e && e < next) next = e;
  return c.time + (next - c.time) * Rational(1, 2);
}

Animation build_animation(const Instance& inst, const Schedule& s) {
  Animation a;
  Simulator sim(inst);
  a.collision = sim.run(s).collision;
  const SpanningTree& tree = sim.tree();
  const size_t nq = inst.couplings().size();
  for (const auto& t : s.start) a.den = std::lcm(a.den, t.den());
  const int64_t D = a.den;
  a.start.resize(nq);
  for (size_t q = 0; q < nq; ++q) {
    a.start[q] = s.start[q].num() * (D / s.start[q].den());
    a.events.push_back(a.start[q]);
    a.events.push_back(a.start[q] + D);
  }
  if (a.events.empty()) a.events.push_back(0);
  std::sort(a.events.begin(), a.events.end());
  a.events.erase(std::unique(a.events.begin(), a.events.end()), a.events.end());
  auto event_index = [&](int64_t t) {
    return static_cast<uint32_t>(std::lower_bound(a.events.begin(), a.events.end(), t) - a.events.begin());
  };

  // Parts: preorder over the tree, a new part below every cut edge.
  a.part_of_node.assign(inst.num_nodes(), kNone);
  for (NodeId w : tree.order) {
    if (w == tree.root || tree.parent_op[w] != kNone) {
      Animation::Part p;
      p.top = w;
      if (w != tree.root) {
        p.parent = a.part_of_node[tree.parent[w]];
        p.coupling = inst.ops()[tree.parent_op[w]].coupling;
      }
      a.part_of_node[w] = static_cast<uint32_t>(a.parts.size());
      a.parts.push_back(std::move(p));
    } else {
      a.part_of_node[w] = a.part_of_node[tree.parent[w]];
    }
  }
  // Keyframes, relative to the parent part: the root part stands still; a
  // child part moves by its cut edge's vector v while that edge's coupling
  // runs: 0 at its start, v at its end, linear in between (no other event
  // changes that velocity).
  a.parts[0].key_event = {0};
  a.parts[0].key_disp = {Vec2{0, 0}};
  for (size_t i = 1; i < a.parts.size(); ++i) {
    Animation::Part& p = a.parts[i];
    const int64_t Tq = a.start[p.coupling];
    p.key_event = {event_index(Tq), event_index(Tq + D)};
    p.key_disp = {Vec2{0, 0}, D * op_child_vector(inst, tree, p.top)};
  }
  if (a.collision) {
    a.stop = collision_draw_time(s, *a.collision);
  } else {
    a.stop = Rational(a.events.back(), D);
  }
  return a;
}

RectQ animation_rect(const Instance& inst, const Regions& regions, const Animation& a, uint32_t r, const Rational& t) {
  const Rational T = t * Rational(a.den);  // in units of 1/D
  // A part's displacement relative to its parent at T, from its keys.
  auto rel = [&](const Animation::Part& p) -> std::pair<Rational, Rational> {
    // j: the last key at or before T (or the first key).
    auto it = std::upper_bound(p.key_event.begin(), p.key_event.end(), T,
                               [&](const Rational& x, uint32_t e) { return x < Rational(a.events[e]); });
    size_t j = it == p.key_event.begin() ? 0 : static_cast<size_t>(it - p.key_event.begin()) - 1;
    Rational dx(p.key_disp[j].x), dy(p.key_disp[j].y);
    if (j + 1 < p.key_event.size() && Rational(a.events[p.key_event[j]]) < T) {
      const int64_t ta = a.events[p.key_event[j]], tb = a.events[p.key_event[j + 1]];
      Rational f = (T - Rational(ta)) / Rational(tb - ta);
      dx = dx + f * Rational(p.key_disp[j + 1].x - p.key_disp[j].x);
      dy = dy + f * Rational(p.key_disp[j + 1].y - p.key_disp[j].y);
    }
    return {dx, dy};
  };
  // The absolute displacement: the sum along the chain of parts to the root.
  auto disp = [&](NodeId w) -> std::pair<Rational, Rational> {
    Rational dx, dy;
    for (uint32_t p = a.part_of_node[w]; p != kNone; p = a.parts[p].parent) {
      auto [rx, ry] = rel(a.parts[p]);
      dx = dx + rx, dy = dy + ry;
    }
    return {dx / Rational(a.den), dy / Rational(a.den)};
  };
  const RegionShape& sh = regions.shapes[r];
  Rational c[4];
  for (int f = 0; f < 4; ++f) {
    auto [dx, dy] = disp(sh.ref[f]);
    c[f] = Rational(sh.base[f]) + (f < 2 ? dx : dy);
    if (sh.grow_op != kNone && f == sh.grow_face) {
      const CouplingId q = inst.ops()[sh.grow_op].coupling;
      c[f] = c[f] + Rational(sh.grow_sign) * clamp01((T - Rational(a.start[q])) / Rational(a.den));
    }
  }
  return RectQ{c[0], c[1], c[2], c[3]};
}

}  // namespace gridlock
