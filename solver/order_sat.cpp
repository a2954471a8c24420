// The order-literal layer shared by the SAT engines (solver/internal/order_sat.hpp).
#include "solver/internal/order_sat.hpp"

#include <algorithm>
#include <stdexcept>

#include "solver/internal/gap_inequalities.hpp"

namespace gridlock {

int OrderSat::before(CouplingId a, CouplingId b) {
  const CouplingId lo = std::min(a, b), hi = std::max(a, b);
  const uint32_t found = var_of_pair_.find(key(lo, hi));
  int var = static_cast<int>(found);
  if (found == FlatMap64::kAbsent) {
    var = sat_.new_var();
    var_of_pair_.emplace(key(lo, hi), static_cast<uint32_t>(var));
    pair_vars_.push_back({var, lo, hi});
    if (cycle_log_) {
      pair_index_.resize(static_cast<size_t>(var) + 1, 0);
      pair_index_[static_cast<size_t>(var)] = static_cast<uint32_t>(pair_vars_.size());
    }
  }
  return a == lo ? var : -var;
}

void OrderSat::prove_to(std::FILE* drat, std::vector<std::vector<int>>* cycles) {
  if (!pair_vars_.empty()) throw std::logic_error("OrderSat: proof mode after the first variable");
  sat_.trace_proof(drat);
  cycle_log_ = cycles;
}

std::pair<CouplingId, CouplingId> OrderSat::pair_of(int var) const {
  const auto v = static_cast<size_t>(var);
  if (var <= 0 || v >= pair_index_.size() || pair_index_[v] == 0)
    throw std::logic_error("OrderSat: a proof variable that is no pair");
  const PairVar& p = pair_vars_[pair_index_[v] - 1];
  return {p.lo, p.hi};
}

bool OrderSat::has_pair(CouplingId a, CouplingId b) const {
  return var_of_pair_.find(key(std::min(a, b), std::max(a, b))) != FlatMap64::kAbsent;
}

// reg[j-1] of literal i means "the literals up to i weigh at least j"; only
// the implications toward larger sums are needed.
bool OrderSat::at_most(const std::vector<std::pair<int, int64_t>>& lits, int64_t bound) {
  if (cycle_log_) throw std::logic_error("OrderSat: a counter in proof mode");
  if (bound < 0) return false;
  std::vector<std::pair<int, int64_t>>& kept = kept_;
  kept.clear();
  int64_t total = 0;
  for (auto [l, w] : lits) {
    if (w > bound) {
      add_unit(-l);
      continue;
    }
    kept.push_back({l, w});
    total += w;
  }
  if (total <= bound) return true;
  // Too much only when every kept literal holds (without any one of them,
  // even the lightest, the rest weigh at most bound): one clause, no
  // counter. Every counter of random 3-SAT's compiled gaps is of this kind
  // (two literals, bound 1, or three, bound 2).
  int64_t lightest = kept.front().second;
  for (const auto& lw : kept) lightest = std::min(lightest, lw.second);
  if (total - lightest <= bound) {
    clause_.clear();
    for (const auto& lw : kept) clause_.push_back(-lw.first);
    sat_.add_clause(clause_);
    return true;
  }
  const auto K = static_cast<size_t>(bound);
  std::vector<int>&prev = prev_, &cur = cur_;  // registers of the literals so far, 1..K
  prev.clear();
  for (size_t i = 0; i < kept.size(); ++i) {
    const int l = kept[i].first;
    const auto w = static_cast<size_t>(kept[i].second);
    if (i > 0) sat_.add_clause({-l, -prev[K - w]});  // prev >= K + 1 - w and l: too much
    if (i + 1 == kept.size()) break;
    cur.assign(K, 0);
    for (size_t j = 0; j < K; ++j) cur[j] = sat_.new_var();
    for (size_t j = 0; j < K; ++j) {
      if (i > 0) sat_.add_clause({-prev[j], cur[j]});
      if (j < w) sat_.add_clause({-l, cur[j]});
      else if (i > 0) sat_.add_clause({-l, -prev[j - w], cur[j]});
    }
    std::swap(prev, cur);
  }
  return true;
}

bool OrderSat::add_order_clauses(const std::vector<std::pair<CouplingId, CouplingId>>& forced) {
  // Partners of each coupling as one flat list (a counting sort of the pair
  // variables, in their creation order, as the per-coupling vectors were):
  // two allocations instead of one vector per coupling.
  Partners partners;
  partners.first.assign(k_ + 1, 0);
  for (const PairVar& p : pair_vars_) ++partners.first[p.lo + 1], ++partners.first[p.hi + 1];
  for (size_t x = 0; x < k_; ++x) partners.first[x + 1] += partners.first[x];
  partners.list.resize(partners.first[k_]);
  std::vector<uint32_t> fill(partners.first.begin(), partners.first.end() - 1);
  for (const PairVar& p : pair_vars_) {
    partners.list[fill[p.lo]++] = {p.hi, p.var};
    partners.list[fill[p.hi]++] = {p.lo, -p.var};
  }
  if (k_ <= kClosureLimit && !add_closure_clauses(forced, partners)) return false;
  add_triangle_clauses(partners);
  return true;
}

bool OrderSat::add_closure_clauses(const std::vector<std::pair<CouplingId, CouplingId>>& forced,
                                   const Partners& partners) {
  const size_t words = (k_ + 63) / 64;
  const Digraph forced_graph = Digraph::from_edges(k_, forced);
  std::vector<CouplingId> topo;
  if (!topological_order(forced_graph, topo)) return false;  // forced relations form a cycle
  std::vector<uint64_t> reach(k_ * words, 0);
  auto r = [&](CouplingId a, CouplingId b) { return (reach[a * words + (b >> 6)] >> (b & 63)) & 1; };
  for (size_t h = topo.size(); h-- > 0;) {
    const CouplingId v = topo[h];
    if ((h & 1023) == 0) budget_.check(st_);
    uint64_t* row = reach.data() + v * words;
    for (uint32_t e = forced_graph.first[v]; e < forced_graph.first[v + 1]; ++e) {
      const CouplingId w = forced_graph.target[e];
      row[w >> 6] |= uint64_t{1} << (w & 63);
      const uint64_t* wr = reach.data() + w * words;
      for (size_t i = 0; i < words; ++i) row[i] |= wr[i];
    }
  }
  for (const PairVar& p : pair_vars_) {
    if (r(p.lo, p.hi)) add_unit(p.var);
    if (r(p.hi, p.lo)) add_unit(-p.var);
  }
  for (CouplingId x = 0; x < k_; ++x) {
    if ((x & 1023) == 0) budget_.check(st_);
    for (auto [c1, l1] : partners.of(x)) {
      // c1 R c2 needs a forced edge out of c1 (most couplings have none).
      if (!reference_ && forced_graph.first[c1] == forced_graph.first[c1 + 1]) continue;
      for (auto [c2, l2] : partners.of(x))
        if (c1 != c2 && r(c1, c2)) sat_.add_clause({-l1, l2});
    }
  }
  return true;
}

// A gap's unit (at_most: one literal outweighs the bound) and the forced
// closure's unit on the same pair are the same clause, added twice. The
// second one reaches CaDiCaL with its literal already true at the root,
// and CaDiCaL drops such a clause on arrival (nothing learned, nothing
// logged: at_most is never used in proof mode), so not sending it leaves
// CaDiCaL's state as it was.
void OrderSat::add_unit(int lit) {
  const auto v = static_cast<size_t>(lit > 0 ? lit : -lit);
  const auto bit = static_cast<uint8_t>(lit > 0 ? 1 : 2);
  if (v >= units_.size()) units_.resize(std::max<size_t>(v + 1, 2 * units_.size()), 0);
  if ((units_[v] & bit) && !reference_) {
    ++skipped_units_;
    return;
  }
  units_[v] |= bit;
  sat_.add_clause({lit});
}

void OrderSat::add_triangle_clauses(const Partners& partners) {
  for (CouplingId x = 0; x < k_; ++x) {
    if ((x & 1023) == 0) budget_.check(st_);
    for (auto [a, la] : partners.of(x)) {
      if (a < x) continue;
      for (auto [c, lc] : partners.of(x)) {
        if (c <= a) continue;
        const uint32_t ac = var_of_pair_.find(key(a, c));  // a < c
        if (ac == FlatMap64::kAbsent) continue;
        const int vac = static_cast<int>(ac);
        // a before x before c implies a before c; c before x before a implies c before a.
        sat_.add_clause({la, -lc, vac});
        sat_.add_clause({-la, lc, -vac});
      }
    }
  }
}

SearchOutcome OrderSat::solve(const std::function<bool(const std::vector<CouplingId>&)>& accept) {
  SearchOutcome out;
  const std::function<bool(uint64_t)> stop = [&](uint64_t conflicts) {
    return budget_.exhausted(st_, conflicts - counted_conflicts_);
  };
  for (;;) {
    budget_.tick(st_);
    ++st_.decisions;
    const Verdict s = sat_.solve(stop);
    const uint64_t conf = sat_.conflicts();
    st_.refuted += conf - counted_conflicts_;
    st_.states += conf - counted_conflicts_;
    counted_conflicts_ = conf;
    if (s == Verdict::Unknown) throw SearchBudget::LimitReached{};
    if (s == Verdict::No) {
      out.status = Verdict::No;
      out.order.clear();
      return out;
    }
    if (order_of_model(out.order) && accept(out.order)) {
      out.status = Verdict::Yes;
      return out;
    }
  }
}

// Orients every pair as the model says. Acyclic: out = a topological order
// of all couplings, true. Cyclic: adds one clause per cycle found (a
// shortest cycle through each uncovered vertex of each non-trivial strongly
// connected component), false.
bool OrderSat::order_of_model(std::vector<CouplingId>& out) {
  const Digraph g = model_orientation();
  const StrongComponents cc = strong_components(g);
  if (cc.count() == k_) {  // every component a single coupling: acyclic
    out.assign(cc.nodes.rbegin(), cc.nodes.rend());
    return true;
  }
  add_cycle_clauses(g, cc);
  return false;
}

Digraph OrderSat::model_orientation() const {
  std::vector<std::pair<CouplingId, CouplingId>> edges;
  edges.reserve(pair_vars_.size());
  for (const PairVar& p : pair_vars_) {
    const bool lo_first = sat_.value(p.var);
    edges.push_back(lo_first ? std::make_pair(p.lo, p.hi) : std::make_pair(p.hi, p.lo));
  }
  return Digraph::from_edges(k_, edges);
}

// Shortest cycles inside each cyclic component (BFS from each vertex not
// yet on a cycle clause of this round); adds "not all of these B's" for each.
void OrderSat::add_cycle_clauses(const Digraph& g, const StrongComponents& cc) {
  const auto& deg = g.first;
  const auto& adj = g.target;
  const auto& comp = cc.component;
  std::vector<char> covered(k_, 0);
  std::vector<CouplingId> parent(k_, kNone), queue;
  std::vector<uint32_t> seen(k_, UINT32_MAX);
  uint32_t stamp = 0;
  std::vector<int> clause;
  for (size_t c = 0; c < cc.count(); ++c) {
    if (cc.size_of(c) < 2) continue;
    for (uint32_t m = cc.start[c]; m < cc.start[c + 1]; ++m) {
      const CouplingId s = cc.nodes[m];
      if (covered[s]) continue;
      ++stamp;
      queue.assign(1, s);
      seen[s] = stamp;
      CouplingId last = kNone;
      for (size_t h = 0; h < queue.size() && last == kNone; ++h) {
        const CouplingId v = queue[h];
        for (uint32_t e = deg[v]; e < deg[v + 1]; ++e) {
          const CouplingId w = adj[e];
          if (comp[w] != comp[s]) continue;
          if (w == s) {
            last = v;
            break;
          }
          if (seen[w] == stamp) continue;
          seen[w] = stamp;
          parent[w] = v;
          queue.push_back(w);
        }
      }
      if (last == kNone) throw std::logic_error("order SAT: no cycle in a strongly connected component");
      clause.clear();
      clause.push_back(-before(last, s));
      covered[s] = 1;
      for (CouplingId v = last; v != s; v = parent[v]) {
        clause.push_back(-before(parent[v], v));
        covered[v] = 1;
      }
      add_cycle_clause(clause);
      ++st_.propagations;
    }
    if ((++stamp & 63) == 0) budget_.check(st_);
  }
}

bool encode_gap_constraint(const CollisionConstraint& c, OrderSat& os) {
  std::vector<PrecedenceTerm>& terms = os.terms_;
  std::vector<std::pair<int, int64_t>>& lits = os.lits_;
  return for_each_gap_inequality(c, terms, [&](auto& ts, int64_t bound) {
    lits.clear();
    for (const PrecedenceTerm& x : ts) lits.push_back({os.before(x.first, x.second), x.weight});
    return os.at_most(lits, bound);
  });
}

}  // namespace gridlock
