// The learning engine of the continuous solver (solver/continuous.hpp): one
// component of pair constraints decided by CaDiCaL over Boolean atoms, with
// every conjunction checked exactly (docs/solver.md, "Engine sat").
//
// Atoms. For two couplings a < b of a gap (a one-form pair) of three or more
// couplings, D = t_a - t_b is compared with the thresholds the clamps need:
// [D <= -1], [D < 0], [D <= 0], [D < 1] (a chain of implications). At an
// event e = t_r + delta (delta in {0, 1}) the clamp of another coupling q of
// the gap is 0 (e <= t_q), 1 (e >= t_q + 1) or partial, and which one is a
// conjunction of these atoms. A two-coupling pair depends only on the offset
// of its two start times (free_offsets, solver/internal/continuous_pairs.hpp): one
// interval is a fixed pair of difference bounds, several get one selector
// atom each ("the offset lies in interval i") and a clause "some selector".
//
// Gap events, enumerated before the search (3^(r-1) branch choices per event
// of a gap of r couplings): given the branches the event's value is
// K + sum over partial q of c_q (e - t_q), each e - t_q in (0, 1). If it is
// > 0 on the whole open box, or <= 0 on it, the choice is decided: a clause
// (the choice is impossible) or nothing. Else, with one partial clamp it is a
// difference bound and with several a linear inequality, both guarded by the
// choice's atoms ("rules"), checked on each model.
//
// Search (difference-logic mode, the default): Z3 on the clauses, meanings
// and difference rules; linear rules checked on its model
// (see ContinuousSatOptions). Search (lazy loop, the twin): CaDiCaL finds a
// model of the clauses; the active difference bounds
// (every atom's bound in its polarity, chosen intervals, rules whose guard is
// true) are checked by Bellman-Ford (queue-based, exact integer weights that
// encode strictness): a negative cycle is learned as the clause "not all of
// its edges' reasons" and CaDiCaL runs again, incrementally. With no cycle,
// the shortest-path potentials are start times meeting every bound; if they
// also meet every active linear rule, they are the answer. Otherwise Z3
// (QF_LRA, exact rationals) decides the model's conjunction under
// assumptions; an unsat core is learned as a clause, a model is the answer.
// Every clause is true of every schedule, so UNSAT is a proof of NO; every
// answer is rechecked pair by pair (pair_free_at_times) before it is
// returned (a failure throws std::logic_error: a bug, never a wrong answer).
//
// Faces (cycles of the shape, lattice/motion.hpp FaceNets): a face stays
// closed iff, at every start time x, the nets of the couplings that start at
// x sum to zero (the net around the face is sum_q progress_q(t) * net_q;
// its derivative jumps by sum_(t_q = x) net_q at x and back at x + 1, so it
// is zero everywhere iff each of these sums is). For each coupling q of a
// face, every way the others can start (before, with or after q) whose
// "with q" nets do not sum to zero is excluded by one clause over the atoms
// [t_r - t_q < 0] and [t_r - t_q <= 0]: 3^(m-1) per coupling of a face of m
// couplings with non-zero nets, all before the search when m is at most
// kEagerFaceCouplings, else only those of the ways the models take: each
// model is checked face by face and a face that opens gives the clause of
// how its couplings start in that model (one per face and model).
//
// Not supported (continuous_sat_unsupported says why; the caller uses Z3 on
// the whole component instead): pairs of
// three or more couplings with several forms unless no two of their forms can
// be <= 0 together (then one form is a gap, picked by a selector), gaps of
// more than kMaxGapCouplings couplings.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "lattice/motion.hpp"
#include "lattice/rational.hpp"
#include "solver/internal/constraints.hpp"
#include "solver/internal/continuous_pairs.hpp"
#include "solver/internal/search.hpp"

namespace gridlock {

// free_offsets results shared between identical pairs (key: base, coef, forms).
using FreeOffsetsCache = std::map<std::vector<int64_t>, std::vector<OffsetInterval>>;

// free_offsets(c) through the cache.
const std::vector<OffsetInterval>& cached_free_offsets(const CollisionConstraint& c, FreeOffsetsCache& cache);

inline constexpr size_t kMaxGapCouplings = 8;
// Faces of at most this many couplings with non-zero nets get every clause
// before the search; larger ones get theirs when a model opens them.
inline constexpr size_t kEagerFaceCouplings = 6;

// The faces of one component (pointers into a FaceNets).
using ComponentFaces = std::vector<const FaceNets::Face*>;

// nullopt if solve_component_sat can decide the component made of `pairs`
// (indices into sys) and any faces (with relax_covers: can take it with
// ContinuousSatOptions::relax_covers); else the reason it cannot.
// O(pairs * forms^2).
std::optional<std::string> continuous_sat_unsupported(const ConstraintSystem& sys, const std::vector<uint32_t>& pairs,
                                                      bool relax_covers = false);

struct ContinuousSatOutcome {
  Verdict verdict = Verdict::Unknown;
  std::vector<Rational> start;  // Yes: per coupling of the component (its order), the earliest at 0
};

// The proof of a NO of the learning engine (difference-logic mode), from
// which solver/no_certificate.hpp writes a continuous NO certificate (kind
// bounds, docs/certificates.md) that certify/ checks. Variables are
// numbered 1..vars.size(); a clause is a list of signed variables. Every
// clause holds in every collision-free schedule:
//  Interval: the pair of regions (moved only by movers: one or two
//    couplings) collides unless the offset t_b - t_a lies in one of the
//    clause's selectors' intervals (no literal: it always collides);
//  Event: at the instant t_runner + delta (runner kNone: before every
//    start) the pair collides whenever every literal is false (each false
//    literal is a difference bound); with a guard's literal negated in it,
//    the guard's form is positive then instead;
//  Forms: one of the guards holds (a pair of several forms that no two can
//    be <= 0 together: the one <= 0 at any moment is <= 0 at every moment);
//  Theory: the literals' negations, difference bounds, are contradictory
//    (the atom chains and Z3's theory lemmas);
//  Definition: a selector implies the bounds of its interval;
//  Face: around the closed walk `walk`, the nets of the couplings that
//    start with `runner` do not sum to zero whenever every literal is false
//    (each false literal says whether some coupling starts before, with or
//    after it).
// They are unsatisfiable together (the writer asks CaDiCaL for the DRAT
// proof).
struct ContinuousProof {
  struct Var {
    bool selector = false;
    bool guard = false;  // form `form` (0..7, CollisionConstraint::form_index) of the pair is <= 0 at every moment
    uint8_t form = 0;
    uint32_t region_a = kNone, region_b = kNone;  // guard
    CouplingId x = kNone, y = kNone;              // bound: t_x - t_y; selector: a = x, b = y
    Rational v;                                   // bound: t_x - t_y <= v (< v if strict)
    bool strict = false;
    std::optional<Rational> lo, hi;  // selector: lo <= t_b - t_a <= hi
  };
  enum class Reason { Interval, Event, Theory, Definition, Forms, Face };
  struct Clause {
    Reason reason = Reason::Theory;
    uint32_t region_a = kNone, region_b = kNone;  // Interval, Event, Forms (lattice/motion.hpp Regions numbering)
    CouplingId runner = kNone;                    // Event: the instant t_runner + delta; Face: the coupling
    int delta = 0;
    std::vector<NodeId> walk;        // Face: the face's closed walk
    std::vector<CouplingId> movers;  // Interval: a (and b)
    std::vector<int> lits;
  };
  std::vector<Var> vars;  // vars[v - 1] for variable v
  std::vector<Clause> clauses;
  bool complete = false;  // true: the clauses are a proof; else why_none says why there is none
  std::string why_none;
};

// How solve_component_sat searches the encoding (the atoms, clauses and
// rules above are the same).
//  difference_logic (the default): Z3 (its SMT kernel with the
//    arith.solver=3 arithmetic solver) on the whole encoding but the linear
//    rules, which are all difference constraints; the linear rules are
//    checked on its model, and if one fails, Z3 on everything decides. Z3
//    propagates bounds inside its CDCL search: on unsatisfiable compiled
//    formulas tens to hundreds of times faster than the lazy loop
//    (docs/performance.md, "Continuous learning engine").
//  else the lazy loop: CaDiCaL over the atoms, each full model checked by
//    Bellman-Ford, negative cycles learned as clauses (the twin; the shape a
//    proof log would take).
//  z3_for_linear (tests): a model with an active linear rule always goes to
//    Z3 on everything, even when it meets every rule (so tests reach that
//    path).
//  proof (certificates): with a NO, the encoding's clauses with their
//    reasons and the theory lemmas of Z3's proof (Z3 runs with proofs on,
//    about 2.5x slower) go to *proof; forces the difference-logic mode.
//  relax_covers (certificates of NOs that Z3 found on the clamped
//    encoding): a pair of three or more couplings with several forms that
//    can be <= 0 together, which the engine cannot decide, is encoded only
//    by the events at which every form is positive (a collision): clauses
//    true in every collision-free schedule, but not all of the pair. A NO
//    is then a NO with a proof; a model proves nothing (Unknown).
struct ContinuousSatOptions {
  bool difference_logic = true;
  bool z3_for_linear = false;
  bool relax_covers = false;
  ContinuousProof* proof = nullptr;
};

// Decides the component (couplings: its couplings, pairs: its pair
// constraints, faces: its faces; requires continuous_sat_unsupported ==
// nullopt). Throws
// LimitReached when budget runs out (time, stop request, nodes: one node per
// conflict (CaDiCaL's or Z3's) and per round of the lazy loop; Z3 is
// interrupted by a watcher thread). stats: decisions += rounds (lazy) or
// Z3's decisions, refuted += conflicts, propagations += learned theory
// clauses (lazy), memo_hits += Z3 calls. Lazy loop, time per round: one
// CaDiCaL call plus O(n * edges) for Bellman-Ford in the worst case (near
// linear in practice). Exponential in the worst case either way (the
// problem is NP-hard).
ContinuousSatOutcome solve_component_sat(const ConstraintSystem& sys, const std::vector<CouplingId>& couplings,
                                         const std::vector<uint32_t>& pairs, const ComponentFaces& faces,
                                         FreeOffsetsCache& cache, SearchBudget& budget, SolveStats& stats,
                                         ContinuousSatOptions options = {});

}  // namespace gridlock
