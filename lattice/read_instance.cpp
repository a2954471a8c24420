// Reader of the .grid format; see lattice/grid_format.hpp for the grammar.
#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string_view>

#include "common/refused_byte.hpp"
#include "lattice/grid_format.hpp"

namespace gridlock {

namespace {

// Lines are bounded so that a binary or runaway file is refused before it
// fills memory. Before the header the bound is kMaxLine; after it, a q line
// naming every declared operation (names of at most 64 bytes and a space
// each) must still fit, or write_instance would write files this reader
// refuses: one coupling of 10^5 operations is longer than 1 MiB.
constexpr size_t kMaxLine = 1 << 20;
constexpr size_t kBytesPerOpName = 65;

class Reader {
 public:
  Reader(std::istream& in, const std::string& name) : in_(in), name_(name) {}

  MaybeError run(Instance& out);

 private:
  Diagnostic error(const std::string& msg) const { return Diagnostic{name_, line_no_, msg}; }
  // The header line t ('p grid NODES EDGES OPS COUPLINGS'): sets expect_.
  MaybeError header_line(const std::vector<std::string_view>& t);
  // A line after the header (n, e, o, q or a): adds its item to b_.
  MaybeError item_line(const std::vector<std::string_view>& t);
  // At the end of input: every promised item given, then the instance built.
  MaybeError finish(Instance& out);
  // Counts one more item of kind k (index into expect_); false (err_ set)
  // past the header's count.
  bool count(int k);
  // False (err_ set) unless t has n fields, form being the line's syntax.
  bool want(const std::vector<std::string_view>& t, size_t n, const char* form);
  // Reads the next line into line_; false at end of input. Sets err_ on bad bytes.
  bool next_line();
  bool integer(std::string_view tok, int64_t lo, int64_t hi, const char* what, int64_t& v);
  bool cell(const std::vector<std::string_view>& t, size_t i, Vec2& c);

  std::istream& in_;
  std::string name_;
  std::string line_;
  long line_no_ = 0;
  MaybeError err_;
  InstanceBuilder b_;
  bool header_ = false;
  long anchor_line_ = 0;
  int64_t expect_[4] = {0, 0, 0, 0};  // nodes, edges, ops, couplings
  int64_t seen_[4] = {0, 0, 0, 0};
  static constexpr const char* kWhat[4] = {"nodes", "edges", "operations", "couplings"};
  std::vector<long> node_line_;  // for "not connected" messages
  size_t max_line_ = kMaxLine;   // raised by the header (kMaxLine's comment)
};

bool Reader::next_line() {
  line_.clear();
  if (!in_.good()) return false;
  int ch;
  bool any = false;
  while ((ch = in_.get()) != EOF) {
    any = true;
    if (ch == '\n') break;
    if (line_.size() >= max_line_) {
      ++line_no_;
      err_ = error("line longer than " + std::to_string(max_line_) + " bytes");
      return false;
    }
    line_.push_back(static_cast<char>(ch));
  }
  if (!any) return false;
  ++line_no_;
  if (!line_.empty() && line_.back() == '\r') line_.pop_back();
  // As in DIMACS (cnf/dimacs.hpp): UTF-8 (bytes >= 0x80) in comments only.
  const size_t first = line_.find_first_not_of(" \t");
  const bool comment = first != std::string::npos &&
                       (line_[first] == '#' ||
                        (line_[first] == 'c' &&
                         (first + 1 == line_.size() || line_[first + 1] == ' ' || line_[first + 1] == '\t')));
  for (size_t i = 0; i < line_.size(); ++i) {
    auto b = static_cast<unsigned char>(line_[i]);
    if ((b < 0x20 && b != '\t') || b == 0x7f || (b >= 0x80 && !comment)) {
      err_ = error(refused_byte_message(line_, i, line_no_));
      return false;
    }
  }
  return true;
}

bool Reader::integer(std::string_view tok, int64_t lo, int64_t hi, const char* what, int64_t& v) {
  const char* b = tok.data();
  const char* e = tok.data() + tok.size();
  // No '+' sign: DIMACS and the times files refuse it too (one reading).
  auto [p, ec] = std::from_chars(b, e, v);
  if (ec == std::errc::result_out_of_range || (ec == std::errc() && p == e && (v < lo || v > hi))) {
    err_ = error(std::string(what) + " out of range: '" + std::string(tok) + "' (allowed " + std::to_string(lo) +
                 " to " + std::to_string(hi) + ")");
    return false;
  }
  if (ec != std::errc() || p != e) {
    err_ = error(std::string("expected an integer ") + what + ", got '" + std::string(tok) + "'");
    return false;
  }
  return true;
}

bool Reader::cell(const std::vector<std::string_view>& t, size_t i, Vec2& c) {
  return integer(t[i], -kMaxCoordinate, kMaxCoordinate, "coordinate", c.x) &&
         integer(t[i + 1], -kMaxCoordinate, kMaxCoordinate, "coordinate", c.y);
}

std::vector<std::string_view> split(std::string_view s) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
    size_t j = i;
    while (j < s.size() && s[j] != ' ' && s[j] != '\t') ++j;
    if (j > i) out.push_back(s.substr(i, j - i));
    i = j;
  }
  return out;
}

bool Reader::count(int k) {
  if (++seen_[k] > expect_[k]) {
    err_ = error(std::string("more ") + kWhat[k] + " than the header's " + std::to_string(expect_[k]));
    return false;
  }
  return true;
}

bool Reader::want(const std::vector<std::string_view>& t, size_t n, const char* form) {
  if (t.size() != n) {
    err_ = error(std::string("expected '") + form + "', got " + std::to_string(t.size() - 1) + " fields");
    return false;
  }
  return true;
}

MaybeError Reader::header_line(const std::vector<std::string_view>& t) {
  if (header_) return error("second header line");
  if (!want(t, 6, "p grid NODES EDGES OPS COUPLINGS")) return err_;
  if (t[1] != "grid") return error("header must start 'p grid', got 'p " + std::string(t[1]) + "'");
  for (int k = 0; k < 4; ++k)
    if (!integer(t[2 + static_cast<size_t>(k)], 0, 2 * kMaxNodes, "count", expect_[k])) return err_;
  header_ = true;
  max_line_ = kMaxLine + kBytesPerOpName * static_cast<size_t>(expect_[2]);
  return std::nullopt;
}

MaybeError Reader::item_line(const std::vector<std::string_view>& t) {
  if (!header_)
    return error("missing header 'p grid NODES EDGES OPS COUPLINGS' before the first " + std::string(t[0]) + " line");
  std::optional<std::string> problem;
  switch (t[0][0]) {
    case 'n': {
      Vec2 c;
      if (!want(t, 3, "n X Y") || !cell(t, 1, c) || !count(0)) return err_;
      problem = b_.add_node(c);
      node_line_.push_back(line_no_);
      break;
    }
    case 'e': {
      Vec2 p, q;
      if (!want(t, 5, "e X1 Y1 X2 Y2") || !cell(t, 1, p) || !cell(t, 3, q) || !count(1)) return err_;
      problem = b_.add_edge(p, q);
      break;
    }
    case 'o': {
      Vec2 c;
      if (!want(t, 6, "o NAME expand|grow|contract X Y DIR") || !cell(t, 3, c) || !count(2)) return err_;
      OpKind k;
      if (t[2] == "expand") k = OpKind::Expand;
      else if (t[2] == "grow") k = OpKind::Grow;
      else if (t[2] == "contract") k = OpKind::Contract;
      else return error("unknown operation kind '" + std::string(t[2]) + "' (expand, grow or contract)");
      auto d = parse_dir(t[5]);
      if (!d) return error("bad direction '" + std::string(t[5]) + "' (one of +x, -x, +y, -y)");
      problem = b_.add_op(std::string(t[1]), k, c, *d);
      break;
    }
    case 'q': {
      if (t.size() < 3) return error("expected 'q NAME OP...' with at least one operation");
      if (!count(3)) return err_;
      std::vector<std::string> ops;
      for (size_t i = 2; i < t.size(); ++i) ops.emplace_back(t[i]);
      problem = b_.add_coupling(std::string(t[1]), ops);
      break;
    }
    case 'a': {
      Vec2 c;
      if (anchor_line_ > 0) return error("second anchor line (the first is line " + std::to_string(anchor_line_) + ")");
      anchor_line_ = line_no_;
      if (!want(t, 3, "a X Y") || !cell(t, 1, c)) return err_;
      problem = b_.set_anchor(c);
      break;
    }
    default: return error("unknown line type '" + std::string(t[0]) + "'");
  }
  if (problem) return error(*problem);
  return std::nullopt;
}

MaybeError Reader::finish(Instance& out) {
  if (err_) return err_;
  if (!header_) return Diagnostic{name_, std::max<long>(line_no_, 1), "empty input: no 'p grid' header"};
  for (int k = 0; k < 4; ++k)
    if (seen_[k] < expect_[k])
      return Diagnostic{name_, line_no_,
                        "unexpected end of input: the header promises " + std::to_string(expect_[k]) + " " + kWhat[k] +
                            ", the file gives " + std::to_string(seen_[k]) + " (truncated?)"};
  if (auto fe = b_.finish(out)) {
    long line = fe->node_index >= 0 ? node_line_[static_cast<size_t>(fe->node_index)] : line_no_;
    return Diagnostic{name_, line, fe->message};
  }
  return std::nullopt;
}

MaybeError Reader::run(Instance& out) {
  while (next_line()) {
    auto t = split(line_);
    if (t.empty() || t[0] == "c" || t[0][0] == '#') continue;
    if (t[0].size() != 1) return error("unknown line type '" + std::string(t[0]) + "'");
    if (MaybeError e = t[0][0] == 'p' ? header_line(t) : item_line(t)) return e;
  }
  return finish(out);
}

}  // namespace

MaybeError read_instance(std::istream& in, const std::string& name, Instance& out) {
  Reader r(in, name);
  return r.run(out);
}

MaybeError read_instance_file(const std::string& path, Instance& out) {
  if (path == "-") return read_instance(std::cin, "<stdin>", out);
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return Diagnostic{path, 0, "is a directory, not a file"};
  std::ifstream in(path, std::ios::binary);
  if (!in) return Diagnostic{path, 0, "cannot open file"};
  return read_instance(in, path, out);
}

}  // namespace gridlock
