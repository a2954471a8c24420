// The reason of an "x" line (kind pairs, docs/certificates.md): the step of
// the runner makes two regions collide whenever the clause is false.
//
// The clause's literals order other couplings against the runner: "q<R"
// false means q runs after R, "R<q" false means q runs before it. The two
// regions' eight forms (certify/internal/geometry.hpp) depend only on which
// couplings ran before R; those the clause does not fix are free. A free
// coupling whose coefficients are all >= 0 (all <= 0) can only raise
// (lower) every form, and raising every form never ends a collision, so the
// check takes it as not run (run); the others, "mixed", are enumerated
// (at most kMaxMixed of them). For each pattern left the step must collide:
// all s_i + p c_i > 0 on an open interval of p in (0, 1) (s the forms
// before R's step, c R's coefficients), the model's collision of two
// regions in the discrete model.
#pragma once

#include <optional>
#include <string>

#include "certify/internal/certificate_text.hpp"
#include "certify/internal/geometry.hpp"

namespace gridlock {

constexpr size_t kMaxMixed = 16;

// Reason the x line `lemma` is not justified, or nullopt. O(forms x
// (clause + 2^mixed x couplings of the pair)).
std::optional<std::string> check_pair_pattern(const Instance& inst, const CertifyGeometry& geo,
                                              const CertificateLemma& lemma);

// True iff all s_i + p c_i > 0 for every p in some open interval inside
// (0, 1). Exact (128-bit products).
bool certify_step_collides(const std::vector<int64_t>& s, const std::vector<int64_t>& c);

}  // namespace gridlock
