#include "certify/internal/pair_pattern.hpp"

#include <algorithm>
#include <map>

namespace gridlock {

bool certify_step_collides(const std::vector<int64_t>& s, const std::vector<int64_t>& c) {
  // Form i needs p > -s/c (c > 0), p < s/(-c) (c < 0) or s > 0 (c == 0).
  // The interval (lo_n/lo_d, hi_n/hi_d) starts as (0, 1); denominators > 0.
  __int128 lo_n = 0, lo_d = 1, hi_n = 1, hi_d = 1;
  for (size_t i = 0; i < s.size(); ++i) {
    if (c[i] == 0) {
      if (s[i] <= 0) return false;
    } else if (c[i] > 0) {
      const __int128 n = -static_cast<__int128>(s[i]), d = c[i];
      if (n * lo_d > lo_n * d) lo_n = n, lo_d = d;
    } else {
      const __int128 n = s[i], d = -static_cast<__int128>(c[i]);
      if (n * hi_d < hi_n * d) hi_n = n, hi_d = d;
    }
  }
  return lo_n * hi_d < hi_n * lo_d;
}

std::optional<std::string> check_pair_pattern(const Instance& inst, const CertifyGeometry& geo,
                                              const CertificateLemma& lemma) {
  const CouplingId run = lemma.runner;
  const auto& names = inst.couplings();
  std::map<CouplingId, int> ran;  // 1: before the runner (the clause false), 0: after
  for (auto [a, b] : lemma.lits) {
    if (a != run && b != run)
      return names[a].name + "<" + names[b].name + " does not order the runner " + names[run].name;
    const CouplingId q = a == run ? b : a;
    const int before = a == run ? 1 : 0;  // "R<q" false: q before R
    auto [it, fresh] = ran.try_emplace(q, before);
    if (!fresh && it->second != before) return std::nullopt;  // both ways: the clause always holds
  }
  const std::vector<CouplingForm> forms = geo.region_forms(lemma.region_a, lemma.region_b);
  const size_t nf = forms.size();
  std::vector<int64_t> s(nf), c(nf, 0);
  std::map<CouplingId, std::vector<int64_t>> coef;  // every coupling the forms name
  for (size_t i = 0; i < nf; ++i) {
    s[i] = forms[i].base;
    for (auto [q, v] : forms[i].terms) {
      if (q == run) c[i] = v;
      else coef.try_emplace(q, std::vector<int64_t>(nf, 0)).first->second[i] = v;
    }
  }
  std::vector<const std::vector<int64_t>*> mixed;
  for (const auto& [q, v] : coef) {
    auto it = ran.find(q);
    const bool up = std::all_of(v.begin(), v.end(), [](int64_t x) { return x >= 0; });
    const bool down = std::all_of(v.begin(), v.end(), [](int64_t x) { return x <= 0; });
    const bool add = it != ran.end() ? it->second == 1 : down;  // free: the lowest choice
    if (it == ran.end() && !up && !down) {
      mixed.push_back(&v);
      continue;
    }
    if (add)
      for (size_t i = 0; i < nf; ++i) s[i] += v[i];
  }
  if (mixed.size() > kMaxMixed)
    return std::to_string(mixed.size()) + " free couplings move the pair both ways (at most " +
           std::to_string(kMaxMixed) + ")";
  std::vector<int64_t> t(nf);
  for (uint64_t mask = 0; mask < (uint64_t{1} << mixed.size()); ++mask) {
    t = s;
    for (size_t j = 0; j < mixed.size(); ++j)
      if ((mask >> j) & 1)
        for (size_t i = 0; i < nf; ++i) t[i] += (*mixed[j])[i];
    if (!certify_step_collides(t, c))
      return "the step of " + names[run].name + " does not make the two regions collide in every order the " +
             "clause excludes (free couplings both ways: pattern " + std::to_string(mask) + ")";
  }
  return std::nullopt;
}

}  // namespace gridlock
