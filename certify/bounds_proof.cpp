#include "certify/internal/bounds_proof.hpp"

#include <algorithm>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <tuple>

#include "certify/internal/clause_proof.hpp"
#include "certify/internal/geometry.hpp"
#include "certify/internal/offsets.hpp"
#include "lattice/rational.hpp"

namespace gridlock {
namespace {

// t_x - t_y <= v (< v if strict).
struct DiffBound {
  CouplingId x = kNone, y = kNone;
  Rational v;
  bool strict = false;
};

struct Var {
  bool declared = false, selector = false, guard = false;
  uint32_t ra = kNone, rb = kNone;  // g line: form `form` (0..7) of this pair is <= 0 at every moment
  size_t form = 0;
  DiffBound bound;                  // a line
  CouplingId a = kNone, b = kNone;  // s line: lo <= t_b - t_a <= hi
  std::optional<Rational> lo, hi;
  size_t line = 0;  // of the declaration
};

using BoundKey = std::tuple<CouplingId, CouplingId, int64_t, int64_t, bool>;

// The bound as a key with x < y, and whether it is the negation of that key
// (t_x - t_y <= v with x > y is not (t_y - t_x < -v)).
std::pair<BoundKey, bool> canonical(const DiffBound& b) {
  if (b.x < b.y) return {{b.x, b.y, b.v.num(), b.v.den(), b.strict}, false};
  const Rational w = Rational(0) - b.v;
  return {{b.y, b.x, w.num(), w.den(), !b.strict}, true};
}

// The negation of a bound: not (t_x - t_y <= v) is t_y - t_x < -v.
DiffBound negation(const DiffBound& b) { return {b.y, b.x, Rational(0) - b.v, !b.strict}; }

// The values of t_Q - t_q allowed so far: an interval with open or closed ends.
struct Range {
  bool lo_inf = true, hi_inf = true;
  Rational lo, hi;
  bool lo_open = false, hi_open = false;
  bool empty() const { return !lo_inf && !hi_inf && (lo > hi || (lo == hi && (lo_open || hi_open))); }
};

// The least progress clamp(x) over x in the range shifted by delta, and
// whether it is reached (lower: from the low end; else the high end).
std::pair<Rational, bool> progress_end(const Range& r, const Rational& delta, bool lower) {
  const Rational zero(0), one(1);
  if (lower) {
    if (r.lo_inf) return {zero, true};
    const Rational x = r.lo + delta;
    if (x < zero) return {zero, true};
    if (x >= one) return {one, true};
    return {x, !r.lo_open};
  }
  if (r.hi_inf) return {one, true};
  const Rational x = r.hi + delta;
  if (x > one) return {one, true};
  if (x <= zero) return {zero, true};
  return {x, !r.hi_open};
}

class BoundsChecker {
 public:
  BoundsChecker(const Instance& inst, const CertificateText& c, CertifyResult& r)
      : inst_(inst), c_(c), r_(r), geo_(inst) {}

  // The reason the certificate fails, or empty when it proves NO.
  std::string run() {
    for (const auto& [line, w] : c_.body)
      if (w[0] == "a" || w[0] == "s" || w[0] == "g") {
        if (auto e = w[0] == "g" ? declare_guard(w) : declare(w)) return at(line, *e);
        vars_[std::stoul(w[1])].line = line;
      }
    ClauseProof proof(static_cast<uint32_t>(vars_.size()));
    proof_ = &proof;
    for (size_t v = 1; v < vars_.size(); ++v)
      if (vars_[v].selector)
        if (auto e = define_selector(static_cast<int>(v))) return at(vars_[v].line, *e);
    bool ended = false;
    for (const auto& [line, w] : c_.body) {
      if (w[0] == "a" || w[0] == "s" || w[0] == "g") continue;
      if (ended) return at(line, "a line after the empty clause");
      std::vector<int> lits;
      size_t first = w[0] == "i" || w[0] == "e" ? 5 : w[0] == "f" ? 3 : w[0] == "w" ? 2 : 1;
      if (w[0] == "w")  // the walk's cells, then the literals
        while (first < w.size() && w[first].find(',') != std::string::npos) ++first;
      if (w.size() < first) return at(line, "too few words for an " + w[0] + " line");
      if (auto e = literals(w, first, lits)) return at(line, *e);
      if (w[0] == "l") {
        if (!proof.add_lemma(lits)) return at(line, "the lemma is not RUP");
        ++r_.lemmas;
        ended = lits.empty();
        continue;
      }
      std::optional<std::string> e = w[0] == "i"   ? interval_clause(w, lits)
                                     : w[0] == "e" ? event_clause(w, lits)
                                     : w[0] == "f" ? forms_clause(w, lits)
                                     : w[0] == "w" ? face_clause(w, first, lits)
                                                   : theory_clause(lits);
      if (e) return at(line, *e);
      proof.add_axiom(lits);
      ++r_.inequalities;
    }
    if (!ended) return "the proof does not end with the empty clause (a line 'l' alone)";
    if (!proof.refuted()) return "the empty clause was accepted but the clauses are not refuted";
    return {};
  }

 private:
  static std::string at(size_t line, const std::string& what) { return "line " + std::to_string(line) + ": " + what; }

  static std::optional<Rational> rational(const std::string& w) { return Rational::parse(w); }

  // The variable a declaration line names (w[1]), new.
  std::optional<std::string> new_var(const std::vector<std::string>& w, size_t& n) {
    try {
      n = std::stoul(w[1]);
    } catch (const std::exception&) {
      return "'" + w[1] + "' is not a variable number";
    }
    if (n == 0 || n > c_.body.size() || std::to_string(n) != w[1]) return "variable '" + w[1] + "' out of range";
    if (vars_.size() <= n) vars_.resize(n + 1);
    if (vars_[n].declared) return "variable " + w[1] + " declared twice";
    vars_[n].declared = true;
    return std::nullopt;
  }

  // "g N R1 R2 K": form K (1..8) of the pair stays <= 0.
  std::optional<std::string> declare_guard(const std::vector<std::string>& w) {
    if (w.size() != 5) return "expected 'g N REGION REGION FORM'";
    size_t n = 0;
    if (auto e = new_var(w, n)) return e;
    Var& v = vars_[n];
    v.guard = true;
    if (auto e = regions_of(w, v.ra, v.rb, 2)) return e;
    if (w[4].size() != 1 || w[4][0] < '1' || w[4][0] > '8') return "form '" + w[4] + "' is not 1..8";
    v.form = static_cast<size_t>(w[4][0] - '1');
    return std::nullopt;
  }

  // "a N X Y <= V" / "a N X Y < V" / "s N A B LO HI".
  std::optional<std::string> declare(const std::vector<std::string>& w) {
    if (w.size() != 6) return "expected 'a N X Y <= V', 'a N X Y < V' or 's N A B LO HI'";
    size_t n = 0;
    if (auto e = new_var(w, n)) return e;
    Var& v = vars_[n];
    CouplingId x = kNone, y = kNone;
    if (auto e = read_coupling(inst_, w[2], x)) return e;
    if (auto e = read_coupling(inst_, w[3], y)) return e;
    if (x == y) return "a bound of a coupling against itself";
    if (w[0] == "a") {
      if (w[4] != "<=" && w[4] != "<") return "expected <= or <";
      auto val = rational(w[5]);
      if (!val) return "'" + w[5] + "' is not a rational";
      v.bound = {x, y, *val, w[4] == "<"};
      bound_var_.emplace(canonical(v.bound).first, static_cast<int>(n));
      return std::nullopt;
    }
    v.selector = true, v.a = x, v.b = y;
    for (int i = 0; i < 2; ++i) {
      if (w[4 + static_cast<size_t>(i)] == "*") continue;
      auto val = rational(w[4 + static_cast<size_t>(i)]);
      if (!val) return "'" + w[4 + static_cast<size_t>(i)] + "' is not a rational or *";
      (i == 0 ? v.lo : v.hi) = *val;
    }
    if (v.lo && v.hi && *v.lo > *v.hi) return "an empty interval";
    return std::nullopt;
  }

  // The variable literal of bound b if it is declared, else 0.
  int literal_of(const DiffBound& b) const {
    const auto [key, negated] = canonical(b);
    auto it = bound_var_.find(key);
    if (it == bound_var_.end()) return 0;
    return negated ? -it->second : it->second;
  }

  // A selector implies the bounds of its interval: lo <= t_b - t_a is
  // t_a - t_b <= -lo, and t_b - t_a <= hi.
  std::optional<std::string> define_selector(int v) {
    const Var& s = vars_[static_cast<size_t>(v)];
    std::vector<DiffBound> need;
    if (s.lo) need.push_back({s.a, s.b, Rational(0) - *s.lo, false});
    if (s.hi) need.push_back({s.b, s.a, *s.hi, false});
    for (const DiffBound& b : need) {
      const int l = literal_of(b);
      if (l == 0)
        return "selector " + std::to_string(v) + " needs the bound " + inst_.couplings()[b.x].name + " - " +
               inst_.couplings()[b.y].name + " <= " + b.v.str() + " declared";
      proof_->add_axiom({-v, l});
      ++r_.axioms;
    }
    return std::nullopt;
  }

  std::optional<std::string> literals(const std::vector<std::string>& w, size_t first, std::vector<int>& out) const {
    for (size_t i = first; i < w.size(); ++i) {
      long long l = 0;
      try {
        size_t used = 0;
        l = std::stoll(w[i], &used);
        if (used != w[i].size()) throw std::invalid_argument("");
      } catch (const std::exception&) {
        return "'" + w[i] + "' is not a literal";
      }
      if (l < -INT32_MAX || l > INT32_MAX) return "literal " + w[i] + " out of range";
      const auto v = static_cast<size_t>(l < 0 ? -l : l);
      if (l == 0 || v >= vars_.size() || !vars_[v].declared) return "literal " + w[i] + " of no declared variable";
      out.push_back(static_cast<int>(l));
    }
    return std::nullopt;
  }

  // The negations of the literals, all of which must be bounds.
  std::optional<std::string> negations(const std::vector<int>& lits, std::vector<DiffBound>& out) const {
    for (int l : lits) {
      const Var& v = vars_[static_cast<size_t>(l < 0 ? -l : l)];
      if (v.selector || v.guard) return "literal " + std::to_string(l) + " is not a bound";
      out.push_back(l > 0 ? negation(v.bound) : v.bound);
    }
    return std::nullopt;
  }

  const std::vector<CouplingForm>& forms(uint32_t ra, uint32_t rb) {
    auto it = forms_.find({ra, rb});
    if (it == forms_.end()) it = forms_.emplace(std::make_pair(ra, rb), geo_.region_forms(ra, rb)).first;
    return it->second;
  }

  // The regions named by w[first] and w[first + 1].
  std::optional<std::string> regions_of(const std::vector<std::string>& w, uint32_t& ra, uint32_t& rb,
                                        size_t first = 1) const {
    if (auto e = read_region(inst_, geo_.regions(), w[first], ra)) return e;
    if (auto e = read_region(inst_, geo_.regions(), w[first + 1], rb)) return e;
    if (ra == rb) return std::string("a region paired with itself");
    return std::nullopt;
  }

  // i R1 R2 A B LITS (B '-': one coupling, no literals).
  std::optional<std::string> interval_clause(const std::vector<std::string>& w, const std::vector<int>& lits) {
    uint32_t ra = kNone, rb = kNone;
    if (auto e = regions_of(w, ra, rb)) return e;
    CouplingId a = kNone, b = kNone;
    if (auto e = read_coupling(inst_, w[3], a)) return e;
    if (w[4] != "-")
      if (auto e = read_coupling(inst_, w[4], b)) return e;
    if (a == b) return std::string("the two couplings must differ");
    std::vector<FreeOffsets> free;
    for (int l : lits) {
      const Var& v = vars_[static_cast<size_t>(l < 0 ? -l : l)];
      if (l < 0 || !v.selector || v.a != a || v.b != b)
        return "literal " + std::to_string(l) + " is not a selector of " + w[4] + " - " + w[3];
      free.push_back({v.lo, v.hi});
    }
    std::vector<OffsetForm> fs;
    for (const CouplingForm& f : forms(ra, rb)) {
      OffsetForm o{Rational(f.base), Rational(0), Rational(0)};
      for (auto [q, coef] : f.terms) {
        if (q == a) o.ca = Rational(coef);
        else if (q == b) o.cb = Rational(coef);
        else if (coef < 0) o.base = o.base + Rational(coef);  // any other coupling at its worst
      }
      fs.push_back(o);
    }
    if (auto e = offsets_outside_collide(fs, free))
      return "the pair does not always collide outside the intervals: " + *e;
    return std::nullopt;
  }

  // e R1 R2 Q DELTA LITS.
  std::optional<std::string> event_clause(const std::vector<std::string>& w, const std::vector<int>& lits) {
    uint32_t ra = kNone, rb = kNone;
    if (auto e = regions_of(w, ra, rb)) return e;
    CouplingId runner = kNone;  // '-': before every start
    if (w[3] != "-")
      if (auto e = read_coupling(inst_, w[3], runner)) return e;
    const auto delta = rational(w[4]);
    if (!delta) return "'" + w[4] + "' is not a rational";
    // A guard's literal, negated in the clause, asks its form alone to be positive.
    std::vector<int> bounds;
    size_t only = SIZE_MAX;
    for (int l : lits) {
      const Var& v = vars_[static_cast<size_t>(l < 0 ? -l : l)];
      if (!v.guard) {
        bounds.push_back(l);
        continue;
      }
      if (l > 0 || only != SIZE_MAX || v.ra != ra || v.rb != rb)
        return "literal " + std::to_string(l) + ": at most one guard of this pair, negated";
      only = v.form;
    }
    std::vector<DiffBound> neg;
    if (auto e = negations(bounds, neg)) return e;
    if (runner == kNone) neg.clear();   // every progress is 0
    std::map<CouplingId, Range> range;  // of t_Q - t_q
    for (const DiffBound& b : neg) {
      if (b.x == runner) {  // t_Q - t_y <= v
        Range& r = range[b.y];
        if (r.hi_inf || b.v < r.hi) r.hi_inf = false, r.hi = b.v, r.hi_open = b.strict;
        else if (b.v == r.hi) r.hi_open = r.hi_open || b.strict;
      } else if (b.y == runner) {  // t_x - t_Q <= v: t_Q - t_x >= -v
        Range& r = range[b.x];
        const Rational lo = Rational(0) - b.v;
        if (r.lo_inf || lo > r.lo) r.lo_inf = false, r.lo = lo, r.lo_open = b.strict;
        else if (lo == r.lo) r.lo_open = r.lo_open || b.strict;
      }
    }
    for (const auto& [q, r] : range)
      if (r.empty()) return std::nullopt;  // the negations contradict each other: the clause always holds
    const std::vector<CouplingForm>& fs = forms(ra, rb);
    for (size_t k = 0; k < fs.size(); ++k) {
      if (only != SIZE_MAX && k != only) continue;
      Rational inf(fs[k].base);
      bool reached = true;
      for (auto [q, coef] : fs[k].terms) {
        Rational p;
        bool at_end = true;
        if (runner == kNone) {
          p = Rational(0);
        } else if (q == runner) {
          p = *delta < Rational(0) ? Rational(0) : *delta > Rational(1) ? Rational(1) : *delta;
        } else {
          auto it = range.find(q);
          const Range r = it == range.end() ? Range{} : it->second;
          std::tie(p, at_end) = progress_end(r, *delta, coef > 0);
        }
        inf = inf + Rational(coef) * p;
        reached = reached && at_end;
      }
      if (inf < Rational(0) || (inf == Rational(0) && reached))
        return "at " + w[3] + " + " + w[4] + " form " + std::to_string(k + 1) + " of the pair can be " +
               (inf == Rational(0) ? "0" : "negative") + ": no collision follows";
    }
    return std::nullopt;
  }

  // f R1 R2 LITS: guards of the pair, one of which holds: every other form
  // is positive everywhere on the progress cube, and no two of theirs can
  // be <= 0 together (f_i + f_j > 0 on the cube). The set of moments where
  // a form is <= 0 is closed; in a collision-free schedule these sets of
  // the guards' forms cover the time line, and they are disjoint, so one
  // of them is all of it.
  std::optional<std::string> forms_clause(const std::vector<std::string>& w, const std::vector<int>& lits) {
    uint32_t ra = kNone, rb = kNone;
    if (auto e = regions_of(w, ra, rb)) return e;
    const std::vector<CouplingForm>& fs = forms(ra, rb);
    std::vector<char> listed(fs.size(), 0);
    for (int l : lits) {
      const Var& v = vars_[static_cast<size_t>(l < 0 ? -l : l)];
      if (l < 0 || !v.guard || v.ra != ra || v.rb != rb || listed[v.form])
        return "literal " + std::to_string(l) + " is not a new guard of this pair";
      listed[v.form] = 1;
    }
    // The least value on the cube of the sum of the listed forms (one or two).
    auto least = [&](size_t i, size_t j) {
      std::map<CouplingId, int64_t> coef;
      int64_t base = fs[i].base + (j == i ? 0 : fs[j].base);
      for (auto [q, c] : fs[i].terms) coef[q] += c;
      if (j != i)
        for (auto [q, c] : fs[j].terms) coef[q] += c;
      for (auto [q, c] : coef) base += std::min<int64_t>(c, 0);
      return base;
    };
    for (size_t i = 0; i < fs.size(); ++i) {
      if (!listed[i] && least(i, i) <= 0) return "form " + std::to_string(i + 1) + " is not listed but can be <= 0";
      for (size_t j = i + 1; j < fs.size(); ++j)
        if (listed[i] && listed[j] && least(i, j) <= 0)
          return "forms " + std::to_string(i + 1) + " and " + std::to_string(j + 1) + " can be <= 0 together";
    }
    return std::nullopt;
  }

  // w Q CELLS LITS: the cells are a closed walk; with every literal false
  // each coupling with a non-zero net around it starts before, with or
  // after Q (each literal a bound between Q and it, of constant 0), and the
  // nets of Q and of those that start with Q do not sum to zero. In a
  // collision-free schedule the walk stays closed: its net
  // sum_q progress_q(t) * net_q is zero at every t, so at each start time
  // the nets of the couplings starting then sum to zero (certificates.md).
  std::optional<std::string> face_clause(const std::vector<std::string>& w, size_t first,
                                         const std::vector<int>& lits) const {
    CouplingId runner = kNone;
    if (auto e = read_coupling(inst_, w[1], runner)) return e;
    std::vector<NodeId> walk;
    for (size_t i = 2; i < first; ++i) {
      NodeId v = kNone;
      if (auto e = read_cell(inst_, w[i], v)) return e;
      walk.push_back(v);
    }
    if (walk.size() < 3) return std::string("a closed walk needs three cells or more");
    std::vector<Vec2> nets;
    if (auto e = geo_.walk_nets(walk, nets)) return e;
    std::vector<DiffBound> neg;
    if (auto e = negations(lits, neg)) return e;
    std::map<CouplingId, Range> range;  // of t_q - t_Q
    for (const DiffBound& b : neg) {
      if (b.v != Rational(0) || (b.x != runner && b.y != runner))
        return "literal bound " + inst_.couplings()[b.x].name + " - " + inst_.couplings()[b.y].name +
               " is not against " + w[1] + " with constant 0";
      Range& r = range[b.x == runner ? b.y : b.x];
      if (b.x == runner) {  // t_Q - t_q <= 0 (< 0): t_q - t_Q >= 0 (> 0)
        if (r.lo_inf || r.lo_open < b.strict) r.lo_inf = false, r.lo = Rational(0), r.lo_open = b.strict;
      } else if (r.hi_inf || r.hi_open < b.strict) {  // t_q - t_Q <= 0 (< 0)
        r.hi_inf = false, r.hi = Rational(0), r.hi_open = b.strict;
      }
    }
    Vec2 sum = nets[runner];
    for (size_t q = 0; q < nets.size(); ++q) {
      if (q == runner || nets[q].is_zero()) continue;
      auto it = range.find(static_cast<CouplingId>(q));
      if (it == range.end()) return "coupling " + inst_.couplings()[q].name + " has a net but no bound against " + w[1];
      const Range& r = it->second;
      if (r.empty()) return std::nullopt;        // the negations contradict each other: the clause always holds
      const bool with = !r.lo_inf && !r.hi_inf;  // 0 <= t_q - t_Q <= 0
      const bool apart = (!r.lo_inf && r.lo_open) || (!r.hi_inf && r.hi_open);
      if (!with && !apart) return "coupling " + inst_.couplings()[q].name + " may or may not start with " + w[1];
      if (with) sum = sum + nets[q];
    }
    if (sum.is_zero()) return "the nets of " + w[1] + " and the couplings that start with it sum to zero";
    return std::nullopt;
  }

  // t LITS: the negations, in order, are a cycle of difference bounds
  // t_x1 - t_y1 <= v1, t_x2 - t_y2 <= v2, ... with y_i = x_(i+1) and
  // y_k = x_1. Their sum says 0 <= v1 + ... + vk (< if one is strict),
  // which must be false: they cannot hold together.
  std::optional<std::string> theory_clause(const std::vector<int>& lits) const {
    std::vector<DiffBound> neg;
    if (auto e = negations(lits, neg)) return e;
    if (neg.empty()) return std::string("a theory lemma needs literals");
    Rational sum(0);
    bool strict = false;
    for (size_t i = 0; i < neg.size(); ++i) {
      const DiffBound& next = neg[(i + 1) % neg.size()];
      if (neg[i].y != next.x)
        return "the negated bounds are no cycle: literal " + std::to_string(i + 1) + " ends at " +
               inst_.couplings()[neg[i].y].name + ", the next starts at " + inst_.couplings()[next.x].name;
      sum = sum + neg[i].v;
      strict = strict || neg[i].strict;
    }
    if (sum > Rational(0) || (sum == Rational(0) && !strict))
      return "the negated bounds' cycle sums to " + sum.str() + (strict ? " (strict)" : "") +
             ": they can hold together";
    return std::nullopt;
  }

  const Instance& inst_;
  const CertificateText& c_;
  CertifyResult& r_;
  CertifyGeometry geo_;
  std::vector<Var> vars_;  // vars_[v]; vars_[0] unused
  std::map<BoundKey, int> bound_var_;
  std::map<std::pair<uint32_t, uint32_t>, std::vector<CouplingForm>> forms_;
  ClauseProof* proof_ = nullptr;
};

}  // namespace

void check_bounds_proof(const Instance& inst, const CertificateText& c, CertifyResult& r) {
  try {
    BoundsChecker checker(inst, c, r);
    r.reason = checker.run();
  } catch (const std::overflow_error&) {
    r.reason = "a number beyond the checker's exact arithmetic (64-bit rationals)";
  }
  r.proved = r.reason.empty();
}

}  // namespace gridlock
