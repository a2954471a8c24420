// Depth-first search over states (sets of done couplings), for any
// constraint system. Why each rule keeps the answer exact: docs/solver.md.
#include <algorithm>
#include <unordered_set>
#include "common/random.hpp"

#include "solver/internal/search.hpp"

namespace gridlock {
namespace {

struct StateKey {
  std::vector<uint64_t> bits;
  uint64_t hash = 0;
  bool operator==(const StateKey& o) const { return hash == o.hash && bits == o.bits; }
};
struct StateKeyHash {
  size_t operator()(const StateKey& k) const { return static_cast<size_t>(k.hash); }
};

class StateSearch {
 public:
  StateSearch(const ConstraintSystem& sys, SearchBudget& budget, SolveStats& st)
      : sys_(sys), budget_(budget), st_(st), k_(sys.num_couplings) {
    words_ = (k_ + 63) / 64;
    done_.assign(words_, 0);
    Rng rng(0x5eed5eedULL);
    zobrist_.resize(k_);
    for (auto& z : zobrist_) z = rng.next();
    offset_.resize(sys.constraints.size() + 1, 0);
    for (size_t c = 0; c < sys.constraints.size(); ++c) offset_[c + 1] = offset_[c] + sys.constraints[c].num_forms;
    cur_.resize(offset_.back());
    pos_rem_.assign(offset_.back(), 0);
    for (size_t c = 0; c < sys.constraints.size(); ++c) {
      const CollisionConstraint& cc = sys.constraints[c];
      for (uint32_t i = 0; i < cc.num_forms; ++i) cur_[offset_[c] + i] = cc.base[i];
      for (size_t j = 0; j < cc.rel.size(); ++j)
        for (uint32_t i = 0; i < cc.num_forms; ++i) pos_rem_[offset_[c] + i] += std::max<int64_t>(cc.coef_of(j)[i], 0);
    }
    // Per (coupling, its constraint): does it only lower the forms?
    lowers_.resize(k_);
    for (CouplingId q = 0; q < k_; ++q) {
      for (auto [c, j] : sys.of_coupling[q]) {
        const CollisionConstraint& cc = sys.constraints[c];
        bool lo = true;
        for (uint32_t i = 0; i < cc.num_forms; ++i)
          if (cc.coef_of(j)[i] > 0) lo = false;
        lowers_[q].push_back(lo);
      }
    }
  }

  SearchOutcome run() {
    SearchOutcome out;
    if (dfs()) {
      out.status = Verdict::Yes;
      out.order = path_;
    } else {
      out.status = Verdict::No;
    }
    return out;
  }

 private:
  bool is_done(CouplingId q) const { return (done_[q >> 6] >> (q & 63)) & 1; }

  // Some form of c can never be positive again from the current state.
  bool dead(uint32_t c) const {
    for (uint32_t i = offset_[c]; i < offset_[c + 1]; ++i)
      if (cur_[i] + pos_rem_[i] <= 0) return true;
    return false;
  }
  // The same, after q (a coupling of c, index j in its rel) is done.
  bool dead_after(uint32_t c, uint32_t j) const {
    const int64_t* coef = sys_.constraints[c].coef_of(j);
    for (uint32_t i = offset_[c], f = 0; i < offset_[c + 1]; ++i, ++f)
      if (cur_[i] + coef[f] + pos_rem_[i] - std::max<int64_t>(coef[f], 0) <= 0) return true;
    return false;
  }

  bool enabled(CouplingId q) const {
    for (auto [c, j] : sys_.of_coupling[q]) {
      const CollisionConstraint& cc = sys_.constraints[c];
      if (step_collides(cur_.data() + offset_[c], cc.coef_of(j), cc.num_forms)) return false;
    }
    return true;
  }

  // Doing q now loses no solution: q only lowers each of its constraints or
  // leaves it unable to collide ever again (exchange argument, docs/solver.md).
  bool safe(CouplingId q) const {
    const auto& oc = sys_.of_coupling[q];
    for (size_t x = 0; x < oc.size(); ++x)
      if (!lowers_[q][x] && !dead_after(oc[x].first, oc[x].second)) return false;
    return true;
  }

  void apply(CouplingId q, int sign) {
    for (auto [c, j] : sys_.of_coupling[q]) {
      const int64_t* coef = sys_.constraints[c].coef_of(j);
      for (uint32_t i = offset_[c], f = 0; i < offset_[c + 1]; ++i, ++f) {
        cur_[i] += sign * coef[f];
        pos_rem_[i] -= sign * std::max<int64_t>(coef[f], 0);
      }
    }
    done_[q >> 6] ^= uint64_t{1} << (q & 63);
    hash_ ^= zobrist_[q];
    if (sign > 0) path_.push_back(q);
    else path_.pop_back();
  }

  // The stubborn set grown from seed: closed under "t in T and u could
  // interfere with t through a live constraint => u in T". Returns its
  // enabled members.
  std::vector<CouplingId> stubborn(CouplingId seed, std::vector<char>& in, std::vector<CouplingId>& members) {
    std::vector<CouplingId> en;
    for (CouplingId m : members) in[m] = 0;
    members.clear();
    members.push_back(seed);
    in[seed] = 1;
    for (size_t head = 0; head < members.size(); ++head) {
      CouplingId t = members[head];
      const auto& oc = sys_.of_coupling[t];
      for (size_t x = 0; x < oc.size(); ++x) {
        auto [c, j] = oc[x];
        if (dead(c)) continue;
        const CollisionConstraint& cc = sys_.constraints[c];
        for (size_t jj = 0; jj < cc.rel.size(); ++jj) {
          CouplingId u = cc.rel[jj];
          if (in[u] || is_done(u)) continue;
          if (lowers_[t][x]) {
            // t only lowers c: u matters only if it can lower c too (then
            // doing t first might meet c at a higher value than before).
            bool u_raises = true;
            for (uint32_t i = 0; i < cc.num_forms; ++i)
              if (cc.coef_of(jj)[i] < 0) u_raises = false;
            if (u_raises) continue;
          }
          in[u] = 1;
          members.push_back(u);
        }
      }
    }
    for (CouplingId m : members)
      if (enabled(m)) en.push_back(m);
    return en;
  }

  bool dfs() {
    budget_.set_depth(path_.size());
    budget_.tick(st_);
    if (path_.size() == k_) return true;
    StateKey key{done_, hash_};
    if (memo_.count(key)) {
      ++st_.memo_hits;
      return false;
    }
    std::vector<CouplingId> undone;
    for (CouplingId q = 0; q < k_; ++q)
      if (!is_done(q)) undone.push_back(q);
    // A safe move is the only move tried; otherwise the enabled couplings
    // of the stubborn set with the fewest of them (a few seeds tried).
    std::vector<CouplingId> moves;
    for (CouplingId q : undone)
      if (safe(q) && enabled(q)) {
        ++st_.safe_moves;
        ++st_.propagations;
        moves = {q};
        break;
      }
    if (moves.empty()) {
      std::vector<char> in(k_, 0);
      std::vector<CouplingId> members;
      bool have = false;
      size_t tried = 0;
      for (CouplingId seed : undone) {
        if (tried++ >= 24) break;
        budget_.check();  // a closure can cost as much as the whole system
        std::vector<CouplingId> en = stubborn(seed, in, members);
        if (!have || en.size() < moves.size()) moves = std::move(en), have = true;
        if (moves.size() <= 1) break;
      }
      if (moves.size() > 1) ++st_.decisions;
    }
    for (CouplingId q : moves) {
      apply(q, +1);
      if (dfs()) return true;
      apply(q, -1);
    }
    refute(std::move(key));
    return false;
  }

  void refute(StateKey&& key) {
    ++st_.refuted;
    memo_.insert(std::move(key));
  }

  const ConstraintSystem& sys_;
  SearchBudget& budget_;
  SolveStats& st_;
  size_t k_, words_ = 0;
  std::vector<uint64_t> done_, zobrist_;
  uint64_t hash_ = 0;
  std::vector<uint32_t> offset_;
  std::vector<int64_t> cur_, pos_rem_;
  std::vector<std::vector<char>> lowers_;
  std::vector<CouplingId> path_;
  std::unordered_set<StateKey, StateKeyHash> memo_;
};

}  // namespace

SearchOutcome search_states(const ConstraintSystem& sys, SearchBudget& budget, SolveStats& st) {
  StateSearch s(sys, budget, st);
  return s.run();
}

}  // namespace gridlock
