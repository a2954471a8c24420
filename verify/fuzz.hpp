// The fuzzer's parts (tools/fuzz_command.cpp runs the campaign): formula
// number i of a campaign, drawn from its seed alone, and the shrinking of a
// formula on which `verify` disagrees.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cnf/formula.hpp"
#include "common/random.hpp"
#include "verify/shrink.hpp"
#include "verify/verify.hpp"

namespace gridlock {

enum class FuzzKind { Ksat, Lsat, Planted };
const char* fuzz_kind_name(FuzzKind k);  // "ksat", "lsat", "planted"

struct FuzzParams {
  uint64_t seed = 1;
  int min_vars = 3, max_vars = 6;                                                     // 1 <= min_vars <= max_vars <= 64
  std::vector<FuzzKind> kinds = {FuzzKind::Ksat, FuzzKind::Lsat, FuzzKind::Planted};  // non-empty
};

// The seed of formula `index`: derive_seed(seed, index) (common/random.hpp),
// so any formula of any campaign is replayed from two numbers, whatever the
// sharding.
inline uint64_t fuzz_formula_seed(uint64_t seed, uint64_t index) { return derive_seed(seed, index); }

// Formula `index` of the campaign: kind kinds[index % |kinds|], variables
// uniform in [min_vars, max_vars], then
//   ksat    3-SAT (k = min(3, n)) with m uniform in [1, 7n] (both sides of
//           the threshold);
//   lsat    LSAT<=3, clauses of 1 to 3 literals, m uniform in [1, max];
//   planted planted 3-SAT, m uniform in [1, 7n] (always satisfiable).
// Its comments record the campaign seed, the index and the parameters.
// Deterministic. O(n + m).
Formula fuzz_formula(const FuzzParams& p, uint64_t index);

// A formula on which verify disagrees, shrunk (verify/shrink.hpp) while
// it still disagrees; UNKNOWN answers count as agreement, so the shrunk
// formula disagrees for sure. Requires !verify_formula(f, ...).agree.
Formula shrink_disagreement(const Formula& f, const VerifyOptions& opt, ShrinkStats* stats = nullptr);

}  // namespace gridlock
