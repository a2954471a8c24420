#include "certify/internal/offsets.hpp"

#include <algorithm>

namespace gridlock {
namespace {

// a t + b d + c > 0 (strict) or >= 0.
struct Lin {
  Rational a, b, c;
  bool strict = false;
};

// One end of an interval of d: absent (infinite) or a value, open or closed.
struct End {
  bool inf = true;
  Rational v;
  bool open = true;
};

struct Interval {
  End lo, hi;  // lo.inf: from -inf; hi.inf: to +inf
};

bool empty(const Interval& i) {
  if (i.lo.inf || i.hi.inf) return false;
  return i.lo.v > i.hi.v || (i.lo.v == i.hi.v && (i.lo.open || i.hi.open));
}

// b d + c (> | >=) 0 intersected into r; false if it can never hold.
bool restrict_d(const Rational& b, const Rational& c, bool strict, Interval& r) {
  const Rational zero(0);
  if (b == zero) return c > zero || (c == zero && !strict);
  const Rational x = (zero - c) / b;
  End& e = b > zero ? r.lo : r.hi;
  const bool tighter = e.inf || (b > zero ? x > e.v : x < e.v);
  if (tighter) e = {false, x, strict};
  else if (x == e.v && strict) e.open = true;
  return true;
}

// The projection onto d of the set the constraints describe (Fourier-Motzkin
// on t), or nullopt if it is empty.
std::optional<Interval> project(const std::vector<Lin>& cs) {
  const Rational zero(0);
  Interval r;
  std::vector<const Lin*> low, up;
  for (const Lin& l : cs) {
    if (l.a == zero) {
      if (!restrict_d(l.b, l.c, l.strict, r)) return std::nullopt;
    } else {
      (l.a > zero ? low : up).push_back(&l);
    }
  }
  for (const Lin* p : low)
    for (const Lin* q : up) {
      // (-q.a) * p + p.a * q: t cancels.
      const Rational m1 = zero - q->a, m2 = p->a;
      if (!restrict_d(m1 * p->b + m2 * q->b, m1 * p->c + m2 * q->c, p->strict || q->strict, r)) return std::nullopt;
    }
  if (empty(r)) return std::nullopt;
  return r;
}

// The colliding offsets of the nine cells.
std::vector<Interval> colliding(const std::vector<OffsetForm>& forms) {
  const Rational zero(0), one(1);
  std::vector<Interval> out;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      std::vector<Lin> cs;
      // a: before (t <= 0), during (0 <= t <= 1), after (t >= 1).
      if (i == 0) cs.push_back({Rational(-1), zero, zero, false});
      if (i == 1) cs.push_back({one, zero, zero, false}), cs.push_back({Rational(-1), zero, one, false});
      if (i == 2) cs.push_back({one, zero, Rational(-1), false});
      // b, with s = t - d: before (s <= 0), during, after (s >= 1).
      if (j == 0) cs.push_back({Rational(-1), one, zero, false});
      if (j == 1) cs.push_back({one, Rational(-1), zero, false}), cs.push_back({Rational(-1), one, one, false});
      if (j == 2) cs.push_back({one, Rational(-1), Rational(-1), false});
      for (const OffsetForm& f : forms) {
        // base + ca pa + cb pb > 0 with pa in {0, t, 1}, pb in {0, t - d, 1}.
        Lin l{zero, zero, f.base, true};
        if (i == 1) l.a = l.a + f.ca;
        if (i == 2) l.c = l.c + f.ca;
        if (j == 1) l.a = l.a + f.cb, l.b = l.b - f.cb;
        if (j == 2) l.c = l.c + f.cb;
        cs.push_back(l);
      }
      if (auto r = project(cs)) out.push_back(*r);
    }
  return out;
}

// Frontier of a sweep: every offset below v (and v itself if past) is covered.
struct Frontier {
  bool minus_inf = true;  // nothing covered yet, from -inf
  Rational v;
  bool past = false;  // v itself covered
};

// Does interval i cover the next offsets after frontier f (and f's v if not past)?
bool continues(const Interval& i, const Frontier& f) {
  if (f.minus_inf) return i.lo.inf;
  const bool starts = i.lo.inf || i.lo.v < f.v || (i.lo.v == f.v && (f.past || !i.lo.open));
  const bool reaches = i.hi.inf || i.hi.v > f.v || (i.hi.v == f.v && !f.past && !i.hi.open);
  return starts && reaches;
}

// Is the open interval (s, e) (s absent: -inf, e absent: +inf) inside the union?
std::optional<std::string> covered(const std::optional<Rational>& s, const std::optional<Rational>& e,
                                   const std::vector<Interval>& u) {
  Frontier f;
  if (s) f = {false, *s, true};
  for (size_t round = 0; round <= 2 * u.size() + 1; ++round) {
    if (!f.minus_inf && e && (f.v > *e || f.v == *e)) return std::nullopt;
    const Interval* best = nullptr;
    for (const Interval& i : u) {
      if (!continues(i, f)) continue;
      if (i.hi.inf) return std::nullopt;
      if (!best || i.hi.v > best->hi.v || (i.hi.v == best->hi.v && !i.hi.open)) best = &i;
    }
    if (!best) break;
    f = {false, best->hi.v, !best->hi.open};
  }
  if (f.minus_inf) return std::string("very early offsets do not collide");
  return "offset " + f.v.str() + (f.past ? " (just above)" : "") + " does not collide";
}

}  // namespace

std::optional<std::string> offsets_outside_collide(const std::vector<OffsetForm>& forms,
                                                   const std::vector<FreeOffsets>& free) {
  const std::vector<Interval> hit = colliding(forms);
  std::vector<FreeOffsets> iv = free;
  std::sort(iv.begin(), iv.end(), [](const FreeOffsets& p, const FreeOffsets& q) {
    if (!p.lo || !q.lo) return !p.lo && q.lo;
    return *p.lo < *q.lo;
  });
  // The gaps between the free intervals are open intervals (s, e); reach:
  // the free intervals so far cover up to it (closed).
  bool any = false;
  Rational reach;
  for (const FreeOffsets& f : iv) {
    if (f.lo && (!any || *f.lo > reach))
      if (auto why = covered(any ? std::optional<Rational>(reach) : std::nullopt, f.lo, hit)) return why;
    if (!f.hi) return std::nullopt;  // free up to +inf
    reach = any ? std::max(reach, *f.hi) : *f.hi;
    any = true;
  }
  return covered(any ? std::optional<Rational>(reach) : std::nullopt, std::nullopt, hit);
}

}  // namespace gridlock
