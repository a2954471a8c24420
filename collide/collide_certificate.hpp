// The certificate of a NO of Colliding Schedule (docs/certificates.md,
// "Collide certificates"; checked by certify/, 'gridlock certify').
//
// When no coupling breaks a cycle, regions A and B overlap at progress p iff
// eight strict inequalities f_i(p) > 0, affine in p, hold; in continuous
// time every p in [0,1]^k occurs. By Motzkin's transposition theorem (the
// cube alone is feasible) the pair never overlaps iff some lambda >= 0,
// lambda != 0 makes sum_i lambda_i f_i <= 0 on the whole cube. The writer
// runs the pairwise traversal (collide/internal/collide_pairs.hpp) and, for
// every pair that no single f_i rules out, derives lambda from a
// Fourier-Motzkin elimination of the pair's projected system that carries
// each constraint's multipliers along (exact 128-bit integers).
//
// When every operation moves along one axis, the first collision is always
// between two regions of one row group (docs/collide.md, "One axis, any
// couplings"), so the certificate's p line says `one-axis` and covers only
// the O(n) group pairs; the checker computes the groups itself. With one
// coupling whose faces keep their order along one axis, the p line says
// `kept-order x` (or y) and covers only the pairs of the fixed-axis sweep
// (collide/single_coupling.hpp, single_coupling_kept_order_pairs): if none
// of them overlaps, nothing does; the checker runs its own sweep. When
// the regions are cut into separated groups, each keeping one order, the
// p line says `kept-order separated` and covers every group's sweep pairs;
// the checker cuts the groups itself.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "common/limits.hpp"
#include "lattice/instance.hpp"

namespace gridlock {

struct CollideCertificate {
  std::string text;       // the certificate; empty when there is none
  std::string why_none;   // when text is empty: why
  uint64_t pairs = 0;     // region pairs covered
  uint64_t lines = 0;     // of which with an r line (the others: one form rules them out)
  bool one_axis = false;  // the one-axis kind: pairs are the row groups' pairs only
  int kept_axis = -1;     // the kept-order kind (0 x, 1 y, 2 separated groups, 3 time slabs): the sweeps' pairs only
  // Some pair can overlap in continuous time: the first one found (regions).
  uint32_t meet_a = kNone, meet_b = kNone;
};

// The certificate that no schedule of inst collides in continuous time
// (hence none in discrete time either). None (why_none) when a coupling
// breaks a cycle or some pair of regions can overlap in continuous time
// (then some discrete schedule collides too: docs/collide.md, "the models
// agree"; a discrete NO without a certificate would be a bug).
// Kind: when every operation moves along one axis (and every_pair is
// false), the one-axis kind: the row groups' pairs only, walked as
// listed_pairs_collision walks them, O(n log n + n sqrt(n)) plus O(nets)
// per pair found apart; else, with one coupling whose faces keep their
// order along one axis, the kept-order kind: the sweep's O(n) pairs,
// walked the same way; otherwise every pair: the pairwise traversal,
// O(n^2) steps and O(R^2) pair tests, plus O(nets) per pair. Deadline as
// in find_collision (LimitReached).
// partial (for tests): when a pair can overlap, text still holds the lines
// of the pairs found apart before it (a certificate the checker refuses,
// whose lines it checks one by one). on_source (optional): (source nodes
// done, total) of the traversal before each source node, and (total,
// total) when a certificate is complete (the one-axis kind calls it at
// the end only).
CollideCertificate collide_no_certificate(const Instance& inst, const Deadline* deadline = nullptr,
                                          bool partial = false,
                                          const std::function<void(uint64_t, uint64_t)>& on_source = {},
                                          bool every_pair = false);

}  // namespace gridlock
