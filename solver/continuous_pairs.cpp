#include "solver/internal/continuous_pairs.hpp"

#include <algorithm>
#include <stdexcept>

namespace gridlock {

namespace {

Rational clamp01(const Rational& x) { return x < Rational(0) ? Rational(0) : x > Rational(1) ? Rational(1) : x; }

int64_t coef(const CollisionConstraint& c, size_t j, uint32_t i) { return j < c.rel.size() ? c.coef_of(j)[i] : 0; }

}  // namespace

bool pair_free_at_times(const CollisionConstraint& c, const std::vector<Rational>& start) {
  if (start.size() != c.rel.size()) throw std::invalid_argument("pair_free_at_times needs one start per coupling");
  const uint32_t nf = c.num_forms;
  auto value = [&](uint32_t i, const Rational& t) {
    Rational v(c.base[i]);
    for (size_t j = 0; j < start.size(); ++j)
      if (int64_t a = c.coef_of(j)[i]; a != 0) v = v + Rational(a) * clamp01(t - start[j]);
    return v;
  };
  std::vector<Rational> ev;
  for (const Rational& s : start) ev.push_back(s), ev.push_back(s + Rational(1));
  if (ev.empty()) ev.push_back(Rational(0));
  std::sort(ev.begin(), ev.end());
  ev.erase(std::unique(ev.begin(), ev.end()), ev.end());
  // Before the first and after the last event every form is constant.
  for (const Rational& t : {ev.front(), ev.back()}) {
    bool all = true;
    for (uint32_t i = 0; i < nf && all; ++i) all = value(i, t) > Rational(0);
    if (all) return false;
  }
  // On each piece, t = lo + tau (hi - lo) with tau in (0, 1): the forms are
  // s_i + tau c_i, all positive on an open set iff max lower < min upper.
  for (size_t e = 0; e + 1 < ev.size(); ++e) {
    Rational L(0), U(1);
    bool empty = false;
    for (uint32_t i = 0; i < nf && !empty; ++i) {
      Rational s = value(i, ev[e]), cc = value(i, ev[e + 1]) - s;
      if (cc == Rational(0)) {
        empty = s <= Rational(0);
      } else if (cc > Rational(0)) {
        L = std::max(L, (Rational(0) - s) / cc);
      } else {
        U = std::min(U, s / (Rational(0) - cc));
      }
    }
    if (!empty && L < U) return false;
  }
  return true;
}

bool pair_free_at_offset(const CollisionConstraint& c, const Rational& d) {
  if (c.rel.size() > 2) throw std::invalid_argument("pair_free_at_offset needs at most two couplings");
  std::vector<Rational> start = {Rational(0)};
  if (c.rel.size() == 2) start.push_back(d);
  if (c.rel.empty()) start.clear();
  return pair_free_at_times(c, start);
}

std::vector<OffsetInterval> free_offsets(const CollisionConstraint& c) {
  if (c.rel.size() != 2) throw std::invalid_argument("free_offsets needs exactly two couplings");
  // Lines t = u + v d: the events, and every form's zero on every piece kind
  // (each coupling not started, done or running).
  std::vector<std::pair<Rational, Rational>> lines = {
      {Rational(0), Rational(0)}, {Rational(1), Rational(0)}, {Rational(0), Rational(1)}, {Rational(1), Rational(1)}};
  std::vector<Rational> cand = {Rational(-1), Rational(0), Rational(1)};
  for (uint32_t i = 0; i < c.num_forms; ++i) {
    const int64_t a = coef(c, 0, i), b = coef(c, 1, i);
    for (int s1 = 0; s1 < 3; ++s1)
      for (int s2 = 0; s2 < 3; ++s2) {
        // f = K + S t + V d (state 0: not started, 1: done, 2: running).
        int64_t K = c.base[i] + (s1 == 1 ? a : 0) + (s2 == 1 ? b : 0);
        int64_t S = (s1 == 2 ? a : 0) + (s2 == 2 ? b : 0);
        int64_t V = s2 == 2 ? -b : 0;
        if (S != 0) {
          lines.push_back({Rational(-K, S), Rational(-V, S)});
        } else if (V != 0) {
          cand.push_back(Rational(-K, V));
        }
      }
  }
  std::sort(lines.begin(), lines.end());
  lines.erase(std::unique(lines.begin(), lines.end()), lines.end());
  for (size_t x = 0; x < lines.size(); ++x)
    for (size_t y = x + 1; y < lines.size(); ++y)
      if (lines[x].second != lines[y].second)
        cand.push_back((lines[y].first - lines[x].first) / (lines[x].second - lines[y].second));
  std::sort(cand.begin(), cand.end());
  cand.erase(std::unique(cand.begin(), cand.end()), cand.end());

  // Regions in order: (-inf, c0), {c0}, (c0, c1), {c1}, ..., {cm}, (cm, inf).
  const size_t m = cand.size();
  std::vector<char> free(2 * m + 1);
  free[0] = pair_free_at_offset(c, cand[0] - Rational(1));
  for (size_t j = 0; j < m; ++j) {
    free[2 * j + 1] = pair_free_at_offset(c, cand[j]);
    free[2 * j + 2] = pair_free_at_offset(c, j + 1 < m ? (cand[j] + cand[j + 1]) / Rational(2) : cand[j] + Rational(1));
  }
  std::vector<OffsetInterval> out;
  for (size_t r = 0; r < free.size();) {
    if (!free[r]) {
      ++r;
      continue;
    }
    size_t e = r;
    while (e + 1 < free.size() && free[e + 1]) ++e;
    // The free set is closed: a run starts and ends at a point or at infinity.
    if ((r != 0 && r % 2 == 0) || (e != free.size() - 1 && e % 2 == 0))
      throw std::logic_error("free offsets of a pair are not closed");
    OffsetInterval iv;
    if (r != 0) iv.lo = cand[(r - 1) / 2];
    if (e != free.size() - 1) iv.hi = cand[(e - 1) / 2];
    out.push_back(iv);
    r = e + 1;
  }
  return out;
}

bool forms_never_both_nonpositive(const CollisionConstraint& c) {
  for (uint32_t i = 0; i < c.num_forms; ++i)
    for (uint32_t j = i + 1; j < c.num_forms; ++j) {
      int64_t m = c.base[i] + c.base[j];
      for (size_t q = 0; q < c.rel.size(); ++q) m += std::min<int64_t>(0, c.coef_of(q)[i] + c.coef_of(q)[j]);
      if (m <= 0) return false;
    }
  return true;
}

}  // namespace gridlock
