#include "cnf/lsat.hpp"

#include <algorithm>
#include <cstdint>
#include <set>
#include <stdexcept>
#include <tuple>

#include "common/assert.hpp"

namespace gridlock {

namespace {

// "3 (1 -2 4)": a clause as messages show it, 1-based, at most 6 literals.
std::string show_clause(const Formula& f, size_t i) {
  std::string s = std::to_string(i + 1) + " (";
  const auto& c = f.clauses[i];
  for (size_t k = 0; k < c.size() && k < 6; ++k) s += (k ? " " : "") + std::to_string(c[k]);
  if (c.size() > 6) s += " ... " + std::to_string(c.size()) + " literals";
  return s + ")";
}

std::string join(const std::vector<int>& lits) {
  std::string s;
  for (size_t k = 0; k < lits.size(); ++k) s += (k ? " " : "") + std::to_string(lits[k]);
  return s;
}

// How many other occurrences of one literal a clause looks at. Three others
// already prove a violation, so the scan is bounded and the check stays
// O(L log L) even when a literal occurs a million times.
constexpr size_t kNeighbourScan = 4;

// Every occurrence of a literal in f, sorted by literal so that each
// literal's clauses form one run. Sorting instead of indexing by variable
// keeps memory independent of num_vars (a header may declare two billion
// variables); sorting the entries themselves, not indices to them, keeps the
// sort cache-friendly. Built in O(L log L).
struct OccurrenceIndex {
  struct Occ {
    int lit;
    size_t clause;
    size_t slot;  // position in the clause-ordered list of all occurrences
  };
  std::vector<Occ> sorted;
  std::vector<size_t> first;  // clause i's occurrences: slots first[i]..first[i+1]
  std::vector<int> lit_of;    // by slot
  // run_of[slot]: the run [begin, end) in `sorted` holding that occurrence;
  // pos_of[slot]: its own place there.
  std::vector<std::pair<size_t, size_t>> run_of;
  std::vector<size_t> pos_of;

  explicit OccurrenceIndex(const Formula& f) : first(f.clauses.size() + 1, 0) {
    sorted.reserve(num_literals(f));
    for (size_t i = 0; i < f.clauses.size(); ++i) {
      first[i] = sorted.size();
      for (int lit : f.clauses[i]) sorted.push_back({lit, i, sorted.size()});
    }
    first[f.clauses.size()] = sorted.size();
    lit_of.resize(sorted.size());
    for (const auto& o : sorted) lit_of[o.slot] = o.lit;
    std::sort(sorted.begin(), sorted.end(), [](const Occ& a, const Occ& b) {
      return std::tie(a.lit, a.clause, a.slot) < std::tie(b.lit, b.clause, b.slot);
    });
    run_of.resize(sorted.size());
    pos_of.resize(sorted.size());
    for (size_t b = 0; b < sorted.size();) {
      size_t e = b;
      while (e < sorted.size() && sorted[e].lit == sorted[b].lit) ++e;
      for (size_t k = b; k < e; ++k) {
        run_of[sorted[k].slot] = {b, e};
        pos_of[sorted[k].slot] = k;
      }
      b = e;
    }
  }

  // A literal clause i holds twice, if any: the clause occurs twice in one
  // literal's run (runs are sorted by clause, so the entries are adjacent:
  // O(1) per literal however long the run is).
  std::optional<int> repeated_literal(size_t i) const {
    std::optional<int> repeated;
    for (size_t k = first[i]; k < first[i + 1] && !repeated; ++k) {
      const size_t p = pos_of[k];
      const auto [b, e] = run_of[k];
      if ((p > b && sorted[p - 1].clause == i) || (p + 1 < e && sorted[p + 1].clause == i)) repeated = lit_of[k];
    }
    return repeated;
  }

  // Clause i's neighbours: (other clause, shared literal), sorted, without
  // duplicates (a neighbour repeating the literal counts once), at most
  // kNeighbourScan other occurrences looked at per literal.
  std::vector<std::pair<size_t, int>> neighbours(size_t i) const {
    std::vector<std::pair<size_t, int>> nb;
    for (size_t k = first[i]; k < first[i + 1]; ++k) {
      auto [b, e] = run_of[k];
      size_t seen = 0;
      for (size_t r = b; r < e && seen < kNeighbourScan; ++r) {
        size_t j = sorted[r].clause;
        if (j == i) continue;
        nb.push_back({j, lit_of[k]});
        ++seen;
      }
    }
    std::sort(nb.begin(), nb.end());
    nb.erase(std::unique(nb.begin(), nb.end()), nb.end());
    return nb;
  }
};

}  // namespace

const char* rule_name(LsatRule rule) {
  switch (rule) {
    case LsatRule::ClauseLength: return "clause-length";
    case LsatRule::RepeatedLiteral: return "repeated-literal";
    case LsatRule::SharesTwoLiterals: return "shares-two-literals";
    case LsatRule::IntersectsTwoClauses: return "intersects-two-clauses";
  }
  return "?";
}

LsatReport check_lsat(const Formula& f, LsatForm form, size_t max_violations) {
  GRIDLOCK_ASSERT(validate(f).empty(), "check_lsat needs a valid formula");
  LsatReport rep;
  const OccurrenceIndex occ(f);

  std::set<std::pair<size_t, size_t>> reported_pairs;  // SharesTwoLiterals, reported once per pair
  auto add = [&](LsatViolation v) {
    rep.ok = false;
    if (rep.violations.size() < max_violations) rep.violations.push_back(std::move(v));
  };
  for (size_t i = 0; i < f.clauses.size(); ++i) {
    const auto& c = f.clauses[i];
    if (is_tautology(c)) rep.tautologies.push_back(i);
    if (!rep.ok && rep.violations.size() >= max_violations) continue;  // only the verdict and tautologies left
    const bool bad_length = form == LsatForm::Exact3 ? c.size() != 3 : (c.empty() || c.size() > 3);
    if (bad_length) {
      add({LsatRule::ClauseLength,
           {i},
           {},
           "clause " + show_clause(f, i) + " has " + std::to_string(c.size()) + " literals, not " +
               (form == LsatForm::Exact3 ? "3" : "1 to 3")});
      continue;
    }
    if (std::optional<int> repeated = occ.repeated_literal(i)) {
      add({LsatRule::RepeatedLiteral,
           {i},
           {*repeated},
           "clause " + show_clause(f, i) + " repeats literal " + std::to_string(*repeated)});
      continue;
    }
    // Neighbours: (other clause, shared literal), a bounded number per literal.
    const std::vector<std::pair<size_t, int>> nb = occ.neighbours(i);
    bool found = false;
    for (size_t a = 0; a + 1 < nb.size() && !found; ++a) {
      if (nb[a].first != nb[a + 1].first) continue;
      found = true;
      size_t j = nb[a].first;
      std::vector<int> shared;
      for (const auto& [jj, lit] : nb)
        if (jj == j) shared.push_back(lit);
      if (reported_pairs.insert({std::min(i, j), std::max(i, j)}).second)
        add({LsatRule::SharesTwoLiterals,
             {i, j},
             shared,
             "clauses " + show_clause(f, i) + " and " + show_clause(f, j) + " share " + std::to_string(shared.size()) +
                 " literals (" + join(shared) + "), not exactly 1"});
    }
    if (found) continue;
    if (nb.size() >= 2) {  // all neighbours distinct here: two or more other clauses
      add({LsatRule::IntersectsTwoClauses,
           {i, nb[0].first, nb[1].first},
           {nb[0].second, nb[1].second},
           "clause " + show_clause(f, i) + " intersects clauses " + std::to_string(nb[0].first + 1) + " (in literal " +
               std::to_string(nb[0].second) + ") and " + std::to_string(nb[1].first + 1) + " (in literal " +
               std::to_string(nb[1].second) + "), not at most one"});
    }
  }
  return rep;
}

bool is_lsat(const Formula& f, LsatForm form) { return check_lsat(f, form, 0).ok; }

std::optional<std::vector<bool>> hall_assignment(const Formula& f) {
  if (!validate(f).empty()) throw std::invalid_argument("hall_assignment: " + validate(f));
  // Work on the variables that occur, renumbered 0..k-1 (sorted), so that the
  // matching's memory is O(L) whatever num_vars the header declares; only
  // the returned assignment has num_vars + 1 entries (bits).
  std::vector<int> vars;
  vars.reserve(num_literals(f));
  for (const auto& c : f.clauses)
    for (int lit : c) vars.push_back(var_of(lit));
  std::sort(vars.begin(), vars.end());
  vars.erase(std::unique(vars.begin(), vars.end()), vars.end());
  auto dense = [&](int lit) {
    return static_cast<size_t>(std::lower_bound(vars.begin(), vars.end(), var_of(lit)) - vars.begin());
  };
  const size_t k = vars.size();
  const size_t m = f.clauses.size();
  std::vector<std::vector<size_t>> cvars(m);  // clause -> its dense variables
  for (size_t c = 0; c < m; ++c)
    for (int lit : f.clauses[c]) cvars[c].push_back(dense(lit));
  std::vector<long> owner(k, -1);           // variable -> clause it represents
  std::vector<size_t> chosen(m, SIZE_MAX);  // clause -> its variable
  // Augmenting paths by breadth-first search from each clause in turn
  // (iterative: no recursion depth to overflow on large formulas).
  std::vector<size_t> parent_clause(k);
  std::vector<size_t> stamp(k, 0);
  std::vector<size_t> queue;
  for (size_t i = 0; i < m; ++i) {
    const size_t mark = i + 1;
    queue.assign(1, i);
    size_t end_var = SIZE_MAX;
    for (size_t q = 0; q < queue.size() && end_var == SIZE_MAX; ++q) {
      const size_t c = queue[q];
      for (size_t v : cvars[c]) {
        if (stamp[v] == mark) continue;
        stamp[v] = mark;
        parent_clause[v] = c;
        if (owner[v] < 0) {
          end_var = v;
          break;
        }
        queue.push_back(static_cast<size_t>(owner[v]));
      }
    }
    if (end_var == SIZE_MAX) return std::nullopt;  // Hall's condition fails for the clauses reached
    // Flip the path: each clause on it takes the variable that led to it.
    for (size_t v = end_var;;) {
      const size_t c = parent_clause[v];
      const size_t prev = chosen[c];
      chosen[c] = v;
      owner[v] = static_cast<long>(c);
      if (c == i) break;
      v = prev;
    }
  }
  std::vector<bool> value(static_cast<size_t>(f.num_vars) + 1, false);
  for (size_t c = 0; c < m; ++c) {
    // The clause's literal on its own variable decides the value (for a
    // tautology either sign satisfies it; take the first one written).
    for (int lit : f.clauses[c])
      if (dense(lit) == chosen[c]) {
        value[static_cast<size_t>(var_of(lit))] = lit > 0;
        break;
      }
  }
  return value;
}

}  // namespace gridlock
