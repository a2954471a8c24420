#include "gadgets/internal/canvas.hpp"

#include <stdexcept>
#include <utility>

namespace gridlock {

void Canvas::path(Vec2 a, Vec2 b) {
  if (a.x != b.x && a.y != b.y) throw std::logic_error("Canvas::path: ends not on one row or column");
  Vec2 step{(b.x > a.x) - (b.x < a.x), (b.y > a.y) - (b.y < a.y)};
  node(a);
  for (Vec2 c = a; !(c == b);) {
    Vec2 next = c + step;
    node(next);
    edge(c, next);
    c = next;
  }
}

void Canvas::expansion(const std::string& name, Vec2 u, Dir d) {
  if (!is_horizontal(d)) throw std::logic_error("Canvas::expansion: gadgets use horizontal expansions only");
  any_expansion(name, u, d);
}

void Canvas::any_expansion(const std::string& name, Vec2 u, Dir d) {
  edges_.emplace_back(u, u + unit(d));
  ops_.push_back(Op{name, u, d});
}

void Canvas::couple(const std::string& name, std::vector<std::string> ops) {
  couplings_.emplace_back(name, std::move(ops));
}

Instance Canvas::build() const {
  InstanceBuilder b;
  auto must = [](const std::optional<std::string>& e) {
    if (e) throw std::logic_error("gadget drawing is not a valid instance: " + *e);
  };
  b.reserve(nodes_.size(), edges_.size(), ops_.size(), couplings_.size() + ops_.size());
  for (Vec2 c : nodes_) must(b.add_node(c));
  for (const auto& [a, c] : edges_) must(b.add_edge(a, c));
  for (const Op& op : ops_) must(b.add_op(op.name, OpKind::Expand, op.u, op.d));
  for (const auto& [name, ops] : couplings_) must(b.add_coupling(name, ops));
  if (has_anchor_) must(b.set_anchor(anchor_));
  Instance out;
  if (auto e = b.finish(out)) throw std::logic_error("gadget drawing is not a valid instance: " + e->message);
  return out;
}

}  // namespace gridlock
