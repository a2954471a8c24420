// Grid geometry: directions, integer vectors and cells.
//
// A cell (x, y) is the closed unit square [x, x+1] x [y, y+1] (docs/model.md).
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace gridlock {

struct Vec2 {
  int64_t x = 0;
  int64_t y = 0;
  friend Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
  friend Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
  friend Vec2 operator*(int64_t k, Vec2 a) { return {k * a.x, k * a.y}; }
  Vec2& operator+=(Vec2 b) {
    x += b.x, y += b.y;
    return *this;
  }
  Vec2& operator-=(Vec2 b) {
    x -= b.x, y -= b.y;
    return *this;
  }
  friend bool operator==(Vec2 a, Vec2 b) = default;
  bool is_zero() const { return x == 0 && y == 0; }
};

// The four grid directions, in counter-clockwise order (so (d + 1) % 4 turns
// left by 90 degrees; the face walk in lattice/motion.cpp relies on it).
enum class Dir : uint8_t { PosX = 0, PosY = 1, NegX = 2, NegY = 3 };

inline constexpr Dir kDirs[4] = {Dir::PosX, Dir::PosY, Dir::NegX, Dir::NegY};

inline Vec2 unit(Dir d) {
  switch (d) {
    case Dir::PosX: return {1, 0};
    case Dir::PosY: return {0, 1};
    case Dir::NegX: return {-1, 0};
    case Dir::NegY: return {0, -1};
  }
  return {0, 0};
}
inline Dir opposite(Dir d) { return static_cast<Dir>((static_cast<int>(d) + 2) % 4); }
inline bool is_horizontal(Dir d) { return d == Dir::PosX || d == Dir::NegX; }
inline bool is_positive(Dir d) { return d == Dir::PosX || d == Dir::PosY; }
inline const char* dir_name(Dir d) {
  static const char* names[4] = {"+x", "+y", "-x", "-y"};
  return names[static_cast<int>(d)];
}
// Accepts exactly "+x", "-x", "+y", "-y" (docs/grid-format.md: a bare "x"
// or "y" is an error, as the message says, not a silent +x / +y).
inline std::optional<Dir> parse_dir(std::string_view s) {
  if (s == "+x") return Dir::PosX;
  if (s == "-x") return Dir::NegX;
  if (s == "+y") return Dir::PosY;
  if (s == "-y") return Dir::NegY;
  return std::nullopt;
}
// The direction from a to b when b is an orthogonal neighbour of a.
inline std::optional<Dir> dir_between(Vec2 a, Vec2 b) {
  Vec2 d = b - a;
  for (Dir dir : kDirs)
    if (unit(dir) == d) return dir;
  return std::nullopt;
}

}  // namespace gridlock
