// The lattice model of docs/model.md: a connected shape of unit-square
// nodes on Z^2, operations on it, and a coupling partition of the operations.
//
// An Instance is always valid once built: InstanceBuilder checks every rule
// (one node per cell, edges between orthogonal neighbours, operations on the
// right kind of place, a node in at most one operation, every operation in
// exactly one coupling, a connected shape) and reports the first broken one.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/diagnostic.hpp"
#include "lattice/flat_map.hpp"
#include "lattice/geometry.hpp"

namespace gridlock {

using NodeId = uint32_t;
using OpId = uint32_t;
using CouplingId = uint32_t;
inline constexpr uint32_t kNone = UINT32_MAX;

// Coordinates and counts are bounded so that every sum the simulator and the
// solvers form fits in 64 bits with room to spare (positions stay below 2^31,
// and times are scaled by at most 2^30, see lattice/schedule.hpp).
inline constexpr int64_t kMaxCoordinate = 1'000'000'000;
inline constexpr int64_t kMaxNodes = 1 << 25;

enum class OpKind : uint8_t {
  Expand,    // edge expansion u->v: a node is inserted, v's side moves along dir
  Grow,      // growth: a node grows from u's face into the cell u + dir
  Contract,  // contraction "v into u": v's side moves toward u, v narrows away
};
const char* op_kind_name(OpKind k);  // "expand", "grow", "contract"

struct Operation {
  std::string name;
  OpKind kind = OpKind::Expand;
  NodeId u = kNone;     // the node that performs it
  Dir dir = Dir::PosX;  // from u toward the cell c = u + dir
  NodeId v = kNone;     // the node in c (expand, contract); kNone for grow
  CouplingId coupling = kNone;
  bool is_edge_op() const { return kind != OpKind::Grow; }
};

struct Coupling {
  std::string name;
  std::vector<OpId> ops;  // non-empty, in the order written
};

struct Edge {
  NodeId a = kNone, b = kNone;  // orthogonal neighbours
  OpId op = kNone;              // the expansion or contraction on this edge, if any
};

// Names -> ids (operations or couplings) in one flat array: open addressing,
// linear probing, load at most 1/2. A slot holds an id and its name's hash;
// the names stay in the instance's lists, so an entry costs no allocation
// and no copy of its name (std::unordered_map<std::string, id> allocated a
// node per name and freed it with the instance, hundreds per compiled
// formula). Copying the index with its instance keeps it valid.
class NameIndex {
 public:
  // Room for n names without growing. O(n).
  void reserve(size_t n);
  // The id whose name (name_of(id)) is name, or kNone. O(|name|) expected.
  template <class NameOf>
  uint32_t find(std::string_view name, const NameOf& name_of) const {
    if (slots_.empty()) return UINT32_MAX;
    const uint32_t h = hash(name);
    const size_t mask = slots_.size() - 1;
    for (size_t i = h & mask;; i = (i + 1) & mask) {
      const Slot& s = slots_[i];
      if (s.id == UINT32_MAX) return UINT32_MAX;
      if (s.hash == h && std::string_view(name_of(s.id)) == name) return s.id;
    }
  }
  // Adds name -> id. Requires name absent (find first) and id != kNone.
  // O(|name|) amortised.
  void insert(std::string_view name, uint32_t id);

 private:
  struct Slot {
    uint32_t hash = 0;
    uint32_t id = UINT32_MAX;
  };
  static uint32_t hash(std::string_view s);
  void rehash(size_t cap);
  std::vector<Slot> slots_;
  size_t size_ = 0;
};

class Instance {
 public:
  // Nodes, in the order given; node i sits in cell cells[i].
  const std::vector<Vec2>& cells() const { return cells_; }
  const std::vector<Edge>& edges() const { return edges_; }
  const std::vector<Operation>& ops() const { return ops_; }
  const std::vector<Coupling>& couplings() const { return couplings_; }
  NodeId anchor() const { return anchor_; }
  bool has_explicit_anchor() const { return explicit_anchor_; }

  size_t num_nodes() const { return cells_.size(); }
  // The node in cell c, or kNone. O(1) expected.
  NodeId node_at(Vec2 c) const;
  // The operation node w takes part in (as u, or as v of an edge operation), or kNone.
  OpId op_of_node(NodeId w) const { return op_of_node_[w]; }
  // Neighbour of w in direction d joined by an edge, or kNone; and that edge.
  NodeId neighbour(NodeId w, Dir d) const { return adj_[4 * w + static_cast<int>(d)]; }
  uint32_t edge_index(NodeId w, Dir d) const { return adj_edge_[4 * w + static_cast<int>(d)]; }
  // Lookup by name; kNone if absent.
  OpId find_op(const std::string& name) const;
  CouplingId find_coupling(const std::string& name) const;

  // True iff every operation moves along the x axis.
  bool horizontal_only() const;
  // The one axis every operation moves along: 0 for x (also with no
  // operations), 1 for y; nullopt when the operations use both. O(ops).
  std::optional<int> moving_axis() const;
  // "(x,y)", how a node is named in messages and witnesses.
  std::string node_label(NodeId w) const;
  // Same shape, same operations, another anchor (any node).
  Instance with_anchor(NodeId w) const;

 private:
  friend class InstanceBuilder;
  std::vector<Vec2> cells_;
  std::vector<Edge> edges_;
  std::vector<Operation> ops_;
  std::vector<Coupling> couplings_;
  NodeId anchor_ = 0;
  bool explicit_anchor_ = false;
  FlatMap64 cell_index_;            // cell_key -> node: no allocation per node
  NameIndex op_index_;              // name -> operation
  NameIndex coupling_index_;        // name -> coupling
  std::vector<NodeId> adj_;         // 4 per node
  std::vector<uint32_t> adj_edge_;  // 4 per node
  std::vector<OpId> op_of_node_;
};

// The 64-bit key of a cell (x in the high half, y in the low half), for
// hash tables. Inline: the simulator's broad phase takes one per cell query.
inline uint64_t cell_key(Vec2 c) {
  return (static_cast<uint64_t>(static_cast<uint32_t>(c.x)) << 32) | static_cast<uint32_t>(c.y);
}

// True iff s is a valid name for an operation or a coupling: 1 to 64
// characters from [A-Za-z0-9_.:~+'-], not starting with '-' or '+'.
bool valid_name(const std::string& s);

// FNV-1a (64 bits) of the coupling names in instance order, each followed
// by '\n': ties a certificate to its instance's couplings. O(total name
// length).
uint64_t coupling_digest(const Instance& inst);

// The certificate line "couplings K DIGEST\n": K the number of couplings,
// DIGEST coupling_digest as 16 lower-case hex digits (docs/certificates.md,
// "Format"). Shared by every certificate writer; certify/ keeps its own
// copy on purpose, so that the checker stays independent.
std::string couplings_line(const Instance& inst);

// Builds an Instance step by step; each add_* checks what it can at once and
// returns the problem (message only; the caller adds file and line). finish()
// checks the rules that need everything (couplings, connectivity).
//
// Used by the .grid reader (with line numbers) and by the gadget compiler.
class InstanceBuilder {
 public:
  // Each returns an error message, or nullopt on success.
  // Optional: room for this many of each (no rehashing of the cell index
  // while nodes are added). Changes nothing else.
  void reserve(size_t nodes, size_t edges, size_t ops, size_t couplings);
  std::optional<std::string> add_node(Vec2 cell);
  std::optional<std::string> add_edge(Vec2 a, Vec2 b);
  // kind Expand/Contract: c = u + dir must hold a node joined to u by an edge.
  // kind Grow: c must not hold a node joined to u by an edge (an unjoined node
  // there is allowed: the growth then collides at once, docs/model.md).
  std::optional<std::string> add_op(const std::string& name, OpKind kind, Vec2 u, Dir dir);
  std::optional<std::string> add_coupling(const std::string& name, const std::vector<std::string>& ops);
  std::optional<std::string> set_anchor(Vec2 cell);

  // Operations in no coupling become singleton couplings named after the
  // operation. Fails if a singleton's name is taken by another coupling, or
  // the shape is empty or not connected (then names a node that cannot be
  // reached from the first node). On success the builder is left empty.
  struct FinishError {
    std::string message;
    long node_index = -1;  // the unreachable node, for the reader's line number
  };
  std::optional<FinishError> finish(Instance& out);

  size_t num_nodes() const { return inst_.cells_.size(); }

 private:
  Instance inst_;
  std::vector<std::pair<uint64_t, uint64_t>> edge_keys_;
};

}  // namespace gridlock
