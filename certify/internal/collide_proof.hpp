// The check of a NO certificate of gridlock collide (docs/certificates.md,
// "Collide certificates"): no schedule of the instance collides.
//   1. every coupling sums to zero around every cycle (checked here from
//      the fundamental cycles of the spanning tree), so the positions are
//      the tree displacements and each pair of regions overlaps at progress
//      p in [0,1]^k iff its eight forms (CertifyGeometry::region_forms) are
//      all > 0;
//   2. for every pair of distinct regions, either one form alone is <= 0
//      over the whole cube (the checker tries the eight itself, after a
//      sweep over bounds of each region's faces that settles far pairs
//      in O(1), CertifyGeometry::region_boxes, and bounds along the tree
//      path in O(log n), PathBounds), or an
//      'r A B L1 ... L8' line gives multipliers L >= 0, not all zero, whose
//      combination of the eight forms is <= 0 over the whole cube (its base
//      plus its positive coefficients: the maximum over the cube).
// Continuous time reaches every p in the cube and the discrete model's
// states are among them, so the certificate proves NO in both models.
//
// The one-axis kind (p line ending in `one-axis`): every operation moves
// along one axis, and step 2 is required only of the pairs of each row
// group (row_group_pairs_of). The first collision of any schedule is
// between two regions of one group (docs/collide.md, "One axis, any
// couplings", a proof), so these pairs apart means no collision at all.
//
// The kept-order kind (p line ending in `kept-order x` or `kept-order y`):
// the instance has one coupling, the faces of that axis (of every live
// region) keep their order while it runs, and step 2 is required only of
// the pairs of the checker's own sweep along that axis
// (kept_order_pairs_of). Then the fixed-axis sweep of gridlock collide,
// run with the exact test, would find none of its pairs overlapping, so
// no pair overlaps (docs/collide.md, "One coupling: one axis keeps its
// order", Lemmas 1 and 2).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "certify/certify.hpp"
#include "certify/internal/geometry.hpp"
#include "lattice/motion.hpp"

namespace gridlock {

// True iff the first p line is that of a collide certificate (so that a
// collide certificate whose p line is not first is refused by the collide
// reader, which names what it expected first).
bool is_collide_certificate(std::string_view text);

// Checks text as a collide certificate of inst; sets r.kind ("collide"),
// r.proved or r.reason ("line N: ..." where a line is to blame),
// r.inequalities (r lines checked), r.lemmas (pairs the checker ruled
// out without a line) and, for the one-axis kind, r.axioms (the row
// groups' pairs). Exact integers, overflow a reason. Time: O(R log R)
// for the face bounds of every region and a sweep over them, O(log n) for
// the path bounds of each pair the sweep meets (O(R^2) of them at worst;
// one-axis: the O(R) group pairs only), O(L) for the forms of each r line
// and of each pair those bounds leave (tree paths of length L); O(e L)
// for the cycles.
void check_collide_proof(const Instance& inst, std::string_view text, CertifyResult& r);

// The pairs the kept-order kind needs covered, for one coupling and the
// kept axis s (0: x, 1: y), each once as (smaller, larger). Live regions
// (both widths positive at some common moment of (0, 1)) only. Their s
// faces at progress 0 and 1 (sorted by the order just after 0, the values
// at 1 never decrease) must keep their order, and their widths across s
// must be positive on all of (0, 1); else the reason. Then a sweep along s
// at progress 1/2 (a leaving end before an entering one at one
// coordinate) keeps the regions on the sweep line by their low face across
// s at 1/2 and pairs each entering region with its two neighbours there.
// O(R log R + n). s = 2: the live regions cut into separated groups
// first, each swept along the axis it keeps; s = 3: the same over dyadic
// slabs of the progress, the faces rescaled to each (docs/certificates.md,
// "Time slabs"), each pair once. The caller checks that there is one
// coupling and the cycles (CertifyGeometry::cycle_breaker).
std::optional<std::string> kept_order_pairs_of(const Instance& inst, const CertifyGeometry& geo, int s,
                                               std::vector<std::pair<uint32_t, uint32_t>>& out);

// The pairs of every row group along axis (0: x, 1: y), each once: the
// regions of each row (same position across the axis) sorted by (lo, hi,
// region id) of their extent along the axis at the start; the units
// (nodes whose two faces along the axis follow one node, so their width
// never changes) cut each row into groups, a group being two consecutive
// units with every region between them (and the regions before a row's
// first unit or after its last, with it). Every row has a unit: an
// inserted, grown or contracting region lies in the row of the unit it
// is attached to. O(R log R + pairs); O(R) pairs when each node takes
// part in at most one operation.
std::vector<std::pair<uint32_t, uint32_t>> row_group_pairs_of(const Regions& regions, int axis);

}  // namespace gridlock
