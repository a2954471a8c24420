#include "solver/continuous.hpp"

#include <algorithm>
#include <map>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>

#include <z3++.h>

#include "common/clock.hpp"
#include "lattice/motion.hpp"
#include "lattice/simulate.hpp"
#include "solver/gaps.hpp"
#include "solver/internal/constraints.hpp"
#include "solver/internal/continuous_pairs.hpp"
#include "solver/internal/continuous_sat.hpp"
#include "solver/internal/search.hpp"

namespace gridlock {

namespace {

struct UnionFind {
  std::vector<uint32_t> parent;
  explicit UnionFind(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  uint32_t find(uint32_t a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  }
  void unite(uint32_t a, uint32_t b) { parent[find(a)] = find(b); }
};

// The exact all-at-once test of one pair: every coupling of the pair starts
// at the same moment, so all forms share one progress p.
bool pair_free_all_at_once(const CollisionConstraint& c) {
  std::vector<int64_t> sum(c.num_forms, 0);
  for (size_t j = 0; j < c.rel.size(); ++j)
    for (uint32_t i = 0; i < c.num_forms; ++i) sum[i] += c.coef_of(j)[i];
  return !step_collides(c.base.data(), sum.data(), c.num_forms);
}

// One component: its couplings, pair constraints and faces.
struct Component {
  std::vector<CouplingId> couplings;
  std::vector<uint32_t> pairs;  // indices into the ConstraintSystem
  std::vector<uint32_t> faces;  // indices into FaceNets::faces
};

// The Z3 encoding of one component (see the header, step 5).
class ComponentEncoder {
 public:
  ComponentEncoder(z3::context& ctx, z3::solver& s, const Component& comp, const ConstraintSystem& sys,
                   const FaceNets& faces, std::vector<int>& var_of, PairEncoding encoding,
                   FreeOffsetsCache& offsets_cache)
      : ctx_(ctx),
        s_(s),
        comp_(comp),
        sys_(sys),
        faces_(faces),
        var_of_(var_of),
        encoding_(encoding),
        cache_(offsets_cache) {}

  void encode() {
    const int64_t k = static_cast<int64_t>(comp_.couplings.size());
    for (CouplingId q : comp_.couplings) {
      var_of_[q] = static_cast<int>(t_.size());
      t_.push_back(ctx_.real_const(("t" + std::to_string(q)).c_str()));
      s_.add(t_.back() >= 0 && t_.back() <= real(k));
    }
    for (uint32_t ci : comp_.pairs) encode_pair(sys_.constraints[ci]);
    for (uint32_t fi : comp_.faces) encode_face(faces_.faces[fi]);
  }

  const z3::expr& time_of(CouplingId q) const { return t_[static_cast<size_t>(var_of_[q])]; }

 private:
  z3::expr num(int64_t v) { return ctx_.real_val(v); }
  z3::expr real(int64_t v) { return ctx_.real_val(v); }

  // p_q(x) = clamp(x - t_q, 0, 1).
  z3::expr progress(const z3::expr& x, CouplingId q) {
    const z3::expr& tq = time_of(q);
    return z3::ite(x <= tq, real(0), z3::ite(x >= tq + 1, real(1), x - tq));
  }
  // Form i of c at time x. ev_q / ev_end mark x as t_q or t_q + 1 of a known
  // coupling, whose own progress is then 0 or 1 without a case split.
  z3::expr form_at(const CollisionConstraint& c, uint32_t i, const z3::expr& x, CouplingId at_q, bool at_end) {
    z3::expr sum = real(c.base[i]);
    for (size_t j = 0; j < c.rel.size(); ++j) {
      int64_t a = c.coef_of(j)[i];
      if (a == 0) continue;
      CouplingId q = c.rel[j];
      if (q == at_q) {
        if (at_end) sum = sum + real(a);
      } else {
        sum = sum + real(a) * progress(x, q);
      }
    }
    return sum;
  }

  z3::expr rational(const Rational& v) { return ctx_.real_val(v.str().c_str()); }

  void encode_pair(const CollisionConstraint& c) {
    const size_t r = c.rel.size();
    if (encoding_ == PairEncoding::Auto && r == 1) {
      if (!pair_free_at_offset(c, Rational(0))) s_.add(ctx_.bool_val(false));
      return;
    }
    if (encoding_ == PairEncoding::Auto && r == 2) {
      encode_by_free_offsets(c);
      return;
    }
    // Events: t_q and t_q + 1 of the pair's couplings.
    std::vector<z3::expr> ev;
    std::vector<CouplingId> ev_q;
    std::vector<char> ev_end;
    for (CouplingId q : c.rel) {
      ev.push_back(time_of(q)), ev_q.push_back(q), ev_end.push_back(0);
      ev.push_back(time_of(q) + 1), ev_q.push_back(q), ev_end.push_back(1);
    }
    // f_i at every event, shared by the segments.
    std::vector<std::vector<z3::expr>> at_ev(c.num_forms);
    for (uint32_t i = 0; i < c.num_forms; ++i)
      for (size_t e = 0; e < ev.size(); ++e) at_ev[i].push_back(form_at(c, i, ev[e], ev_q[e], ev_end[e] != 0));
    if (c.num_forms == 1) {
      // f is piecewise linear with breakpoints at the events (and constant
      // before the first and after the last): <= 0 everywhere iff at every event.
      for (auto& v : at_ev[0]) s_.add(v <= 0);
      return;
    }
    if (encoding_ == PairEncoding::Auto && forms_never_both_nonpositive(c)) {
      // No two forms are ever <= 0 at the same moment, so a cover can never
      // hand over from one form to another (both would be <= 0 at the switch):
      // one form must be <= 0 for all time. E.g. the two x-overlaps of two
      // unit nodes in a row sum to 2.
      z3::expr_vector options(ctx_);
      for (uint32_t i = 0; i < c.num_forms; ++i) {
        z3::expr_vector all(ctx_);
        for (auto& v : at_ev[i]) all.push_back(v <= 0);
        options.push_back(z3::mk_and(all));
      }
      s_.add(z3::mk_or(options));
      return;
    }
    encode_segment_cover(c, ev, at_ev);
  }

  // A two-coupling pair: the offset t_b - t_a lies in one of the pair's free
  // offset intervals (none: false).
  void encode_by_free_offsets(const CollisionConstraint& c) {
    // Identical pairs (same forms) are common in gadget rows: cache.
    std::vector<int64_t> key(c.base);
    c.append_coef(key);
    key.push_back(c.num_forms);
    auto it = cache_.find(key);
    if (it == cache_.end()) it = cache_.emplace(std::move(key), free_offsets(c)).first;
    z3::expr d = time_of(c.rel[1]) - time_of(c.rel[0]);
    z3::expr_vector options(ctx_);
    for (const OffsetInterval& iv : it->second) {
      z3::expr in = ctx_.bool_val(true);
      if (iv.lo) in = in && d >= rational(*iv.lo);
      if (iv.hi) in = in && d <= rational(*iv.hi);
      options.push_back(in);
    }
    s_.add(z3::mk_or(options));  // false if empty
  }

  // The general pair: a cover of the time axis by M = 4r - 2 segments
  // [x_{m-1}, x_m], on each of which one form is <= 0 at both ends and at
  // every event inside. ev are the events (t_q and t_q + 1 of the pair's
  // couplings), at_ev[i][e] form i at event e.
  void encode_segment_cover(const CollisionConstraint& c, const std::vector<z3::expr>& ev,
                            const std::vector<std::vector<z3::expr>>& at_ev) {
    const size_t r = c.rel.size();
    const size_t M = 4 * r - 2;
    std::vector<z3::expr> x;
    for (size_t m = 0; m <= M; ++m) {
      x.push_back(ctx_.real_const(("x" + std::to_string(counter_) + "_" + std::to_string(m)).c_str()));
      if (m > 0) s_.add(x[m - 1] <= x[m]);
    }
    ++counter_;
    for (CouplingId q : c.rel) s_.add(x[0] <= time_of(q) && x[M] >= time_of(q) + 1);
    std::vector<std::vector<z3::expr>> at_x(c.num_forms);
    for (uint32_t i = 0; i < c.num_forms; ++i)
      for (size_t m = 0; m <= M; ++m) at_x[i].push_back(form_at(c, i, x[m], kNone, false));
    for (size_t m = 1; m <= M; ++m) {
      z3::expr_vector options(ctx_);
      for (uint32_t i = 0; i < c.num_forms; ++i) {
        z3::expr_vector conj(ctx_);
        conj.push_back(at_x[i][m - 1] <= 0);
        conj.push_back(at_x[i][m] <= 0);
        for (size_t e = 0; e < ev.size(); ++e)
          conj.push_back(z3::implies(x[m - 1] < ev[e] && ev[e] < x[m], at_ev[i][e] <= 0));
        options.push_back(z3::mk_and(conj));
      }
      s_.add(z3::mk_or(options));
    }
  }

  // Around the face, the couplings that start together must have nets that
  // sum to zero: for each coupling q with a net, the nets of those with
  // t_r == t_q sum to zero, per axis.
  void encode_face(const FaceNets::Face& f) {
    for (auto& [q, v] : f.nets) {
      z3::expr sx = num(0), sy = num(0);
      for (auto& [r, w] : f.nets) {
        if (r == q) {
          sx = sx + num(w.x), sy = sy + num(w.y);
        } else {
          z3::expr same = time_of(r) == time_of(q);
          if (w.x != 0) sx = sx + z3::ite(same, num(w.x), num(0));
          if (w.y != 0) sy = sy + z3::ite(same, num(w.y), num(0));
        }
      }
      s_.add(sx == 0 && sy == 0);
    }
  }

  z3::context& ctx_;
  z3::solver& s_;
  const Component& comp_;
  const ConstraintSystem& sys_;
  const FaceNets& faces_;
  std::vector<int>& var_of_;
  PairEncoding encoding_;
  FreeOffsetsCache& cache_;
  std::vector<z3::expr> t_;
  uint64_t counter_ = 0;
};

// The second cheap sufficient test: the schedule that the two-coupling pairs
// alone ask for, as early as possible. Each such pair that collides at offset
// 0 but is free at every offset >= lo > 0 (or <= hi < 0) gives
// t_b >= t_a + lo (or t_a >= t_b - hi); longest paths from 0 give the times.
// Accepted only if every pair and face of the component is collision-free at
// them (pair_free_at_times, exact); nullopt otherwise.
std::optional<std::vector<Rational>> layered_candidate(const Component& comp, const ConstraintSystem& sys,
                                                       const FaceNets& faces, std::vector<uint32_t>& local,
                                                       FreeOffsetsCache& cache) {
  for (uint32_t j = 0; j < comp.couplings.size(); ++j) local[comp.couplings[j]] = j;
  struct Arc {
    uint32_t from, to;
    Rational w;
  };
  std::vector<Arc> arcs;
  for (uint32_t ci : comp.pairs) {
    const CollisionConstraint& c = sys.constraints[ci];
    if (c.rel.size() != 2) continue;
    std::vector<int64_t> key(c.base);
    c.append_coef(key);
    key.push_back(c.num_forms);
    auto it = cache.find(key);
    if (it == cache.end()) it = cache.emplace(std::move(key), free_offsets(c)).first;
    const auto& iv = it->second;
    if (iv.empty()) return std::nullopt;
    bool zero_free = std::any_of(iv.begin(), iv.end(), [](const OffsetInterval& x) { return x.contains(Rational(0)); });
    if (zero_free) continue;
    uint32_t a = local[c.rel[0]], b = local[c.rel[1]];
    if (!iv.back().hi && *iv.back().lo > Rational(0)) {
      arcs.push_back({a, b, *iv.back().lo});
    } else if (!iv.front().lo && *iv.front().hi < Rational(0)) {
      arcs.push_back({b, a, Rational(0) - *iv.front().hi});
    }
  }
  if (arcs.empty()) return std::nullopt;  // the candidate would be "all at once"
  const size_t n = comp.couplings.size();
  std::vector<Rational> t(n, Rational(0));
  bool changed = true;
  for (size_t round = 0; changed; ++round) {
    if (round > n) return std::nullopt;  // a positive cycle: no such schedule
    changed = false;
    for (const Arc& e : arcs)
      if (t[e.from] + e.w > t[e.to]) t[e.to] = t[e.from] + e.w, changed = true;
  }
  for (uint32_t ci : comp.pairs) {
    const CollisionConstraint& c = sys.constraints[ci];
    std::vector<Rational> st;
    for (CouplingId q : c.rel) st.push_back(t[local[q]]);
    if (!pair_free_at_times(c, st)) return std::nullopt;
  }
  for (uint32_t fi : comp.faces) {
    const auto& nets = faces.faces[fi].nets;
    for (auto& [q, v] : nets) {
      Vec2 sum{0, 0};
      for (auto& [r, w] : nets)
        if (t[local[r]] == t[local[q]]) sum += w;
      if (!sum.is_zero()) return std::nullopt;
    }
  }
  return t;
}

uint64_t z3_stat(const z3::stats& st, const char* key) {
  for (unsigned i = 0; i < st.size(); ++i)
    if (st.key(i) == key && st.is_uint(i)) return st.uint_value(i);
  return 0;
}

// The components of the couplings joined by a pair constraint or a face
// (union-find), in order of their smallest coupling, each with its pairs
// and faces.
std::vector<Component> components_of(size_t k, const ConstraintSystem& sys, const FaceNets& faces) {
  UnionFind uf(k);
  for (const auto& c : sys.constraints)
    for (size_t j = 1; j < c.rel.size(); ++j) uf.unite(c.rel[0], c.rel[j]);
  for (const auto& f : faces.faces)
    for (size_t j = 1; j < f.nets.size(); ++j) uf.unite(f.nets[0].first, f.nets[j].first);
  std::vector<int> comp_of(k, -1);
  std::vector<Component> comps;
  for (CouplingId q = 0; q < k; ++q) {
    uint32_t root = uf.find(q);
    if (comp_of[root] < 0) comp_of[root] = static_cast<int>(comps.size()), comps.emplace_back();
    comp_of[q] = comp_of[root];
    comps[static_cast<size_t>(comp_of[q])].couplings.push_back(q);
  }
  for (uint32_t ci = 0; ci < sys.constraints.size(); ++ci)
    comps[static_cast<size_t>(comp_of[sys.constraints[ci].rel[0]])].pairs.push_back(ci);
  for (uint32_t fi = 0; fi < faces.faces.size(); ++fi)
    comps[static_cast<size_t>(comp_of[faces.faces[fi].nets[0].first])].faces.push_back(fi);
  return comps;
}

// The first cheap sufficient test: the whole component at once (every pair
// free with all its couplings starting together, every face's nets summing
// to zero).
bool component_free_all_at_once(const Component& comp, const ConstraintSystem& sys, const FaceNets& faces) {
  bool at_once = true;
  for (uint32_t ci : comp.pairs)
    if (!pair_free_all_at_once(sys.constraints[ci])) {
      at_once = false;
      break;
    }
  for (uint32_t fi = 0; at_once && fi < comp.faces.size(); ++fi) {
    Vec2 sum{0, 0};
    for (auto& [q, v] : faces.faces[comp.faces[fi]].nets) sum += v;
    if (!sum.is_zero()) at_once = false;
  }
  return at_once;
}

// What Z3 says of one component: Yes with its couplings' start times (in
// comp.couplings order, the earliest at 0), No, or Unknown (opt's time or
// conflict budget spent, Z3 gave up, or a time is no Rational).
struct ComponentOutcome {
  Verdict verdict = Verdict::Unknown;
  std::vector<Rational> start;
};

// Encodes comp (ComponentEncoder) and asks Z3 within what is left of opt's
// budgets: opt.seconds counted from start, opt.max_states conflicts counted
// in conflicts (which the call's conflicts are added to, as are stats'
// refuted, decisions and propagations).
ComponentOutcome solve_component_z3(z3::context& ctx, const Component& comp, const ConstraintSystem& sys,
                                    const FaceNets& faces, std::vector<int>& var_of, PairEncoding encoding,
                                    FreeOffsetsCache& offsets_cache, const SolveOptions& opt, double elapsed,
                                    uint64_t& conflicts, SolveStats& stats) {
  ComponentOutcome out;
  z3::solver s(ctx, "QF_LRA");
  ComponentEncoder enc(ctx, s, comp, sys, faces, var_of, encoding, offsets_cache);
  enc.encode();
  if (opt.seconds > 0) {
    double left = opt.seconds - elapsed;
    if (left <= 0) return out;
    s.set("timeout", static_cast<unsigned>(std::max(1.0, left * 1000)));
  }
  if (opt.max_states > 0) {
    if (conflicts >= opt.max_states) return out;
    s.set("max_conflicts", static_cast<unsigned>(std::min<uint64_t>(opt.max_states - conflicts, UINT32_MAX)));
  }
  z3::check_result cr = s.check();
  z3::stats st = s.statistics();
  conflicts += z3_stat(st, "conflicts");
  stats.refuted += z3_stat(st, "conflicts");
  stats.decisions += z3_stat(st, "decisions");
  stats.propagations += z3_stat(st, "propagations");
  if (cr == z3::unsat) {
    out.verdict = Verdict::No;
    return out;
  }
  if (cr == z3::unknown) return out;
  z3::model m = s.get_model();
  std::vector<Rational> vals;
  for (CouplingId q : comp.couplings) {
    z3::expr v = m.eval(enc.time_of(q), true);
    auto parsed = Rational::parse(Z3_get_numeral_string(ctx, v));
    if (!parsed) return out;
    vals.push_back(*parsed);
  }
  Rational lo = *std::min_element(vals.begin(), vals.end());
  for (const Rational& v : vals) out.start.push_back(v - lo);
  out.verdict = Verdict::Yes;
  return out;
}

// Runs a YES through the simulator within dl (nullptr: no limit): false if
// the limit (or a stop request) came first, so the answer is UNKNOWN.
bool check_witness(const Instance& inst, const Schedule& sched, const Deadline* dl) {
  if (auto e = check_schedule_bounds(inst, sched)) throw std::logic_error("solver schedule out of bounds: " + *e);
  Simulator sim(inst);
  sim.set_deadline(dl);
  SimResult check;
  try {
    check = sim.run(sched);
  } catch (const LimitReached&) {
    return false;
  }
  if (check.collision)
    throw std::logic_error("continuous solver returned a schedule that collides in the simulator: " +
                           describe(inst, sim.regions(), *check.collision));
  return true;
}

}  // namespace

std::optional<ContinuousEngine> continuous_engine_named(const std::string& name) {
  if (name == "auto") return ContinuousEngine::Auto;
  if (name == "dl") return ContinuousEngine::Dl;
  if (name == "sat") return ContinuousEngine::Sat;
  if (name == "z3") return ContinuousEngine::Z3;
  return std::nullopt;
}

ContinuousResult solve_continuous(const Instance& inst, const SolveOptions& opt, ContinuousEngine engine) {
  if (!inst.horizontal_only()) return solve_continuous_general(inst, opt, PairEncoding::Auto, engine);
  const Stopwatch clock;
  auto elapsed = [&] { return clock.seconds(); };
  ContinuousResult res;
  const size_t k = inst.couplings().size();
  {
    res.stats.engine = "gaps";
    GapVerdict v = check_gaps(inst);
    res.stats.constraints = v.gaps_checked + v.cycles_checked;
    if (v.collision_free) {
      res.status = Verdict::Yes;
      res.schedule.start.assign(k, Rational(0));
      // The final check is inside --timeout too (a row of 25 000 expansions
      // all at once takes minutes to simulate).
      const Deadline dl(opt.seconds > 0 ? std::max(opt.seconds - elapsed(), 1e-6) : 0);
      if (!check_witness(inst, res.schedule, &dl)) {
        res.status = Verdict::Unknown;
        res.schedule.start.clear();
      }
    } else {
      res.status = Verdict::No;
    }
    res.stats.seconds = elapsed();
    return res;
  }
}

namespace {

// The discrete solver's order as start times 0, 1, 2, ... (a discrete YES is
// a continuous YES); empty if it found no order. Bounded by search nodes
// (kDiscreteAttemptNodes, the same on any machine and under any load: a
// wall-clock bound of 1 s made compiled uf50 formulas UNKNOWN on a loaded
// machine although the discrete engine needs 0.3 s of CPU) and, with a
// deadline, by a third of the time left.
constexpr uint64_t kDiscreteAttemptNodes = 20000;
std::vector<Rational> discrete_candidate(const Instance& inst, const SearchBudget& budget) {
  SolveOptions d;
  d.max_states = kDiscreteAttemptNodes;
  if (budget.deadline().limit() > 0) {
    d.seconds = (budget.deadline().limit() - budget.elapsed()) / 3;
    if (d.seconds <= 0.01) return {};
  }
  SolveResult r = solve_discrete(inst, d);
  if (r.status != Verdict::Yes) return {};
  std::vector<Rational> t(inst.couplings().size(), Rational(0));
  for (size_t i = 0; i < r.order.size(); ++i) t[r.order[i]] = Rational(static_cast<int64_t>(i));
  return t;
}

// True iff the times t (per coupling of the instance) keep every pair and
// face of comp collision-free (exact).
bool component_free_at(const Component& comp, const ConstraintSystem& sys, const FaceNets& faces,
                       const std::vector<Rational>& t) {
  for (uint32_t ci : comp.pairs) {
    const CollisionConstraint& c = sys.constraints[ci];
    std::vector<Rational> st;
    for (CouplingId q : c.rel) st.push_back(t[q]);
    if (!pair_free_at_times(c, st)) return false;
  }
  for (uint32_t fi : comp.faces) {
    const auto& nets = faces.faces[fi].nets;
    for (auto& [q, v] : nets) {
      Vec2 sum{0, 0};
      for (auto& [r, w] : nets)
        if (t[r] == t[q]) sum += w;
      if (!sum.is_zero()) return false;
    }
  }
  return true;
}

// Everything solve_continuous_general shares between its steps.
struct GeneralRun {
  const Instance& inst;
  const SolveOptions& opt;
  PairEncoding encoding;
  ContinuousEngine engine;
  SearchBudget budget;
  ContinuousResult res;
  FreeOffsetsCache offsets_cache;
  bool tried_discrete = false;
  std::vector<Rational> discrete_times;
  bool used_z3 = false, used_sat = false, used_dl = false;
  ContinuousProof* proof = nullptr;  // solve_continuous_proved
};

bool no_shortcuts(ContinuousEngine e) {
  return e == ContinuousEngine::SatNoShortcuts || e == ContinuousEngine::DlNoShortcuts;
}

// A proof of a NO that Z3 found on the clamped encoding: the learning
// engine on its relaxation (ContinuousSatOptions::relax_covers), if it takes
// the component and finds the NO too; else why_none says why there is none.
void prove_clamped_no(GeneralRun& run, const Component& comp, const ConstraintSystem& sys,
                      const ComponentFaces& comp_faces) {
  *run.proof = {};
  const auto why = continuous_sat_unsupported(sys, comp.pairs);
  const std::string none = "decided by Z3 on the clamped encoding" + (why ? " (" + *why + ")" : std::string());
  if (!continuous_sat_unsupported(sys, comp.pairs, true)) {
    ContinuousSatOptions o;
    o.proof = run.proof;
    o.relax_covers = true;
    ContinuousSatOutcome got;
    try {
      got = solve_component_sat(sys, comp.couplings, comp.pairs, comp_faces, run.offsets_cache, run.budget,
                                run.res.stats, o);
    } catch (const LimitReached&) {  // the NO stands; only its proof is missing
      *run.proof = {};
      run.proof->why_none = none + "; the limit came before the learning engine's proof";
      return;
    }
    if (got.verdict == Verdict::No && run.proof->complete) return;
    *run.proof = {};
    run.proof->why_none = none + "; the learning engine's relaxation of its pairs of several forms " +
                          (got.verdict == Verdict::No ? "found no proof" : "has a model") + ", so no proof";
    return;
  }
  // The relaxation does not take the component either: say what stops it
  // (a pair of more than kMaxGapCouplings couplings), not only why the
  // learning engine declined the component in the first place.
  run.proof->why_none = none + ", which writes no proof, and the learning engine's relaxation cannot take it (" +
                        *continuous_sat_unsupported(sys, comp.pairs, true) + ")";
}

// Decides one component that the cheap tests did not settle: the discrete
// order (once per instance), then the sat engine or Z3. Writes the times
// into run.res.schedule; returns the verdict.
Verdict solve_hard_component(GeneralRun& run, const Component& comp, const ConstraintSystem& sys, const FaceNets& faces,
                             z3::context& ctx, std::vector<int>& var_of, uint64_t& conflicts) {
  if (run.encoding == PairEncoding::Auto && !no_shortcuts(run.engine)) {
    if (!run.tried_discrete) run.tried_discrete = true, run.discrete_times = discrete_candidate(run.inst, run.budget);
    if (!run.discrete_times.empty() && component_free_at(comp, sys, faces, run.discrete_times)) {
      Rational lo = run.discrete_times[comp.couplings[0]];
      for (CouplingId q : comp.couplings) lo = std::min(lo, run.discrete_times[q]);
      for (CouplingId q : comp.couplings) run.res.schedule.start[q] = run.discrete_times[q] - lo;
      ++run.res.stats.safe_moves;
      return Verdict::Yes;
    }
  }
  ++run.res.stats.states;
  ComponentFaces comp_faces;
  for (uint32_t fi : comp.faces) comp_faces.push_back(&faces.faces[fi]);
  const bool sat_ok = run.encoding == PairEncoding::Auto && run.engine != ContinuousEngine::Z3 &&
                      !continuous_sat_unsupported(sys, comp.pairs);
  if (sat_ok) {
    ContinuousSatOptions o;
    o.difference_logic = run.engine != ContinuousEngine::Sat && run.engine != ContinuousEngine::SatNoShortcuts;
    o.z3_for_linear = no_shortcuts(run.engine);
    o.proof = run.proof;
    (o.difference_logic || o.proof ? run.used_dl : run.used_sat) = true;
    ContinuousSatOutcome got = solve_component_sat(sys, comp.couplings, comp.pairs, comp_faces, run.offsets_cache,
                                                   run.budget, run.res.stats, o);
    for (size_t j = 0; j < got.start.size(); ++j) run.res.schedule.start[comp.couplings[j]] = got.start[j];
    return got.verdict;
  }
  run.used_z3 = true;
  ComponentOutcome got = solve_component_z3(ctx, comp, sys, faces, var_of, run.encoding, run.offsets_cache, run.opt,
                                            run.budget.elapsed(), conflicts, run.res.stats);
  if (run.proof && got.verdict == Verdict::No) prove_clamped_no(run, comp, sys, comp_faces);
  for (size_t j = 0; j < got.start.size(); ++j) run.res.schedule.start[comp.couplings[j]] = got.start[j];
  return got.verdict;
}

// The general path inside the budget (throws LimitReached).
Verdict solve_general_within(GeneralRun& run) {
  const size_t k = run.inst.couplings().size();
  const FaceNets faces = FaceNets::build(run.inst);
  run.budget.check();
  const SpanningTree tree = SpanningTree::build(run.inst);
  const ConstraintSystem sys = build_pair_constraints(run.inst, tree, &run.budget.deadline(),
                                                      /*stop_at_refuting=*/true);
  run.res.stats.constraints = sys.constraints.size() + faces.faces.size();
  if (sys.refuting != kNone) {
    // A pair only one coupling moves collides during its run whatever the
    // start times: NO, proved by that pair's interval clause alone (in a
    // collision-free schedule positions are the tree's, docs/certificates.md).
    const CollisionConstraint& c = sys.constraints[sys.refuting];
    run.res.lone_collider = c.rel[0];
    run.res.lone_pair = constraint_label(run.inst, Regions::build(run.inst), c);
    if (run.proof) {
      *run.proof = {};
      ContinuousProof::Clause cl;
      cl.reason = ContinuousProof::Reason::Interval;
      cl.region_a = c.region_a, cl.region_b = c.region_b;
      cl.movers = c.rel;
      run.proof->clauses.push_back(std::move(cl));
      run.proof->complete = true;
    }
    return Verdict::No;
  }
  const std::vector<Component> comps = components_of(k, sys, faces);
  run.res.schedule.start.assign(k, Rational(0));
  z3::context ctx;
  std::vector<int> var_of(k, -1);
  std::vector<uint32_t> local(k, 0);
  uint64_t conflicts = 0;
  for (const Component& comp : comps) {
    run.budget.check();
    const bool shortcuts = !no_shortcuts(run.engine);
    if (shortcuts && component_free_all_at_once(comp, sys, faces)) {
      ++run.res.stats.safe_moves;
      continue;
    }
    if (shortcuts && run.encoding == PairEncoding::Auto) {
      if (auto t = layered_candidate(comp, sys, faces, local, run.offsets_cache)) {
        for (size_t j = 0; j < comp.couplings.size(); ++j) run.res.schedule.start[comp.couplings[j]] = (*t)[j];
        ++run.res.stats.safe_moves;
        continue;
      }
    }
    Verdict v = solve_hard_component(run, comp, sys, faces, ctx, var_of, conflicts);
    if (v != Verdict::Yes) return v;
  }
  return Verdict::Yes;
}

}  // namespace

ContinuousResult solve_continuous_proved(const Instance& inst, const SolveOptions& opt, ContinuousEngine engine,
                                         ContinuousProof& proof) {
  proof = {};
  proof.why_none = "no NO";
  return solve_continuous_general(inst, opt, PairEncoding::Auto, engine, &proof);
}

ContinuousResult solve_continuous_general(const Instance& inst, const SolveOptions& opt, PairEncoding encoding,
                                          ContinuousEngine engine, ContinuousProof* proof) {
  GeneralRun run{inst, opt, encoding, engine, SearchBudget(opt), {}, {}, false, {}, false, false, false, proof};
  ContinuousResult& res = run.res;
  Verdict v = Verdict::Unknown;
  try {
    v = solve_general_within(run);
  } catch (const LimitReached&) {
    v = Verdict::Unknown;
  }
  run.budget.clear_progress();
  res.stats.engine = run.used_dl ? "dl" : run.used_sat ? "sat" : run.used_z3 ? "z3" : "trivial";
  if (v == Verdict::Yes && check_schedule_bounds(inst, res.schedule)) v = Verdict::Unknown;  // see the header
  if (v == Verdict::Yes && !check_witness(inst, res.schedule, &run.budget.deadline())) v = Verdict::Unknown;
  res.status = v;
  if (v != Verdict::Yes) res.schedule.start.clear();
  res.stats.seconds = run.budget.elapsed();
  return res;
}

}  // namespace gridlock
