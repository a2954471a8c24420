// CNF -> LSAT<=3; the construction is described in reductions/to_lsat.hpp and
// proved in docs/formulas.md.
#include "reductions/to_lsat.hpp"

#include <algorithm>
#include <climits>
#include <set>
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

// The construction's steps (to_lsat.hpp), on one input.
class LsatBuilder {
 public:
  using Recipe = LsatReduction::Recipe;
  LsatBuilder(const Formula& in, const ToLsatOptions& opt) : in_(in), opt_(opt), st_(red_.stats_) {
    red_.source_vars_ = in.num_vars;
    st_.in_vars = in.num_vars;
    st_.in_clauses = in.clauses.size();
    next_var_ = static_cast<int64_t>(in.num_vars) + 1;
  }

  LsatReduction build() {
    if (opt_.passthrough && may_be_lsat() && is_lsat(in_, LsatForm::AtMost3)) return pass_through();
    normalise();
    plan_paths();
    emit_clauses();
    finish();
    return std::move(red_);
  }

 private:
  int fresh() {
    if (next_var_ > INT_MAX) throw InputTooLarge("to-lsat: the output would have more than INT_MAX variables");
    return static_cast<int>(next_var_++);
  }

  // Pass-through test. A literal occurring three times rules LSAT<=3 out
  // at once (the usual case for 3-CNF), without the full check's sort.
  bool may_be_lsat() const {
    std::vector<uint8_t> count(2 * static_cast<size_t>(in_.num_vars) + 2, 0);
    for (const auto& c : in_.clauses) {
      if (c.empty() || c.size() > 3) return false;
      for (int lit : c) {
        uint8_t& k = count[2 * static_cast<size_t>(var_of(lit)) + (lit < 0)];
        if (++k > 2) return false;
      }
    }
    return true;
  }

  LsatReduction pass_through() {
    st_.identity = true;
    red_.out_.num_vars = in_.num_vars;
    red_.out_.clauses = in_.clauses;
    red_.out_.comments = {"to-lsat: the input already is LSAT<=3; passed through unchanged (identity maps)"};
    red_.recipe_.assign(static_cast<size_t>(in_.num_vars) + 1, {});
    st_.out_vars = in_.num_vars;
    st_.out_clauses = in_.clauses.size();
    st_.normalised_clauses = in_.clauses.size();
    return std::move(red_);
  }

  // The clause's distinct literals in lits_ (repeats counted). Short clauses
  // (the usual case) scan; long ones use a hash set so that one clause of a
  // million literals stays linear.
  void distinct_literals(const std::vector<int>& c) {
    lits_.clear();
    const bool long_clause = c.size() > 16;
    if (long_clause) seen_long_.clear();
    for (int lit : c) {
      bool seen = false;
      if (long_clause) seen = !seen_long_.insert(lit).second;
      else
        for (int x : lits_) seen = seen || x == lit;
      if (seen) ++st_.repeated_literals;
      else lits_.push_back(lit);
    }
  }

  // A clause with the same set of literals as an earlier one (it adds
  // nothing: every assignment satisfies both or neither).
  bool is_duplicate() {
    if (opt_.keep_duplicates) return false;
    std::vector<int> key = lits_;
    std::sort(key.begin(), key.end());
    return !seen_clauses_.insert(std::move(key)).second;
  }

  // (l1 l2 a1)(-a1 l3 a2)...(-a_{s-3} l_{s-1} l_s) with fresh chain variables.
  void split_long_clause() {
    ++st_.split_clauses;
    LsatReduction::ChainRecord ch;
    ch.lits = lits_;
    const size_t s = lits_.size();
    int prev = fresh();
    ch.first_var = prev;
    norm_.push_back({lits_[0], lits_[1], prev});
    for (size_t j = 2; j + 2 < s; ++j) {
      int a = fresh();
      norm_.push_back({-prev, lits_[j], a});
      prev = a;
    }
    norm_.push_back({-prev, lits_[s - 2], lits_[s - 1]});
    st_.normalised_clauses += s - 2;
    st_.chain_vars += s - 3;
    red_.chains_.push_back(std::move(ch));
  }

  // Step 1: clauses of 1..3 distinct, non-complementary literals over
  // variables 1..n+A; an empty vector marks an empty input clause (to become
  // (u)(-u)).
  void normalise() {
    norm_.reserve(in_.clauses.size());
    for (const auto& c : in_.clauses) {
      distinct_literals(c);
      if (is_tautology(lits_)) {
        ++st_.tautologies;
      } else if (lits_.empty()) {
        ++st_.empty_clauses;
        norm_.emplace_back();
      } else if (is_duplicate()) {
        ++st_.duplicate_clauses;
      } else if (lits_.size() <= 3) {
        norm_.push_back(lits_);
        ++st_.normalised_clauses;
      } else {
        split_long_clause();
      }
    }
    n1_ = static_cast<int>(next_var_ - 1);  // n + A
  }

  bool cycled(size_t x) const { return pos_[x] >= 2 || neg_[x] >= 2; }
  // Path w_1 .. w_k of x: positives take w_1 .. w_p, negatives -w_s .. -w_k
  // with s = max(p, 1) the pivot (w_s is x itself).
  int pivot(size_t x) const { return std::max(pos_[x], 1); }
  int path_len(size_t x) const { return neg_[x] > 0 ? pivot(x) + neg_[x] - 1 : pos_[x]; }
  int path_var(size_t x, int i) const {
    const int s = pivot(x);
    return i == s ? static_cast<int>(x) : base_[x] + (i < s ? i - 1 : i - 2);
  }

  // Steps 2/3: occurrence counts, the variables that need a path, and where
  // their path variables are numbered (w_i, i != s, of x is variable
  // base[x] + i - 1 for i < s, base[x] + i - 2 for i > s).
  void plan_paths() {
    const size_t N = static_cast<size_t>(n1_) + 1;
    pos_.assign(N, 0);
    neg_.assign(N, 0);
    for (const auto& c : norm_)
      for (int lit : c) ++(lit > 0 ? pos_ : neg_)[static_cast<size_t>(var_of(lit))];
    base_.assign(N, 0);
    for (size_t x = 1; x < N; ++x) {
      if (!cycled(x)) continue;
      ++st_.cycle_vars;
      const int k = path_len(x);
      st_.copies += static_cast<size_t>(k);
      base_[x] = static_cast<int>(next_var_);
      for (int i = 1; i < k; ++i) fresh();
    }
    red_.recipe_.assign(static_cast<size_t>(next_var_), {});
    for (size_t x = 1; x < N; ++x)
      for (int i = 1; cycled(x) && i <= path_len(x); ++i)
        if (i != pivot(x)) red_.recipe_[static_cast<size_t>(path_var(x, i))] = {Recipe::Copy, static_cast<int>(x)};
    for (size_t v = static_cast<size_t>(in_.num_vars) + 1; v <= static_cast<size_t>(n1_); ++v)
      red_.recipe_[v] = {Recipe::Chain, 0};
  }

  void add_recipe(int v, Recipe r) {
    if (red_.recipe_.size() <= static_cast<size_t>(v)) red_.recipe_.resize(static_cast<size_t>(v) + 1);
    red_.recipe_[static_cast<size_t>(v)] = r;
  }

  // Step 4 for one normalised clause: free literals as they are, and so the
  // first other path literal; each further one becomes a fresh y with the
  // link (-y path-literal) after the clause.
  void emit_clause(const std::vector<int>& c) {
    Formula& out = red_.out_;
    if (c.empty()) {
      int u = fresh();
      add_recipe(u, {Recipe::False, 0});
      out.clauses.push_back({u});
      out.clauses.push_back({-u});
      return;
    }
    std::vector<int> oc;
    links_.clear();
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
      const int i = lit > 0 ? ++pos_seen_[x] : pivot(x) + neg_seen_[x]++;
      const int z = path_var(x, i);
      const int zlit = lit > 0 ? z : -z;
      const bool free_end = lit > 0 ? i == 1 : i == path_len(x);
      if (free_end || !direct_used) {
        direct_used = direct_used || !free_end;
        oc.push_back(zlit);
        continue;
      }
      int y = fresh();
      add_recipe(y, {Recipe::Occurrence, lit});
      oc.push_back(y);
      links_.push_back({-y, zlit});
      ++st_.links;
    }
    out.clauses.push_back(std::move(oc));
    for (auto& l : links_) out.clauses.push_back(std::move(l));
  }

  // Step 4: the clauses, each followed by its links, then the path clauses.
  void emit_clauses() {
    const size_t N = static_cast<size_t>(n1_) + 1;
    red_.out_.clauses.reserve(norm_.size() * 3 + 2 * st_.empty_clauses + st_.copies);
    pos_seen_.assign(N, 0);
    neg_seen_.assign(N, 0);
    for (const auto& c : norm_) emit_clause(c);
    for (size_t x = 1; x < N; ++x) {
      if (!cycled(x)) continue;
      const int k = path_len(x);
      for (int i = 1; i < k; ++i) red_.out_.clauses.push_back({-path_var(x, i), path_var(x, i + 1)});
    }
  }

  void finish() {
    Formula& out = red_.out_;
    out.num_vars = static_cast<int>(next_var_ - 1);
    red_.recipe_.resize(static_cast<size_t>(out.num_vars) + 1);
    st_.out_vars = out.num_vars;
    st_.out_clauses = out.clauses.size();
    out.comments = {"to-lsat: variables 1.." + std::to_string(in_.num_vars) + " are the input's; " +
                        std::to_string(st_.chain_vars) + " chain, " + std::to_string(st_.copies - st_.cycle_vars) +
                        " copy, " + std::to_string(st_.links) + " occurrence and " + std::to_string(st_.empty_clauses) +
                        " false variables follow",
                    "to-lsat: " + std::to_string(st_.cycle_vars) + " variables occur with a literal more than once: " +
                        std::to_string(st_.copies - st_.cycle_vars) + " path clauses, " + std::to_string(st_.links) +
                        " links; " + std::to_string(st_.tautologies) + " tautologies and " +
                        std::to_string(st_.duplicate_clauses) + " duplicate clauses dropped, " +
                        std::to_string(st_.split_clauses) + " long clauses split"};
  }

  const Formula& in_;
  const ToLsatOptions& opt_;
  LsatReduction red_;
  ToLsatStats& st_;
  int64_t next_var_ = 1;
  int n1_ = 0;
  std::vector<std::vector<int>> norm_, links_;
  std::vector<int> lits_;
  std::unordered_set<int> seen_long_;
  std::set<std::vector<int>> seen_clauses_;
  std::vector<int> pos_, neg_, base_, pos_seen_, neg_seen_;
};

LsatReduction reduce_to_lsat(const Formula& in, const ToLsatOptions& opt) {
  if (std::string bad = validate(in); !bad.empty()) throw std::invalid_argument("reduce_to_lsat: " + bad);
  return LsatBuilder(in, opt).build();
}

}  // namespace gridlock
