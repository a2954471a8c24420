#include "lattice/random_instance.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <vector>

#include "common/assert.hpp"
#include "common/random.hpp"

namespace gridlock {

namespace {

// The shape: cells grown one by one from (0,0), each joined to the cell it
// grew from (a tree). Returns the cells in the order added.
std::vector<Vec2> grow_shape(const RandomInstanceParams& p, Rng& rng, InstanceBuilder& b,
                             std::unordered_set<uint64_t>& taken) {
  std::vector<Vec2> cells{{0, 0}};
  taken.insert(cell_key({0, 0}));
  b.add_node({0, 0});
  while (cells.size() < p.nodes) {
    size_t from = p.path_shape ? cells.size() - 1 : rng.below(cells.size());
    Dir d = kDirs[rng.below(4)];
    if (p.spread > 0 && rng.below(p.spread + 1) != 0) {
      // Prefer growing from recent cells: sparser, longer shapes.
      from = cells.size() - 1 - rng.below(std::min<uint64_t>(cells.size(), 4));
    }
    Vec2 c = cells[from] + unit(d);
    if (taken.count(cell_key(c))) {
      if (p.path_shape) {
        // A path that boxed itself in: try the other directions, else give up.
        bool placed = false;
        for (Dir d2 : kDirs) {
          Vec2 c2 = cells[from] + unit(d2);
          if (!taken.count(cell_key(c2))) {
            c = c2;
            placed = true;
            break;
          }
        }
        if (!placed) break;
      } else {
        continue;
      }
    }
    taken.insert(cell_key(c));
    b.add_node(c);
    b.add_edge(cells[from], c);
    cells.push_back(c);
  }
  return cells;
}

// Group sizes for exactly `want` couplings over n operations (each 1..max,
// as even as the draws allow), or fewer couplings when n < want.
std::vector<size_t> exact_group_sizes(Rng& rng, size_t n, size_t want, size_t max) {
  want = std::min(want, n);
  std::vector<size_t> len(want, 1);
  size_t left = n - want;
  while (left > 0) {
    size_t i = rng.below(want);
    if (len[i] >= max) {
      for (i = 0; i < want && len[i] >= max; ++i) {
      }
      if (i == want) break;  // every group full: the extra operations are dropped
    }
    ++len[i];
    --left;
  }
  return len;
}

// Random couplings: shuffle, then cut into groups of 1..max_coupling
// (exactly `exact` groups when exact > 0).
void add_random_couplings(Rng& rng, InstanceBuilder& b, std::vector<std::string>& names, uint32_t max_coupling,
                          uint32_t exact) {
  rng.shuffle(names);
  std::vector<size_t> sizes;
  if (exact > 0) sizes = exact_group_sizes(rng, names.size(), exact, std::max<uint32_t>(max_coupling, 1));
  size_t i = 0, q = 0, g = 0;
  while (i < names.size()) {
    if (exact > 0 && g == sizes.size()) break;  // dropped operations stay uncoupled singletons
    size_t len = exact > 0 ? sizes[g++] : 1 + rng.below(std::max<uint32_t>(max_coupling, 1));
    len = std::min(len, names.size() - i);
    if (len > 1) {
      std::vector<std::string> group(names.begin() + static_cast<long>(i), names.begin() + static_cast<long>(i + len));
      b.add_coupling("Q" + std::to_string(++q), group);
    }
    i += len;
  }
}

}  // namespace

Instance random_instance(const RandomInstanceParams& p, uint64_t seed) {
  GRIDLOCK_REQUIRE(p.nodes > 0, "random_instance needs at least one node");
  if (!p.allow_expand && !p.allow_contract && !p.allow_grow)
    throw std::invalid_argument("random_instance needs at least one operation kind");
  // The instance stream starts from this scramble of the seed (kept so that
  // every seed gives the instance it always gave).
  Rng rng(seed * 0x2545F4914F6CDD1DULL + 0x1234567ULL);
  InstanceBuilder b;
  std::unordered_set<uint64_t> taken;
  const std::vector<Vec2> cells = grow_shape(p, rng, b, taken);
  if (p.extra_edge_percent > 0)
    for (const Vec2& c : cells)
      for (Dir d : {Dir::PosX, Dir::PosY}) {
        Vec2 o = c + unit(d);
        if (taken.count(cell_key(o)) && rng.bernoulli(std::min(p.extra_edge_percent, 100U), 100))
          b.add_edge(c, o);  // may repeat: ignored
      }
  // Operations on distinct nodes.
  std::vector<char> used(cells.size(), 0);
  std::vector<std::string> names;
  uint32_t tries = 0;
  while (names.size() < p.ops && tries++ < 20 * (p.ops + 4)) {
    size_t ui = rng.below(cells.size());
    if (used[ui]) continue;
    Dir d = p.horizontal_only ? (rng.below(2) ? Dir::PosX : Dir::NegX) : kDirs[rng.below(4)];
    Vec2 u = cells[ui];
    uint64_t kind_roll = rng.below(10);
    OpKind kind = OpKind::Expand;
    if (kind_roll >= 6 && p.allow_contract) kind = OpKind::Contract;
    if (kind_roll >= 8 && p.allow_grow) kind = OpKind::Grow;
    if (kind == OpKind::Expand && !p.allow_expand)
      kind = p.allow_contract && (!p.allow_grow || rng.below(2) == 0) ? OpKind::Contract : OpKind::Grow;
    std::string name = "o" + std::to_string(names.size() + 1);
    if (kind == OpKind::Grow) {
      // Growth needs no edge toward c; it may still be into an occupied cell.
      if (b.add_op(name, OpKind::Grow, u, d)) continue;
      used[ui] = 1;
    } else {
      if (b.add_op(name, kind, u, d)) continue;  // no edge there, or v is busy
      used[ui] = 1;
    }
    names.push_back(name);
  }
  add_random_couplings(rng, b, names, p.max_coupling, p.couplings);
  Instance inst;
  if (auto err = b.finish(inst)) throw std::logic_error("random_instance built a bad instance: " + err->message);
  return inst;
}

bool parse_shape_family(const std::string& name, ShapeFamily& out) {
  for (ShapeFamily f :
       {ShapeFamily::Tree, ShapeFamily::Cycles, ShapeFamily::Sparse, ShapeFamily::Dense, ShapeFamily::Path})
    if (name == shape_family_name(f)) {
      out = f;
      return true;
    }
  return false;
}

const char* shape_family_name(ShapeFamily f) {
  switch (f) {
    case ShapeFamily::Tree: return "tree";
    case ShapeFamily::Cycles: return "cycles";
    case ShapeFamily::Sparse: return "sparse";
    case ShapeFamily::Dense: return "dense";
    case ShapeFamily::Path: return "path";
  }
  return "?";
}

RandomInstanceParams family_params(const RandomFamilyParams& f) {
  GRIDLOCK_REQUIRE(f.couplings > 0, "a random family instance needs at least one coupling");
  GRIDLOCK_REQUIRE(f.max_coupling > 0, "couplings need at least one operation");
  GRIDLOCK_REQUIRE(f.expand || f.contract || f.grow, "no operation kind allowed");
  RandomInstanceParams p;
  p.couplings = f.couplings;
  p.max_coupling = f.max_coupling;
  p.ops = static_cast<uint32_t>((uint64_t{f.couplings} * (1 + f.max_coupling) + 1) / 2);
  p.allow_expand = f.expand;
  p.allow_contract = f.contract;
  p.allow_grow = f.grow;
  p.horizontal_only = f.horizontal_only;
  p.nodes = 3 * p.ops;
  switch (f.family) {
    case ShapeFamily::Tree: break;
    case ShapeFamily::Cycles: p.extra_edge_percent = 35; break;
    case ShapeFamily::Sparse:
      p.nodes = 4 * p.ops;
      p.spread = 3;
      break;
    case ShapeFamily::Dense:
      p.nodes = p.ops + (p.ops + 1) / 2;
      p.extra_edge_percent = 80;
      break;
    case ShapeFamily::Path: p.path_shape = true; break;
  }
  return p;
}

Instance random_family_instance(const RandomFamilyParams& f, uint64_t seed) {
  return random_instance(family_params(f), seed);
}

}  // namespace gridlock
