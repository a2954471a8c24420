// The exact solver of Continuous Collision-free Schedule (docs/model.md,
// "Couplings and schedules"): is there a start time t_q per coupling q (q runs
// over [t_q, t_q + 1], couplings may overlap) that performs every operation
// with no collision?
//
// Any instance: all four directions, expansions, contractions, growths,
// cycles, couplings of any size. docs/solver.md ("Continuous model") explains
// the method, why it is exact, its limits and measured figures.
//
// Pipeline:
//  1. horizontal-only instances: the linear gap checker (solver/gaps.hpp);
//     YES with every coupling at time 0, or NO;
//  2. otherwise the collision constraints of build_pair_constraints
//     (solver/internal/constraints.hpp): every pair of regions that can come close,
//     with up to eight linear forms f_i = s_i + sum_q c_iq p_q, and a
//     collision of the pair at t iff every f_i(t) > 0. With progress
//     p_q(t) = clamp(t - t_q, 0, 1) the same forms describe the continuous
//     model. Plus the cycle constraints of FaceNets: around every face,
//     sum_q p_q(t) net_q == 0 for all t, i.e. the couplings with a non-zero
//     net, grouped by equal start time, sum to zero in every group;
//  3. couplings that share no constraint are independent: union-find splits
//     them into components, each decided on its own;
//  4. per component, cheap sufficient tests first, each checked exactly:
//     starting all of it at once (one progress p for all); then the
//     "layered" schedule that its two-coupling pairs ask for (t_b >= t_a + lo
//     where offset 0 collides), as early as possible (longest paths), checked
//     pair by pair (pair_free_at_times) and face by face;
//  4b. then the discrete solver's order (solve_discrete, at most 20 000
//     search nodes and a third of the time left, once per instance) as
//     start times 0, 1, 2, ..., checked exactly per pair;
//  4c. then the learning engine (solver/internal/continuous_sat.hpp: CaDiCaL over
//     difference atoms, Bellman-Ford and Z3 on conjunctions) for every
//     component it supports (no faces with non-zero nets; see its header);
//  5. otherwise (or with ContinuousEngine::Z3) Z3 (QF_LRA, exact rationals) decides the component: start
//     times t_q in [0, k] (k couplings; idle time can always be cut out).
//     A pair of two couplings depends only on the offset of their start
//     times; its collision-free offsets are computed exactly beforehand
//     (solver/internal/continuous_pairs.hpp) and asserted as difference bounds. A
//     pair of three or more couplings gets a cover of the time axis by at most 4r - 2 segments
//     (r couplings in the pair) with switch times as auxiliary variables,
//     each segment assigned one form that is <= 0 on it (checked at its ends
//     and at every event t_q, t_q + 1 inside it: the forms are piecewise
//     linear with breakpoints at the events). One-form pairs (gaps) need no
//     segments: f <= 0 at every event. Per pair and per linear piece between
//     events, two forms always suffice (the set where a form is <= 0 is a
//     prefix or a suffix of the piece), so the cover exists iff the pair never
//     overlaps: the encoding is exact, not a relaxation;
//  6. a YES schedule is shifted so that its minimum is 0 and replayed by the
//     exact Simulator before it is returned; if the simulator disagrees,
//     solve_continuous throws std::logic_error (a bug, never a silent wrong
//     answer).
//
// Limits: SolveOptions::seconds covers everything, the pair building
// included (checked every few pairs; stop requests too), and is passed to Z3
// as the remaining time per component; SolveOptions::max_states bounds the
// learning engine's rounds plus CaDiCaL conflicts, and the sum of Z3
// conflicts on the Z3 path (a component that needs more stops with
// Unknown). SolveOptions::progress draws the progress line. A Z3 model whose start
// times do not fit kMaxStartTime / kMaxDenominator (lattice/schedule.hpp)
// gives Unknown (never observed; the model's values are vertices of small
// integer systems). SolveOptions::engine is ignored (see ContinuousEngine).
//
// Sizes measured (docs/performance.md, CPU time on the loaded CI machine):
// separation chains t_b >= t_a + 1 (the continuous reduction's contract) of
// 1 025 / 4 097 couplings in 4.5 ms / 24 ms (layered candidate, no Z3); with
// a third operation per coupling in a row of expansions, 2.7 s at 1 025
// couplings, mostly build_pair_constraints. A compiled uf20 instance
// (2 466 couplings, 3 031 pair constraints, one vertical operation) in 0.5 s
// (all at once). Z3 itself, when a component needs it, is fast up to a few
// hundred couplings of difference bounds (1 025-chain: 96 ms) but did not
// finish a 2 466-coupling compiled component in 250 s: instances that need a
// real search at that size may end in Unknown.
//
// Requirements: inst is a valid Instance (InstanceBuilder guarantees it).
#pragma once

#include <optional>
#include <string>

#include "lattice/instance.hpp"
#include "lattice/schedule.hpp"
#include "solver/solve.hpp"

namespace gridlock {

struct ContinuousProof;  // solver/internal/continuous_sat.hpp

struct ContinuousResult {
  Verdict status = Verdict::Unknown;
  Schedule schedule;  // Yes: a start time per coupling (exact rationals), accepted by the Simulator
  SolveStats stats;   // engine name, counts, seconds
  // No because this coupling alone moves two regions that collide during
  // its run, whatever the start times (found while building the pair
  // constraints; no search runs, stats.engine "trivial"): its coupling and
  // "node (1,2) and node inserted by a".
  CouplingId lone_collider = kNone;
  std::string lone_pair;
};

// Decides Continuous Collision-free Schedule exactly (any instance), or
// Unknown on a limit of opt. stats.engine: "gaps" (horizontal-only),
// "trivial" (every component settled by a cheap test), "dl" or "sat" (the
// learning engine, difference-logic mode or lazy loop, decided some
// component), "z3". stats.constraints: pair and cycle
// constraints built; stats.decisions / refuted: Z3 decisions and conflicts
// (learning engine: rounds and CaDiCaL conflicts) summed over the
// components; stats.states: components searched plus search nodes;
// stats.propagations: learned theory clauses; stats.safe_moves: components
// settled by a cheap test (steps 4, 4b).
// Which search decides a component that the cheap tests do not settle.
// Auto and Dl: the learning engine (solver/internal/continuous_sat.hpp) in its
// difference-logic mode (Z3 QF_RDL over the atoms) when it supports the
// component, else Z3 on the clamped encoding; Sat: the learning engine's
// lazy loop (CaDiCaL + Bellman-Ford) instead; Z3: the Z3 encoding of step 5
// always. DlNoShortcuts and SatNoShortcuts (tests): as Dl and Sat, without
// the cheap tests (all at once, layered, the discrete order), so the
// learning engine meets every component it supports, and every model with
// an active linear rule goes to Z3 on everything (not only those whose
// times break one).
enum class ContinuousEngine { Auto, Dl, Sat, Z3, DlNoShortcuts, SatNoShortcuts };

// The engine a user names (`gridlock solve --engine`, Python `engine=`):
// "auto", "dl", "sat" or "z3" (kContinuousEngineNames, for messages);
// nullopt for any other name (the test-only engines have no name).
std::optional<ContinuousEngine> continuous_engine_named(const std::string& name);
inline constexpr const char* kContinuousEngineNames = "auto, dl, sat or z3";

ContinuousResult solve_continuous(const Instance& inst, const SolveOptions& opt = {},
                                  ContinuousEngine engine = ContinuousEngine::Auto);

// How the general path encodes a pair constraint for Z3. Auto: a pair of
// one coupling is decided at once; a pair of two couplings becomes "the
// offset of their start times lies in one of these closed intervals"
// (free_offsets, solver/internal/continuous_pairs.hpp: difference bounds, which Z3
// handles in near-linear time); larger pairs get the segment cover.
// Segments: no shortcut after the all-at-once test: no layered candidate,
// and the segment cover for every pair (tests compare the two).
enum class PairEncoding { Auto, Segments };

// Steps 2-6 alone, on any instance (horizontal-only ones too, where tests
// and benchmarks compare it with check_gaps). Same contract.
// Segments implies the Z3 engine. proof: see solve_continuous_proved.
ContinuousResult solve_continuous_general(const Instance& inst, const SolveOptions& opt = {},
                                          PairEncoding encoding = PairEncoding::Auto,
                                          ContinuousEngine engine = ContinuousEngine::Auto,
                                          ContinuousProof* proof = nullptr);

// solve_continuous_general with the learning engine in proof mode
// (ContinuousSatOptions::proof; engine Sat becomes Dl): with a NO that the
// learning engine found, `proof` is the proof for the component that has
// no schedule (proof.complete); otherwise proof.why_none says why there is
// none (a component decided by Z3 on the clamped encoding, a limit, ...).
// For certificates of instances that are not horizontal-only
// (solver/no_certificate.hpp).
ContinuousResult solve_continuous_proved(const Instance& inst, const SolveOptions& opt, ContinuousEngine engine,
                                         ContinuousProof& proof);

}  // namespace gridlock
