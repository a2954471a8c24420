// Animation: the exact motion of a schedule, in a form a player can show by
// interpolating linearly between events (render/animation_page.cpp and render/viewer/viewer.js draw it).
//
// Between two consecutive events (starts and ends of couplings) every
// coupling's progress is linear in time, so every face moves linearly
// (lattice/simulate.hpp). Cutting the spanning tree (lattice/motion.hpp) at
// every edge operation's tree edge leaves the rigid parts: the nodes of one
// part keep their relative positions for the whole schedule, so a player
// moves parts, not nodes. Parts form a tree (the part above each cut edge is
// the parent); a part moves relative to its parent by the cut edge's vector
// v times its coupling's progress, so its keyframes are two: displacement 0
// at its coupling's start, v at its end, linear in between. A part's position
// is the sum along its chain to the root part (which stands still), exactly
// what nested SVG groups compute; the data stays O(parts) however deep the
// tree. The regions whose width changes (inserted, grown and contracting
// nodes) take each face from the part of the node that face follows
// (RegionShape::ref), plus the growth's progress for a grown node's far face.
//
// All values are integers over one denominator D, the lcm of the start
// times' denominators: every event time and every displacement at an event
// is a multiple of 1/D (|values| < 2^51 under the bounds of schedule.hpp and
// instance.hpp, so they are exact in a JavaScript number too).
#pragma once

#include <optional>
#include <vector>

#include "lattice/instance.hpp"
#include "lattice/motion.hpp"
#include "lattice/rational.hpp"
#include "lattice/schedule.hpp"
#include "lattice/simulate.hpp"

namespace gridlock {

struct Animation {
  int64_t den = 1;                     // D
  std::vector<int64_t> events;         // event times * D, increasing; at least one
  std::vector<int64_t> start;          // per coupling: start time * D
  std::vector<uint32_t> part_of_node;  // per node: its rigid part
  struct Part {
    NodeId top = kNone;           // the node just below the cut edge (the root for part 0)
    uint32_t parent = kNone;      // the part above the cut edge (kNone for part 0)
    CouplingId coupling = kNone;  // the cut edge operation's coupling (kNone for part 0)
    // Displacement relative to the parent part, * D, at these events (indices
    // into events, increasing), linear in between and constant outside:
    // part 0 {0: (0,0)}; others {start: (0,0), end: D * v}.
    std::vector<uint32_t> key_event;
    std::vector<Vec2> key_disp;
  };
  std::vector<Part> parts;             // parents before children
  std::optional<Collision> collision;  // the simulator's first collision
  // Where a player stops: the last event; with a collision, the moment the
  // still pictures draw it (half way from its start to the next event, where
  // the overlap shows and motion is still linear).
  Rational stop;
  size_t keyframes() const;  // total over the parts (at most 2 per part)
};

// Runs the simulator on s and builds the keyframes. Requires
// check_schedule_bounds(inst, s) to pass. O(n + e log e) plus the simulator.
Animation build_animation(const Instance& inst, const Schedule& s);

// The moment at which a collision is drawn: half way from c.time to the next
// start or end of a coupling after it (or to c.time + 1).
Rational collision_draw_time(const Schedule& s, const Collision& c);

// Region r's exact rectangle at time t computed from the keyframes alone
// (what the player draws, in exact arithmetic): relative displacements
// summed along the chain of parts. O(depth) per face. Tests compare it with
// configuration_at.
RectQ animation_rect(const Instance& inst, const Regions& regions, const Animation& a, uint32_t r, const Rational& t);

}  // namespace gridlock
