#include "lattice/animation.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace gridlock {

namespace {

// Exact division of a value that is known to be an integer multiple.
int64_t exact_div(__int128 a, int64_t b) {
  if (a % b != 0) throw std::logic_error("animation: keyframe interpolation is not exact");
  return static_cast<int64_t>(a / b);
}

// The displacement * D of part p at event index e (any event, not only a key).
Vec2 disp_at_event(const Animation& a, const Animation::Part& p, uint32_t e) {
  auto it = std::lower_bound(p.key_event.begin(), p.key_event.end(), e);
  size_t j = static_cast<size_t>(it - p.key_event.begin());
  if (j < p.key_event.size() && p.key_event[j] == e) return p.key_disp[j];
  if (j == 0) return p.key_disp.front();
  if (j == p.key_event.size()) return p.key_disp.back();
  const int64_t ta = a.events[p.key_event[j - 1]], tb = a.events[p.key_event[j]], t = a.events[e];
  const Vec2 va = p.key_disp[j - 1], vb = p.key_disp[j];
  return {va.x + exact_div(static_cast<__int128>(vb.x - va.x) * (t - ta), tb - ta),
          va.y + exact_div(static_cast<__int128>(vb.y - va.y) * (t - ta), tb - ta)};
}

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
  const uint32_t last = static_cast<uint32_t>(a.events.size() - 1);

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
  // Keyframes: the root part stands still; a child part adds its cut edge's
  // motion to its parent's, so its keys are the parent's plus the start and
  // end of its own coupling (collinear keys dropped).
  a.parts[0].key_event = {0, last};
  a.parts[0].key_disp = {Vec2{0, 0}, Vec2{0, 0}};
  if (last == 0) a.parts[0].key_event.pop_back(), a.parts[0].key_disp.pop_back();
  for (size_t i = 1; i < a.parts.size(); ++i) {
    Animation::Part& p = a.parts[i];
    const Animation::Part& up = a.parts[p.parent];
    const int64_t Tq = a.start[p.coupling];
    const Vec2 v = op_child_vector(inst, tree, p.top);
    std::vector<uint32_t> keys = up.key_event;
    keys.push_back(event_index(Tq));
    keys.push_back(event_index(Tq + D));
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    std::vector<Vec2> vals(keys.size());
    for (size_t j = 0; j < keys.size(); ++j)
      vals[j] = disp_at_event(a, up, keys[j]) + std::clamp<int64_t>(a.events[keys[j]] - Tq, 0, D) * v;
    for (size_t j = 0; j < keys.size(); ++j) {
      if (j > 0 && j + 1 < keys.size()) {
        // Drop a key that lies on the line through its neighbours.
        const int64_t t0 = a.events[p.key_event.back()], t1 = a.events[keys[j]], t2 = a.events[keys[j + 1]];
        const Vec2 v0 = p.key_disp.back(), v1 = vals[j], v2 = vals[j + 1];
        auto coll = [&](int64_t y0, int64_t y1, int64_t y2) {
          return static_cast<__int128>(y1 - y0) * (t2 - t1) == static_cast<__int128>(y2 - y1) * (t1 - t0);
        };
        if (coll(v0.x, v1.x, v2.x) && coll(v0.y, v1.y, v2.y)) continue;
      }
      p.key_event.push_back(keys[j]);
      p.key_disp.push_back(vals[j]);
    }
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
  auto disp = [&](NodeId w) -> std::pair<Rational, Rational> {
    const Animation::Part& p = a.parts[a.part_of_node[w]];
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
