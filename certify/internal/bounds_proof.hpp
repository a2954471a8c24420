// The check of a continuous NO certificate of kind bounds (docs/
// certificates.md, "Kind bounds"): variables that stand for difference
// bounds between start times or for intervals of two couplings' offset,
// clauses that hold in every collision-free schedule, each checked here
// from the instance with exact rationals, and a clausal proof (RUP) that
// they cannot all hold.
//   i lines  the pair collides at every offset outside the intervals
//            (certify/internal/offsets.hpp: exact projection of the colliding set)
//   e lines  at the instant t_Q + delta the pair collides whenever every
//            literal is false (the literals bound each clamp; every form's
//            infimum over the box of clamps is positive)
//   t lines  the literals' negations are contradictory (a negative cycle,
//            found by Bellman-Ford over exact weights)
//   l lines  RUP lemmas (certify/internal/clause_proof.hpp), the last one empty
// Sound only when every cycle of the shape closes for each coupling alone
// (then the tree displacements are the positions at every moment): checked
// first (CertifyGeometry::cycles_close).
#pragma once

#include "certify/certify.hpp"
#include "certify/internal/certificate_text.hpp"

namespace gridlock {

// Checks c (kind bounds) against inst; sets r.proved or r.reason, and the
// counts (inequalities: i, e and t lines; lemmas: l lines; axioms: selector
// definitions). Rational overflow is a reason, never an exception.
// Time: O(lines x forms) for i and e lines (after the region forms, cached
// per pair), O(k^3) per t line of k literals, the RUP check like a SAT
// solver's propagation per l line.
void check_bounds_proof(const Instance& inst, const CertificateText& c, CertifyResult& r);

}  // namespace gridlock
