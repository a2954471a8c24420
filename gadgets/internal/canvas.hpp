// A shape under construction: the gadgets draw on it, the compiler turns it
// into an Instance.
//
// The gadgets of the discrete reduction use horizontal edge expansions only;
// the separation gadget of the continuous reduction adds one vertical one. So
// a Canvas knows three things: nodes (cells), plain edges between orthogonal
// neighbours, and named edge expansions. Couplings are added
// by name at the end (build). Nothing is checked until build(), which runs
// every rule of lattice/instance.hpp through InstanceBuilder, so a gadget
// that draws something impossible is a loud error, never a silent one.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "lattice/instance.hpp"

namespace gridlock {

class Canvas {
 public:
  void node(Vec2 c) { nodes_.push_back(c); }
  // Nodes a, a+step, ..., b along one axis, joined by plain edges
  // (a and b on one row or one column; a == b gives a single node).
  void path(Vec2 a, Vec2 b);
  void edge(Vec2 a, Vec2 b) { edges_.emplace_back(a, b); }
  // A horizontal expansion on the edge between u and u + unit(d): the edge is
  // added here (do not add it as a plain edge too). Requires is_horizontal(d).
  void expansion(const std::string& name, Vec2 u, Dir d);
  // The same along any direction (the separation gadget's vertical lift).
  void any_expansion(const std::string& name, Vec2 u, Dir d);
  // Puts the operations named in ops into one coupling called name.
  // ops is taken by value: a caller done with its list moves it in.
  void couple(const std::string& name, std::vector<std::string> ops);
  void anchor(Vec2 c) {
    anchor_ = c;
    has_anchor_ = true;
  }

  // Room for `nodes` nodes and as many edges (a tree drawing has one edge
  // fewer), so drawing a compiled formula does not regrow them. O(nodes).
  void reserve(size_t nodes) {
    nodes_.reserve(nodes);
    edges_.reserve(nodes);
  }
  size_t num_nodes() const { return nodes_.size(); }
  size_t num_ops() const { return ops_.size(); }

  // The instance; throws std::logic_error naming the broken rule if the
  // drawing is not a valid instance (a bug in a gadget, never user input).
  // O(size) expected.
  Instance build() const;

 private:
  struct Op {
    std::string name;
    Vec2 u;
    Dir d;
  };
  std::vector<Vec2> nodes_;
  std::vector<std::pair<Vec2, Vec2>> edges_;
  std::vector<Op> ops_;
  std::vector<std::pair<std::string, std::vector<std::string>>> couplings_;
  Vec2 anchor_{};
  bool has_anchor_ = false;
};

}  // namespace gridlock
