// The animation pages the command line writes: `gridlock animate`, and the
// pages verify and fuzz write beside their still pictures. The page itself
// is render/animation_page.hpp; this file only chooses schedules and writes.
#pragma once

#include <string>
#include <vector>

#include "lattice/animation.hpp"
#include "lattice/instance.hpp"
#include "lattice/schedule.hpp"

namespace gridlock {

// Builds the animation (runs the simulator) and writes the page to path
// (throws UserError if unwritable). Returns the animation for messages.
Animation write_animation(const std::string& path, const Instance& inst, const Schedule& s, const std::string& title);

struct VerifyResult;

// Animations of a verify/fuzz result's schedules, written into dir: one page
// per non-empty schedule (sat-schedule.html: CaDiCaL's model lifted;
// solver-schedule.html: the exact solver's order), or, when both are empty,
// all-false-schedule.html (the all-false assignment lifted, which collides
// when the formula is unsatisfiable). Returns the files written.
std::vector<std::string> write_result_animations(const VerifyResult& r, const std::string& dir);

}  // namespace gridlock
