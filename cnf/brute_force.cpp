#include "cnf/brute_force.hpp"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "common/limits.hpp"

namespace gridlock {

namespace {

void require_valid(const Formula& f, const char* who) {
  if (std::string bad = validate(f); !bad.empty()) throw std::invalid_argument(std::string(who) + ": " + bad);
}

struct Masks {
  uint32_t pos = 0, neg = 0;  // bit v-1: the clause holds v / -v
};

std::vector<Masks> clause_masks(const Formula& f, const char* who) {
  require_valid(f, who);
  if (f.num_vars > kExhaustiveMaxVars)
    throw std::invalid_argument(std::string(who) + ": " + std::to_string(f.num_vars) + " variables, at most " +
                                std::to_string(kExhaustiveMaxVars));
  std::vector<Masks> masks;
  masks.reserve(f.clauses.size());
  for (const auto& c : f.clauses) {
    Masks m;
    for (int lit : c) (lit > 0 ? m.pos : m.neg) |= uint32_t{1} << (var_of(lit) - 1);
    masks.push_back(m);
  }
  return masks;
}

bool all_true(const std::vector<Masks>& masks, uint32_t a) {
  for (const auto& m : masks)
    if (((a & m.pos) | (~a & m.neg)) == 0) return false;
  return true;
}

}  // namespace

SatResult exhaustive_sat(const Formula& f, const SatLimits& lim) {
  const auto masks = clause_masks(f, "exhaustive_sat");
  const Deadline clock(lim.seconds);
  SatResult res;
  res.status = Verdict::No;
  const uint64_t end = uint64_t{1} << f.num_vars;
  for (uint64_t a = 0; a < end; ++a) {
    if ((a & 0xffff) == 0 && clock.expired()) {
      res.status = Verdict::Unknown;
      break;
    }
    if (!all_true(masks, static_cast<uint32_t>(a))) continue;
    res.status = Verdict::Yes;
    res.model.assign(static_cast<size_t>(f.num_vars) + 1, false);
    for (int v = 1; v <= f.num_vars; ++v) res.model[static_cast<size_t>(v)] = (a >> (v - 1)) & 1;
    break;
  }
  res.seconds = clock.elapsed();
  return res;
}

uint64_t count_models(const Formula& f) {
  const auto masks = clause_masks(f, "count_models");
  uint64_t count = 0;
  const uint64_t end = uint64_t{1} << f.num_vars;
  for (uint64_t a = 0; a < end; ++a) count += all_true(masks, static_cast<uint32_t>(a));
  return count;
}

namespace {

class Dpll {
 public:
  explicit Dpll(const Formula& f) : f_(f), val_(static_cast<size_t>(f.num_vars) + 1, 0), occ_(2 * val_.size()) {
    for (size_t c = 0; c < f.clauses.size(); ++c)
      for (int lit : f.clauses[c]) occ_[index(lit)].push_back(c);
  }

  SatResult run(uint64_t max_decisions, const SatLimits& lim) {
    const Deadline clock(lim.seconds);
    SatResult res;
    // Empty and unit clauses are the starting facts.
    for (const auto& c : f_.clauses) {
      if (c.empty()) {
        res.status = Verdict::No;
        return res;
      }
      if (c.size() == 1 && !assign(c[0])) {
        res.status = Verdict::No;
        return res;
      }
    }
    struct Decision {
      size_t trail_size;
      int lit;
      bool flipped;
    };
    std::vector<Decision> stack;
    uint64_t decisions = 0;
    int64_t conflicts = 0;
    while (true) {
      if (clock.expired()) break;  // Unknown
      if (!propagate()) {
        if (lim.conflicts >= 0 && ++conflicts > lim.conflicts) break;  // Unknown
        while (!stack.empty() && stack.back().flipped) {
          undo(stack.back().trail_size);
          stack.pop_back();
        }
        if (stack.empty()) {
          res.status = Verdict::No;
          return res;
        }
        undo(stack.back().trail_size);
        stack.back().flipped = true;
        assign(-stack.back().lit);
        continue;
      }
      int lit = choose();
      if (lit == 0) {  // every clause satisfied
        res.status = Verdict::Yes;
        break;
      }
      if (++decisions > max_decisions) break;  // Unknown
      stack.push_back({trail_.size(), lit, false});
      assign(lit);
    }
    res.seconds = clock.elapsed();
    if (res.status != Verdict::Yes) return res;
    res.model.assign(val_.size(), false);
    for (size_t v = 1; v < val_.size(); ++v) res.model[v] = val_[v] > 0;
    // An oracle that is wrong is worse than none: check before answering.
    if (!satisfies(f_, res.model)) throw std::logic_error("dpll_sat: model check failed (bug)");
    return res;
  }

 private:
  static size_t index(int lit) { return 2 * static_cast<size_t>(var_of(lit)) + (lit < 0); }
  int value(int lit) const {  // 1 true, -1 false, 0 open
    int v = val_[static_cast<size_t>(var_of(lit))];
    return lit > 0 ? v : -v;
  }
  // false if lit is already false (a conflict).
  bool assign(int lit) {
    int v = value(lit);
    if (v != 0) return v > 0;
    val_[static_cast<size_t>(var_of(lit))] = lit > 0 ? 1 : -1;
    trail_.push_back(lit);
    return true;
  }
  void undo(size_t size) {
    while (trail_.size() > size) {
      val_[static_cast<size_t>(var_of(trail_.back()))] = 0;
      trail_.pop_back();
    }
    head_ = std::min(head_, size);
  }
  // Unit propagation from the trail's unprocessed part; false on conflict.
  bool propagate() {
    while (head_ < trail_.size()) {
      int lit = trail_[head_++];
      for (size_t c : occ_[index(-lit)]) {
        int open = 0, unit = 0;
        bool sat = false;
        for (int x : f_.clauses[c]) {
          int v = value(x);
          if (v > 0) {
            sat = true;
            break;
          }
          if (v == 0) {
            ++open;
            unit = x;
          }
        }
        if (sat) continue;
        if (open == 0) return false;
        if (open == 1) assign(unit);
      }
    }
    return true;
  }
  // A literal of a shortest open unsatisfied clause, or 0 if all are satisfied.
  int choose() const {
    int best = 0;
    size_t best_open = SIZE_MAX;
    for (const auto& c : f_.clauses) {
      size_t open = 0;
      int first = 0;
      bool sat = false;
      for (int x : c) {
        int v = value(x);
        if (v > 0) {
          sat = true;
          break;
        }
        if (v == 0 && !open++) first = x;
      }
      if (!sat && open < best_open) {
        best_open = open;
        best = first;
        if (open <= 1) break;
      }
    }
    return best;
  }

  const Formula& f_;
  std::vector<int> val_;  // per variable: 1 true, -1 false, 0 open
  std::vector<std::vector<size_t>> occ_;
  std::vector<int> trail_;
  size_t head_ = 0;
};

}  // namespace

SatResult dpll_sat(const Formula& f, uint64_t max_decisions, const SatLimits& lim) {
  require_valid(f, "dpll_sat");
  return Dpll(f).run(max_decisions, lim);
}

}  // namespace gridlock
