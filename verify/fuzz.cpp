#include "verify/fuzz.hpp"

#include <algorithm>

#include "cnf/generate.hpp"

namespace gridlock {

const char* fuzz_kind_name(FuzzKind k) {
  switch (k) {
    case FuzzKind::Ksat: return "ksat";
    case FuzzKind::Lsat: return "lsat";
    case FuzzKind::Planted: return "planted";
  }
  return "?";
}

Formula fuzz_formula(const FuzzParams& p, uint64_t index) {
  const uint64_t s = fuzz_formula_seed(p.seed, index);
  Rng rng(s);
  const FuzzKind kind = p.kinds[index % p.kinds.size()];
  const int n = static_cast<int>(rng.between(p.min_vars, p.max_vars));
  // Random and planted 3-SAT draw the same parameters, in this order.
  auto three_sat = [&](auto params) {
    params.n = n;
    params.k = std::min(3, n);
    params.m = static_cast<int>(rng.between(1, 7 * static_cast<int64_t>(n)));
    params.seed = rng.next();
    return params;
  };
  Formula f;
  switch (kind) {
    case FuzzKind::Ksat: f = random_ksat(three_sat(KSatParams{})); break;
    case FuzzKind::Lsat: {
      LsatParams l;
      l.n = n;
      l.min_len = 1;
      l.max_len = std::min(3, n);
      l.m = static_cast<int>(rng.between(1, std::max(1, lsat_max_clauses(n, 1))));
      l.seed = rng.next();
      f = random_lsat(l);
      break;
    }
    case FuzzKind::Planted: f = planted_ksat(three_sat(PlantedParams{})); break;
  }
  f.comments.insert(f.comments.begin(), "gridlock fuzz formula " + std::to_string(index) + " of campaign seed " +
                                            std::to_string(p.seed) + " (" + fuzz_kind_name(kind) + ", formula seed " +
                                            std::to_string(s) + ")");
  return f;
}

Formula shrink_disagreement(const Formula& f, const VerifyOptions& opt, ShrinkStats* stats) {
  Verifier verifier;  // one simulator's work arrays for every try
  auto disagrees = [&](const Formula& g) { return !verifier.verify(g, "shrink", opt).agree; };
  Formula g = shrink_formula(f, disagrees, stats);
  g.comments.push_back("shrunk from a formula with " + std::to_string(f.num_vars) + " variables and " +
                       std::to_string(f.clauses.size()) + " clauses");
  return g;
}

}  // namespace gridlock
