// The animated schedule viewer: one self-contained HTML file (inline style,
// inline script, the data as embedded JSON; no network, no external font).
//
// The page receives the exact keyframes of lattice/animation.hpp (integers
// over one denominator) and only interpolates linearly between consecutive
// events, which is exact because the motion is linear there. It draws one
// SVG group per rigid part (translated as a whole) and the resizing regions
// on their own, so a frame costs O(parts + resizing regions), not O(nodes).
//
// Controls: play/pause, a time slider, step to the previous/next event,
// speed; the running couplings are highlighted and listed; the first
// collision is marked (the colliding regions outlined, the overlap shaded)
// and the player stops at the moment the still pictures draw it; hovering a
// node names it. The URL fragment #t=P/Q (or #t=3) sets the time; the page
// keeps a JSON summary of what it draws in <pre id="state"> (time, running
// couplings, the colliding regions' and the overlap's boxes in grid units
// and in CSS pixels, and every script error), which the browser tests read.
#pragma once

#include <string>

#include "lattice/animation.hpp"
#include "lattice/instance.hpp"
#include "lattice/schedule.hpp"

namespace gridlock {

// The whole HTML text: render/viewer/viewer.html with viewer.css and
// viewer.js inlined and the data embedded as JSON (made safe inside
// <script>); the title is shown as text, whatever it holds. O(n + keyframes).
std::string animation_html(const Instance& inst, const Schedule& s, const Animation& a, const std::string& title);

}  // namespace gridlock
