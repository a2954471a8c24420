#include "support/random_gap_system.hpp"

#include <algorithm>
#include <numeric>
#include <utility>
#include <vector>

namespace gridlock::test {

ConstraintSystem random_gap_system(Rng& rng, size_t k, const GapSystemShape& shape) {
  ConstraintSystem s;
  s.kind = ConstraintKind::Gaps;
  s.num_couplings = k;
  const auto gaps = static_cast<size_t>(rng.between(1, shape.max_gaps));
  const auto kk = static_cast<int64_t>(k);
  for (size_t g = 0; g < gaps; ++g) {
    std::vector<CouplingId> ids(k);
    std::iota(ids.begin(), ids.end(), 0);
    rng.shuffle(ids);
    int64_t most = shape.max_size > 0 ? std::min(shape.max_size, kk) : kk;
    if (shape.sometimes_three && rng.coin()) most = std::min<int64_t>(3, kk);
    ids.resize(static_cast<size_t>(rng.between(2, most)));
    std::sort(ids.begin(), ids.end());
    CollisionConstraint c;
    c.num_forms = 1;
    c.base = {rng.between(shape.min_base, 0)};
    c.rel = ids;
    std::vector<int64_t> coef;
    for (size_t j = 0; j < ids.size(); ++j) {
      const int64_t v = rng.between(1, shape.max_coef);
      coef.push_back(rng.coin() ? v : -v);
    }
    c.set_coef(coef);
    s.constraints.push_back(std::move(c));
  }
  s.index();
  return s;
}

}  // namespace gridlock::test
