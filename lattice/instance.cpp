#include "lattice/instance.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <initializer_list>
#include <string_view>
#include <utility>

namespace gridlock {

const char* op_kind_name(OpKind k) {
  switch (k) {
    case OpKind::Expand: return "expand";
    case OpKind::Grow: return "grow";
    case OpKind::Contract: return "contract";
  }
  return "?";
}

namespace {
// name_char[c]: c may occur in a name, [A-Za-z0-9_.:~+'-].
constexpr std::array<bool, 256> make_name_chars() {
  std::array<bool, 256> ok{};
  for (int c = 'a'; c <= 'z'; ++c) ok[static_cast<size_t>(c)] = true;
  for (int c = 'A'; c <= 'Z'; ++c) ok[static_cast<size_t>(c)] = true;
  for (int c = '0'; c <= '9'; ++c) ok[static_cast<size_t>(c)] = true;
  for (char c : {'_', '.', ':', '~', '+', '\'', '-'}) ok[static_cast<unsigned char>(c)] = true;
  return ok;
}
constexpr std::array<bool, 256> kNameChar = make_name_chars();

// Puts slot s into the first free slot from its hash on (linear probing;
// the table has a free slot: load at most 1/2). Shared by insert and rehash.
template <class Slots, class Slot>
void place(Slots& slots, const Slot& s) {
  const size_t mask = slots.size() - 1;
  size_t i = s.hash & mask;
  while (slots[i].id != UINT32_MAX) i = (i + 1) & mask;
  slots[i] = s;
}
}  // namespace

bool valid_name(const std::string& s) {
  if (s.empty() || s.size() > 64 || s[0] == '-' || s[0] == '+') return false;
  for (char ch : s)
    if (!kNameChar[static_cast<unsigned char>(ch)]) return false;
  return true;
}

void NameIndex::reserve(size_t n) {
  size_t cap = 16;
  while (cap < 2 * n) cap <<= 1;
  if (cap > slots_.size()) rehash(cap);
}

uint32_t NameIndex::hash(std::string_view s) {  // FNV-1a, then the high bits folded in
  uint64_t h = 0xCBF29CE484222325ull;
  for (char ch : s) h = (h ^ static_cast<unsigned char>(ch)) * 0x100000001B3ull;
  h ^= h >> 29;
  h *= 0xBF58476D1CE4E5B9ull;
  h ^= h >> 32;
  return static_cast<uint32_t>(h);
}

void NameIndex::insert(std::string_view name, uint32_t id) {
  if (2 * (size_ + 1) > slots_.size()) rehash(slots_.empty() ? 16 : 2 * slots_.size());
  place(slots_, Slot{hash(name), id});
  ++size_;
}

void NameIndex::rehash(size_t cap) {
  std::vector<Slot> old(cap);
  old.swap(slots_);
  for (const Slot& o : old)
    if (o.id != UINT32_MAX) place(slots_, o);
}

NodeId Instance::node_at(Vec2 c) const {
  const uint32_t w = cell_index_.find(cell_key(c));
  return w == FlatMap64::kAbsent ? kNone : w;
}

OpId Instance::find_op(const std::string& name) const {
  return op_index_.find(name, [this](uint32_t k) -> const std::string& { return ops_[k].name; });
}

CouplingId Instance::find_coupling(const std::string& name) const {
  return coupling_index_.find(name, [this](uint32_t q) -> const std::string& { return couplings_[q].name; });
}

bool Instance::horizontal_only() const {
  return std::all_of(ops_.begin(), ops_.end(), [](const Operation& o) { return is_horizontal(o.dir); });
}

std::optional<int> Instance::moving_axis() const {
  bool x = false, y = false;
  for (const Operation& o : ops_) (is_horizontal(o.dir) ? x : y) = true;
  if (x && y) return std::nullopt;
  return y ? 1 : 0;
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
  inst_.adj_.insert(inst_.adj_.end(), 4, kNone);
  inst_.adj_edge_.insert(inst_.adj_edge_.end(), 4, kNone);
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
  if (inst_.find_op(name) != kNone) return "operation '" + name + "' defined twice";
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
  inst_.op_index_.insert(name, id);
  inst_.ops_.push_back(std::move(op));
  return std::nullopt;
}

std::optional<std::string> InstanceBuilder::add_coupling(const std::string& name, const std::vector<std::string>& ops) {
  if (!valid_name(name)) return "bad coupling name '" + name + "'";
  if (inst_.find_coupling(name) != kNone) return "coupling '" + name + "' defined twice";
  if (ops.empty()) return "coupling '" + name + "' has no operations";
  auto id = static_cast<CouplingId>(inst_.couplings_.size());
  Coupling q{name, {}};
  q.ops.reserve(ops.size());
  for (const auto& o : ops) {
    OpId op = inst_.find_op(o);
    if (op == kNone) return cat({"unknown operation '", o, "' in coupling '", name, "'"});
    if (inst_.ops_[op].coupling == id) return cat({"operation '", o, "' named twice in coupling '", name, "'"});
    if (inst_.ops_[op].coupling != kNone)
      return cat({"operation '", o, "' is already in coupling '", inst_.couplings_[inst_.ops_[op].coupling].name, "'"});
    inst_.ops_[op].coupling = id;
    q.ops.push_back(op);
  }
  inst_.coupling_index_.insert(name, id);
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
    if (inst_.find_coupling(name) != kNone)
      return FinishError{"operation '" + name + "' is in no coupling, and its singleton coupling's name is taken", -1};
    auto id = static_cast<CouplingId>(inst_.couplings_.size());
    inst_.coupling_index_.insert(name, id);
    inst_.couplings_.push_back(Coupling{name, {o}});
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

uint64_t coupling_digest(const Instance& inst) {
  uint64_t h = 14695981039346656037ull;
  auto add = [&](char ch) { h = (h ^ static_cast<unsigned char>(ch)) * 1099511628211ull; };
  for (const Coupling& c : inst.couplings()) {
    for (char ch : c.name) add(ch);
    add('\n');
  }
  return h;
}

std::string couplings_line(const Instance& inst) {
  char digest[17];
  std::snprintf(digest, sizeof digest, "%016llx", static_cast<unsigned long long>(coupling_digest(inst)));
  return "couplings " + std::to_string(inst.couplings().size()) + " " + digest + "\n";
}

}  // namespace gridlock
