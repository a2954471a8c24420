// Twin of IncrementalSat's buffered clauses (handed to CaDiCaL at the next
// solve or set_phase, after one reserve of every variable) against adding
// each clause at once, the path before buffering: on thousands of seeded
// random incremental runs both must give the same verdicts, the same
// conflict counts and the same models, i.e. CaDiCaL must reach the same
// state. The runs mix what the engines do: variables created in batches and
// used late or never, units, duplicate and tautological clauses, phases,
// and clauses added between solve calls (blocking the model found).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "cnf/internal/incremental_sat.hpp"
#include "common/random.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

// One run's observable trace: per solve its verdict, the conflicts so far
// and the model (when satisfiable), flattened into one vector.
std::vector<int64_t> run(uint64_t seed, bool buffered) {
  Rng rng(seed);
  IncrementalSat sat;
  sat.set_buffered(buffered);
  std::vector<int64_t> trace;
  const int rounds = static_cast<int>(rng.between(1, 4));
  std::vector<int> clause;
  for (int round = 0; round < rounds; ++round) {
    const int fresh = static_cast<int>(rng.between(round == 0 ? 1 : 0, 30));
    for (int i = 0; i < fresh; ++i) sat.new_var();
    const int n = sat.num_vars();
    const auto clauses = static_cast<int>(rng.between(0, int64_t{5} * n));
    for (int c = 0; c < clauses; ++c) {
      clause.clear();
      const auto len = static_cast<int>(rng.bernoulli(1, 10) ? 1 : rng.between(2, 4));
      for (int j = 0; j < len; ++j) {
        // Favour the newest variables, as the engines' encodings do.
        const int v = rng.coin() ? static_cast<int>(rng.between(1, n))
                                 : n - static_cast<int>(rng.below(std::min(n, 5)));
        clause.push_back(rng.coin() ? v : -v);
      }
      if (rng.bernoulli(1, 8)) sat.set_phase(rng.coin() ? clause[0] : -clause[0]);
      if (rng.coin()) sat.add_clause(clause);
      else if (len == 1) sat.add_clause({clause[0]});
      else if (len == 2) sat.add_clause({clause[0], clause[1]});
      else sat.add_clause({clause[0], clause[1], clause[2]});
    }
    const Verdict v = sat.solve([](uint64_t) { return false; });
    trace.push_back(static_cast<int64_t>(v));
    trace.push_back(static_cast<int64_t>(sat.conflicts()));
    if (v != Verdict::Yes) break;
    clause.clear();
    for (int x = 1; x <= n; ++x) {
      const bool val = sat.value(x);
      trace.push_back(val ? x : -x);
      if (rng.bernoulli(1, 3)) clause.push_back(val ? -x : x);
    }
    if (!clause.empty()) sat.add_clause(clause);  // block (part of) the model
  }
  return trace;
}

TEST(IncrementalTwin, BufferedClausesReachTheSameSolverState) {
  const uint64_t base = test::base_seed(2408);
  const int cases = test::scaled(4000);
  for (int t = 0; t < cases; ++t) {
    const uint64_t seed = derive_seed(base, static_cast<uint64_t>(t));
    SCOPED_TRACE("seed " + std::to_string(seed) + " (GRIDLOCK_TEST_SEED=" + std::to_string(base) + ", case " +
                 std::to_string(t) + ")");
    ASSERT_EQ(run(seed, true), run(seed, false));
  }
}

}  // namespace
}  // namespace gridlock
