#include "certify/internal/certificate_text.hpp"

#include "lattice/motion.hpp"

#include <charconv>
#include <cstdio>

namespace gridlock {

std::vector<std::string_view> certificate_words(std::string_view line) {
  std::vector<std::string_view> w;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) w.push_back(line.substr(start, i - start));
  }
  return w;
}

bool certificate_int(std::string_view s, int64_t& v) {
  auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return ec == std::errc() && p == s.data() + s.size();
}

std::optional<std::string> for_each_certificate_line(std::string_view text, const CertificateLineFn& f) {
  size_t line = 0;
  for (size_t pos = 0; pos < text.size();) {
    const size_t end = std::min(text.find('\n', pos), text.size());
    const std::vector<std::string_view> w = certificate_words(text.substr(pos, end - pos));
    pos = end + 1;
    ++line;
    if (w.empty() || w[0] == "c" || w[0].front() == '#') continue;  // comments, as in .grid files
    if (auto e = f(line, w)) return e;
  }
  return std::nullopt;
}

namespace {

// "x,y" -> the node in that cell.
std::optional<std::string> cell_node(const Instance& inst, std::string_view w, NodeId& out) {
  const size_t comma = w.find(',');
  Vec2 c{};
  if (comma == std::string_view::npos || !certificate_int(w.substr(0, comma), c.x) ||
      !certificate_int(w.substr(comma + 1), c.y))
    return "'" + std::string(w) + "' is not a cell x,y";
  out = inst.node_at(c);
  if (out == kNone) return "no node in cell " + std::string(w);
  return std::nullopt;
}

std::optional<std::string> coupling(const Instance& inst, std::string_view w, CouplingId& out) {
  out = inst.find_coupling(std::string(w));
  if (out == kNone) return "unknown coupling '" + std::string(w) + "'";
  return std::nullopt;
}

// "a<b" -> (a, b).
std::optional<std::string> literal(const Instance& inst, std::string_view w, OrderLiteral& out) {
  const size_t lt = w.find('<');
  if (lt == std::string_view::npos) return "'" + std::string(w) + "' is not an order literal a<b";
  if (auto e = coupling(inst, w.substr(0, lt), out.first)) return e;
  if (auto e = coupling(inst, w.substr(lt + 1), out.second)) return e;
  if (out.first == out.second) return "'" + std::string(w) + "' orders a coupling before itself";
  return std::nullopt;
}

// "x,y" -> that node's region; "+NAME" -> the region operation NAME inserts or grows.
std::optional<std::string> region(const Instance& inst, const Regions& regions, std::string_view w, uint32_t& out) {
  if (w.empty() || w[0] != '+') {
    NodeId v = kNone;
    if (auto e = cell_node(inst, w, v)) return e;
    out = v;  // regions 0..n-1 are the nodes
    return std::nullopt;
  }
  const OpId k = inst.find_op(std::string(w.substr(1)));
  if (k == kNone) return "unknown operation '" + std::string(w.substr(1)) + "'";
  out = regions.region_of_op[k];
  if (out == kNone) return "operation '" + std::string(w.substr(1)) + "' inserts or grows no region";
  return std::nullopt;
}

std::string at(size_t line, const std::string& what) { return "line " + std::to_string(line) + ": " + what; }

// The "p" and "couplings" lines.
std::optional<std::string> header_line(const Instance& inst, const std::vector<std::string_view>& w, size_t line,
                                       CertificateText& out) {
  if (w[0] == "p") {
    if (!out.model.empty()) return at(line, "a second p line");
    if (w.size() != 4 || w[1] != "gridlock-no-certificate" || w[2] != "1")
      return at(line, "expected 'p gridlock-no-certificate 1 MODEL'");
    if (w[3] != "discrete" && w[3] != "continuous") return at(line, "model must be discrete or continuous");
    out.model = std::string(w[3]);
    return std::nullopt;
  }
  if (auto e = check_couplings_line(inst, w)) return at(line, *e);
  return std::nullopt;
}

std::optional<std::string> lemma_line(const Instance& inst, const Regions& regions,
                                      const std::vector<std::string_view>& w, size_t line, CertificateText& out) {
  if (out.kind != "gaps" && out.kind != "pairs") return at(line, "lemma line outside a gaps or pairs proof");
  CertificateLemma lem;
  lem.line = line;
  lem.cycle = w[0] == "o";
  size_t first = 1;
  if (w[0] == "x") {
    if (out.kind != "pairs") return at(line, "an x line outside a pairs proof");
    if (w.size() < 4) return at(line, "expected 'x REGION REGION COUPLING LITERALS'");
    if (auto e = region(inst, regions, w[1], lem.region_a)) return at(line, *e);
    if (auto e = region(inst, regions, w[2], lem.region_b)) return at(line, *e);
    if (lem.region_a == lem.region_b) return at(line, "a region paired with itself");
    if (auto e = coupling(inst, w[3], lem.runner)) return at(line, *e);
    first = 4;
  }
  for (size_t i = first; i < w.size(); ++i) {
    OrderLiteral l;
    if (auto e = literal(inst, w[i], l)) return at(line, *e);
    lem.lits.push_back(l);
  }
  out.lemmas.push_back(std::move(lem));
  return std::nullopt;
}

std::optional<std::string> evidence_line(const Instance& inst, const std::vector<std::string_view>& w, size_t line,
                                         CertificateText& out) {
  if (out.model.empty()) return at(line, "evidence before the p line");
  if (!out.kind.empty()) return at(line, "a second kind of evidence ('" + std::string(w[0]) + "')");
  out.kind = std::string(w[0]);
  out.kind_line = line;
  size_t first = 1;
  if (out.kind == "breaker") {
    if (w.size() < 2) return at(line, "breaker needs a coupling");
    if (auto e = coupling(inst, w[1], out.breaker)) return at(line, *e);
    first = 2;
  }
  for (size_t i = first; i < w.size(); ++i) {
    NodeId v = kNone;
    if (auto e = cell_node(inst, w[i], v)) return at(line, *e);
    out.nodes.push_back(v);
  }
  if ((out.kind == "gaps" || out.kind == "pairs" || out.kind == "bounds") && !out.nodes.empty())
    return at(line, out.kind + " takes no cells");
  if (out.kind == "final-gap" && out.nodes.size() != 2) return at(line, "final-gap takes two cells");
  return std::nullopt;
}

}  // namespace

std::optional<std::string> read_coupling(const Instance& inst, std::string_view w, CouplingId& out) {
  return coupling(inst, w, out);
}

std::optional<std::string> read_cell(const Instance& inst, std::string_view w, NodeId& out) {
  return cell_node(inst, w, out);
}

std::optional<std::string> read_region(const Instance& inst, const Regions& regions, std::string_view w,
                                       uint32_t& out) {
  return region(inst, regions, w, out);
}

std::optional<std::string> check_couplings_line(const Instance& inst, const std::vector<std::string_view>& w) {
  int64_t k = 0;
  if (w.size() != 3 || !certificate_int(w[1], k)) return std::string("expected 'couplings COUNT DIGEST'");
  char digest[17];
  std::snprintf(digest, sizeof digest, "%016llx", static_cast<unsigned long long>(certificate_digest(inst)));
  if (k != static_cast<int64_t>(inst.couplings().size()) || w[2] != digest)
    return "certificate for another instance: its couplings are " + std::to_string(k) + " with digest " +
           std::string(w[2]) + ", this instance has " + std::to_string(inst.couplings().size()) + " with digest " +
           digest;
  return std::nullopt;
}

uint64_t certificate_digest(const Instance& inst) {
  uint64_t h = 14695981039346656037ull;
  for (const Coupling& c : inst.couplings()) {
    for (char ch : c.name + "\n") h = (h ^ static_cast<unsigned char>(ch)) * 1099511628211ull;
  }
  return h;
}

std::optional<std::string> read_certificate(const Instance& inst, std::string_view text, CertificateText& out) {
  out = CertificateText{};
  bool digest_seen = false;
  Regions regions;  // built at the first lemma line
  auto one = [&](size_t line, const std::vector<std::string_view>& w) -> std::optional<std::string> {
    if (w[0] == "p" || w[0] == "couplings") {
      digest_seen |= w[0] == "couplings";
      return header_line(inst, w, line, out);
    }
    if (out.kind == "bounds" && w[0].size() == 1 &&
        std::string_view("asietlgfw").find(w[0][0]) != std::string_view::npos) {
      out.body.emplace_back(line, std::vector<std::string>(w.begin(), w.end()));
      return std::nullopt;
    }
    if (w[0] == "o" || w[0] == "l" || w[0] == "x") {
      if (regions.size() == 0) regions = Regions::build(inst);
      return lemma_line(inst, regions, w, line, out);
    }
    if (w[0] == "breaker" || w[0] == "gaps" || w[0] == "pairs" || w[0] == "final-gap" || w[0] == "final-cycle" ||
        w[0] == "bounds")
      return evidence_line(inst, w, line, out);
    return at(line, "unknown line kind '" + std::string(w[0]) + "'");
  };
  if (auto e = for_each_certificate_line(text, one)) return e;
  if (out.model.empty()) return std::string("no 'p gridlock-no-certificate 1 MODEL' line");
  if (!digest_seen) return std::string("no 'couplings COUNT DIGEST' line");
  if (out.kind.empty()) return std::string("no evidence (breaker, gaps, pairs, final-gap, final-cycle or bounds)");
  return std::nullopt;
}

}  // namespace gridlock
