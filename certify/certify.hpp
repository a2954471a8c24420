// The independent checker of NO certificates (docs/certificates.md).
//
// A certificate claims that an instance has no collision-free schedule.
// certify() re-derives everything it needs from the instance with its own
// code (the model's definitions in lattice/ are shared; nothing of solver/
// is used): the displacement of every node, the gap inequalities of a
// horizontal-only instance, the forms of any pair of regions, and unit
// propagation over order literals. A
// third party should be able to read certify/ in an afternoon:
//   certificate_text.*  reading the text (names, cells, literals)
//   geometry.*          displacements, cycle sums, gaps, gap inequalities
//   order_proof.*       the forward RUP check of a lemma log
//   pair_pattern.*      why an x line's clause holds (a colliding pair of regions)
//   collide_proof.*     gridlock collide's NO: every pair of regions kept apart
//   certify.cpp         which kind proves what
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "lattice/instance.hpp"

namespace gridlock {

struct CertifyResult {
  bool proved = false;        // true: the certificate proves that inst has no schedule
  std::string reason;         // not proved: what failed, "line N: ..." where a line is to blame
  std::string kind;           // breaker, gaps, pairs, final-gap, final-cycle, bounds or collide (once read)
  uint64_t inequalities = 0;  // gaps: gap inequalities derived from the instance; pairs: x lines checked;
                              // collide: r lines checked
  uint64_t lemmas = 0;        // gaps: lemma lines checked; pairs: o and l lines; collide: pairs one form rules out
  uint64_t axioms = 0;        // gaps: order-closure clauses derived; collide, one-axis: row group pairs;
                              // collide, kept-order: the sweep's pairs
  bool one_axis = false;      // collide: the one-axis kind (only the row groups' pairs covered)
  int kept_axis =
      -1;  // collide: the kept-order kind's axis (0 x, 1 y, 2 separated groups, 3 time slabs; the sweeps' pairs)
};

// Checks `text` as a NO certificate of inst in the model `model`
// ("discrete" or "continuous"; the certificate's own p line must agree).
// A certificate of gridlock collide (p gridlock-collide-no-certificate,
// kind "collide") proves instead that no schedule collides, in either
// model (certify/internal/collide_proof.hpp).
// Never throws on bad text: every problem is a reason. Time: reading and
// geometry O(text + n + sum of tree-path lengths of the gaps); the proof
// check O(lemmas x propagation), like the solver that wrote it; memory
// k^2 / 8 bytes for the order closure (k couplings).
CertifyResult certify(const Instance& inst, std::string_view text, const std::string& model);

}  // namespace gridlock
