// Certificates of gridlock collide's NO (collide/collide_certificate.hpp,
// checked by certify/internal/collide_proof.hpp) on seeded random instances:
// every NO of the continuous model gets a certificate the checker accepts
// (in both models), discrete-only NOs say why they have none, mutated
// certificates are refused, and no YES instance gets one accepted.
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "bench/bench_families.hpp"
#include "certify/certify.hpp"
#include "certify/internal/collide_proof.hpp"
#include "certify/internal/geometry.hpp"
#include "collide/adversarial.hpp"
#include "collide/collide.hpp"
#include "collide/collide_certificate.hpp"
#include "collide/internal/collide_pairs.hpp"
#include "collide/single_coupling.hpp"
#include "common/random.hpp"
#include "lattice/motion.hpp"
#include "lattice/random_instance.hpp"
#include "support/instance_io.hpp"
#include "support/reference_collide.hpp"
#include "support/test_scale.hpp"

namespace gridlock {
namespace {

RandomInstanceParams cert_params(Rng& rng) {
  RandomInstanceParams p;
  if (rng.below(2) == 0) {  // collide's random twin test's larger couplings: continuous-only collisions
    p.nodes = 2 + static_cast<uint32_t>(rng.below(13));
    p.ops = 1 + static_cast<uint32_t>(rng.below(10));
    p.max_coupling = 4;
    p.extra_edge_percent = rng.below(3) == 0 ? 40 : 0;
    p.spread = static_cast<uint32_t>(rng.below(3));
    return p;
  }
  p.nodes = 4 + static_cast<uint32_t>(rng.below(16));
  p.ops = 2 + static_cast<uint32_t>(rng.below(12));
  p.max_coupling = 2 + static_cast<uint32_t>(rng.below(5));
  if (rng.below(2) == 0) p.couplings = 1 + static_cast<uint32_t>(rng.below(3)), p.max_coupling = 8;
  p.extra_edge_percent = rng.below(3) == 0 ? 40 : 0;
  p.horizontal_only = rng.below(6) == 0;
  p.path_shape = rng.below(5) == 0;
  p.spread = static_cast<uint32_t>(rng.below(3));
  return p;
}

// A path that leaves (0,0) to the left, climbs, crosses over and comes down
// to (bx, by) on its right, with expansions or contractions on every other
// edge of its first two legs, in one or two couplings: the far end moves diagonally past (0,0),
// where often no single form rules a pair out and an r line is needed.
std::string curl_instance(Rng& rng) {
  const int64_t left = 2 + static_cast<int64_t>(rng.below(4)), height = 2 + static_cast<int64_t>(rng.below(5));
  const int64_t bx = 1 + static_cast<int64_t>(rng.below(3)), by = rng.below(4) == 0 ? 1 : 0;
  std::vector<std::pair<int64_t, int64_t>> cells{{0, 0}};
  auto walk = [&](int64_t dx, int64_t dy, int64_t steps) {
    for (int64_t i = 0; i < steps; ++i) cells.push_back({cells.back().first + dx, cells.back().second + dy});
  };
  walk(-1, 0, left), walk(0, 1, height), walk(1, 0, left + bx), walk(0, -1, height - by);
  std::string text, ops, q[2] = {"q Q", "q R"};
  size_t n_ops = 0;
  const bool two = rng.below(2) == 0;
  auto xy = [](std::pair<int64_t, int64_t> c) { return std::to_string(c.first) + " " + std::to_string(c.second); };
  for (size_t i = 0; i + 1 < cells.size(); ++i) {
    const auto [x, y] = cells[i];
    const auto [x2, y2] = cells[i + 1];
    text += "e " + xy(cells[i]) + " " + xy(cells[i + 1]) + "\n";
    if (i % 2 == 1 || i >= static_cast<size_t>(left + height) || rng.below(4) == 0) continue;
    const std::string dir = x2 > x ? "+x" : x2 < x ? "-x" : y2 > y ? "+y" : "-y";
    const std::string name = "o" + std::to_string(n_ops++);
    ops += "o " + name + (rng.below(8) == 0 ? " contract " : " expand ");
    ops += xy(cells[i]) + " " + dir + "\n";
    q[two ? rng.below(2) : 0] += " " + name;
  }
  if (n_ops == 0) return "";
  std::string nodes;
  for (const auto& c : cells) nodes += "n " + xy(c) + "\n";
  const bool second = q[1].size() > 3, first = q[0].size() > 3;
  return "p grid " + std::to_string(cells.size()) + " " + std::to_string(cells.size() - 1) + " " +
         std::to_string(n_ops) + " " + std::to_string(int{first} + int{second}) + "\n" + nodes + text + ops +
         (first ? q[0] + "\n" : "") + (second ? q[1] + "\n" : "");
}

// Instance i of a run: a curl (curl_instance) unless i is a multiple of
// plain_every, else a random instance (cert_params).
Instance test_instance(int i, int plain_every, uint64_t seed, Rng& rng) {
  const std::string curl = i % plain_every ? curl_instance(rng) : "";
  return curl.empty() ? random_instance(cert_params(rng), seed) : test::parse_instance(curl);
}

std::string where(uint64_t seed) {
  return "seed " + std::to_string(seed) + "; replay with GRIDLOCK_TEST_SEED=" + std::to_string(seed);
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  size_t pos = 0;
  while (pos < text.size()) {
    const size_t end = text.find('\n', pos);
    out.push_back(text.substr(pos, end - pos));
    pos = end + 1;
  }
  return out;
}

std::string join(const std::vector<std::string>& lines) {
  std::string s;
  for (const std::string& l : lines) s += l + "\n";
  return s;
}

std::vector<std::string> words_of(const std::string& line) {
  std::vector<std::string> words;
  for (size_t p = 0; p < line.size();) {
    const size_t e = std::min(line.find(' ', p), line.size());
    words.push_back(line.substr(p, e - p));
    p = e + 1;
  }
  return words;
}

bool blames_line(const CertifyResult& r, size_t line) {
  return r.reason.rfind("line " + std::to_string(line) + ":", 0) == 0;
}

// Every r line with its multipliers replaced by one unit vector is refused
// at that line (the writer writes a line only when no single form rules
// the pair out); in a whole certificate, dropping the line is refused too.
void expect_mutations_refused(const Instance& inst, const std::string& text, bool whole, Rng& rng,
                              const std::string& at) {
  const std::vector<std::string> lines = lines_of(text);
  for (size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].rfind("r ", 0) != 0) continue;
    const std::vector<std::string> words = words_of(lines[i]);
    ASSERT_EQ(words.size(), 11u) << at;
    std::vector<std::string> changed = lines;
    std::string unit = "r " + words[1] + " " + words[2];
    const size_t one = rng.below(8);
    for (size_t k = 0; k < 8; ++k) unit += k == one ? " 1" : " 0";
    changed[i] = unit;
    const CertifyResult r = certify(inst, join(changed), "continuous");
    EXPECT_TRUE(!r.proved && blames_line(r, i + 1)) << at << ": " << unit << ": " << r.reason;
    if (!whole) continue;
    changed[i] = "c dropped";
    EXPECT_FALSE(certify(inst, join(changed), "continuous").proved) << at << ": without " << lines[i];
  }
}

// A region as certificates name it.
std::string region_word(const Instance& inst, uint32_t r) {
  const Regions regions = Regions::build(inst);
  const RegionShape& s = regions.shapes[r];
  if (s.kind != RegionKind::Node) return "+" + inst.ops()[s.id].name;
  return std::to_string(inst.cells()[s.id].x) + "," + std::to_string(inst.cells()[s.id].y);
}

struct Counts {
  int instances = 0, no = 0, discrete_only_no = 0, lines = 0, with_lines = 0, foreign_refused = 0, brute = 0;
};

// A YES instance (continuous): another instance's certificate and a bare
// header are refused.
void expect_foreign_refused(const Instance& inst, const std::string& other, Counts& n, const std::string& at) {
  if (other.empty()) return;
  EXPECT_FALSE(certify(inst, other, "continuous").proved) << at;
  const std::string bare = "p gridlock-collide-no-certificate 1 continuous\n" + lines_of(other).at(1) + "\n";
  EXPECT_FALSE(certify(inst, bare, "discrete").proved) << at;
  ++n.foreign_refused;
}

TEST(CertifyCollide, EveryNoCertifiedAndMutationsRefused) {
  Counts n;
  std::string last_no;  // a certificate of an earlier NO instance, tried on the YES ones
  for (int i = 0; i < test::scaled(6000); ++i) {
    const uint64_t seed = test::base_seed(31000) + static_cast<uint64_t>(i);
    Rng rng(seed * 6151 + 5);
    const Instance inst = test_instance(i, 4, seed, rng);
    const std::string at = where(seed);
    ++n.instances;
    const bool cont = find_collision(inst, TimeModel::Continuous).collides;
    const bool disc = find_collision(inst, TimeModel::Discrete).collides;
    const CollideCertificate cert = collide_no_certificate(inst);
    if (cont) {
      ASSERT_TRUE(cert.text.empty()) << at;
      if (!disc) {
        ++n.discrete_only_no;
        EXPECT_NE(cert.why_none.find("continuous"), std::string::npos) << at;
      }
      expect_foreign_refused(inst, last_no, n, at);
      continue;
    }
    ASSERT_FALSE(disc) << at << ": continuous NO but discrete YES";
    if (inst.couplings().size() <= 4) {
      ASSERT_FALSE(test::brute_continuous(inst).collides) << at << ": the brute-force twin finds a collision";
      ++n.brute;
    }
    ++n.no;
    ASSERT_FALSE(cert.text.empty()) << at << ": " << cert.why_none;
    for (const char* model : {"continuous", "discrete"}) {
      const CertifyResult r = certify(inst, cert.text, model);
      ASSERT_TRUE(r.proved) << at << ": " << r.reason << "\n" << cert.text;
      EXPECT_EQ(r.inequalities, cert.lines) << at;
    }
    n.lines += static_cast<int>(cert.lines);
    n.with_lines += cert.lines > 0;
    expect_mutations_refused(inst, cert.text, true, rng, at);
    last_no = cert.text;
    if (::testing::Test::HasFailure()) return;
  }
  std::cout << "[certify-collide] " << n.instances << " instances: " << n.no << " NO certified (" << n.brute
            << " confirmed by the brute-force twin, " << n.with_lines << " with r lines, " << n.lines << " lines), "
            << n.discrete_only_no << " discrete-only NO without a certificate, " << n.foreign_refused
            << " YES refused foreign certificates\n";
  EXPECT_GT(n.no, test::scaled(1000));
  EXPECT_GT(n.with_lines, test::scaled(15));
}

// Progress: the every-pair writer reports its traversal's source nodes
// (growing, the last with done == total), and a listener changes nothing
// in the text.
TEST(CertifyCollide, WriterReportsProgress) {
  const Instance inst = test::parse_instance(test::expansion_row_grid(40, 0));
  std::vector<std::pair<uint64_t, uint64_t>> seen;
  const CollideCertificate cert = collide_no_certificate(
      inst, nullptr, false, [&](uint64_t done, uint64_t total) { seen.emplace_back(done, total); }, true);
  ASSERT_FALSE(cert.text.empty()) << cert.why_none;
  EXPECT_EQ(cert.text, collide_no_certificate(inst, nullptr, false, {}, true).text);
  // The one-axis kind (a row: fast) reports its end only.
  std::vector<std::pair<uint64_t, uint64_t>> one_axis;
  const CollideCertificate rows = collide_no_certificate(
      inst, nullptr, false, [&](uint64_t done, uint64_t total) { one_axis.emplace_back(done, total); });
  EXPECT_TRUE(rows.one_axis);
  EXPECT_EQ(one_axis, (std::vector<std::pair<uint64_t, uint64_t>>{{inst.num_nodes(), inst.num_nodes()}}));
  ASSERT_GE(seen.size(), 2u);
  for (size_t i = 0; i < seen.size(); ++i) {
    EXPECT_EQ(seen[i].second, inst.num_nodes());
    EXPECT_LE(seen[i].first, seen[i].second);
    if (i > 0) {
      EXPECT_GE(seen[i].first, seen[i - 1].first);
    }
  }
  EXPECT_EQ(seen.back().first, seen.back().second);
  EXPECT_TRUE(certify(inst, cert.text, "continuous").proved);
}

// YES instances: the lines written for the pairs found apart before the
// meeting pair are each accepted, their unit mutations refused at their
// line, and random multipliers for the meeting pair (which overlaps at some
// progress, so every combination is positive there) always refused at theirs.
TEST(CertifyCollide, LinesOfYesInstancesCheckedOneByOne) {
  int instances = 0, lines = 0, tries = 0;
  for (int i = 0; i < test::scaled(3000); ++i) {
    const uint64_t seed = test::base_seed(61000) + static_cast<uint64_t>(i);
    Rng rng(seed * 4099 + 3);
    const Instance inst = test_instance(i, 2, seed, rng);
    const std::string at = where(seed);
    const CollideCertificate part = collide_no_certificate(inst, nullptr, true);
    if (part.meet_a == kNone) continue;  // NO, or a coupling breaks a cycle
    ASSERT_FALSE(part.text.empty()) << at;
    ++instances;
    lines += static_cast<int>(part.lines);
    const CertifyResult whole = certify(inst, part.text, "continuous");
    ASSERT_FALSE(whole.proved) << at;
    ASSERT_EQ(whole.reason.rfind("line ", 0), std::string::npos) << at << ": a line refused: " << whole.reason;
    EXPECT_EQ(whole.inequalities, part.lines) << at;
    expect_mutations_refused(inst, part.text, false, rng, at);
    const std::string pair = "r " + region_word(inst, part.meet_a) + " " + region_word(inst, part.meet_b);
    const size_t at_line = lines_of(part.text).size() + 1;
    for (int t = 0; t < 20; ++t, ++tries) {
      std::string line = pair;
      for (int k = 0; k < 8; ++k)
        line += " " + std::to_string(k == t % 8 ? 1 + rng.below(9) : rng.below(t < 10 ? 2 : 50));
      const CertifyResult r = certify(inst, part.text + line + "\n", "continuous");
      ASSERT_TRUE(!r.proved && blames_line(r, at_line)) << at << ": " << line << ": " << r.reason;
    }
    if (::testing::Test::HasFailure()) return;
  }
  std::cout << "[certify-collide] " << instances << " YES instances: " << lines << " lines checked one by one, "
            << tries << " multipliers for a meeting pair refused\n";
  EXPECT_GT(tries, test::scaled(10000));
}

// The face bounds the checker's sweep relies on hold at every progress
// vector: each overlap form of a pair at p (random vertices and points of
// the cube, as multiples of 1/8) is at most the bound from the two boxes;
// and the path bounds set a pair apart only when one form really is <= 0
// on the whole cube (its base plus its positive coefficients).
TEST(CertifyCollide, FaceAndPathBoundsHoldEverywhere) {
  int checked = 0, apart = 0;
  for (int i = 0; i < test::scaled(400); ++i) {
    const uint64_t seed = test::base_seed(91000) + static_cast<uint64_t>(i);
    Rng rng(seed * 7 + 1);
    const Instance inst = test_instance(i, 2, seed, rng);
    const CertifyGeometry geo(inst);
    const std::vector<CertifyGeometry::RegionBox> box = geo.region_boxes(geo.displacement_ranges());
    const PathBounds bounds(geo);
    const uint32_t nr = static_cast<uint32_t>(geo.regions().size());
    for (int t = 0; t < 40; ++t) {
      const uint32_t a = static_cast<uint32_t>(rng.below(nr)), b = static_cast<uint32_t>(rng.below(nr));
      if (a == b) continue;
      const std::vector<CouplingForm> forms = geo.region_forms(a, b);
      // PathBounds::apart only when one form is <= 0 on the whole cube.
      if (bounds.apart(a, b)) {
        bool one = false;
        for (const CouplingForm& f : forms) {
          int64_t m = f.base;
          for (auto [q, c] : f.terms) m += std::max<int64_t>(0, c);
          one = one || m <= 0;
        }
        ASSERT_TRUE(one) << where(seed) << ": regions " << a << ", " << b << " set apart by the path bounds alone";
        ++apart;
      }
      // Forms 0..3: A.xhi - B.xlo, B.xhi - A.xlo, A.yhi - B.ylo, B.yhi - A.ylo.
      const int64_t bound[4] = {box[a].hi[1] - box[b].lo[0], box[b].hi[1] - box[a].lo[0], box[a].hi[3] - box[b].lo[2],
                                box[b].hi[3] - box[a].lo[2]};
      std::vector<int64_t> p8(inst.couplings().size());  // progress times 8
      for (int64_t& v : p8)
        v = rng.below(2) == 0 ? 8 * static_cast<int64_t>(rng.below(2)) : static_cast<int64_t>(rng.below(9));
      for (int f = 0; f < 4; ++f) {
        int64_t at8 = 8 * forms[f].base;
        for (auto [q, c] : forms[f].terms) at8 += c * p8[q];
        ASSERT_LE(at8, 8 * bound[f]) << where(seed) << ": regions " << a << ", " << b << ", form " << f;
        ++checked;
      }
    }
  }
  std::cout << "[certify-collide] " << checked << " overlap forms within the face bounds; " << apart
            << " pairs set apart by the path bounds, each with a form <= 0 on the cube\n";
  EXPECT_GT(apart, test::scaled(1000));
}

// One axis, any couplings: the checker's row groups (row_group_pairs_of,
// its own code) are collide's (one_axis_group_pairs), pair for pair; on a
// NO the one-axis certificate is accepted in both models, its r lines are
// among those of the every-pair certificate, and each line dropped, or
// the one-axis p line on an instance whose operations use both axes, is
// refused; on a YES the one-axis p line without lines is refused (some
// group pair can overlap). Horizontal instances, some transposed to
// vertical.
std::set<std::pair<uint32_t, uint32_t>> ordered(const std::vector<std::pair<uint32_t, uint32_t>>& pairs) {
  std::set<std::pair<uint32_t, uint32_t>> out;
  for (auto [a, b] : pairs) out.emplace(std::min(a, b), std::max(a, b));
  return out;
}

std::vector<std::string> r_lines(const std::string& text) {
  std::vector<std::string> out;
  for (const std::string& l : lines_of(text))
    if (l.rfind("r ", 0) == 0) out.push_back(l);
  std::ranges::sort(out);
  return out;
}

std::string with_one_axis(const std::string& text) {
  std::vector<std::string> lines = lines_of(text);
  lines.at(0) += " one-axis";
  return join(lines);
}

TEST(CertifyCollide, OneAxisKindCoversTheRowGroups) {
  int instances = 0, one_axis = 0, no = 0, lines = 0, fewer = 0, two_axes = 0, yes_refused = 0;
  uint64_t group_pairs = 0, all_pairs = 0;
  for (int i = 0; i < test::scaled(3000); ++i) {
    const uint64_t seed = test::base_seed(97000) + static_cast<uint64_t>(i);
    Rng rng(seed * 8191 + 11);
    RandomInstanceParams p = cert_params(rng);
    const bool horizontal = rng.below(8) != 0;
    p.horizontal_only = horizontal;
    if (rng.below(3) == 0)
      p.nodes += static_cast<uint32_t>(rng.below(60)), p.ops += static_cast<uint32_t>(rng.below(30));
    const Instance made = random_instance(p, seed);
    const Instance inst = horizontal && rng.below(2) == 0 ? test::rebuilt(made, true, false) : made;
    const std::string at = where(seed);
    const FaceNets faces = FaceNets::build(inst);
    if (std::ranges::any_of(faces.coupling_breaks_cycle, [](char b) { return b != 0; })) continue;
    ++instances;
    const Regions regions = Regions::build(inst);
    const auto groups = one_axis_group_pairs(inst, regions);
    const std::optional<int> axis = inst.moving_axis();
    ASSERT_EQ(groups.has_value(), axis.has_value()) << at;
    if (axis) {
      const auto mine = ordered(row_group_pairs_of(regions, *axis));
      ASSERT_EQ(mine, ordered(*groups)) << at;
      ++one_axis;
      group_pairs += mine.size();
      all_pairs += regions.size() * (regions.size() - 1) / 2;
    }
    const CollideCertificate cert = collide_no_certificate(inst);
    if (cert.text.empty()) {  // YES: a one-axis certificate without lines is refused
      const std::string bare = "p gridlock-collide-no-certificate 1 continuous one-axis\n" + couplings_line(inst);
      EXPECT_FALSE(certify(inst, bare, "continuous").proved) << at;
      yes_refused += axis.has_value();
      continue;
    }
    ++no;
    const CollideCertificate every = collide_no_certificate(inst, nullptr, false, {}, true);
    ASSERT_FALSE(every.text.empty()) << at;
    ASSERT_FALSE(every.one_axis) << at;
    EXPECT_TRUE(certify(inst, every.text, "continuous").proved) << at;
    if (!axis) {  // both axes: the one-axis p line is refused whatever the lines
      ASSERT_FALSE(cert.one_axis) << at;
      const CertifyResult r = certify(inst, with_one_axis(cert.text), "continuous");
      EXPECT_TRUE(!r.proved && blames_line(r, 1)) << at << ": " << r.reason;
      ++two_axes;
      continue;
    }
    ASSERT_TRUE(cert.one_axis) << at;
    for (const char* model : {"continuous", "discrete"}) {
      const CertifyResult r = certify(inst, cert.text, model);
      ASSERT_TRUE(r.proved) << at << ": " << r.reason << "\n" << cert.text;
      EXPECT_TRUE(r.one_axis) << at;
      EXPECT_EQ(r.axioms, groups->size()) << at;
      EXPECT_EQ(r.inequalities, cert.lines) << at;
    }
    const std::vector<std::string> mine = r_lines(cert.text), all = r_lines(every.text);
    EXPECT_TRUE(std::ranges::includes(all, mine)) << at << ":\n" << cert.text << "every pair:\n" << every.text;
    lines += static_cast<int>(mine.size());
    fewer += mine.size() < all.size();
    expect_mutations_refused(inst, cert.text, true, rng, at);
    if (::testing::Test::HasFailure()) return;
  }
  std::cout << "[certify-collide] one axis: " << instances << " instances (" << one_axis << " on one axis), "
            << group_pairs << " group pairs of " << all_pairs << " pairs; " << no << " NO certified (" << two_axes
            << " on both axes refused the one-axis p line), " << lines << " r lines, " << fewer
            << " certificates with fewer lines than every pair's; " << yes_refused
            << " YES refused a one-axis certificate without lines\n";
  EXPECT_GT(no, test::scaled(300));
  EXPECT_GT(yes_refused, test::scaled(300));
}

// One coupling whose faces keep their order along one axis: the checker's
// sweep pairs (kept_order_pairs_of, its own code) are collide's
// (single_coupling_kept_order_pairs), pair for pair; on a NO the
// kept-order certificate is accepted in both models, its r lines are among
// the every-pair certificate's, each line dropped or weakened is refused,
// and so are the other axis's word where that order changes and the word
// on an instance of several couplings; on a YES a bare kept-order
// certificate is refused. Random shapes with every operation in one
// coupling, some transposed.
std::string with_kind(const std::string& text, const std::string& kind) {
  std::vector<std::string> lines = lines_of(text);
  lines.at(0) = "p gridlock-collide-no-certificate 1 continuous" + kind;
  return join(lines);
}

TEST(CertifyCollide, KeptOrderKindCoversTheSweepPairs) {
  int instances = 0, kept = 0, kept_kind = 0, no = 0, lines = 0, other_refused = 0, yes_refused = 0,
      several_refused = 0, y_axis = 0, separated = 0;
  uint64_t sweep_pairs = 0, all_pairs = 0;
  for (int i = 0; i < test::scaled(3000); ++i) {
    const uint64_t seed = test::base_seed(98000) + static_cast<uint64_t>(i);
    Rng rng(seed * 8191 + 13);
    RandomInstanceParams p = cert_params(rng);
    if (rng.below(3) == 0)
      p.nodes += static_cast<uint32_t>(rng.below(60)), p.ops += static_cast<uint32_t>(rng.below(30));
    const Instance made = random_instance(p, seed);
    const std::string at = where(seed);
    const FaceNets faces = FaceNets::build(made);
    if (std::ranges::any_of(faces.coupling_breaks_cycle, [](char b) { return b != 0; })) continue;
    if (made.couplings().size() > 1 && rng.below(4) == 0) {  // several couplings: the word is refused at line 1
      const CollideCertificate c = collide_no_certificate(made);
      if (!c.text.empty()) {
        EXPECT_EQ(c.kept_axis, -1) << at;
        const CertifyResult r = certify(made, with_kind(c.text, " kept-order x"), "continuous");
        EXPECT_TRUE(!r.proved && blames_line(r, 1)) << at << ": " << r.reason;
        ++several_refused;
      }
    }
    const Instance inst = test::rebuilt(made, rng.below(2) == 0, true);
    if (std::ranges::any_of(FaceNets::build(inst).coupling_breaks_cycle, [](char b) { return b != 0; })) continue;
    ++instances;
    const Regions regions = Regions::build(inst);
    const SpanningTree tree = SpanningTree::build(inst);
    const CertifyGeometry geo(inst);
    const std::optional<FixedAxisAnswer> fixed = single_coupling_fixed_axis(inst, tree, regions);
    const std::optional<KeptOrderPairs> pairs = single_coupling_kept_order_pairs(inst, tree, regions);
    ASSERT_EQ(pairs.has_value(), fixed && !fixed->answer.collides) << at;
    const CollideCertificate cert = collide_no_certificate(inst);
    if (fixed && fixed->answer.collides) {  // YES: a bare kept-order certificate is refused
      const std::string bare = "p gridlock-collide-no-certificate 1 continuous kept-order " +
                               std::string(fixed->axis == 0   ? "x"
                                           : fixed->axis == 1 ? "y"
                                                              : "separated") +
                               "\n" + couplings_line(inst);
      EXPECT_FALSE(certify(inst, bare, "continuous").proved) << at;
      EXPECT_TRUE(cert.text.empty()) << at;
      ++yes_refused;
      continue;
    }
    if (!pairs) {
      if (!cert.text.empty() && !cert.one_axis) {
        EXPECT_TRUE(cert.kept_axis == -1 || cert.kept_axis == 3) << at;  // every pair, or over time slabs
      }
      continue;
    }
    ++kept;
    std::vector<std::pair<uint32_t, uint32_t>> mine;
    if (const auto e = kept_order_pairs_of(inst, geo, pairs->axis, mine)) FAIL() << at << ": " << *e;
    ASSERT_EQ(ordered(mine), ordered(pairs->pairs)) << at;
    ASSERT_EQ(mine.size(), pairs->pairs.size()) << at;
    sweep_pairs += mine.size();
    all_pairs += regions.size() * (regions.size() - 1) / 2;
    ASSERT_FALSE(cert.text.empty()) << at << ": " << cert.why_none;
    ++no;
    if (cert.one_axis) continue;  // every operation along one axis: that kind comes first
    ASSERT_EQ(cert.kept_axis, pairs->axis) << at;
    ++kept_kind;
    y_axis += pairs->axis == 1;
    separated += pairs->axis == 2;
    for (const char* model : {"continuous", "discrete"}) {
      const CertifyResult r = certify(inst, cert.text, model);
      ASSERT_TRUE(r.proved) << at << ": " << r.reason << "\n" << cert.text;
      EXPECT_EQ(r.kept_axis, pairs->axis) << at;
      EXPECT_EQ(r.axioms, mine.size()) << at;
      EXPECT_EQ(r.inequalities, cert.lines) << at;
    }
    const CollideCertificate every = collide_no_certificate(inst, nullptr, false, {}, true);
    const std::vector<std::string> ours = r_lines(cert.text), all = r_lines(every.text);
    EXPECT_TRUE(std::ranges::includes(all, ours)) << at << ":\n" << cert.text << "every pair:\n" << every.text;
    lines += static_cast<int>(ours.size());
    // The other axis: refused at line 1 where its order changes.
    const int other = pairs->axis == 2 ? 0 : 1 - pairs->axis;  // separated: x alone does not hold
    std::vector<std::pair<uint32_t, uint32_t>> unused;
    if (kept_order_pairs_of(inst, geo, other, unused)) {
      const CertifyResult r = certify(
          inst, with_kind(cert.text, std::string(" kept-order ") + (other == 0 ? "x" : "y")), "continuous");
      EXPECT_TRUE(!r.proved && blames_line(r, 1)) << at << ": " << r.reason;
      ++other_refused;
    }
    expect_mutations_refused(inst, cert.text, true, rng, at);
    if (::testing::Test::HasFailure()) return;
  }
  std::cout << "[certify-collide] kept order: " << instances << " one-coupling instances, " << kept
            << " NOs with a kept order, " << kept_kind << " of them of the kept-order kind (" << y_axis << " along y, "
            << separated << " separated), " << sweep_pairs << " sweep pairs of " << all_pairs << " pairs; " << no
            << " certified, " << lines << " r lines; " << other_refused << " refused the other axis, " << yes_refused
            << " YES refused a bare certificate, " << several_refused << " of several couplings refused the word\n";
  EXPECT_GT(kept_kind, test::scaled(300));
  EXPECT_GT(yes_refused, test::scaled(100));
  EXPECT_GT(other_refused, test::scaled(50));
  EXPECT_GT(several_refused, test::scaled(50));
  EXPECT_GT(separated, test::scaled(5));
}

// The band sweeps (collide/adversarial.hpp), NO: cut along x - p y (for
// p = 1 the diagonal x - y, else across the commonest motion), each
// certificate is of the separated kind and lists only its groups' pairs;
// certify makes the same cuts (so it finds the same direction from the
// motion, without the moving frame) and accepts it in both models. Each
// p line with a bare couplings line is refused on the hit (YES).
TEST(CertifyCollide, BandSweepsAreCertified) {
  for (uint32_t p : {1u, 2u, 3u})
    for (uint32_t K : {5u, 12u, 30u}) {
      const std::string at = "p " + std::to_string(p) + ", K " + std::to_string(K);
      const Instance inst = band_sweep_instance(K, p);
      const CollideCertificate cert = collide_no_certificate(inst);
      ASSERT_FALSE(cert.text.empty()) << at << ": " << cert.why_none;
      EXPECT_EQ(cert.kept_axis, 2) << at;
      for (const char* model : {"continuous", "discrete"}) {
        const CertifyResult r = certify(inst, cert.text, model);
        EXPECT_TRUE(r.proved) << at << ": " << r.reason;
      }
      const Instance hit = band_sweep_instance(K, p, 3, true);
      ASSERT_TRUE(find_collision(hit, TimeModel::Continuous).collides) << at;
      const std::string bare = lines_of(cert.text).at(0) + "\n" + couplings_line(hit);
      EXPECT_FALSE(certify(hit, bare, "continuous").proved) << at;
    }
}

// The slabs kind (`kept-order slabs`): on random stalactite combs, the
// stalactite combs of bench_families.hpp (plain and own-speed, NO, no cut
// over (0, 1)) and the random one-coupling instances, the checker's own
// slabs, cuts and sweeps meet exactly the pairs collide's do
// (single_coupling_slab_pairs); a NO's certificate of that kind is
// accepted in both models and its mutations refused; a YES refuses a bare
// one (its overlapping pair is among the pairs met); on several couplings
// the word is refused at line 1.
TEST(CertifyCollide, SlabsKindCoversTheSlabPairs) {
  int slab_kind = 0, yes_refused = 0, declined = 0, several_refused = 0;
  uint64_t slab_pairs = 0, all_pairs = 0;
  auto check = [&](const Instance& inst, const std::string& at, Rng& rng) {
    if (std::ranges::any_of(FaceNets::build(inst).coupling_breaks_cycle, [](char b) { return b != 0; })) return;
    const Regions regions = Regions::build(inst);
    const SpanningTree tree = SpanningTree::build(inst);
    const CertifyGeometry geo(inst);
    std::vector<std::pair<uint32_t, uint32_t>> mine;
    const std::optional<std::string> refused = kept_order_pairs_of(inst, geo, 3, mine);
    const std::optional<KeptOrderPairs> pairs = single_coupling_slab_pairs(inst, tree, regions);
    const std::optional<TimeSlabAnswer> slabs = single_coupling_time_slabs(inst, tree, regions, nullptr, 0,
                                                                           true);  // the same slabs, whatever the cost
    if (refused) {  // the slabs decline (or their budget): collide lists no pairs either
      ASSERT_FALSE(pairs) << at << ": " << *refused;
      ++declined;
      return;
    }
    ASSERT_TRUE(slabs) << at;
    if (slabs->answer.collides) {  // YES: collide lists nothing, and a bare certificate is refused
      ASSERT_FALSE(pairs) << at;
      const std::string bare = "p gridlock-collide-no-certificate 1 continuous kept-order slabs\n" +
                               couplings_line(inst);
      EXPECT_FALSE(certify(inst, bare, "continuous").proved) << at;
      ++yes_refused;
      return;
    }
    ASSERT_TRUE(pairs) << at;
    ASSERT_EQ(ordered(mine), ordered(pairs->pairs)) << at;
    const CollideCertificate cert = collide_no_certificate(inst);
    ASSERT_FALSE(cert.text.empty()) << at << ": " << cert.why_none;
    if (cert.one_axis || cert.kept_axis != 3) return;  // a kind tried before the slabs held
    ++slab_kind;
    slab_pairs += ordered(mine).size();
    all_pairs += regions.size() * (regions.size() - 1) / 2;
    for (const char* model : {"continuous", "discrete"}) {
      const CertifyResult r = certify(inst, cert.text, model);
      ASSERT_TRUE(r.proved) << at << ": " << r.reason << "\n" << cert.text;
      EXPECT_EQ(r.kept_axis, 3) << at;
      EXPECT_EQ(r.axioms, ordered(mine).size()) << at;
    }
    expect_mutations_refused(inst, cert.text, true, rng, at);
  };
  for (int64_t L = 1; L <= 40; ++L)
    for (bool own : {false, true}) {
      Rng rng(static_cast<uint64_t>(L) * 2 + own);
      check(bench::stalactite_comb(L, own), "stalactite comb of " + std::to_string(L) + (own ? ", own speeds" : ""),
            rng);
      if (::testing::Test::HasFailure()) return;
    }
  for (int i = 0; i < test::scaled(1500); ++i) {
    const uint64_t seed = test::base_seed(99000) + static_cast<uint64_t>(i);
    const std::string at = where(seed);
    Rng rng(seed * 131 + 7);
    if (i % 3 == 2) {  // a random one-coupling instance (seldom without a cut over (0, 1))
      RandomInstanceParams p = cert_params(rng);
      p.nodes += static_cast<uint32_t>(rng.below(40)), p.ops += static_cast<uint32_t>(rng.below(20));
      const Instance made = random_instance(p, seed);
      if (made.couplings().size() > 1 && rng.below(4) == 0 &&
          std::ranges::none_of(FaceNets::build(made).coupling_breaks_cycle, [](char b) { return b != 0; })) {
        const CollideCertificate c = collide_no_certificate(made);
        if (!c.text.empty()) {
          const CertifyResult r = certify(made, with_kind(c.text, " kept-order slabs"), "continuous");
          EXPECT_TRUE(!r.proved && blames_line(r, 1)) << at << ": " << r.reason;
          ++several_refused;
        }
      }
      check(test::rebuilt(made, rng.below(2) == 0, true), at, rng);
    } else {
      check(bench::random_stalactite_comb(seed), at + " (a random stalactite comb)", rng);
    }
    if (::testing::Test::HasFailure()) return;
  }
  std::cout << "[certify-collide] slabs: " << slab_kind << " NOs certified by the slabs kind (" << slab_pairs
            << " pairs met of " << all_pairs << "), " << yes_refused << " YES refused a bare certificate, " << declined
            << " declined alike, " << several_refused << " of several couplings refused the word\n";
  EXPECT_GT(slab_kind, 60);
  EXPECT_GT(yes_refused, test::scaled(100));
  EXPECT_GT(several_refused, test::scaled(5));
}

}  // namespace
}  // namespace gridlock
