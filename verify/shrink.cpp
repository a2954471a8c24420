#include "verify/shrink.hpp"

#include <algorithm>
#include <optional>
#include <vector>

namespace gridlock {

Formula compact_variables(const Formula& f) {
  std::vector<int> renum(static_cast<size_t>(f.num_vars) + 1, 0);
  int next = 0;
  Formula g;
  g.comments = f.comments;
  for (const auto& c : f.clauses) {
    std::vector<int> nc;
    for (int lit : c) {
      int v = var_of(lit);
      if (!renum[static_cast<size_t>(v)]) renum[static_cast<size_t>(v)] = ++next;
      nc.push_back(lit < 0 ? -renum[static_cast<size_t>(v)] : renum[static_cast<size_t>(v)]);
    }
    g.clauses.push_back(nc);
  }
  g.num_vars = next;
  return g;
}

namespace {

// f with variable v fixed to value; nullopt if a clause would become empty.
std::optional<Formula> fix_variable(const Formula& f, int v, bool value) {
  Formula g;
  g.num_vars = f.num_vars;
  g.comments = f.comments;
  for (const auto& c : f.clauses) {
    bool satisfied = false;
    std::vector<int> nc;
    for (int lit : c) {
      if (var_of(lit) != v) {
        nc.push_back(lit);
      } else if ((lit > 0) == value) {
        satisfied = true;
      }
    }
    if (satisfied) continue;
    if (nc.empty()) return std::nullopt;
    g.clauses.push_back(nc);
  }
  return g;
}

}  // namespace

Formula shrink_formula(const Formula& f, const std::function<bool(const Formula&)>& still_fails, ShrinkStats* stats) {
  ShrinkStats local;
  ShrinkStats& st = stats ? *stats : local;
  auto fails = [&](const Formula& g) {
    ++st.tries;
    return still_fails(g);
  };
  Formula cur = f;
  bool changed = true;
  while (changed) {
    changed = false;
    // 1. Clause chunks, ddmin style.
    for (size_t chunk = std::max<size_t>(cur.clauses.size() / 2, 1); chunk >= 1; chunk /= 2) {
      for (size_t start = 0; start < cur.clauses.size();) {
        Formula g = cur;
        size_t end = std::min(start + chunk, g.clauses.size());
        g.clauses.erase(g.clauses.begin() + static_cast<long>(start), g.clauses.begin() + static_cast<long>(end));
        if (!g.clauses.empty() && fails(g)) {
          cur = std::move(g);
          ++st.steps;
          changed = true;
        } else {
          start += chunk;
        }
      }
      if (chunk == 1) break;
    }
    // 2. Single literals.
    for (size_t c = 0; c < cur.clauses.size(); ++c)
      for (size_t i = 0; i < cur.clauses[c].size() && cur.clauses[c].size() > 1;) {
        Formula g = cur;
        g.clauses[c].erase(g.clauses[c].begin() + static_cast<long>(i));
        if (fails(g)) {
          cur = std::move(g);
          ++st.steps;
          changed = true;
        } else {
          ++i;
        }
      }
    // 3. Fix variables.
    for (int v = 1; v <= cur.num_vars; ++v)
      for (bool value : {false, true}) {
        auto g = fix_variable(cur, v, value);
        if (g && !g->clauses.empty() && g->clauses.size() < cur.clauses.size() + 1 && *g != cur && fails(*g)) {
          cur = std::move(*g);
          ++st.steps;
          changed = true;
          break;
        }
      }
  }
  // 4. Renumber what is left, if the failure survives it.
  Formula g = compact_variables(cur);
  if (g.num_vars < cur.num_vars && fails(g)) cur = std::move(g), ++st.steps;
  return cur;
}

}  // namespace gridlock
