// Collision constraints: the discrete model as arithmetic on couplings.
//
// In the discrete model only the set S of couplings done decides where
// everything is (docs/model.md). Every face of every region is its base coordinate
// plus a sum over couplings q of [q in S] * (integer), so for two regions A, B
// each quantity below is such a linear form in the indicator vector of S:
//   A.xhi - B.xlo,  B.xhi - A.xlo,  A.yhi - B.ylo,  B.yhi - A.ylo   (overlap)
//   A.xhi - A.xlo,  B.xhi - B.xlo,  A.yhi - A.ylo,  B.yhi - B.ylo   (widths)
// A and B overlap with positive area iff all eight are > 0. While coupling Q
// runs from S with progress p in [0, 1], each form is s_i + p * c_i (s_i its
// value at S, c_i the coefficient of Q), so Q's step makes A and B collide
// iff all s_i + p c_i > 0 on some open sub-interval of (0, 1): exactly the
// simulator's test, restricted to one pair (see step_collides).
//
// A CollisionConstraint is one such pair with its forms: forms that are
// always positive are dropped; pairs that can never collide are not built.
// Two builders:
//  - gap constraints (horizontal-only instances): nodes stay in their rows,
//    and a collision is a gap between consecutive nodes of a row going
//    negative (docs/model.md, "Consequences"). One form per gap: the overlap
//    right(a) - left(b), growths counted as part of their node. O(n) pairs.
//  - pair constraints (any instance): every pair of regions that could ever
//    overlap (a necessary distance test against the operations on the tree
//    path between them), with up to eight forms.
// Both are exact when no coupling breaks a cycle (checked first by the
// solver; such a coupling makes every schedule collide).
#pragma once

#include "common/limits.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "lattice/instance.hpp"
#include "lattice/motion.hpp"
#include "lattice/prepared.hpp"

namespace gridlock {

// Distinct coefficient rows, each stored once and never moved: a pointer
// returned by intern stays valid while the table lives. Pair systems repeat
// a few rows very many times (a planted 300-coupling sparse shape: 244 216
// constraints, 8.7 million rows of 1-8 coefficients, 137 distinct), so a
// constraint keeps one pointer per row instead of the row. Interning is not
// thread-safe; reading is.
class CoefRows {
 public:
  // The stored copy of row[0..n) (n >= 1), added if new. O(n) expected;
  // O(1) for one small value (every gap row of a compiled formula).
  const int64_t* intern(const int64_t* row, uint32_t n) {
    if (n != 1 || row[0] < -kSmall || row[0] > kSmall) return intern_hashed(row, n);
    const int64_t*& p = small_[static_cast<size_t>(row[0] + kSmall)];
    if (p == nullptr) p = intern_hashed(row, n);
    return p;
  }
  size_t size() const { return rows_.size(); }

 private:
  static constexpr int64_t kSmall = 16;
  const int64_t* intern_hashed(const int64_t* row, uint32_t n);
  void grow();
  std::array<const int64_t*, 2 * kSmall + 1> small_{};  // one-value rows -kSmall..kSmall, once interned
  std::vector<std::unique_ptr<int64_t[]>> rows_;        // each: n, then the n values
  std::vector<uint32_t> slots_;                         // open addressing: index in rows_ + 1, 0 empty
};

struct CollisionConstraint {
  uint32_t region_a = kNone, region_b = kNone;  // Regions numbering (for messages)
  uint32_t num_forms = 0;                       // 1..8
  std::vector<int64_t> base;                    // per form: value with no coupling done
  std::vector<CouplingId> rel;                  // couplings with a non-zero coefficient, increasing
  std::vector<const int64_t*> coef_rows;        // per rel entry j: its num_forms coefficients (in *rows)
  std::shared_ptr<CoefRows> rows;               // owns what coef_rows points to (shared by a system)
  std::vector<uint8_t> form_index;              // per form: its place among the eight above (0..7; gaps: 0)
  // Coupling rel[j]'s coefficient on each form. O(1).
  const int64_t* coef_of(size_t j) const { return coef_rows[j]; }
  // Sets the rows from the row-major matrix coef[j * num_forms + i]
  // (rel.size() * num_forms entries; num_forms and rel set first), interned
  // into table (a new one when null). O(size) expected.
  void set_coef(const std::vector<int64_t>& coef, std::shared_ptr<CoefRows> table = nullptr);
  // That matrix back (tests), or appended to out (cache keys).
  // O(rel.size() * num_forms).
  std::vector<int64_t> coef() const;
  void append_coef(std::vector<int64_t>& out) const;
};

enum class ConstraintKind { Gaps, Pairs };

// Per coupling q: the entries (constraint index, index j of q in that
// constraint's rel), in constraint order, as one flat array (no vector per
// coupling, no growth slack: a pair system has millions of entries).
class CouplingIndex {
 public:
  using Entry = std::pair<uint32_t, uint32_t>;
  // Coupling q's entries. O(1); q < size().
  std::span<const Entry> operator[](size_t q) const {
    return {entries_.data() + start_[q], entries_.data() + start_[q + 1]};
  }
  size_t size() const { return start_.empty() ? 0 : start_.size() - 1; }
  // Rebuilds from every rel of cs (couplings < num_couplings). O(num_couplings + entries).
  void build(size_t num_couplings, const std::vector<CollisionConstraint>& cs);

 private:
  std::vector<size_t> start_;  // num_couplings + 1 offsets into entries_
  std::vector<Entry> entries_;
};

struct ConstraintSystem {
  ConstraintKind kind = ConstraintKind::Pairs;
  size_t num_couplings = 0;
  std::vector<CollisionConstraint> constraints;
  // Per coupling: (constraint index, index j of the coupling in its rel).
  CouplingIndex of_coupling;
  uint64_t candidate_pairs = 0;  // pairs examined by the builder (statistics)
  // The last constraint when the builder stopped at one that alone makes
  // every schedule collide (see build_pair_constraints); kNone otherwise.
  uint32_t refuting = kNone;

  size_t total_forms() const;
  // Fills of_coupling from constraints. O(total size).
  void index();
};

// The exact step test. s: the forms' values at the state, c: the running
// coupling's coefficients, nf forms. True iff all s_i + p c_i > 0 for every p
// in some open interval inside (0, 1). O(nf), 128-bit products.
bool step_collides(const int64_t* s, const int64_t* c, uint32_t nf);

// Gap constraints of a horizontal-only instance. Requires
// inst.horizontal_only() and no coupling breaking a cycle (else the result
// does not describe the instance). O(n + sum over gaps of the operations on
// the tree path between the gap's two nodes); O(n) time for the rows.
// deadline (optional) is checked every few pairs: LimitReached ends the build.
ConstraintSystem build_gap_constraints(const Instance& inst, const SpanningTree& tree,
                                       const Deadline* deadline = nullptr);
// The same from prepared tables (no tree, regions or row order rebuilt).
ConstraintSystem build_gap_constraints(const PreparedInstance& prep, const Deadline* deadline = nullptr);

// Pair constraints of any instance. Requires no coupling breaking a cycle.
// A pair (A, B) is kept iff it passes the distance test (each region stays in
// its base cell shifted by one node's displacement, and that displacement
// differs between the two by at most H horizontal and V vertical unit steps,
// H and V the operations of each axis on the tree path) and some form
// changes. Time O(sum over regions of min(#regions, scanned cells)) plus the
// path walks of the candidates: quadratic in the worst case (long rows of
// operations), near linear when operations are sparse.
// deadline (optional) is checked every few pairs: LimitReached ends the build.
//
// stop_at_refuting: stop at the first constraint that alone refutes every
// schedule, in both models: a pair that only one coupling q moves (rel =
// {q}) and whose forms collide during q's step from their base values
// (step_collides(base, coef)); whenever q runs the pair sees nothing else,
// so it collides. The system then holds the constraints built so far and
// refuting is the last one's index: a subset of the full system whose
// every schedule collides, so engines answer NO on it (and NO certificates
// name only its constraints). Random instances with no order are mostly of
// this kind; the full build can take minutes and gigabytes.
ConstraintSystem build_pair_constraints(const Instance& inst, const SpanningTree& tree,
                                        const Deadline* deadline = nullptr, bool stop_at_refuting = false);
// The same from prepared tables (no tree or regions rebuilt).
ConstraintSystem build_pair_constraints(const PreparedInstance& prep, const Deadline* deadline = nullptr,
                                        bool stop_at_refuting = false);

// "gap between (1,0) and (3,0)" / "node (1,1) and node inserted by a".
std::string constraint_label(const Instance& inst, const Regions& regions, const CollisionConstraint& c);

// Replays an order on the constraint system. Returns the index in `order` of
// the first step that collides (and the constraint), or order.size() if none.
// O(sum over the steps of their constraints' sizes).
struct ReplayResult {
  size_t failed_step = 0;
  uint32_t constraint = kNone;
};
ReplayResult replay_order(const ConstraintSystem& sys, const std::vector<CouplingId>& order);

}  // namespace gridlock
