#include "cnf/generate.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <stdexcept>
#include <string>

namespace gridlock {

namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument(what);
}

// k distinct variables of 1..n, uniform, with uniform signs, in draw order.
// Rejection is fine: callers have k <= n, and k is small in practice.
void draw_clause(Rng& rng, int n, int k, std::vector<int>& clause) {
  clause.clear();
  while (static_cast<int>(clause.size()) < k) {
    int v = static_cast<int>(rng.below(static_cast<uint64_t>(n))) + 1;
    bool fresh = true;
    for (int lit : clause) fresh = fresh && var_of(lit) != v;
    if (!fresh) continue;
    clause.push_back(rng.coin() ? v : -v);
  }
}

void check_ksat(int n, int m, int k) {
  require(n >= 1, "n must be at least 1 (got " + std::to_string(n) + ")");
  require(m >= 0, "m must be at least 0 (got " + std::to_string(m) + ")");
  require(k >= 1 && k <= n, "k must be between 1 and n = " + std::to_string(n) + " (got " + std::to_string(k) + ")");
}

}  // namespace

Formula random_ksat(const KSatParams& p) {
  check_ksat(p.n, p.m, p.k);
  Rng rng(p.seed);
  Formula f;
  f.num_vars = p.n;
  f.comments = {"generator: random-ksat (uniform: k distinct variables per clause, uniform signs)",
                "parameters: n=" + std::to_string(p.n) + " m=" + std::to_string(p.m) + " k=" + std::to_string(p.k) +
                    " seed=" + std::to_string(p.seed)};
  f.clauses.resize(static_cast<size_t>(p.m));
  for (auto& c : f.clauses) draw_clause(rng, p.n, p.k, c);
  return f;
}

int clauses_for_ratio(int n, double ratio) {
  require(std::isfinite(ratio) && ratio >= 0, "the ratio must be a finite number >= 0");
  double m = std::round(ratio * static_cast<double>(n));
  require(m <= static_cast<double>(INT_MAX), "ratio * n is too large");
  return static_cast<int>(m);
}

int lsat_max_clauses(int n, int min_len) {
  require(min_len >= 1 && min_len <= 3, "min_len must be 1, 2 or 3");
  if (n <= 0) return 0;
  // m = 2t: t (2 min_len - 1) <= 2n; m = 2t + 1: t (2 min_len - 1) + min_len <= 2n.
  const int64_t lits = 2 * static_cast<int64_t>(n), per_pair = 2 * min_len - 1;
  int64_t best = 2 * (lits / per_pair);
  if (lits >= min_len) best = std::max(best, 2 * ((lits - min_len) / per_pair) + 1);
  return static_cast<int>(std::min<int64_t>(best, INT_MAX));
}

namespace {

void check_lsat_params(const LsatParams& p) {
  require(p.min_len >= 1 && p.min_len <= p.max_len && p.max_len <= 3,
          "clause lengths must satisfy 1 <= min <= max <= 3 (got " + std::to_string(p.min_len) + ".." +
              std::to_string(p.max_len) + ")");
  require(p.n >= p.max_len, "n must be at least the longest clause length " + std::to_string(p.max_len) + " (got " +
                                std::to_string(p.n) + ")");
  require(p.m >= 0, "m must be at least 0 (got " + std::to_string(p.m) + ")");
  const int cap = lsat_max_clauses(p.n, p.min_len);
  require(p.m <= cap, "an LSAT formula with " + std::to_string(p.n) + " variables and clauses of at least " +
                          std::to_string(p.min_len) + " literals has at most " + std::to_string(cap) +
                          " clauses (got m=" + std::to_string(p.m) + ")");
}

// Lengths, shortened at random until the clauses fit: a pair of clauses of
// lengths a, b shares one literal, so it uses a + b - 1 distinct literals.
// total: the sum of the lengths.
std::vector<int> draw_lengths(Rng& rng, const LsatParams& p, int64_t& total) {
  const size_t m = static_cast<size_t>(p.m);
  const int64_t lits = 2 * static_cast<int64_t>(p.n);
  std::vector<int> len(m);
  total = 0;
  for (auto& l : len) total += l = static_cast<int>(rng.between(p.min_len, p.max_len));
  const int64_t max_pairs = static_cast<int64_t>(m / 2);
  while (total - max_pairs > lits) {
    std::vector<size_t> longer;
    for (size_t i = 0; i < m; ++i)
      if (len[i] > p.min_len) longer.push_back(i);
    // Shorten several at once: the loop runs O(1) times, not O(m).
    int64_t excess = total - max_pairs - lits;
    for (int64_t s = 0; s < excess && !longer.empty(); ++s) {
      size_t at = static_cast<size_t>(rng.below(longer.size()));
      --len[longer[at]];
      --total;
      longer[at] = longer.back();
      longer.pop_back();
    }
  }
  return len;
}

// Moves a random literal of pool whose variable clause does not hold yet
// into clause (the first usable one from a random start); false if none.
bool take_literal(Rng& rng, std::vector<int>& pool, std::vector<int>& clause) {
  if (pool.empty()) return false;
  size_t start = static_cast<size_t>(rng.below(pool.size()));
  for (size_t d = 0; d < pool.size(); ++d) {
    size_t at = (start + d) % pool.size();
    int lit = pool[at];
    bool ok = true;
    for (int x : clause) ok = ok && var_of(x) != var_of(lit);
    if (!ok) continue;
    clause.push_back(lit);
    pool[at] = pool.back();
    pool.pop_back();
    return true;
  }
  return false;
}

// One attempt at the clauses: literals drawn without replacement from all
// 2n literals; the clauses perm[2i], perm[2i+1] (i < pairs) share their first
// literal. False if the pool ran out of usable literals.
bool fill_lsat_clauses(Rng& rng, int n, const std::vector<size_t>& perm, int64_t pairs, const std::vector<int>& len,
                       std::vector<std::vector<int>>& clauses) {
  std::vector<int> pool;
  for (int v = 1; v <= n; ++v) {
    pool.push_back(v);
    pool.push_back(-v);
  }
  const size_t m = perm.size();
  clauses.assign(m, {});
  bool ok = true;
  for (size_t t = 0; ok && t < m; ++t) {
    const size_t a = perm[t];
    auto& ca = clauses[a];
    if (static_cast<int64_t>(t) < 2 * pairs) {
      if (t % 2 == 1) continue;  // filled with its partner
      const size_t b = perm[t + 1];
      auto& cb = clauses[b];
      ok = take_literal(rng, pool, ca);
      if (ok) cb.push_back(ca[0]);
      while (ok && ca.size() < static_cast<size_t>(len[a])) ok = take_literal(rng, pool, ca);
      while (ok && cb.size() < static_cast<size_t>(len[b])) ok = take_literal(rng, pool, cb);
    } else {
      while (ok && ca.size() < static_cast<size_t>(len[a])) ok = take_literal(rng, pool, ca);
    }
  }
  return ok;
}

}  // namespace

Formula random_lsat(const LsatParams& p) {
  check_lsat_params(p);
  Rng rng(p.seed);
  const size_t m = static_cast<size_t>(p.m);
  const int64_t lits = 2 * static_cast<int64_t>(p.n);
  int64_t total = 0;
  const std::vector<int> len = draw_lengths(rng, p, total);
  const int64_t max_pairs = static_cast<int64_t>(m / 2);
  const int64_t pairs = rng.between(std::max<int64_t>(0, total - lits), max_pairs);

  // Which clauses pair up: the first 2*pairs of a random permutation.
  std::vector<size_t> perm(m);
  for (size_t i = 0; i < m; ++i) perm[i] = i;
  rng.shuffle(perm);

  Formula f;
  f.num_vars = p.n;
  f.comments = {std::string("generator: random-lsat (") +
                    (p.min_len == 3 ? "exactly 3 literals per clause" : "clause lengths uniform in [min,max]") +
                    "; clause pairs sharing one literal, all other literals used once)",
                "parameters: n=" + std::to_string(p.n) + " m=" + std::to_string(p.m) +
                    " min=" + std::to_string(p.min_len) + " max=" + std::to_string(p.max_len) +
                    " seed=" + std::to_string(p.seed)};
  // Near the cap the pool can run out of usable literals for the last
  // clause: then start over (the generator's state moves on, so the result
  // is still a function of seed).
  for (int attempt = 0; attempt < 1000; ++attempt) {
    if (!fill_lsat_clauses(rng, p.n, perm, pairs, len, f.clauses)) continue;
    // The shared literal would always come first: shuffle within clauses.
    for (auto& c : f.clauses) rng.shuffle(c);
    return f;
  }
  throw std::runtime_error("random_lsat: no formula found after 1000 attempts");
}

Formula planted_ksat(const PlantedParams& p, std::vector<bool>* planted) {
  check_ksat(p.n, p.m, p.k);
  Rng rng(p.seed);
  std::vector<bool> hidden(static_cast<size_t>(p.n) + 1, false);
  for (int v = 1; v <= p.n; ++v) hidden[static_cast<size_t>(v)] = rng.coin();
  Formula f;
  f.num_vars = p.n;
  std::string lits;
  for (int lit : model_literals(hidden, p.n)) lits += " " + std::to_string(lit);
  f.comments = {"generator: planted-ksat (random k-SAT clauses redrawn while the planted assignment falsifies them)",
                "parameters: n=" + std::to_string(p.n) + " m=" + std::to_string(p.m) + " k=" + std::to_string(p.k) +
                    " seed=" + std::to_string(p.seed),
                "planted:" + lits};
  f.clauses.resize(static_cast<size_t>(p.m));
  for (auto& c : f.clauses) {
    do {
      draw_clause(rng, p.n, p.k, c);
    } while (std::none_of(c.begin(), c.end(), [&](int lit) { return literal_value(lit, hidden); }));
  }
  if (planted) *planted = hidden;
  return f;
}

}  // namespace gridlock
