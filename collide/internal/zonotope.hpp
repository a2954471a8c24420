// The continuous pair test's geometry (docs/collide.md): the zonotope of the
// path's nets through its support function, the projection of the own
// progresses, and the support table the traversal keeps. Internal to
// collide/ (not installed).
#pragma once

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "collide/internal/angle_tree.hpp"
#include "collide/internal/pair_system.hpp"

namespace gridlock::pairs {

// The support function of the zonotope of gens on the normal set.
struct Normals {
  std::vector<Vec2> u;
  std::vector<i128> h;
};

// The line direction of w != 0: primitive, with x > 0 or (x == 0, y > 0).
Vec2 line_direction(Vec2 w);

// The axis normals and both normals of every line direction among gens,
// with the zonotope's support on each. O(K log K + d K).
Normals normals_of(const std::vector<std::pair<CouplingId, Vec2>>& gens);

// All constraints on (v0, v1) after eliminating Delta'. O(|N|).
std::vector<Lin> projected_constraints(const PairSystem& S, const Normals& N);

// Is the projected system on the own progresses feasible? N must hold the
// support of the zonotope of S.gens on a set of normals that contains the
// axis normals and both normals of every direction among S.gens (a larger
// set is harmless: the extra conditions hold whenever 0 lies in the open
// polygon Z' - R).
bool projected_feasible(const PairSystem& S, const Normals& N);

// The support values of the zonotope of the path's non-zero nets, kept as
// the path changes: on the four axis normals, and on both normals of every
// line direction present among the nets (with how many nets have it).
struct SupportTable {
  struct Line {
    uint32_t count = 0;            // active nets on this line
    i128 h_plus = 0, h_minus = 0;  // support on (-d.y, d.x) and on (d.y, -d.x)
  };
  i128 h_axis[4] = {0, 0, 0, 0};                      // on (1,0), (-1,0), (0,1), (0,-1)
  std::map<std::pair<int64_t, int64_t>, Line> lines;  // by line direction, axis lines excluded
  size_t empty_lines = 0;                             // lines with count 0

  static i128 pos(i128 v) { return v > 0 ? v : 0; }
  static i128 dot_plus(Vec2 d, Vec2 w) { return static_cast<i128>(-d.y) * w.x + static_cast<i128>(d.x) * w.y; }
  // Adds (sign +1) or removes (-1) the contribution of a net w: O(lines).
  void contribute(Vec2 w, int sign) {
    h_axis[0] += sign * pos(w.x), h_axis[1] += sign * pos(-w.x);
    h_axis[2] += sign * pos(w.y), h_axis[3] += sign * pos(-w.y);
    for (auto& [key, line] : lines) {
      i128 t = dot_plus(Vec2{key.first, key.second}, w);
      line.h_plus += sign * pos(t), line.h_minus += sign * pos(-t);
    }
  }
  // The table as normals and supports (the order of normals_of's axes first).
  Normals normals() const {
    Normals N;
    N.u = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    N.h.assign(h_axis, h_axis + 4);
    for (const auto& [key, line] : lines) {
      if (line.count == 0) continue;
      N.u.push_back({-key.second, key.first}), N.h.push_back(line.h_plus);
      N.u.push_back({key.second, -key.first}), N.h.push_back(line.h_minus);
    }
    return N;
  }
};

// What the own progresses allow for Delta' (docs/collide.md, "The angle
// tree"): J = {v in [0,1]^nv : widths > 0, rectangle R(v) non-empty} (an
// unused variable is pinned to 0). J empty: no overlap. Otherwise the
// union U of the open boxes R(v) over J is open and convex with
// cl U = conv{cl R(v) : v a vertex of cl J} (box bounds are affine in v,
// so R at a convex combination is the Minkowski combination of the R's).
// Fills the corners of -cl R(v) at the vertices of cl J, scaled by *scale
// (the lcm of the vertices' denominators) to integers.
enum class OwnPolygon { Empty, Ready, TooFine };

OwnPolygon own_polygon(const PairSystem& S, int64_t* scale, std::vector<WidePoint>* pts);

}  // namespace gridlock::pairs
