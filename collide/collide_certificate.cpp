// The writer of collide's NO certificates (collide/collide_certificate.hpp).
#include "collide/collide_certificate.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "collide/internal/collide_pairs.hpp"
#include "collide/internal/pair_system.hpp"
#include "collide/internal/zonotope.hpp"
#include "collide/single_coupling.hpp"

namespace gridlock {

using namespace pairs;

namespace {

using Lambda = std::array<i128, 8>;  // multipliers of the pair system's rows (PairSystem order)

i128 pos(i128 v) { return v > 0 ? v : 0; }

// The maximum over the cube of sum_i lam_i row_i: constant, plus the
// positive parts of the own progresses' and every other coupling's
// coefficients.
i128 combined_max(const PairSystem& S, const Lambda& lam) {
  i128 c = 0, e[2] = {0, 0};
  for (int i = 0; i < 8; ++i) c += lam[i] * S.c[i], e[0] += lam[i] * S.e[i][0], e[1] += lam[i] * S.e[i][1];
  i128 m = c + pos(e[0]) + pos(e[1]);
  for (const auto& [q, w] : S.gens) {
    i128 g = 0;
    for (int i = 0; i < 8; ++i)
      if (S.axis[i] >= 0) g += lam[i] * S.sign[i] * comp(w, S.axis[i]);
    m += pos(g);
  }
  return m;
}

// A constraint of the projected system with the row multipliers it came from.
struct Tagged {
  Lin lin;
  Lambda lam{};
};

// projected_constraints(S, N) with each constraint's multipliers, in its
// order: one per normal u (rows whose Delta' terms add up to u . Delta'),
// the two non-empty rectangle sides, the four widths, the box (none).
std::vector<Tagged> tagged_constraints(const PairSystem& S, const Normals& N) {
  const std::vector<Lin> cons = projected_constraints(S, N);
  std::vector<Tagged> out(cons.size());
  for (size_t k = 0; k < cons.size(); ++k) out[k].lin = cons[k];
  for (size_t k = 0; k < N.u.size(); ++k) {
    const Vec2 u = N.u[k];
    Lambda& l = out[k].lam;
    (u.x > 0 ? l[1] : l[0]) += u.x > 0 ? u.x : -u.x;
    (u.y > 0 ? l[3] : l[2]) += u.y > 0 ? u.y : -u.y;
  }
  const size_t r = N.u.size();
  out[r].lam[0] = out[r].lam[1] = 1;
  out[r + 1].lam[2] = out[r + 1].lam[3] = 1;
  for (int i = 4; i < 8; ++i) out[r + 2 + static_cast<size_t>(i - 4)].lam[static_cast<size_t>(i)] = 1;
  return out;
}

// x * P + y * M (x, y > 0), divided by the gcd of everything.
Tagged combine(const Tagged& P, i128 x, const Tagged& M, i128 y) {
  Tagged t;
  t.lin.a[0] = x * P.lin.a[0] + y * M.lin.a[0];
  t.lin.a[1] = x * P.lin.a[1] + y * M.lin.a[1];
  t.lin.c = x * P.lin.c + y * M.lin.c;
  t.lin.strict = P.lin.strict || M.lin.strict;
  i128 g = gcd128(gcd128(t.lin.a[0], t.lin.a[1]), t.lin.c);
  for (int i = 0; i < 8; ++i) t.lam[i] = x * P.lam[i] + y * M.lam[i], g = gcd128(g, t.lam[i]);
  if (g > 1) {
    t.lin.a[0] /= g, t.lin.a[1] /= g, t.lin.c /= g;
    for (i128& v : t.lam) v /= g;
  }
  return t;
}

// Fourier-Motzkin on v1, multipliers carried along.
std::vector<Tagged> eliminate_tagged(const std::vector<Tagged>& in) {
  std::vector<Tagged> out;
  for (const Tagged& t : in)
    if (t.lin.a[1] == 0) out.push_back(t);
  for (const Tagged& P : in)
    if (P.lin.a[1] > 0)
      for (const Tagged& M : in)
        if (M.lin.a[1] < 0) out.push_back(combine(P, -M.lin.a[1], M, P.lin.a[1]));
  return out;
}

// A contradiction among constraints in v0 alone: a constant one, or the
// highest lower bound against the lowest upper bound.
std::optional<Lambda> contradiction(const std::vector<Tagged>& cons) {
  const Tagged *lo = nullptr, *hi = nullptr;
  for (const Tagged& t : cons) {
    const Lin& L = t.lin;
    if (L.a[0] == 0) {
      if (L.c < 0 || (L.c == 0 && L.strict)) return t.lam;
    } else if (L.a[0] > 0) {  // v0 > -c / a
      const i128 cmp = lo ? -L.c * lo->lin.a[0] - -lo->lin.c * L.a[0] : 1;
      if (cmp > 0 || (cmp == 0 && L.strict)) lo = &t;
    } else {  // v0 < c / -a
      const i128 cmp = hi ? L.c * -hi->lin.a[0] - hi->lin.c * -L.a[0] : -1;
      if (cmp < 0 || (cmp == 0 && L.strict)) hi = &t;
    }
  }
  if (!lo || !hi) return std::nullopt;
  const Tagged t = combine(*lo, -hi->lin.a[0], *hi, lo->lin.a[0]);
  if (t.lin.c < 0 || (t.lin.c == 0 && t.lin.strict)) return t.lam;
  return std::nullopt;
}

// The multipliers of an r line, in the certificate's order of the forms
// (A.xhi - B.xlo, B.xhi - A.xlo, A.yhi - B.ylo, B.yhi - A.ylo, widths A.x,
// B.x, A.y, B.y); nullopt when one form alone rules the pair out.
std::optional<std::array<int64_t, 8>> pair_multipliers(const RegionForm& A, const RegionForm& B, const PathNets& nets) {
  const PairSystem S = build_system(A, B, nets);
  for (size_t i = 0; i < 8; ++i) {
    Lambda unit{};
    unit[i] = 1;
    if (combined_max(S, unit) <= 0) return std::nullopt;
  }
  const Normals N = normals_of(S.gens);
  const std::vector<Tagged> cons = tagged_constraints(S, N);
  const std::optional<Lambda> lam = contradiction(S.nv == 2 ? eliminate_tagged(cons) : cons);
  if (!lam || combined_max(S, *lam) > 0)
    throw std::logic_error("collide certificate: no multipliers for a pair the test found apart");
  static constexpr int kOrder[8] = {0, 1, 2, 3, 4, 6, 5, 7};  // PairSystem rows: widths A.x, A.y, B.x, B.y
  std::array<int64_t, 8> out{};
  for (int i = 0; i < 8; ++i) {
    const i128 v = (*lam)[kOrder[i]];
    if (v < 0 || v > INT64_MAX) throw std::logic_error("collide certificate: a multiplier out of range");
    out[i] = static_cast<int64_t>(v);
  }
  return out;
}

// A region as the certificate names it: "x,y" or "+NAME".
std::string region_word(const Instance& inst, const Regions& regions, uint32_t r) {
  const RegionShape& s = regions.shapes[r];
  if (s.kind != RegionKind::Node) return "+" + inst.ops()[s.id].name;
  const Vec2 c = inst.cells()[s.id];
  return std::to_string(c.x) + "," + std::to_string(c.y);
}

// The p and couplings lines (docs/certificates.md, "Format").
std::string header(const Instance& inst, const CollideCertificate& c) {
  const std::string kind = c.one_axis         ? " one-axis"
                           : c.kept_axis == 0 ? " kept-order x"
                           : c.kept_axis == 1 ? " kept-order y"
                           : c.kept_axis == 2 ? " kept-order separated"
                           : c.kept_axis == 3 ? " kept-order slabs"
                                              : "";
  return "p gridlock-collide-no-certificate 1 continuous" + kind + "\n" + couplings_line(inst);
}

}  // namespace

CollideCertificate collide_no_certificate(const Instance& inst, const Deadline* deadline, bool partial,
                                          const std::function<void(uint64_t, uint64_t)>& on_source, bool every_pair) {
  CollideCertificate out;
  const FaceNets faces = FaceNets::build(inst);
  if (std::ranges::any_of(faces.coupling_breaks_cycle, [](char b) { return b != 0; })) {
    out.why_none = "a coupling breaks a cycle: running it alone collides";
    return out;
  }
  const SpanningTree tree = SpanningTree::build(inst);
  const Regions regions = Regions::build(inst);
  const std::vector<RegionForm> forms = region_forms(inst, regions);
  std::string body;
  auto on_apart = [&](uint32_t a, uint32_t b, const PathNets& nets) {
    const auto lam = pair_multipliers(forms[a], forms[b], nets);
    if (!lam) return;
    ++out.lines;
    body += "r " + region_word(inst, regions, a) + " " + region_word(inst, regions, b);
    for (int64_t v : *lam) body += " " + std::to_string(v);
    body += "\n";
  };
  // One axis: only the row groups' pairs (the first collision is in one).
  std::optional<std::vector<std::pair<uint32_t, uint32_t>>> groups;
  if (!every_pair) groups = one_axis_group_pairs(inst, regions);
  out.one_axis = groups.has_value();
  // One coupling whose faces keep their order on one axis: only the pairs
  // the fixed-axis sweep tests (if none overlaps, nothing does).
  if (!every_pair && !groups && inst.couplings().size() == 1) {
    std::optional<KeptOrderPairs> kept = single_coupling_kept_order_pairs(inst, tree, regions, deadline);
    if (!kept && (kept = single_coupling_slab_pairs(inst, tree, regions, deadline))) {  // cut over time slabs
      std::ranges::sort(kept->pairs);  // a pair met in several slabs is listed once
      kept->pairs.erase(std::unique(kept->pairs.begin(), kept->pairs.end()), kept->pairs.end());
    }
    if (kept) {
      out.kept_axis = kept->axis;
      groups = std::move(kept->pairs);
    }
  }
  PairwiseStats stats;
  const std::optional<PairCollision> hit = groups ? listed_pairs_collision(inst, tree, regions, TimeModel::Continuous,
                                                                           *groups, &stats, deadline, on_apart)
                                                  : pairwise_collision(inst, tree, regions, TimeModel::Continuous,
                                                                       &stats, deadline, ZonotopeTest::Incremental,
                                                                       on_source, on_apart);
  out.pairs = stats.pairs;
  if (hit) {
    out.why_none = region_label(inst, regions, hit->a) + " and " + region_label(inst, regions, hit->b) +
                   " can collide in continuous time";
    out.meet_a = hit->a, out.meet_b = hit->b;
    if (partial) out.text = header(inst, out) + body;
    return out;
  }
  if (on_source) on_source(inst.num_nodes(), inst.num_nodes());
  out.text = header(inst, out) + body;
  return out;
}

}  // namespace gridlock
