// Reading a NO certificate (docs/certificates.md, "Format"): lines of
// words, '#'-free; 'c' lines are comments. Names are resolved against the
// instance here, so everything after works on ids.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "lattice/instance.hpp"
#include "lattice/motion.hpp"

namespace gridlock {

using OrderLiteral = std::pair<CouplingId, CouplingId>;  // (a, b): "a before b"

struct CertificateLemma {
  size_t line = 0;
  bool cycle = false;  // 'o': no total order has all of `lits`; 'l', 'x': one of `lits` holds
  std::vector<OrderLiteral> lits;
  // 'x' (kind pairs): the step of `runner` makes regions region_a and
  // region_b (lattice/motion.hpp numbering) collide whenever every literal is false.
  CouplingId runner = kNone;
  uint32_t region_a = kNone, region_b = kNone;
};

struct CertificateText {
  std::string model;  // discrete | continuous
  std::string kind;   // breaker | gaps | pairs | final-gap | final-cycle | bounds
  size_t kind_line = 0;
  CouplingId breaker = kNone;            // breaker
  std::vector<NodeId> nodes;             // breaker, final-cycle: a closed walk; final-gap: the two ends
  std::vector<CertificateLemma> lemmas;  // gaps, pairs
  // bounds: the lines after the kind line, as words (read by bounds_proof.cpp)
  std::vector<std::pair<size_t, std::vector<std::string>>> body;
};

// Parses text against inst. Returns the reason on failure ("line N: ...").
std::optional<std::string> read_certificate(const Instance& inst, std::string_view text, CertificateText& out);

// A coupling by name, a node by its cell ("x,y"), and a region as the
// certificate writes it ("x,y": the node in that cell; "+NAME": the region
// operation NAME inserts or grows): the reason if there is none.
std::optional<std::string> read_coupling(const Instance& inst, std::string_view w, CouplingId& out);
std::optional<std::string> read_cell(const Instance& inst, std::string_view w, NodeId& out);
std::optional<std::string> read_region(const Instance& inst, const Regions& regions, std::string_view w, uint32_t& out);

// The blank-separated words of one line, and a whole word as an integer.
std::vector<std::string_view> certificate_words(std::string_view line);
bool certificate_int(std::string_view s, int64_t& v);

// Calls f(line number, words) for every line that is not empty and not a
// comment ('c'), in order; stops at and returns the first reason f gives.
using CertificateLineFn = std::function<std::optional<std::string>(size_t, const std::vector<std::string_view>&)>;
std::optional<std::string> for_each_certificate_line(std::string_view text, const CertificateLineFn& f);

// The words of a "couplings COUNT DIGEST" line against inst: the reason if
// they are malformed or name another instance.
std::optional<std::string> check_couplings_line(const Instance& inst, const std::vector<std::string_view>& w);

// FNV-1a (64 bits) of the coupling names in instance order, each followed
// by '\n' (the "couplings" line).
uint64_t certificate_digest(const Instance& inst);

}  // namespace gridlock
