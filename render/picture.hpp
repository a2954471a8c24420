// Pictures of instances: SVG (for people), ASCII (for terminals), TikZ (for papers).
//
// SVG and TikZ draw nodes as squares, edges as lines, operations as arrows
// (expansion: double arrow; contraction: arrow toward u with a cross on the
// edge; growth: arrow into a dashed target cell), each coloured by its
// coupling and labelled with the operation name (and the coupling's, when it
// differs), and the anchor as a dot. Given a schedule and a moment, SVG draws
// the configuration at that moment instead, with inserted and grown nodes and
// any collision marked in red. Coordinates are drawn with doubles, which is
// fine for a picture; no verdict is ever taken from them.
#pragma once

#include <string>

#include "lattice/instance.hpp"
#include "lattice/rational.hpp"
#include "lattice/schedule.hpp"
#include "lattice/simulate.hpp"

namespace gridlock {

struct RenderOptions {
  const Schedule* schedule = nullptr;  // with time: draw the configuration then
  Rational time;
  const Collision* collision = nullptr;  // mark it
  std::string title;                     // drawn above the picture
  int cell_px = 40;                      // SVG pixels per grid unit
};

// O(n) plus the size of the output.
std::string render_svg(const Instance& inst, const RenderOptions& opt = {});
std::string render_tikz(const Instance& inst);
// One character per cell and one between cells: 'o' node, '@' anchor,
// '-' and '|' plain edges, 'E' expansion edge, 'C' contraction edge,
// '>' '<' '^' 'v' growth from the neighbour, '!' growth into an occupied
// cell; a legend of the operations follows.
// An instance wider or taller than 401 cells is not drawn: the text is one
// line "(too large for ASCII: W x H cells)"; ascii_too_large says so first
// (the command line makes it an error), "" when it fits.
std::string render_ascii(const Instance& inst);
std::string ascii_too_large(const Instance& inst);

}  // namespace gridlock
