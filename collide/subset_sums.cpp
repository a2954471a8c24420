// The discrete pair tests (collide/internal/collide_pairs.hpp): subset sums of the
// path's vectors, per running choice, and the one-variable test per cell.
#include <algorithm>
#include <optional>
#include <stdexcept>
#include <vector>

#include "collide/internal/collide_pairs.hpp"
#include "collide/internal/pair_system.hpp"

namespace gridlock {

using namespace pairs;

namespace {

// Subset sums of vectors on a grid [x0, x0+W) x [y0, y0+H).
struct SumGrid {
  int64_t x0 = 0, y0 = 0, W = 1, H = 1;
  std::vector<uint8_t> cell;
  uint8_t& at(int64_t x, int64_t y) { return cell[static_cast<size_t>((x - x0) * H + (y - y0))]; }
  bool get(int64_t x, int64_t y) const {
    if (x < x0 || y < y0 || x >= x0 + W || y >= y0 + H) return false;
    return cell[static_cast<size_t>((x - x0) * H + (y - y0))] != 0;
  }
};

SumGrid subset_sums(const std::vector<Vec2>& vecs, std::vector<SumGrid>* layers) {
  SumGrid g;
  int64_t xmin = 0, xmax = 0, ymin = 0, ymax = 0;
  for (Vec2 w : vecs) {
    (w.x < 0 ? xmin : xmax) += w.x;
    (w.y < 0 ? ymin : ymax) += w.y;
  }
  g.x0 = xmin, g.y0 = ymin, g.W = xmax - xmin + 1, g.H = ymax - ymin + 1;
  g.cell.assign(static_cast<size_t>(g.W * g.H), 0);
  g.at(0, 0) = 1;
  for (Vec2 w : vecs) {
    if (layers) layers->push_back(g);
    // In place: visit targets before their sources.
    for (int64_t i = 0; i < g.W; ++i) {
      int64_t x = w.x > 0 ? g.x0 + g.W - 1 - i : g.x0 + i;
      int64_t tx = x + w.x;
      if (tx < g.x0 || tx >= g.x0 + g.W) continue;
      for (int64_t jj = 0; jj < g.H; ++jj) {
        int64_t y = w.y > 0 ? g.y0 + g.H - 1 - jj : g.y0 + jj;
        int64_t ty = y + w.y;
        if (ty < g.y0 || ty >= g.y0 + g.H) continue;
        if (g.at(x, y)) g.at(tx, ty) = 1;
      }
    }
  }
  return g;
}

// A choice of the coupling that runs last (is caught mid-way): an own
// coupling of the pair (var >= 0), or the path coupling S.gens[gen].
struct RunChoice {
  int var = -1;    // own coupling index, or -1
  size_t gen = 0;  // else: index into S.gens
};

// The choices worth trying: each own coupling, and one per distinct vector
// among the others (which copy of equal vectors runs last does not matter:
// the subset sums of the rest are the same).
std::vector<RunChoice> running_choices(const PairSystem& S) {
  std::vector<RunChoice> choices;
  choices.reserve(static_cast<size_t>(S.nv) + S.gens.size());
  for (int j = 0; j < S.nv; ++j) choices.push_back({j, 0});
  std::vector<Vec2> seen;
  for (size_t g = 0; g < S.gens.size(); ++g) {
    Vec2 w = S.gens[g].second;
    if (std::find(seen.begin(), seen.end(), w) != seen.end()) continue;
    seen.push_back(w);
    choices.push_back({-1, g});
  }
  return choices;
}

// Fills want with the witness of a meeting found at subset sum (x, y) of
// rest (the path vectors S.gens[rest_idx[i]] not running): a subset of rest
// with that sum (by backtracking through subset_sums' layers), the own
// couplings done (val[j] = 1), and the running coupling ch.
void recover_witness(const PairSystem& S, const RunChoice& ch, const std::vector<Vec2>& rest,
                     const std::vector<size_t>& rest_idx, const int64_t val[2], int64_t x, int64_t y,
                     PairWitness* want) {
  std::vector<SumGrid> layers;
  subset_sums(rest, &layers);
  std::vector<char> used(rest.size(), 0);
  int64_t cx = x, cy = y;
  for (size_t i = rest.size(); i-- > 0;) {
    if (layers[i].get(cx, cy)) continue;  // reachable without vector i
    used[i] = 1;
    cx -= rest[i].x, cy -= rest[i].y;
  }
  if (cx != 0 || cy != 0) throw std::logic_error("collide: subset-sum backtrack failed");
  for (size_t i = 0; i < rest.size(); ++i)
    if (used[i]) want->done.push_back(S.gens[rest_idx[i]].first);
  for (int j = 0; j < S.nv; ++j)
    if (j != ch.var && val[j]) want->done.push_back(S.var[j]);
  want->running = ch.var >= 0 ? S.var[ch.var] : S.gens[ch.gen].first;
}

// True iff some running progress s in [0,1] makes the eight rows
// c_i + k_i s + sign_i Delta[axis_i] positive at the cell Delta = (x, y):
// an exact one-variable interval test. cs is scratch space (cleared).
bool cell_meets(const PairSystem& S, const i128 cst[8], const i128 ks[8], int64_t x, int64_t y, std::vector<Lin>& cs) {
  cs.clear();
  for (int i = 0; i < 8; ++i) {
    Lin L;
    L.a[0] = ks[i];
    L.c = cst[i] + (S.axis[i] < 0 ? 0 : S.sign[i] * (S.axis[i] == 0 ? x : y));
    cs.push_back(L);
  }
  Lin lo, hi;
  lo.a[0] = 1, lo.strict = false;
  hi.a[0] = -1, hi.c = 1, hi.strict = false;
  cs.push_back(lo), cs.push_back(hi);
  return !interval_of(cs).empty();
}

}  // namespace

bool discrete_pair_collides_per_vector(const RegionForm& A, const RegionForm& B, const PathNets& nets,
                                       PairWitness* want) {
  PairSystem S = build_system(A, B, nets);
  const std::vector<RunChoice> choices = running_choices(S);
  if (choices.empty()) {  // nothing moves the pair: overlap now or never (never, in a valid instance)
    for (int i = 0; i < 8; ++i)
      if (S.c[i] <= 0) return false;
    return true;
  }
  for (const RunChoice& ch : choices) {
    std::vector<Vec2> rest;
    std::vector<size_t> rest_idx;
    for (size_t g = 0; g < S.gens.size(); ++g)
      if (ch.var >= 0 || g != ch.gen) rest.push_back(S.gens[g].second), rest_idx.push_back(g);
    SumGrid sums = subset_sums(rest, nullptr);
    // States of the own couplings that do not run: 0 or 1 each.
    int free_vars = S.nv - (ch.var >= 0 ? 1 : 0);
    for (int mask = 0; mask < (1 << free_vars); ++mask) {
      int64_t val[2] = {0, 0};
      {
        int bit = 0;
        for (int j = 0; j < S.nv; ++j) {
          if (j == ch.var) continue;
          val[j] = (mask >> bit++) & 1;
        }
      }
      // Per row: constant part (without z), the coefficient of s.
      i128 cst[8], ks[8];
      for (int i = 0; i < 8; ++i) {
        cst[i] = S.c[i];
        for (int j = 0; j < S.nv; ++j)
          if (j != ch.var) cst[i] += static_cast<i128>(S.e[i][j]) * val[j];
        if (ch.var >= 0) ks[i] = S.e[i][ch.var];
        else ks[i] = S.axis[i] >= 0 ? S.sign[i] * comp(S.gens[ch.gen].second, S.axis[i]) : 0;
      }
      for (int64_t x = sums.x0; x < sums.x0 + sums.W; ++x)
        for (int64_t y = sums.y0; y < sums.y0 + sums.H; ++y) {
          if (!sums.get(x, y)) continue;
          std::vector<Lin> cs;
          if (!cell_meets(S, cst, ks, x, y, cs)) continue;
          if (want) recover_witness(S, ch, rest, rest_idx, val, x, y, want);
          return true;
        }
    }
  }
  return false;
}

namespace {

// Subset sums of a multiset given as distinct vectors with multiplicities:
// one pass over the grid per distinct vector (O(c A) for c distinct
// vectors and grid area A, against O(K A) one vector at a time). A cell is
// reachable after vector w (m copies) iff one of the m + 1 cells
// p, p - w, ..., p - m w was reachable before: walked in an order where
// p - w comes before p, cnt[p] = steps since the last reachable cell on
// that chain.
SumGrid grouped_subset_sums(const std::vector<std::pair<Vec2, uint32_t>>& groups, std::vector<int32_t>& cnt) {
  SumGrid g;
  int64_t xmin = 0, xmax = 0, ymin = 0, ymax = 0;
  for (const auto& [w, m] : groups) {
    (w.x < 0 ? xmin : xmax) += w.x * m;
    (w.y < 0 ? ymin : ymax) += w.y * m;
  }
  g.x0 = xmin, g.y0 = ymin, g.W = xmax - xmin + 1, g.H = ymax - ymin + 1;
  g.cell.assign(static_cast<size_t>(g.W * g.H), 0);
  g.at(0, 0) = 1;
  constexpr int32_t kFar = INT32_MAX / 2;
  cnt.resize(g.cell.size());
  for (const auto& [w, m] : groups) {
    if (m == 0) continue;
    for (int64_t i = 0; i < g.W; ++i) {
      const int64_t x = w.x >= 0 ? g.x0 + i : g.x0 + g.W - 1 - i;
      for (int64_t j = 0; j < g.H; ++j) {
        const int64_t y = w.y >= 0 ? g.y0 + j : g.y0 + g.H - 1 - j;
        const auto at = static_cast<size_t>((x - g.x0) * g.H + (y - g.y0));
        int32_t c = 0;
        if (g.cell[at] == 0) {
          const int64_t px = x - w.x, py = y - w.y;
          const bool in = px >= g.x0 && py >= g.y0 && px < g.x0 + g.W && py < g.y0 + g.H;
          const int32_t prev = in ? cnt[static_cast<size_t>((px - g.x0) * g.H + (py - g.y0))] : kFar;
          c = prev >= kFar ? kFar : prev + 1;
        }
        cnt[at] = c;
        g.cell[at] = c <= static_cast<int32_t>(m) ? 1 : 0;
      }
    }
  }
  return g;
}

// Does some reachable Delta (a cell of sums) with the running progress s
// in [0,1] satisfy the eight rows c_i + k_i s + sign_i Delta[axis_i] > 0?
// Only the cells of the rows' bounding box over s in [0,1] can (Delta.x in
// (min(-c1, -c1 - k1), max(c0, c0 + k0)), and so for y): O(1 + |k|^2)
// cells, each an exact one-variable interval test. Returns the cell.
std::optional<std::pair<int64_t, int64_t>> meeting_cell(const PairSystem& S, const SumGrid& sums, const i128 cst[8],
                                                        const i128 ks[8], std::vector<Lin>& cs) {
  const i128 xlo = std::min(-cst[1], -cst[1] - ks[1]), xhi = std::max(cst[0], cst[0] + ks[0]);
  const i128 ylo = std::min(-cst[3], -cst[3] - ks[3]), yhi = std::max(cst[2], cst[2] + ks[2]);
  const int64_t x_from = static_cast<int64_t>(std::max<i128>(xlo, sums.x0));
  const int64_t x_to = static_cast<int64_t>(std::min<i128>(xhi, sums.x0 + sums.W - 1));
  const int64_t y_from = static_cast<int64_t>(std::max<i128>(ylo, sums.y0));
  const int64_t y_to = static_cast<int64_t>(std::min<i128>(yhi, sums.y0 + sums.H - 1));
  for (int64_t x = x_from; x <= x_to; ++x)
    for (int64_t y = y_from; y <= y_to; ++y) {
      if (!sums.get(x, y)) continue;
      if (cell_meets(S, cst, ks, x, y, cs)) return std::pair{x, y};
    }
  return std::nullopt;
}

}  // namespace

bool discrete_pair_collides(const RegionForm& A, const RegionForm& B, const PathNets& nets, PairWitness* want) {
  PairSystem S = build_system(A, B, nets);
  const std::vector<RunChoice> choices = running_choices(S);
  if (choices.empty()) {  // nothing moves the pair: overlap now or never (never, in a valid instance)
    for (int i = 0; i < 8; ++i)
      if (S.c[i] <= 0) return false;
    return true;
  }
  // The path's vectors as distinct vectors with multiplicities (c groups).
  std::vector<std::pair<Vec2, uint32_t>> groups;
  for (const auto& g : S.gens) {
    auto it = std::find_if(groups.begin(), groups.end(), [&](const auto& e) { return e.first == g.second; });
    if (it == groups.end()) groups.push_back({g.second, 1});
    else ++it->second;
  }
  std::vector<int32_t> cnt;
  std::vector<Lin> cs;
  cs.reserve(10);
  for (const RunChoice& ch : choices) {
    // The rest: every vector, minus one copy of the running one.
    auto rest_groups = groups;
    if (ch.var < 0)
      for (auto& e : rest_groups)
        if (e.first == S.gens[ch.gen].second) --e.second;
    const SumGrid sums = grouped_subset_sums(rest_groups, cnt);
    const int free_vars = S.nv - (ch.var >= 0 ? 1 : 0);
    for (int mask = 0; mask < (1 << free_vars); ++mask) {
      int64_t val[2] = {0, 0};
      for (int j = 0, bit = 0; j < S.nv; ++j)
        if (j != ch.var) val[j] = (mask >> bit++) & 1;
      i128 cst[8], ks[8];
      for (int i = 0; i < 8; ++i) {
        cst[i] = S.c[i];
        for (int j = 0; j < S.nv; ++j)
          if (j != ch.var) cst[i] += static_cast<i128>(S.e[i][j]) * val[j];
        if (ch.var >= 0) ks[i] = S.e[i][ch.var];
        else ks[i] = S.axis[i] >= 0 ? S.sign[i] * comp(S.gens[ch.gen].second, S.axis[i]) : 0;
      }
      const auto cell = meeting_cell(S, sums, cst, ks, cs);
      if (!cell) continue;
      if (want) {
        std::vector<Vec2> rest;
        std::vector<size_t> rest_idx;
        for (size_t g = 0; g < S.gens.size(); ++g)
          if (ch.var >= 0 || g != ch.gen) rest.push_back(S.gens[g].second), rest_idx.push_back(g);
        recover_witness(S, ch, rest, rest_idx, val, cell->first, cell->second, want);
      }
      return true;
    }
  }
  return false;
}

}  // namespace gridlock
