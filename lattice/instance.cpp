#include "lattice/instance.hpp"

#include <algorithm>
#include <initializer_list>
#include <string_view>

namespace gridlock {

const char* op_kind_name(OpKind k) {
  switch (k) {
    case OpKind::Expand: return "expand";
    case OpKind::Grow: return "grow";
    case OpKind::Contract: return "contract";
  }
  return "?";
}

bool valid_name(const std::string& s) {
  if (s.empty() || s.size() > 64 || s[0] == '-' || s[0] == '+') return false;
  for (char ch : s) {
    bool ok = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') || ch == '_' ||
              ch == '.' || ch == ':' || ch == '~' || ch == '+' || ch == '\'' || ch == '-';
    if (!ok) return false;
  }
  return true;
}

NodeId Instance::node_at(Vec2 c) const {
  const uint32_t w = cell_index_.find(cell_key(c));
  return w == FlatMap64::kAbsent ? kNone : w;
}

OpId Instance::find_op(const std::string& name) const {
  auto it = op_index_.find(name);
  return it == op_index_.end() ? kNone : it->second;
}

CouplingId Instance::find_coupling(const std::string& name) const {
  auto it = coupling_index_.find(name);
  return it == coupling_index_.end() ? kNone : it->second;
}

bool Instance::horizontal_only() const {
  return std::all_of(ops_.begin(), ops_.end(), [](const Operation& o) { return is_horizontal(o.dir); });
}

std::string Instance::node_label(NodeId w) const {
  return "(" + std::to_string(cells_[w].x) + "," + std::to_string(cells_[w].y) + ")";
}

Instance Instance::with_anchor(NodeId w) const {
  Instance copy = *this;
  copy.anchor_ = w;
  copy.explicit_anchor_ = true;
  return copy;
}

namespace {
// One allocation for a message built from pieces (a + b + c makes temporaries).
std::string cat(std::initializer_list<std::string_view> parts) {
  std::string s;
  for (std::string_view p : parts) s += p;
  return s;
}
std::string cell_str(Vec2 c) { return "(" + std::to_string(c.x) + "," + std::to_string(c.y) + ")"; }
bool in_range(Vec2 c) {
  return c.x >= -kMaxCoordinate && c.x <= kMaxCoordinate && c.y >= -kMaxCoordinate && c.y <= kMaxCoordinate;
}
}  // namespace

void InstanceBuilder::reserve(size_t nodes, size_t edges, size_t ops, size_t couplings) {
  inst_.cells_.reserve(nodes);
  inst_.cell_index_.reserve(nodes);
  inst_.adj_.reserve(4 * nodes);
  inst_.adj_edge_.reserve(4 * nodes);
  inst_.op_of_node_.reserve(nodes);
  inst_.edges_.reserve(edges);
  inst_.ops_.reserve(ops);
  inst_.op_index_.reserve(ops);
  inst_.couplings_.reserve(couplings);
  inst_.coupling_index_.reserve(couplings);
}

std::optional<std::string> InstanceBuilder::add_node(Vec2 cell) {
  if (!in_range(cell)) return "coordinate out of range (|x|, |y| <= " + std::to_string(kMaxCoordinate) + ")";
  if (static_cast<int64_t>(inst_.cells_.size()) >= kMaxNodes)
    return "too many nodes (at most " + std::to_string(kMaxNodes) + ")";
  if (!inst_.cell_index_.emplace(cell_key(cell), static_cast<NodeId>(inst_.cells_.size())).second)
    return "two nodes in cell " + cell_str(cell);
  inst_.cells_.push_back(cell);
  for (int i = 0; i < 4; ++i) inst_.adj_.push_back(kNone), inst_.adj_edge_.push_back(kNone);
  inst_.op_of_node_.push_back(kNone);
  return std::nullopt;
}

std::optional<std::string> InstanceBuilder::add_edge(Vec2 a, Vec2 b) {
  if (!in_range(a) || !in_range(b)) return "coordinate out of range";
  NodeId na = inst_.node_at(a), nb = inst_.node_at(b);
  if (na == kNone) return "edge end " + cell_str(a) + " holds no node";
  if (nb == kNone) return "edge end " + cell_str(b) + " holds no node";
  auto d = dir_between(a, b);
  if (!d) return "edge between non-adjacent cells " + cell_str(a) + " and " + cell_str(b);
  if (inst_.adj_[4 * na + static_cast<int>(*d)] != kNone)
    return "edge between " + cell_str(a) + " and " + cell_str(b) + " given twice";
  auto e = static_cast<uint32_t>(inst_.edges_.size());
  inst_.edges_.push_back(Edge{na, nb, kNone});
  inst_.adj_[4 * na + static_cast<int>(*d)] = nb;
  inst_.adj_[4 * nb + static_cast<int>(opposite(*d))] = na;
  inst_.adj_edge_[4 * na + static_cast<int>(*d)] = e;
  inst_.adj_edge_[4 * nb + static_cast<int>(opposite(*d))] = e;
  return std::nullopt;
}

std::optional<std::string> InstanceBuilder::add_op(const std::string& name, OpKind kind, Vec2 u, Dir dir) {
  if (!valid_name(name)) return "bad operation name '" + name + "'";
  if (inst_.op_index_.count(name)) return "operation '" + name + "' defined twice";
  if (!in_range(u)) return "coordinate out of range";
  NodeId nu = inst_.node_at(u);
  if (nu == kNone) return "operation '" + name + "' on cell " + cell_str(u) + ", which holds no node";
  Vec2 c = u + unit(dir);
  NodeId joined = inst_.adj_[4 * nu + static_cast<int>(dir)];
  Operation op{name, kind, nu, dir, kNone, kNone};
  if (kind == OpKind::Grow) {
    if (joined != kNone)
      return "growth '" + name + "' into " + cell_str(c) + ", which holds a node joined to " + cell_str(u) +
             " by an edge (use expand)";
  } else {
    if (joined == kNone)
      return std::string(op_kind_name(kind)) + " '" + name + "' needs an edge from " + cell_str(u) + " to " +
             cell_str(c) + ", and there is none";
    op.v = joined;
  }
  auto id = static_cast<OpId>(inst_.ops_.size());
  for (NodeId w : {op.u, op.v}) {
    if (w == kNone) continue;
    if (inst_.op_of_node_[w] != kNone)
      return "node " + inst_.node_label(w) + " already takes part in operation '" +
             inst_.ops_[inst_.op_of_node_[w]].name + "'";
  }
  for (NodeId w : {op.u, op.v})
    if (w != kNone) inst_.op_of_node_[w] = id;
  if (op.is_edge_op()) inst_.edges_[inst_.adj_edge_[4 * nu + static_cast<int>(dir)]].op = id;
  inst_.op_index_[name] = id;
  inst_.ops_.push_back(op);
  return std::nullopt;
}

std::optional<std::string> InstanceBuilder::add_coupling(const std::string& name, const std::vector<std::string>& ops) {
  if (!valid_name(name)) return "bad coupling name '" + name + "'";
  if (inst_.coupling_index_.count(name)) return "coupling '" + name + "' defined twice";
  if (ops.empty()) return "coupling '" + name + "' has no operations";
  auto id = static_cast<CouplingId>(inst_.couplings_.size());
  Coupling q{name, {}};
  for (const auto& o : ops) {
    OpId op = inst_.find_op(o);
    if (op == kNone) return cat({"unknown operation '", o, "' in coupling '", name, "'"});
    if (inst_.ops_[op].coupling == id) return cat({"operation '", o, "' named twice in coupling '", name, "'"});
    if (inst_.ops_[op].coupling != kNone)
      return cat({"operation '", o, "' is already in coupling '", inst_.couplings_[inst_.ops_[op].coupling].name, "'"});
    inst_.ops_[op].coupling = id;
    q.ops.push_back(op);
  }
  inst_.coupling_index_[name] = id;
  inst_.couplings_.push_back(std::move(q));
  return std::nullopt;
}

std::optional<std::string> InstanceBuilder::set_anchor(Vec2 cell) {
  NodeId w = inst_.node_at(cell);
  if (w == kNone) return "anchor " + cell_str(cell) + " holds no node";
  inst_.anchor_ = w;
  inst_.explicit_anchor_ = true;
  return std::nullopt;
}

std::optional<InstanceBuilder::FinishError> InstanceBuilder::finish(Instance& out) {
  if (inst_.cells_.empty()) return FinishError{"the shape has no nodes", -1};
  for (OpId o = 0; o < inst_.ops_.size(); ++o) {
    if (inst_.ops_[o].coupling != kNone) continue;
    const std::string& name = inst_.ops_[o].name;
    if (inst_.coupling_index_.count(name))
      return FinishError{"operation '" + name + "' is in no coupling, and its singleton coupling's name is taken", -1};
    auto id = static_cast<CouplingId>(inst_.couplings_.size());
    inst_.couplings_.push_back(Coupling{name, {o}});
    inst_.coupling_index_[name] = id;
    inst_.ops_[o].coupling = id;
  }
  // Connectivity, by an iterative search from node 0.
  std::vector<char> seen(inst_.cells_.size(), 0);
  std::vector<NodeId> stack{0};
  seen[0] = 1;
  while (!stack.empty()) {
    NodeId w = stack.back();
    stack.pop_back();
    for (int d = 0; d < 4; ++d) {
      NodeId x = inst_.adj_[4 * w + d];
      if (x != kNone && !seen[x]) seen[x] = 1, stack.push_back(x);
    }
  }
  for (NodeId w = 0; w < seen.size(); ++w)
    if (!seen[w])
      return FinishError{"the shape is not connected: node " + inst_.node_label(w) + " cannot be reached from node " +
                             inst_.node_label(0),
                         static_cast<long>(w)};
  out = std::move(inst_);
  inst_ = Instance{};
  edge_keys_.clear();
  return std::nullopt;
}

}  // namespace gridlock
