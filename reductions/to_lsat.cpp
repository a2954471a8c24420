// CNF -> LSAT<=3; the construction is described in reductions/to_lsat.hpp and
// proved in docs/formulas.md.
#include "reductions/to_lsat.hpp"

#include <algorithm>
#include <climits>
#include <stdexcept>
#include <string>
#include <unordered_set>

#include "cnf/lsat.hpp"

namespace gridlock {

std::vector<bool> LsatReduction::lift_to_source(const std::vector<bool>& out) const {
  if (out.size() < static_cast<size_t>(out_.num_vars) + 1)
    throw std::invalid_argument("lift_to_source: assignment has " + std::to_string(out.size()) + " entries, needs " +
                                std::to_string(out_.num_vars) + "+1");
  return std::vector<bool>(out.begin(), out.begin() + source_vars_ + 1);
}

std::vector<bool> LsatReduction::lift_to_target(const std::vector<bool>& in) const {
  if (in.size() < static_cast<size_t>(source_vars_) + 1)
    throw std::invalid_argument("lift_to_target: assignment has " + std::to_string(in.size()) + " entries, needs " +
                                std::to_string(source_vars_) + "+1");
  std::vector<bool> val(static_cast<size_t>(out_.num_vars) + 1, false);
  for (size_t v = 1; v <= static_cast<size_t>(source_vars_); ++v) val[v] = in[v];
  // Chain variables first: occurrence variables never stand for them (chain
  // variables occur once per sign), but keep the order obvious anyway.
  for (const auto& ch : chains_) {
    bool all_false = !literal_value(ch.lits[0], in) && !literal_value(ch.lits[1], in);
    for (size_t j = 0; j + 3 < ch.lits.size(); ++j) {
      if (j > 0) all_false = all_false && !literal_value(ch.lits[j + 1], in);
      val[static_cast<size_t>(ch.first_var) + j] = all_false;
    }
  }
  for (size_t v = static_cast<size_t>(source_vars_) + 1; v < recipe_.size(); ++v) {
    const Recipe& r = recipe_[v];
    if (r.kind == Recipe::Copy) val[v] = in[static_cast<size_t>(r.lit)];
    else if (r.kind == Recipe::Occurrence) val[v] = literal_value(r.lit, in);
    else if (r.kind == Recipe::False) val[v] = false;
  }
  return val;
}

LsatReduction reduce_to_lsat(const Formula& in, const ToLsatOptions& opt) {
  if (std::string bad = validate(in); !bad.empty()) throw std::invalid_argument("reduce_to_lsat: " + bad);
  LsatReduction red;
  ToLsatStats& st = red.stats_;
  red.source_vars_ = in.num_vars;
  st.in_vars = in.num_vars;
  st.in_clauses = in.clauses.size();

  // Pass-through test. A literal occurring three times rules LSAT<=3 out
  // at once (the usual case for 3-CNF), without the full check's sort.
  auto may_be_lsat = [&] {
    std::vector<uint8_t> count(2 * static_cast<size_t>(in.num_vars) + 2, 0);
    for (const auto& c : in.clauses) {
      if (c.empty() || c.size() > 3) return false;
      for (int lit : c) {
        uint8_t& k = count[2 * static_cast<size_t>(var_of(lit)) + (lit < 0)];
        if (++k > 2) return false;
      }
    }
    return true;
  };
  if (opt.passthrough && may_be_lsat() && is_lsat(in, LsatForm::AtMost3)) {
    st.identity = true;
    red.out_.num_vars = in.num_vars;
    red.out_.clauses = in.clauses;
    red.out_.comments = {"to-lsat: the input already is LSAT<=3; passed through unchanged (identity maps)"};
    red.recipe_.assign(static_cast<size_t>(in.num_vars) + 1, {});
    st.out_vars = in.num_vars;
    st.out_clauses = in.clauses.size();
    st.normalised_clauses = in.clauses.size();
    return red;
  }

  // Step 1: normalise into clauses of 1..3 distinct, non-complementary
  // literals over variables 1..n+A; an empty vector marks an empty input
  // clause (to become (u)(-u)).
  int64_t next_var = static_cast<int64_t>(in.num_vars) + 1;
  auto fresh = [&]() -> int {
    if (next_var > INT_MAX) throw std::length_error("to-lsat: the output would have more than INT_MAX variables");
    return static_cast<int>(next_var++);
  };
  std::vector<std::vector<int>> norm;
  norm.reserve(in.clauses.size());
  std::vector<int> lits;
  std::unordered_set<int> seen_long;
  for (const auto& c : in.clauses) {
    lits.clear();
    // Short clauses (the usual case) scan; long ones use a hash set so that
    // one clause of a million literals stays linear.
    const bool long_clause = c.size() > 16;
    if (long_clause) seen_long.clear();
    for (int lit : c) {
      bool seen = false;
      if (long_clause) seen = !seen_long.insert(lit).second;
      else
        for (int x : lits) seen = seen || x == lit;
      if (seen) {
        ++st.repeated_literals;
        continue;
      }
      lits.push_back(lit);
    }
    if (is_tautology(lits)) {
      ++st.tautologies;
      continue;
    }
    if (lits.empty()) {
      ++st.empty_clauses;
      norm.emplace_back();
      continue;
    }
    if (lits.size() <= 3) {
      norm.push_back(lits);
      ++st.normalised_clauses;
      continue;
    }
    ++st.split_clauses;
    LsatReduction::ChainRecord ch;
    ch.lits = lits;
    const size_t s = lits.size();
    int prev = fresh();
    ch.first_var = prev;
    norm.push_back({lits[0], lits[1], prev});
    for (size_t j = 2; j + 2 < s; ++j) {
      int a = fresh();
      norm.push_back({-prev, lits[j], a});
      prev = a;
    }
    norm.push_back({-prev, lits[s - 2], lits[s - 1]});
    st.normalised_clauses += s - 2;
    st.chain_vars += s - 3;
    red.chains_.push_back(std::move(ch));
  }
  const int n1 = static_cast<int>(next_var - 1);  // n + A

  // Step 2/3: occurrence counts, the variables that need a path, and where
  // their path variables are numbered.
  const size_t N = static_cast<size_t>(n1) + 1;
  std::vector<int> pos(N, 0), neg(N, 0);
  for (const auto& c : norm)
    for (int lit : c) ++(lit > 0 ? pos : neg)[static_cast<size_t>(var_of(lit))];
  auto cycled = [&](size_t x) { return pos[x] >= 2 || neg[x] >= 2; };
  // Path w_1 .. w_k of x: positives take w_1 .. w_p, negatives -w_s .. -w_k
  // with s = max(p, 1) the pivot (w_s is x itself).
  auto pivot = [&](size_t x) { return std::max(pos[x], 1); };
  auto path_len = [&](size_t x) { return neg[x] > 0 ? pivot(x) + neg[x] - 1 : pos[x]; };
  std::vector<int> base(N, 0);  // w_i (i != s) of x is variable base[x] + i - 1 (i < s) or base[x] + i - 2 (i > s)
  for (size_t x = 1; x < N; ++x) {
    if (!cycled(x)) continue;
    ++st.cycle_vars;
    const int k = path_len(x);
    st.copies += static_cast<size_t>(k);
    base[x] = static_cast<int>(next_var);
    for (int i = 1; i < k; ++i) fresh();
  }
  auto path_var = [&](size_t x, int i) {
    const int s = pivot(x);
    return i == s ? static_cast<int>(x) : base[x] + (i < s ? i - 1 : i - 2);
  };

  red.recipe_.assign(static_cast<size_t>(next_var), {});
  for (size_t x = 1; x < N; ++x)
    for (int i = 1; cycled(x) && i <= path_len(x); ++i)
      if (i != pivot(x))
        red.recipe_[static_cast<size_t>(path_var(x, i))] = {LsatReduction::Recipe::Copy, static_cast<int>(x)};
  for (size_t v = static_cast<size_t>(in.num_vars) + 1; v <= static_cast<size_t>(n1); ++v)
    red.recipe_[v] = {LsatReduction::Recipe::Chain, 0};

  // Step 4: the clauses, each followed by its links.
  Formula& out = red.out_;
  out.clauses.reserve(norm.size() * 3 + 2 * st.empty_clauses + st.copies);
  std::vector<int> pos_seen(N, 0), neg_seen(N, 0);
  auto add_recipe = [&](int v, LsatReduction::Recipe r) {
    if (red.recipe_.size() <= static_cast<size_t>(v)) red.recipe_.resize(static_cast<size_t>(v) + 1);
    red.recipe_[static_cast<size_t>(v)] = r;
  };
  std::vector<std::vector<int>> links;
  for (const auto& c : norm) {
    if (c.empty()) {
      int u = fresh();
      add_recipe(u, {LsatReduction::Recipe::False, 0});
      out.clauses.push_back({u});
      out.clauses.push_back({-u});
      continue;
    }
    std::vector<int> oc;
    links.clear();
    bool direct_used = false;
    for (int lit : c) {
      const size_t x = static_cast<size_t>(var_of(lit));
      if (!cycled(x)) {
        oc.push_back(lit);
        continue;
      }
      // This occurrence's path literal: the j-th positive one is w_{j+1},
      // the j-th negative one -w_{s+j}. w_i's positive literal is in path
      // clause i-1 (none for w_1), its negative literal in path clause i
      // (none for w_k), so the two ends are free and every path clause is
      // met by at most one occurrence.
      const int k = path_len(x);
      const int i = lit > 0 ? ++pos_seen[x] : pivot(x) + neg_seen[x]++;
      const int z = path_var(x, i);
      const int zlit = lit > 0 ? z : -z;
      const bool free_end = lit > 0 ? i == 1 : i == k;
      if (free_end || !direct_used) {
        direct_used = direct_used || !free_end;
        oc.push_back(zlit);
        continue;
      }
      int y = fresh();
      add_recipe(y, {LsatReduction::Recipe::Occurrence, lit});
      oc.push_back(y);
      links.push_back({-y, zlit});
      ++st.links;
    }
    out.clauses.push_back(std::move(oc));
    for (auto& l : links) out.clauses.push_back(std::move(l));
  }
  for (size_t x = 1; x < N; ++x) {
    if (!cycled(x)) continue;
    const int k = path_len(x);
    for (int i = 1; i < k; ++i) out.clauses.push_back({-path_var(x, i), path_var(x, i + 1)});
  }
  out.num_vars = static_cast<int>(next_var - 1);
  red.recipe_.resize(static_cast<size_t>(out.num_vars) + 1);
  st.out_vars = out.num_vars;
  st.out_clauses = out.clauses.size();
  out.comments = {"to-lsat: variables 1.." + std::to_string(in.num_vars) + " are the input's; " +
                      std::to_string(st.chain_vars) + " chain, " + std::to_string(st.copies - st.cycle_vars) +
                      " copy, " + std::to_string(st.links) + " occurrence and " + std::to_string(st.empty_clauses) +
                      " false variables follow",
                  "to-lsat: " + std::to_string(st.cycle_vars) +
                      " variables occur with a literal more than once: " + std::to_string(st.copies - st.cycle_vars) +
                      " path clauses, " + std::to_string(st.links) + " links; " + std::to_string(st.tautologies) +
                      " tautologies dropped, " + std::to_string(st.split_clauses) + " long clauses split"};
  return red;
}

}  // namespace gridlock
