// DIMACS CNF reader; grammar in cnf/dimacs.hpp, messages in docs/formulas.md.
//
// Line by line (so every message has a line number), token by token within
// a line (so clauses may span lines). Nothing is sized from the header: a
// 20-byte file claiming two billion clauses costs nothing.
#include <charconv>
#include <climits>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string_view>

#include "cnf/dimacs.hpp"
#include "common/refused_byte.hpp"

namespace gridlock {

namespace {

constexpr int64_t kMaxCount = INT_MAX;  // variables and clauses: DIMACS literals are C ints

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// Bytes that never occur in a text DIMACS file. Bytes >= 0x80 (UTF-8) are
// tolerated in comments only.
bool is_binary(unsigned char b, bool in_comment) {
  if (b < 0x20) return !is_blank(static_cast<char>(b));
  if (b == 0x7f) return true;
  return b >= 0x80 && !in_comment;
}

// A token as shown in a message: at most 40 bytes (the line is known to be
// printable ASCII by then).
std::string shown(std::string_view tok) {
  if (tok.size() <= 40) return std::string(tok);
  return std::string(tok.substr(0, 40)) + "...";
}

// -?[0-9]+ ; the magnitude saturates instead of overflowing (a saturated
// value is reported "out of range" like any other too large number).
bool parse_integer(std::string_view tok, bool& negative, int64_t& magnitude) {
  size_t i = 0;
  negative = false;
  if (i < tok.size() && tok[i] == '-') {
    negative = true;
    ++i;
  }
  if (i == tok.size()) return false;
  magnitude = 0;
  for (; i < tok.size(); ++i) {
    if (tok[i] < '0' || tok[i] > '9') return false;
    if (magnitude <= INT64_MAX / 16) magnitude = magnitude * 10 + (tok[i] - '0');
  }
  return true;
}

class Reader {
 public:
  Reader(std::istream& in, const std::string& name, const DimacsOptions& opt) : in_(in), name_(name), opt_(opt) {}
  MaybeError run(Formula& out);

 private:
  Diagnostic error(const std::string& msg) const { return Diagnostic{name_, line_no_, msg}; }
  MaybeError header(const std::vector<std::string_view>& tok, std::string_view line);
  MaybeError count(std::string_view tok, const char* what, int64_t& value) const;
  MaybeError literal(std::string_view tok);

  std::istream& in_;
  std::string name_;
  DimacsOptions opt_;
  long line_no_ = 0;
  long header_line_ = 0;  // 0 until the header is read
  int64_t declared_vars_ = 0, declared_clauses_ = 0;
  bool clause_open_ = false;
  long clause_line_ = 0;  // where the open clause started
  std::vector<int> clause_;
  Formula* out_ = nullptr;
};

MaybeError Reader::count(std::string_view tok, const char* what, int64_t& value) const {
  bool neg = false;
  if (!parse_integer(tok, neg, value))
    return error(std::string("expected an integer ") + what + " count in the header, got '" + shown(tok) + "'");
  if (neg && value != 0) value = -value;
  if (value < 0 || value > kMaxCount)
    return error(std::string(what) + " count out of range: '" + shown(tok) + "' (allowed 0 to " +
                 std::to_string(kMaxCount) + ")");
  return std::nullopt;
}

MaybeError Reader::header(const std::vector<std::string_view>& tok, std::string_view line) {
  if (header_line_ > 0) return error("second header line (the first is line " + std::to_string(header_line_) + ")");
  if (tok.size() >= 2 && tok[1] != "cnf")
    return error("unsupported format '" + shown(tok[1]) + "' (expected 'p cnf VARIABLES CLAUSES')");
  if (tok.size() != 4) {
    while (!line.empty() && is_blank(line.back())) line.remove_suffix(1);
    while (!line.empty() && is_blank(line.front())) line.remove_prefix(1);
    return error("expected 'p cnf VARIABLES CLAUSES', got '" + shown(line) + "'");
  }
  if (auto e = count(tok[2], "variable", declared_vars_)) return e;
  if (auto e = count(tok[3], "clause", declared_clauses_)) return e;
  header_line_ = line_no_;
  if (opt_.header_line) *opt_.header_line = line_no_;
  out_->num_vars = static_cast<int>(declared_vars_);
  return std::nullopt;
}

MaybeError Reader::literal(std::string_view tok) {
  bool neg = false;
  int64_t mag = 0;
  if (!parse_integer(tok, neg, mag)) return error("expected an integer literal, got '" + shown(tok) + "'");
  if (neg && mag == 0) return error("'" + shown(tok) + "' is not a literal (0 alone ends a clause)");
  if (header_line_ == 0) return error("missing header 'p cnf VARIABLES CLAUSES' before the first clause");
  if (!clause_open_) {
    if (opt_.strict_count && static_cast<int64_t>(out_->clauses.size()) >= declared_clauses_)
      return error("more clauses than the header's " + std::to_string(declared_clauses_));
    clause_open_ = true;
    clause_line_ = line_no_;
  }
  if (mag == 0) {
    if (opt_.clause_lines) opt_.clause_lines->push_back(clause_line_);
    out_->clauses.push_back(std::move(clause_));
    clause_.clear();
    clause_open_ = false;
    return std::nullopt;
  }
  if (mag > declared_vars_)
    return error("literal '" + shown(tok) + "' out of range: the header declares " + std::to_string(declared_vars_) +
                 " variables");
  int v = static_cast<int>(mag);
  clause_.push_back(neg ? -v : v);
  return std::nullopt;
}

MaybeError Reader::run(Formula& out) {
  out = Formula{};
  out_ = &out;
  if (opt_.clause_lines) opt_.clause_lines->clear();
  std::string line;
  bool any_content = false;
  bool percent = false;
  std::vector<std::string_view> tok;
  while (std::getline(in_, line)) {
    ++line_no_;
    size_t i = 0;
    while (i < line.size() && is_blank(line[i])) ++i;
    const bool comment = i < line.size() && line[i] == 'c';
    for (size_t k = 0; k < line.size(); ++k) {
      auto b = static_cast<unsigned char>(line[k]);
      if (is_binary(b, comment)) return error(refused_byte_message(line, k, line_no_));
    }
    if (i == line.size()) continue;
    any_content = true;
    if (comment) {
      std::string_view text(line);
      text.remove_prefix(i + 1);
      if (!text.empty() && text.front() == ' ') text.remove_prefix(1);
      while (!text.empty() && text.back() == '\r') text.remove_suffix(1);
      out.comments.emplace_back(text);
      continue;
    }
    if (line[i] == '%') {
      percent = true;
      break;
    }
    tok.clear();
    std::string_view rest(line);
    for (size_t k = i; k < rest.size();) {
      while (k < rest.size() && is_blank(rest[k])) ++k;
      size_t start = k;
      while (k < rest.size() && !is_blank(rest[k])) ++k;
      if (k > start) tok.push_back(rest.substr(start, k - start));
    }
    if (tok[0] == "p") {
      if (auto e = header(tok, rest)) return e;
      continue;
    }
    for (auto t : tok)
      if (auto e = literal(t)) return e;
  }
  if (in_.bad()) return error("read error");
  if (header_line_ == 0) {
    if (percent) return error("missing header 'p cnf VARIABLES CLAUSES' before '%'");
    line_no_ = any_content ? 0 : 1;
    return any_content ? error("missing header 'p cnf VARIABLES CLAUSES'") : error("empty input: no 'p cnf' header");
  }
  if (clause_open_) {
    return error(std::string(percent ? "clause not terminated by 0 before '%'" : "last clause not terminated by 0") +
                 " (it starts on line " + std::to_string(clause_line_) + ")");
  }
  if (opt_.strict_count && static_cast<int64_t>(out.clauses.size()) < declared_clauses_)
    return error("unexpected end of clauses: the header declares " + std::to_string(declared_clauses_) +
                 " clauses, the file gives " + std::to_string(out.clauses.size()));
  return std::nullopt;
}

}  // namespace

MaybeError read_dimacs(std::istream& in, const std::string& name, Formula& out, const DimacsOptions& opt) {
  return Reader(in, name, opt).run(out);
}

MaybeError read_dimacs_file(const std::string& path, Formula& out, const DimacsOptions& opt) {
  if (path == "-") return read_dimacs(std::cin, "<stdin>", out, opt);
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return Diagnostic{path, 0, "is a directory, not a file"};
  std::ifstream in(path, std::ios::binary);
  if (!in) return Diagnostic{path, 0, "cannot open file"};
  return read_dimacs(in, path, out, opt);
}

MaybeError read_dimacs_string(const std::string& text, const std::string& name, Formula& out,
                              const DimacsOptions& opt) {
  std::istringstream in(text);
  return read_dimacs(in, name, out, opt);
}

}  // namespace gridlock
