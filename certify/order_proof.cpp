#include "certify/internal/order_proof.hpp"

#include <algorithm>
#include <utility>

#include "common/internal/graph_order.hpp"

namespace gridlock {
namespace {

uint64_t pair_key(CouplingId a, CouplingId b) { return (uint64_t{std::min(a, b)} << 32) | std::max(a, b); }

// True iff the edges a -> b contain a directed cycle (Kahn's algorithm,
// common/internal/graph_order.hpp, cannot order every node). O(E log E).
bool has_cycle(const std::vector<OrderLiteral>& edges) {
  std::vector<CouplingId> nodes;
  for (auto [a, b] : edges) nodes.push_back(a), nodes.push_back(b);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  auto id = [&](CouplingId c) {
    return static_cast<uint32_t>(std::lower_bound(nodes.begin(), nodes.end(), c) - nodes.begin());
  };
  std::vector<std::pair<uint32_t, uint32_t>> dense;
  dense.reserve(edges.size());
  for (auto [a, b] : edges) dense.emplace_back(id(a), id(b));
  std::vector<uint32_t> order;
  return !topological_order(Digraph::from_edges(nodes.size(), dense), order);
}

}  // namespace

OrderProof::OrderProof(size_t k, const std::vector<GapInequality>& inequalities,
                       const std::vector<CertificateLemma>& lemmas)
    : k_(k), partners_(k) {
  for (const GapInequality& g : inequalities)
    for (auto [l, w] : g.terms) var_of(l.first, l.second);
  for (const CertificateLemma& lem : lemmas)
    for (auto [a, b] : lem.lits) var_of(a, b);
  const size_t nv = lo_.size();
  value_.assign(nv, -1);
  occ_.assign(2 * nv, {});
  watches_.assign(2 * nv, {});
  for (const GapInequality& g : inequalities) {
    Ineq q{g.bound, {}};
    for (auto [l, w] : g.terms) q.terms.push_back({lit(l), w});
    std::sort(q.terms.begin(), q.terms.end(), [](auto& x, auto& y) { return x.second > y.second; });
    for (auto [l, w] : q.terms) occ_[l].push_back({static_cast<uint32_t>(ineqs_.size()), w});
    ineqs_.push_back(std::move(q));
  }
  ineq_sum_.assign(ineqs_.size(), 0);
}

uint32_t OrderProof::var_of(CouplingId a, CouplingId b) {
  auto [it, fresh] = index_.try_emplace(pair_key(a, b), static_cast<uint32_t>(lo_.size()));
  if (fresh) {
    lo_.push_back(std::min(a, b));
    hi_.push_back(std::max(a, b));
    partners_[a].push_back({b, it->second});
    partners_[b].push_back({a, it->second});
  }
  return it->second;
}

OrderProof::Lit OrderProof::find_lit(CouplingId a, CouplingId b) const {
  auto it = index_.find(pair_key(a, b));
  if (it == index_.end()) return kNoLit;
  return 2 * it->second + (a < b ? 0 : 1);
}

OrderProof::Lit OrderProof::lit(OrderLiteral l) const { return find_lit(l.first, l.second); }

void OrderProof::assign(Lit l) {
  value_[l >> 1] = static_cast<int8_t>(l & 1);
  trail_.push_back(l);
  for (auto [g, w] : occ_[l]) ineq_sum_[g] += w;
}

bool OrderProof::imply(Lit l) {
  if (l == kNoLit || is_true(l)) return true;
  if (is_false(l)) return false;
  assign(l);
  return true;
}

void OrderProof::undo(size_t trail_size) {
  while (trail_.size() > trail_size) {
    const Lit l = trail_.back();
    trail_.pop_back();
    value_[l >> 1] = -1;
    for (auto [g, w] : occ_[l]) ineq_sum_[g] -= w;
  }
  qhead_ = std::min(qhead_, trail_size);
}

bool OrderProof::propagate() {
  while (qhead_ < trail_.size()) {
    const Lit p = trail_[qhead_++];
    if (!propagate_triangles(p) || !propagate_clauses(p) || !propagate_inequalities(p)) return false;
  }
  return true;
}

// p is a -> b: with b -> x it gives a -> x, with x -> a it gives x -> b.
bool OrderProof::propagate_triangles(Lit p) {
  const CouplingId a = from(p), b = to(p);
  // The literal "from before to" of variable v of that pair (lo < hi).
  auto pair_lit = [](CouplingId from, CouplingId to, uint32_t v) { return 2 * v + (from < to ? 0 : 1); };
  for (auto [x, v] : partners_[b])
    if (x != a && is_true(pair_lit(b, x, v)) && !imply(find_lit(a, x))) return false;
  for (auto [x, v] : partners_[a])
    if (x != b && is_true(pair_lit(x, a, v)) && !imply(find_lit(x, b))) return false;
  return true;
}

// Clauses watching the literal p made false: move the watch, or imply the other watch.
bool OrderProof::propagate_clauses(Lit p) {
  const Lit fl = neg(p);
  std::vector<uint32_t>& ws = watches_[fl];
  size_t i = 0, j = 0;
  bool ok = true;
  while (i < ws.size() && ok) {
    const uint32_t ci = ws[i++];
    std::vector<Lit>& c = clauses_[ci];
    if (c[0] == fl) std::swap(c[0], c[1]);
    if (!is_true(c[0])) {
      auto other = std::find_if(c.begin() + 2, c.end(), [&](Lit l) { return !is_false(l); });
      if (other != c.end()) {
        std::swap(c[1], *other);
        watches_[c[1]].push_back(ci);
        continue;
      }
    }
    ws[j++] = ci;
    if (!is_true(c[0])) ok = imply(c[0]);
  }
  while (i < ws.size()) ws[j++] = ws[i++];
  ws.resize(j);
  return ok;
}

bool OrderProof::propagate_inequalities(Lit p) {
  for (auto [g, w] : occ_[p]) {
    const int64_t slack = ineqs_[g].bound - ineq_sum_[g];
    if (slack < 0) return false;
    for (auto [l, weight] : ineqs_[g].terms) {
      if (weight <= slack) break;
      if (is_free(l)) assign(neg(l));
    }
  }
  return true;
}

bool OrderProof::add_clause(const std::vector<Lit>& c) {
  std::vector<Lit> open;
  for (Lit l : c) {
    if (is_true(l)) return true;  // true at the root for good
    if (is_free(l) && std::find(open.begin(), open.end(), l) == open.end()) open.push_back(l);
  }
  if (open.empty()) return false;
  if (open.size() == 1) {
    assign(open[0]);
    return propagate();
  }
  // Watch two free literals; the false ones stay false at the root.
  const auto ci = static_cast<uint32_t>(clauses_.size());
  watches_[open[0]].push_back(ci);
  watches_[open[1]].push_back(ci);
  clauses_.push_back(std::move(open));
  return true;
}

bool OrderProof::start() {
  for (uint32_t g = 0; g < ineqs_.size() && !refuted_; ++g) {
    if (ineqs_[g].bound < 0) refuted_ = true;
    for (auto [l, w] : ineqs_[g].terms)
      if (w > ineqs_[g].bound && is_free(l)) assign(neg(l));
  }
  if (!refuted_ && !propagate()) refuted_ = true;
  if (!refuted_ && !add_closure()) refuted_ = true;
  return !refuted_;
}

// The root relations, closed transitively (bit rows, k^2 / 8 bytes).
bool OrderProof::add_closure() {
  std::vector<std::pair<uint32_t, uint32_t>> edges;
  edges.reserve(trail_.size());
  for (Lit l : trail_) edges.emplace_back(from(l), to(l));
  const Digraph succ = Digraph::from_edges(k_, edges);
  std::vector<uint32_t> topo;
  if (!topological_order(succ, topo)) return false;  // the root relations form a cycle
  const size_t words = (k_ + 63) / 64;
  std::vector<uint64_t> reach(k_ * words, 0);
  auto before = [&](CouplingId a, CouplingId b) { return (reach[a * words + (b >> 6)] >> (b & 63)) & 1; };
  for (size_t h = k_; h-- > 0;) {
    uint64_t* row = reach.data() + topo[h] * words;
    for (uint32_t e = succ.first[topo[h]]; e < succ.first[topo[h] + 1]; ++e) {
      const CouplingId b = succ.target[e];
      row[b >> 6] |= uint64_t{1} << (b & 63);
      for (size_t i = 0; i < words; ++i) row[i] |= reach[b * words + i];
    }
  }
  for (uint32_t v = 0; v < lo_.size(); ++v) {
    if (before(lo_[v], hi_[v]) && !add_clause({2 * v})) return false;
    if (before(hi_[v], lo_[v]) && !add_clause({2 * v + 1})) return false;
  }
  for (CouplingId x = 0; x < k_; ++x)
    for (auto [c1, v1] : partners_[x])
      for (auto [c2, v2] : partners_[x])
        if (c1 != c2 && before(c1, c2)) {
          ++axioms_;
          if (!add_clause({neg(find_lit(x, c1)), find_lit(x, c2)})) return false;
        }
  return propagate();
}

void OrderProof::add_axiom(const CertificateLemma& lemma) {
  std::vector<Lit> c;
  for (const OrderLiteral& l : lemma.lits) c.push_back(lit(l));
  if (!refuted_ && !add_clause(c)) refuted_ = true;
}

std::string OrderProof::check(const CertificateLemma& lemma) {
  std::vector<Lit> c;
  for (const OrderLiteral& l : lemma.lits) c.push_back(lit(l));
  if (lemma.cycle) {
    if (!has_cycle(lemma.lits)) return "the literals of this o line contain no cycle";
  } else if (!refuted_) {
    const size_t root = trail_.size();
    bool implied = false;
    for (Lit l : c) {
      if (is_true(l)) implied = true;
      if (is_free(l)) assign(neg(l));
    }
    if (!implied) implied = !propagate();
    undo(root);
    if (!implied)
      return c.empty() ? "the empty clause is not implied: propagation over everything before it finds no conflict"
                       : "not implied: with every literal of it false, propagation finds no conflict";
  }
  if (!refuted_ && !add_clause(c)) refuted_ = true;
  return {};
}

}  // namespace gridlock
