#include "lattice/schedule.hpp"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <numeric>
#include <optional>
#include <sstream>

#include "common/assert.hpp"
#include "common/refused_byte.hpp"

namespace gridlock {

namespace {

bool is_permutation_of_ids(const std::vector<CouplingId>& order) {
  std::vector<char> seen(order.size(), 0);
  for (CouplingId q : order) {
    if (q >= order.size() || seen[q]) return false;
    seen[q] = 1;
  }
  return true;
}

}  // namespace

Schedule schedule_from_order(const std::vector<CouplingId>& order) {
  GRIDLOCK_ASSERT(is_permutation_of_ids(order), "schedule_from_order needs a permutation of all coupling ids");
  Schedule s;
  s.order = order;
  s.start.assign(order.size(), Rational(0));
  for (size_t i = 0; i < order.size(); ++i) s.start[order[i]] = Rational(static_cast<int64_t>(i));
  return s;
}

MaybeError parse_order(const Instance& inst, const std::vector<std::string>& names, const std::string& source,
                       long line, std::vector<CouplingId>& order) {
  order.clear();
  std::vector<char> seen(inst.couplings().size(), 0);
  for (const auto& n : names) {
    CouplingId q = inst.find_coupling(n);
    if (q == kNone) return Diagnostic{source, line, "unknown coupling '" + n + "'"};
    if (seen[q]) return Diagnostic{source, line, "coupling '" + n + "' named twice in the order"};
    seen[q] = 1;
    order.push_back(q);
  }
  for (CouplingId q = 0; q < seen.size(); ++q)
    if (!seen[q]) return Diagnostic{source, line, "the order leaves out coupling '" + inst.couplings()[q].name + "'"};
  return std::nullopt;
}

namespace {

// Calls fn(line_no, tokens) for each non-comment line; stops at the first error.
// A line starting with the word "c" is a comment unless is_data(tokens) says
// it is an entry for a coupling named "c" (a valid name, docs/grid-format.md).
template <class IsData, class Fn>
MaybeError for_each_line(const std::string& path, IsData is_data, Fn fn) {
  std::ifstream file;
  std::istream* in = &std::cin;
  std::string name = path == "-" ? "<stdin>" : path;
  if (path != "-") {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) return Diagnostic{path, 0, "is a directory, not a file"};
    file.open(path, std::ios::binary);
    if (!file) return Diagnostic{path, 0, "cannot open file"};
    in = &file;
  }
  std::string text;
  long no = 0;
  while (std::getline(*in, text)) {
    ++no;
    std::istringstream ss(text);
    std::vector<std::string> tok;
    for (std::string w; ss >> w;) tok.push_back(w);
    // As in .grid and DIMACS: UTF-8 (bytes >= 0x80) in comments only.
    const bool comment = !tok.empty() && ((tok[0] == "c" && !is_data(tok)) || tok[0][0] == '#');
    for (size_t k = 0; k < text.size(); ++k) {
      const auto b = static_cast<unsigned char>(text[k]);
      if ((b < 0x20 && b != '\t' && b != '\r') || b == 0x7f || (b >= 0x80 && !comment))
        return Diagnostic{name, no, refused_byte_message(text, k, no)};
    }
    if (tok.empty() || comment) continue;
    if (auto e = fn(name, no, tok)) return e;
  }
  return std::nullopt;
}

// An order line that names couplings only: with a coupling named "c" or
// "s", such a line is part of the order, not a comment or a status line.
bool names_couplings_only(const Instance& inst, const std::vector<std::string>& tok) {
  for (const std::string& w : tok)
    if (inst.find_coupling(w) == kNone) return false;
  return true;
}

// A start time as a times file writes it: an integer or a fraction a/b,
// without '+' (one reading of numbers).
std::optional<Rational> parse_time(const std::string& text) {
  return text[0] == '+' ? std::nullopt : Rational::parse(text);
}

}  // namespace

MaybeError read_order_file(const Instance& inst, const std::string& path, std::vector<CouplingId>& order) {
  // names: a leading "v" dropped (solve's output); kept: a leading "v" kept
  // where the whole line names couplings ("v c s" is the order v, c, s when
  // v is a coupling). At most one of the two lists names every coupling once
  // (kept is longer whenever they differ), so the reading is unambiguous.
  std::vector<std::string> names, kept;
  long last = 0;
  std::string shown = path == "-" ? "<stdin>" : path;
  auto is_data = [&](const std::vector<std::string>& tok) { return names_couplings_only(inst, tok); };
  auto err = for_each_line(path, is_data,
                           [&](const std::string&, long no, std::vector<std::string>& tok) -> MaybeError {
                             last = no;
                             if (tok[0] == "s" && !is_data(tok)) return std::nullopt;
                             if (tok[0] == "v" && is_data(tok)) kept.push_back(tok[0]);
                             size_t i = tok[0] == "v" ? 1 : 0;
                             for (; i < tok.size(); ++i) {
                               names.push_back(tok[i]);
                               kept.push_back(tok[i]);
                             }
                             return std::nullopt;
                           });
  if (err) return err;
  MaybeError dropped = parse_order(inst, names, shown, last, order);
  if (dropped && kept.size() != names.size() && !parse_order(inst, kept, shown, last, order)) return std::nullopt;
  return dropped;
}

std::optional<std::string> check_schedule_bounds(const Instance& inst, const Schedule& s) {
  if (s.start.size() != inst.couplings().size()) return "the schedule does not give every coupling a start time";
  int64_t lcm = 1;
  for (const auto& t : s.start) {
    if (t.num() / t.den() > kMaxStartTime || t.num() / t.den() < -kMaxStartTime)
      return "start time " + t.str() + " out of range (|t| <= 2^30)";
    lcm = std::lcm(lcm, t.den());
    if (lcm > kMaxDenominator) return "the start times' common denominator exceeds 2^20";
  }
  return std::nullopt;
}

MaybeError read_times_file(const Instance& inst, const std::string& path, Schedule& out) {
  out = Schedule{};
  out.start.assign(inst.couplings().size(), Rational(0));
  std::vector<long> line_of(inst.couplings().size(), 0);
  int64_t lcm = 1;
  long last = 0;
  std::string shown = path == "-" ? "<stdin>" : path;
  // "c TIME" is the entry of a coupling named "c" when the instance has one.
  auto is_data = [&](const std::vector<std::string>& tok) {
    return tok.size() == 2 && inst.find_coupling(tok[0]) != kNone && parse_time(tok[1]).has_value();
  };
  auto err = for_each_line(
      path, is_data, [&](const std::string& name, long no, std::vector<std::string>& tok) -> MaybeError {
        last = no;
        // The status line and "v NAME TIME" lines of `gridlock collide` and
        // `gridlock gaps` (a
        // coupling may itself be named "s" or "v": only these exact shapes).
        if (tok[0] == "s" && tok.size() == 2 && (tok[1] == "YES" || tok[1] == "NO" || tok[1] == "UNKNOWN"))
          return std::nullopt;
        if (tok[0] == "v" && tok.size() == 3) tok.erase(tok.begin());
        if (tok.size() != 2) return Diagnostic{name, no, "expected 'COUPLING TIME'"};
        CouplingId q = inst.find_coupling(tok[0]);
        if (q == kNone) return Diagnostic{name, no, "unknown coupling '" + tok[0] + "'"};
        if (line_of[q])
          return Diagnostic{
              name, no,
              "coupling '" + tok[0] + "' given a time twice (first on line " + std::to_string(line_of[q]) + ")"};
        const std::optional<Rational> t = parse_time(tok[1]);
        if (!t) return Diagnostic{name, no, "bad time '" + tok[1] + "' (an integer or a fraction a/b)"};
        if (t->num() / t->den() > kMaxStartTime || t->num() / t->den() < -kMaxStartTime)
          return Diagnostic{name, no, "time out of range: '" + tok[1] + "' (|t| <= 2^30)"};
        lcm = std::lcm(lcm, t->den());
        if (lcm > kMaxDenominator) return Diagnostic{name, no, "the common denominator of the times exceeds 2^20"};
        line_of[q] = no;
        out.start[q] = *t;
        return std::nullopt;
      });
  if (err) return err;
  for (CouplingId q = 0; q < line_of.size(); ++q) {
    if (line_of[q]) continue;
    const std::string& c = inst.couplings()[q].name;
    // A coupling named "c": "c 0.5" is a comment line (its time is not a
    // time), which would otherwise be a silent puzzle.
    return Diagnostic{shown, last,
                      "no start time for coupling '" + c + "'" +
                          (c == "c" ? " (a line 'c TIME' is its entry only with TIME an integer or a fraction a/b; "
                                      "other 'c' lines are comments)"
                                    : "")};
  }
  return std::nullopt;
}

}  // namespace gridlock
